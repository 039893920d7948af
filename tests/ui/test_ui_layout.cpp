// SPDX-License-Identifier: MIT
// The window reads whole at a projector's sizes: for every stage, desktop and lecture
// mode, English and Swedish, no visible label, button, combo box, table header, tab,
// chart title, axis title, tick label or legend label is cut: its text's width (by
// QFontMetrics, or the rich text's laid-out size) fits its rectangle, and no text Qt
// shortened itself (Qt Charts' axes, titles and legends) shows an ellipsis. Every chart
// page is looked at. The accuracy study and the stability suite open inside the screen.
// The offscreen platform's screen is AB_TEST_SCREEN ("1280x720", default 1920x1080),
// given to Qt through its configuration file (Qt 6.4's offscreen plugin reads one). With
// AB_TEST_X11 set it runs on the X server it is started in (xvfb-run, a screen of that size).
#include "ui/export_options_dialog.h"
#include "ui/i18n/language.h"
#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/shell/window_shell.h"
#include "ui/tools/stability_dialog.h"
#include "ui/tools/study_dialog.h"
#include "ui/video/animation_dialog.h"

#include "support/cut_text.h"

#include <QDir>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabBar>
#include <QtTest>

using ab::SceneId;
using ab::ui::Language;
using testing::cutAtViewport;
using testing::cutTexts;

namespace {

QSize screenSize()
{
    const QByteArray wanted = qgetenv("AB_TEST_SCREEN");
    const QList<QByteArray> parts = (wanted.isEmpty() ? QByteArray("1920x1080") : wanted).split('x');
    return parts.size() == 2 ? QSize(parts[0].toInt(), parts[1].toInt()) : QSize(1920, 1080);
}

void settle()
{
    for (int i = 0; i < 4; ++i) {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
    }
}

// A window in the row's language, mode and stage, a short run behind its charts.
struct Arranged {
    std::unique_ptr<ab::ui::WindowShell> shell;
    ab::ui::MainWindow* window = nullptr;
    bool ran = false; // the 200 steps came
};

Arranged arrange(SceneId scene, bool lecture, Language language)
{
    Arranged a;
    a.shell = std::make_unique<ab::ui::WindowShell>();
    a.shell->setLanguage(language);
    ab::ui::MainWindow& w = a.shell->window();
    w.resize(screenSize());
    w.move(0, 0);
    w.show();
    if (lecture)
        a.shell->lecture().setActive(true);
    w.showScene(scene);
    if (scene == SceneId::Street) {
        // 1,000 balls: the layout is the same, and a sanitizer build steps 10,000 too slowly.
        ab::RunSpec spec = w.controller().spec();
        spec.params.parseAssignment("n=1000");
        w.controller().setRun(spec, w.controller().plannedSteps());
    }
    settle();
    for (int i = 0; i < 200; ++i)
        w.controller().stepOnce();
    a.ran = QTest::qWaitFor([&] { return w.controller().status().steps >= 200; }, 60000); // a loaded machine
    w.controller().poll();
    settle();
    a.window = &w;
    return a;
}

void addRows()
{
    QTest::addColumn<SceneId>("scene");
    QTest::addColumn<bool>("lecture");
    QTest::addColumn<Language>("language");
    for (const ab::SceneInfo* s : ab::allScenes())
        for (bool lecture : {false, true})
            for (Language language : {Language::English, Language::Swedish})
                QTest::newRow(qPrintable(QStringLiteral("stage %1 %2 %3")
                                             .arg(s->stage)
                                             .arg(lecture ? "lecture" : "desktop")
                                             .arg(ab::ui::languageCode(language))))
                    << s->id << lecture << language;
}

// The window of the current data row (stage, mode and language), arranged.
Arranged arrangeRow()
{
    QFETCH(SceneId, scene);
    QFETCH(bool, lecture);
    QFETCH(Language, language);
    return arrange(scene, lecture, language);
}

} // namespace

