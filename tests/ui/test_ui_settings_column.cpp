// SPDX-License-Identifier: MIT
// The settings column on a long stage (the street's): a refused entry's reason stands under
// its field, scrolled into sight; a wheel turned over a choice scrolls the column and leaves
// the choice alone, which the keys or a click still change; Ctrl+E in a field exports; a
// comma in a number is never dropped: named in English, the decimal comma in Swedish.
#include "ui/i18n/language.h"
#include "ui/main_window.h"
#include "ui/panels/parameter_panel.h"
#include "ui/sim/run_controller.h"

#include "tests/support/window_helpers.h"

#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QWheelEvent>
#include <QtTest>

using ab::SceneId;
using ab::ui::MainWindow;
using testing::typeInto;

class UiSettingsColumn : public QObject {
    Q_OBJECT

private slots:
    void cleanup() { ab::ui::installLanguage(ab::ui::Language::English); }

    void aCommaInANumberIsNeverDropped()
    {
        // "9,81" typed into g: the comma was refused as a keystroke and g became 981, unseen.
        // In English a comma may group thousands ("2,000"): it stays and the entry is named,
        // nothing applied. In Swedish it is the decimal comma: read as the point and shown so.
        // In a vector it parts the components; a count names "1,5" instead of taking 15.
        MainWindow w;
        w.show();
        w.showScene(SceneId::Box3d);
        QLineEdit* g = w.parameters()->field("g");
        typeInto(g, "9,81");
        QCOMPARE(g->text(), QString("9,81"));
        QVERIFY2(w.parameters()->errorText().contains("'9,81' is not a number"),
                 qPrintable(w.parameters()->errorText()));
        QCOMPARE(w.controller().spec().params.real("g"), 9.82); // nothing applied
        QLineEdit* p0 = w.parameters()->field("p0");
        typeInto(p0, "5,6,7");
        QCOMPARE(p0->text(), QString("5,6,7"));
        ab::ui::installLanguage(ab::ui::Language::Swedish);
        typeInto(g, "9,81");
        QCOMPARE(g->text(), QString("9.81"));
        QCOMPARE(w.controller().spec().params.real("g"), 9.81);
        QVERIFY2(w.parameters()->errorText().isEmpty(), qPrintable(w.parameters()->errorText()));
        w.showScene(SceneId::ManyBalls);
        const ab::ParamValues before = w.controller().spec().params;
        QLineEdit* n = w.parameters()->field("n");
        typeInto(n, "1,5");
        QCOMPARE(n->text(), QString("1.5"));
        QVERIFY2(w.parameters()->errorText().contains("1.5"), qPrintable(w.parameters()->errorText()));
        QVERIFY(w.controller().spec().params == before); // nothing applied
    }

    void aRefusedEntrysReasonIsShownUnderItsFieldInSight()
    {
        // The street's slope is far down a long panel: its reason stands right under it, in
        // the panel's visible part, not at the panel's foot below the fold.
        MainWindow w;
        w.resize(1280, 720);
        w.showScene(SceneId::Street);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QLineEdit* slope = w.parameters()->field("slope");
        auto* note = w.findChild<QLabel*>("paramError-slope");
        QVERIFY(slope && note && note->isHidden());
        typeInto(slope, "-5");
        QCOMPARE(w.controller().spec().params.real("slope"), 17.0); // nothing applied
        QVERIFY(QTest::qWaitFor([&] { return note->isVisible(); }));
        QVERIFY2(note->text().startsWith("Not applied: slope: -5"), qPrintable(note->text()));
        QApplication::processEvents(); // the scroll to the reason
        const QPoint below = note->mapTo(slope->parentWidget(), QPoint(0, 0));
        QVERIFY(below.y() > slope->geometry().bottom() && below.y() - slope->geometry().bottom() < 40);
        auto* area = w.findChild<QScrollArea*>("settingsScroll");
        QVERIFY(area);
        const QRect seen = area->viewport()->rect();
        const QRect noteRect(note->mapTo(area->viewport(), QPoint(0, 0)), note->size());
        QVERIFY2(seen.contains(noteRect), qPrintable(QString("note at %1,%2 %3x%4 in a viewport of height %5")
                                                         .arg(noteRect.x())
                                                         .arg(noteRect.y())
                                                         .arg(noteRect.width())
                                                         .arg(noteRect.height())
                                                         .arg(seen.height())));
        QVERIFY(w.findChild<QLabel*>("parameterError")->isHidden()); // nothing for the whole panel
    }

    void aWheelOverAChoiceScrollsTheSettingsAndChangesNothing()
    {
        // Scrolling down the settings column with the wheel passes over the model, integrator
        // and impacts choices: the column scrolls, the choice stays.
        MainWindow w;
        w.resize(1280, 720);
        w.showScene(SceneId::Street); // its impacts are the physical model's, open to change
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* area = w.findChild<QScrollArea*>("settingsScroll");
        auto* impacts = w.findChild<QComboBox*>("impactsCombo");
        QVERIFY(area && impacts && impacts->isEnabled());
        QVERIFY(area->verticalScrollBar()->maximum() > 0);
        const int choice = impacts->currentIndex(), scrolled = area->verticalScrollBar()->value();
        auto wheel = [&] {
            const QPointF at(impacts->width() / 2.0, impacts->height() / 2.0);
            QWheelEvent down(at, impacts->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                             Qt::NoScrollPhase, false);
            QApplication::sendEvent(impacts, &down);
        };
        wheel();
        QCOMPARE(impacts->currentIndex(), choice);
        QVERIFY(area->verticalScrollBar()->value() > scrolled);
        // Focused or not (the filter asks no focus: a turn would start the run again). The keys
        // still choose.
        QTest::keyClick(impacts, Qt::Key_Down);
        QVERIFY(impacts->currentIndex() != choice);
    }

    void ctrlWithALetterInAFieldIsTheWindowsShortcut()
    {
        // Typing a value, then Ctrl+E to export the chart: the field must not take Ctrl+E as
        // X11's "end of line" (nothing opened). It keeps the keys it edits by.
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QLineEdit* field = w.parameters()->field("k");
        QVERIFY(field);
        auto claimed = [&](int key, Qt::KeyboardModifiers modifiers) {
            QKeyEvent override(QEvent::ShortcutOverride, key, modifiers);
            override.ignore();
            QApplication::sendEvent(field, &override);
            return override.isAccepted();
        };
        QVERIFY(!claimed(Qt::Key_E, Qt::ControlModifier));
        QVERIFY(!claimed(Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier));
        QVERIFY(claimed(Qt::Key_C, Qt::ControlModifier));    // copy
        QVERIFY(claimed(Qt::Key_Z, Qt::ControlModifier));    // undo
        QVERIFY(claimed(Qt::Key_Left, Qt::ControlModifier)); // a word back
    }
};

QTEST_MAIN(UiSettingsColumn)
#include "test_ui_settings_column.moc"