class UiLayout : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { ab::ui::installLanguage(Language::English); }

    void theScreenIsTheOneAsked() { QCOMPARE(QGuiApplication::primaryScreen()->geometry().size(), screenSize()); }

    void aWindowThatGrowsWidensTheSettingsColumnToItsChoices()
    {
        // Opened small and then maximised, the settings column took none of the new width
        // and scrolled sideways, its choices and "Report values" cut at its edge.
        ab::ui::WindowShell shell;
        ab::ui::MainWindow& w = shell.window();
        w.showScene(SceneId::Box3d);
        w.resize(900, 600);
        w.move(0, 0);
        w.show();
        settle();
        auto* settings = w.findChild<QScrollArea*>("settingsScroll");
        QVERIFY(settings);
        w.resize(screenSize());
        // As wide as its choices where that is at most 30 % of the window, else those 30 %,
        // where the choices still fit whole: no sideways scroll at 1280 px either.
        const int need = settings->widget()->minimumWidth() + settings->verticalScrollBar()->sizeHint().width();
        const int expected = std::min(need, int(0.3 * screenSize().width()));
        QTRY_VERIFY2(
            settings->width() >= expected - 2,
            qPrintable(QStringLiteral("settings column %1 px, expected %2").arg(settings->width()).arg(expected)));
        settle();
        QVERIFY(!settings->horizontalScrollBar()->isVisible());
        settle();
        for (SceneId scene : {SceneId::Bounce1d, SceneId::Box3d, SceneId::TwoBalls, SceneId::ManyBalls}) {
            w.showScene(scene);
            settle();
            QVERIFY(!settings->horizontalScrollBar()->isVisible());
            const QStringList cut = cutAtViewport(settings);
            QVERIFY2(cut.isEmpty(), qPrintable(cut.join("\n")));
        }
    }

    void noTextIsCutOnAnyChartPage_data() { addRows(); }
    void noTextIsCutOnAnyChartPage()
    {
        Arranged a = arrangeRow();
        QVERIFY(a.ran);
        ab::ui::MainWindow& w = *a.window;
        QVERIFY(w.frameGeometry().width() <= screenSize().width());
        QTabBar* pages = w.charts()->pages();
        const int count = std::max(pages->count(), 1);
        QStringList cut;
        for (int page = 0; page < count; ++page) {
            if (pages->count() > 0)
                pages->setCurrentIndex(page);
            settle();
            cut << cutTexts(&w);
        }
        cut.removeDuplicates();
        QVERIFY2(cut.isEmpty(), qPrintable(cut.join("\n")));
        // The status bar's last reading ends clear of the window's right edge (in lecture mode
        // at 1280x720 its "unit²/step²" touched the screen's edge).
        const auto* energy = w.findChild<QLabel*>("statusEnergy");
        QVERIFY(energy && energy->isVisible());
        const int textEnd = energy->mapTo(&w, QPoint(0, 0)).x() + energy->contentsMargins().left() +
                            energy->fontMetrics().horizontalAdvance(energy->text());
        QVERIFY2(textEnd <= w.width() - 6,
                 qPrintable(QString("%1 ends at %2 of %3").arg(energy->text()).arg(textEnd).arg(w.width())));
        // Every chart the stage shows is on some page.
        int onPages = 0;
        for (int page = 0; page < count; ++page) {
            if (pages->count() > 0)
                pages->setCurrentIndex(page);
            for (ab::ui::ChartKind kind : w.charts()->shownCharts())
                onPages += w.charts()->onCurrentPage(kind) ? 1 : 0;
        }
        QCOMPARE(onPages, int(w.charts()->shownCharts().size()));
    }

    void exportMenuOffersTheStagesChartsOnly_data()
    {
        QTest::addColumn<SceneId>("scene");
        QTest::addColumn<QStringList>("expected");
        const QStringList motion{"export-position", "export-velocity", "export-energy"};
        // Stages 1-3 have a closed form: the difference chart shows the run minus it.
        const QStringList difference{"export-difference"};
        QTest::newRow("stage 1") << SceneId::Bounce1d << (motion + difference);
        QTest::newRow("stage 2") << SceneId::Box3d << (motion + difference);
        QTest::newRow("stage 3") << SceneId::TwoBalls << (motion + QStringList{"export-momentum"} + difference);
        QTest::newRow("stage 4") << SceneId::ManyBalls << (motion + QStringList{"export-momentum", "export-activity"});
        // The street's balls turn (mu > 0): the spin chart; and its own flood charts.
        QTest::newRow("stage 5") << SceneId::Street
                                 << QStringList{"export-position", "export-velocity",  "export-spin",
                                                "export-energy",   "export-foot-rate", "export-speeds"};
    }
    void exportMenuOffersTheStagesChartsOnly()
    {
        QFETCH(SceneId, scene);
        QFETCH(QStringList, expected);
        ab::ui::WindowShell shell;
        ab::ui::MainWindow& w = shell.window();
        w.showScene(scene);
        auto* menu = w.findChild<QMenu*>("exportChartMenu");
        QVERIFY(menu);
        emit menu->aboutToShow();
        QStringList offered;
        for (QAction* a : menu->actions())
            offered << a->objectName();
        QCOMPARE(offered, expected);
        // A chart hidden from the View menu is not offered either.
        w.charts()->setChartShown(ab::ui::ChartKind::Velocity, false);
        emit menu->aboutToShow();
        offered.clear();
        for (QAction* a : menu->actions())
            offered << a->objectName();
        expected.removeAll("export-velocity");
        QCOMPARE(offered, expected);
    }

    void dialogsOpenInsideTheScreenAndReadWhole_data() { addRows(); }
    void dialogsOpenInsideTheScreenAndReadWhole()
    {
        Arranged a = arrangeRow();
        QVERIFY(a.ran);
        ab::ui::MainWindow& w = *a.window;
        const QRect screen = w.screen()->availableGeometry();
        std::vector<std::unique_ptr<QDialog>> dialogs;
        dialogs.push_back(std::make_unique<ab::ui::StudyDialog>(w.controller().spec(), &w));
        dialogs.push_back(std::make_unique<ab::ui::StabilityDialog>(w.scene(), &w));
        dialogs.push_back(std::make_unique<ab::ui::ExportOptionsDialog>(ab::ui::ChartExportChoice{}, true, &w));
        dialogs.push_back(
            std::make_unique<ab::ui::AnimationDialog>(0.0, 30.0, 1.0, "s", ab::ui::AnimationChoice{}, &w));
        for (const auto& dialog : dialogs) {
            dialog->show();
            settle();
            QVERIFY2(screen.contains(dialog->frameGeometry()),
                     qPrintable(QStringLiteral("%1 at %2,%3 %4x%5 on a %6x%7 screen")
                                    .arg(dialog->windowTitle())
                                    .arg(dialog->frameGeometry().x())
                                    .arg(dialog->frameGeometry().y())
                                    .arg(dialog->frameGeometry().width())
                                    .arg(dialog->frameGeometry().height())
                                    .arg(screen.width())
                                    .arg(screen.height())));
            const QStringList cut = cutTexts(dialog.get());
            QVERIFY2(cut.isEmpty(), qPrintable(cut.join("\n")));
            dialog->close();
        }
    }
};

int main(int argc, char** argv)
{
    // AB_TEST_X11: the X server the test runs in (xvfb-run with a screen of AB_TEST_SCREEN's
    // size), whose window system lays the window out as a user's desktop does.
    if (qEnvironmentVariableIsSet("AB_TEST_X11")) {
        qputenv("QT_QPA_PLATFORM", "xcb");
        QApplication app(argc, argv);
        UiLayout test;
        return QTest::qExec(&test, argc, argv);
    }
    // The offscreen platform with one screen of the size asked, no window frames.
    const QSize size = screenSize();
    const QString config = QDir::temp().filePath(QStringLiteral("amazeballs-layout-%1x%2-%3.json")
                                                     .arg(size.width())
                                                     .arg(size.height())
                                                     .arg(QCoreApplication::applicationPid()));
    QFile file(config);
    if (!file.open(QIODevice::WriteOnly))
        return 1;
    file.write(QStringLiteral("{\"windowFrameMargins\": false, \"screens\": [{\"name\": \"projector\", \"x\": 0, "
                              "\"y\": 0, \"width\": %1, \"height\": %2, \"logicalDpi\": 96, \"logicalBaseDpi\": 96, "
                              "\"dpr\": 1}]}")
                   .arg(size.width())
                   .arg(size.height())
                   .toUtf8());
    file.close();
    qputenv("QT_QPA_PLATFORM", ("offscreen:configfile=" + config).toLocal8Bit());
    QApplication app(argc, argv);
    UiLayout test;
    const int status = QTest::qExec(&test, argc, argv);
    QFile::remove(config);
    return status;
}

#include "test_ui_layout.moc"
