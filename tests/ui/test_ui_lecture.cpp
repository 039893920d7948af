// SPDX-License-Identifier: MIT
// Lecture mode and the themes on the offscreen platform: the walk reveals a stage's
// equations one at a time, then opens the next stage, and backward retraces it; the
// clicker's keys drive it only in lecture mode; the themes set the palette and the
// charts' colours (high-contrast text against its background above WCAG's 7:1); the
// lecture scale enlarges fonts and chart lines without compounding; the colour-blind-safe
// palette draws every coloured line in an Okabe-Ito hue.
#include "ui/charts/motion_chart.h"
#include "ui/lecture/lecture_mode.h"
#include "ui/main_window.h"
#include "ui/panels/equation_rows.h"
#include "ui/panels/stage_navigator.h"
#include "ui/shell/window_shell.h"
#include "ui/theme/theme.h"

#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTextLayout>
#include <QValueAxis>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <set>

using ab::SceneId;
using ab::ui::MainWindow;
using ab::ui::StageNavigator;
using ab::ui::Theme;

namespace {

// WCAG 2 relative luminance and contrast ratio (www.w3.org/TR/WCAG20/#relativeluminancedef).
double luminance(const QColor& c)
{
    auto channel = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
}

double contrast(const QColor& a, const QColor& b)
{
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

// Which of the stage's equations the navigator shows, by their formula and number.
std::vector<bool> shownEquations(const StageNavigator& nav)
{
    std::vector<bool> shown;
    const QString text = nav.text();
    for (const ab::Equation& e : ab::sceneInfo(nav.current()).equations)
        shown.push_back(text.contains(QStringLiteral("(%1)").arg(QString::fromStdString(e.number))) &&
                        text.contains(ab::ui::formulaTypography(QString::fromStdString(e.text))));
    return shown;
}

std::vector<bool> firstShown(const StageNavigator& nav, int count)
{
    std::vector<bool> expected(ab::sceneInfo(nav.current()).equations.size(), false);
    std::fill_n(expected.begin(), count, true);
    return expected;
}

void activate(QWidget& w)
{
    w.show();
    QApplication::setActiveWindow(&w);
    QVERIFY(QTest::qWaitForWindowActive(&w));
}

// Whether the navigator's text shows the whole first line holding `needle` (its block's
// first line, at least): between the top of the scrolled view and its bottom.
bool lineInSight(const QTextBrowser& text, const QString& needle)
{
    const QTextDocument& doc = *text.document();
    const QTextBlock block = doc.find(needle).block();
    if (!block.isValid() || !block.layout() || block.layout()->lineCount() == 0)
        return false;
    const double top = doc.documentLayout()->blockBoundingRect(block).top() + block.layout()->lineAt(0).y();
    const double bottom = top + block.layout()->lineAt(0).height();
    const int from = text.verticalScrollBar()->value();
    return top >= from && bottom <= from + text.viewport()->height();
}

ab::ui::MotionChart* positionChart(MainWindow& w)
{
    return w.charts()->chart(ab::ui::ChartKind::Position);
}

} // namespace

class UiLecture : public QObject {
    Q_OBJECT
private slots:
    void formulasAreSetWithTheirSymbols()
    {
        // The formulas are typed in ASCII (the core's, the street's and the navigator's); the
        // window sets them as a page prints them, as the spin rows already were ("ω²").
        using ab::ui::formulaTypography;
        const QList<QPair<QString, QString>> cases = {
            {"mu >= q tan(theta) / (1 + q)", "\u03bc \u2265 q tan(\u03b8) / (1 + q)"},
            {"a = g (sin(theta) - mu cos(theta)),  domega/dt = mu g cos(theta) / (q r)",
             "a = g (sin(\u03b8) \u2212 \u03bc cos(\u03b8)),  d\u03c9/dt = \u03bc g cos(\u03b8) / (q r)"},
            {"p(t) = p0 + v0 t + g t^2 / 2", "p(t) = p0 + v0 t + g t\u00b2 / 2"},
            {"tz = (-(n.x 0.3) - (n.y 0.3)) / n.z", "tz = (\u2212(n.x 0.3) \u2212 (n.y 0.3)) / n.z"},
            {"v_n' = -e v_n,  Walton's tangential impulse (S9-S10)",
             "v_n' = \u2212e v_n,  Walton's tangential impulse (S9-S10)"}, // a range keeps its hyphen
            {"v = sqrt(2 a L)", "v = \u221a(2 a L)"},
            {"p <= 0 and v != 0 -> v1 = -k v0", "p \u2264 0 and v \u2260 0 \u2192 v1 = \u2212k v0"},
            {"mu_s, x^23, mutual impulse computed, betas, dmu2",
             "\u03bc_s, x^23, mutual impulse computed, betas, dmu2"},
        };
        for (const auto& [ascii, printed] : cases)
            QCOMPARE(formulaTypography(ascii), printed);
        // Every stage's formulas: no Greek name, power or minus left in ASCII.
        const QRegularExpression ascii(QStringLiteral("\\b(theta|mu|omega|beta)\\b|\\^[23]|(^| )-[ (a-z0-9]|<=|>="));
        for (const ab::SceneInfo* scene : ab::allScenes())
            for (const ab::Equation& e : scene->equations) {
                const QString set = formulaTypography(QString::fromStdString(e.text));
                QVERIFY2(!ascii.match(set).hasMatch(), qPrintable(set));
            }
    }

    void aFormulaBreaksOnlyBetweenItsParts()
    {
        // The navigator at lecture size in a narrow column: a formula's line may end after a
        // comma that closes one relation, before "=", "+", "-" or "/", between words of prose
        // beside it or before a note in brackets, never inside a product ("mu" | "g cos(theta)"
        // before), a short bracket ("(1" | "+ q)") or a name.
        QTextDocument doc;
        QFont big = QApplication::font();
        big.setPointSizeF(big.pointSizeF() * ab::ui::LectureMode::scale);
        doc.setDefaultFont(big);
        const QRegularExpression prose(QStringLiteral("^[A-Za-z']{4,}$"));      // words beside a formula
        const QRegularExpression note(QStringLiteral("^\\([A-Za-z']{4,}\\)$")); // "(normalised)"
        int breaks = 0;
        for (const ab::SceneInfo* scene : ab::allScenes()) {
            doc.setHtml(ab::ui::StageNavigator::describe(*scene));
            doc.setTextWidth(380.0);              // the navigator's column in lecture mode at 1280x720
            doc.documentLayout()->documentSize(); // laid out
            for (QTextBlock b = doc.begin(); b.isValid(); b = b.next()) {
                const QString shown = b.text(),
                              text = QString(shown).replace(QChar(0x00A0), QLatin1Char(' ')).remove(QChar(0x2060));
                const bool formula =
                    std::any_of(scene->equations.begin(), scene->equations.end(), [&](const ab::Equation& e) {
                        return ab::ui::formulaTypography(QString::fromStdString(e.text)) == text;
                    });
                if (!formula)
                    continue;
                for (int i = 1; i < b.layout()->lineCount(); ++i) {
                    const int at = b.layout()->lineAt(i).textStart(); // in the text as shown
                    const auto plain = [](QString t) {
                        return t.replace(QChar(0x00A0), QLatin1Char(' ')).remove(QChar(0x2060)).trimmed();
                    };
                    const QString before = plain(shown.left(at)), after = plain(shown.mid(at));
                    const bool clean = before.endsWith(',') || after.startsWith("= ") || after.startsWith("+ ") ||
                                       after.startsWith("- ") || after.startsWith("\u2212 ") ||
                                       after.startsWith("/ ") || after.startsWith("<") || after.startsWith("\u2264") ||
                                       note.match(after.section(' ', 0, 0)).hasMatch() ||
                                       (prose.match(before.section(' ', -1)).hasMatch() &&
                                        prose.match(after.section(' ', 0, 0)).hasMatch());
                    QVERIFY2(clean, qPrintable(QString("%1 | %2").arg(before, after)));
                    QVERIFY2(!shown.at(at).isSpace(), qPrintable(after)); // no line starts indented
                    // A short bracket ("(1 + q)") is one term: the break is not inside one.
                    const int opened = int(before.count('(')) - int(before.count(')'));
                    QVERIFY2(opened <= 0 || before.size() - before.lastIndexOf('(') + after.indexOf(')') > 16,
                             qPrintable(QString("%1 | %2").arg(before, after)));
                    ++breaks;
                }
            }
        }
        QVERIFY2(breaks >= 3, qPrintable(QString::number(breaks))); // long formulas did break
    }

    void walkRevealsEquationsOneAtATimeThenOpensTheNextStage()
    {
        MainWindow w;
        ab::ui::LectureMode lecture;
        lecture.attach(&w, w.navigator());
        lecture.setActive(true);
        StageNavigator& nav = *w.navigator();
        QCOMPARE(nav.current(), SceneId::Bounce1d);
        const int count = nav.equationCount();
        QVERIFY(count >= 2);
        for (int k = 0; k <= count; ++k) {
            QCOMPARE(nav.revealed(), k);
            QCOMPARE(shownEquations(nav), firstShown(nav, k));
            QCOMPARE(nav.text().contains(QStringLiteral("Notes on the report")), k == count); // notes after the last
            QCOMPARE(nav.text().contains(QStringLiteral("Equations")), k > 0);                // no heading over nothing
            lecture.next();
        }
        QCOMPARE(nav.current(), SceneId::Box3d);
        QCOMPARE(w.scene(), SceneId::Box3d); // the window runs the stage, not just the text
        QCOMPARE(nav.revealed(), 0);
        QCOMPARE(shownEquations(nav), firstShown(nav, 0));
    }

    void walkEndsAtTheLastStagesLastEquation()
    {
        // Back goes nowhere before stage 1's first equation, Next nowhere after the street's
        // last: each is greyed out there, and the walk says it is over rather than promise a
        // next stage.
        MainWindow w;
        ab::ui::LectureMode lecture;
        lecture.attach(&w, w.navigator());
        lecture.setActive(true);
        StageNavigator& nav = *w.navigator();
        auto* back = nav.findChild<QPushButton*>("walkBack");
        auto* next = nav.findChild<QPushButton*>("walkNext");
        auto* progress = nav.findChild<QLabel*>("walkProgress");
        QVERIFY(back && next && progress);
        QCOMPARE(nav.current(), SceneId::Bounce1d);
        QVERIFY(!back->isEnabled() && next->isEnabled());
        w.showScene(SceneId::Street);
        QCOMPARE(nav.current(), SceneId::Street);
        const int count = nav.equationCount();
        for (int k = 0; k < count; ++k) {
            QVERIFY(next->isEnabled());
            next->click();
        }
        QCOMPARE(nav.revealed(), count);
        QVERIFY(!next->isEnabled() && back->isEnabled());
        QVERIFY2(!progress->text().contains("next stage"), qPrintable(progress->text()));
        QVERIFY2(progress->text().contains("over"), qPrintable(progress->text()));
        lecture.next(); // a clicker's Next at the end changes nothing
        QCOMPARE(nav.current(), SceneId::Street);
        QCOMPARE(nav.revealed(), count);
        back->click();
        QCOMPARE(nav.revealed(), count - 1);
        QVERIFY(next->isEnabled());
    }

    void walkBackRetracesTheWalkForward()
    {
        MainWindow w;
        ab::ui::LectureMode lecture;
        lecture.attach(&w, w.navigator());
        lecture.setActive(true);
        StageNavigator& nav = *w.navigator();
        const int count = nav.equationCount();
        for (int k = 0; k < count + 2; ++k)
            lecture.next(); // stage 2, first equation shown
        QCOMPARE(nav.current(), SceneId::Box3d);
        QCOMPARE(nav.revealed(), 1);
        lecture.previous();
        QCOMPARE(nav.revealed(), 0);
        lecture.previous(); // back into stage 1 with every equation shown
        QCOMPARE(nav.current(), SceneId::Bounce1d);
        QCOMPARE(w.scene(), SceneId::Bounce1d);
        QCOMPARE(nav.revealed(), count);
        QCOMPARE(shownEquations(nav), firstShown(nav, count));
        lecture.previous();
        QCOMPARE(nav.revealed(), count - 1);
        QCOMPARE(shownEquations(nav), firstShown(nav, count - 1));
    }

    void keysHelpSaysWhatTheKeysDoAndFitsTheScreen()
    {
        // Help > Keys and mouse in lecture mode: Space and the arrows walk the equations there
        // (it said "Right: one step"), and the box fits the screen's free height at lecture
        // size (it was 787 px tall on a 720 px screen, its OK button off the bottom).
        ab::ui::WindowShell shell;
        MainWindow& w = shell.window();
        w.show();
        auto* keys = [&]() -> QAction* {
            for (QAction* a : w.findChildren<QAction*>())
                if (a->text() == QStringLiteral("Keys and mouse"))
                    return a;
            return nullptr;
        }();
        QVERIFY(keys);
        auto shown = [&] {
            keys->trigger();
            auto* dialog = w.findChild<QDialog*>("keysDialog");
            auto* text = dialog ? dialog->findChild<QTextBrowser*>("keysText") : nullptr;
            return std::pair{dialog, text ? text->toPlainText() : QString()};
        };
        auto [plain, plainText] = shown();
        QVERIFY(plain && plainText.contains("one step") && !plainText.contains("lecture mode"));
        delete plain;
        shell.lecture().setActive(true);
        auto [lecture, lectureText] = shown();
        QVERIFY(lecture);
        QVERIFY2(lectureText.contains("the next equation") && !lectureText.contains("one step"),
                 qPrintable(lectureText));
        const QRect screen = w.screen()->availableGeometry();
        QVERIFY2(lecture->height() <= screen.height() - 40,
                 qPrintable(QString("%1 of %2").arg(lecture->height()).arg(screen.height())));
        delete lecture;
        shell.lecture().setActive(false);
    }

    void walkKeepsTheTitleThenTheNewestEquationInSight()
    {
        // Lecture mode's fonts in a small full screen: the stage's text is longer than its panel.
        ab::ui::WindowShell shell;
        MainWindow& w = shell.window();
        shell.lecture().setActive(true);
        activate(w);
        StageNavigator& nav = *w.navigator();
        auto* text = nav.findChild<QTextBrowser*>("stageText");
        QVERIFY(text);
        const ab::SceneInfo& info = ab::sceneInfo(nav.current());
        const QString title = QStringLiteral("Stage %1: ").arg(info.stage);
        QTRY_VERIFY(lineInSight(*text, title)); // the title's first line, not scrolled past
        QCOMPARE(text->verticalScrollBar()->value(), 0);
        bool overflowed = false;
        for (int k = 1; k <= nav.equationCount(); ++k) {
            shell.lecture().next();
            const ab::Equation& e = info.equations[static_cast<std::size_t>(k - 1)];
            const QString number = QStringLiteral("(%1)").arg(QString::fromStdString(e.number));
            QTRY_VERIFY2(lineInSight(*text, number), qPrintable(number));
            overflowed = overflowed || text->verticalScrollBar()->maximum() > 0;
        }
        QVERIFY(overflowed); // else nothing here needed scrolling
        shell.lecture().previous();
        QTRY_VERIFY(lineInSight(*text, QStringLiteral("(%1)").arg(QString::fromStdString(
                                           info.equations[static_cast<std::size_t>(nav.equationCount() - 2)].number))));
        while (nav.revealed() > 0)
            shell.lecture().previous();
        QTRY_VERIFY(lineInSight(*text, title));
    }

    void outsideTheWalkTheNavigatorShowsEveryEquation()
    {
        MainWindow w;
        StageNavigator& nav = *w.navigator();
        QVERIFY(!nav.walking());
        QCOMPARE(nav.revealed(), nav.equationCount());
        QCOMPARE(shownEquations(nav), firstShown(nav, nav.equationCount()));
        nav.stepForward(); // a whole stage
        QCOMPARE(nav.current(), SceneId::Box3d);
    }

    void clickerKeysDriveTheWalkInLectureModeOnly()
    {
        ab::ui::WindowShell shell;
        MainWindow& w = shell.window();
        activate(w);
        StageNavigator& nav = *w.navigator();
        // Outside lecture mode Space keeps its meaning (play / pause) and PageDown opens the next stage.
        QTest::keyClick(&w, Qt::Key_Space);
        QVERIFY(w.controller().playing());
        QTest::keyClick(&w, Qt::Key_Space);
        QVERIFY(!w.controller().playing());
        QTest::keyClick(&w, Qt::Key_PageDown);
        QCOMPARE(nav.current(), SceneId::Box3d);
        QTest::keyClick(&w, Qt::Key_PageUp);
        QCOMPARE(nav.current(), SceneId::Bounce1d);

        shell.lecture().setActive(true);
        QVERIFY(w.isFullScreen());
        // A text field with the focus keeps Space and the arrows for typing; PageDown still walks.
        QLineEdit* field = w.findChild<QLineEdit*>("param-k");
        QVERIFY(field);
        activate(w);                     // full screen may have moved the focus
        QTRY_VERIFY(field->isVisible()); // a new row shows at the next event loop pass
        field->setFocus();
        QTRY_COMPARE(QApplication::focusWidget(), field);
        QTest::keyClick(&w, Qt::Key_Right);
        QCOMPARE(nav.revealed(), 0);
        QTest::keyClick(&w, Qt::Key_PageDown);
        QCOMPARE(nav.revealed(), 1);
        field->clearFocus();
        for (Qt::Key key : {Qt::Key_Space, Qt::Key_Right})
            QTest::keyClick(&w, key);
        QCOMPARE(nav.current(), SceneId::Bounce1d);
        QCOMPARE(nav.revealed(), 3);
        QVERIFY(!w.controller().playing()); // Space revealed; it did not play
        QTest::keyClick(&w, Qt::Key_Left);
        QTest::keyClick(&w, Qt::Key_PageUp);
        QCOMPARE(nav.revealed(), 1);

        QTest::keyClick(&w, Qt::Key_Escape);
        QVERIFY(!w.isFullScreen());
        QTest::keyClick(&w, Qt::Key_F11);
        QVERIFY(w.isFullScreen());
        shell.lecture().setActive(false);
        QVERIFY(!w.isFullScreen());
        QVERIFY(!nav.walking());
    }

    void themesSetThePaletteAndTheCharts_data()
    {
        QTest::addColumn<Theme>("theme");
        for (Theme t : ab::ui::allThemes())
            QTest::newRow(qPrintable(ab::ui::themeKey(t))) << t;
    }

    void themesSetThePaletteAndTheCharts()
    {
        QFETCH(Theme, theme);
        ab::ui::WindowShell shell;
        shell.setTheme(theme);
        const QPalette p = QApplication::palette();
        QCOMPARE(p.color(QPalette::Window), ab::ui::themePalette(theme).color(QPalette::Window));
        QCOMPARE(p.color(QPalette::Text), ab::ui::themePalette(theme).color(QPalette::Text));
        QCOMPARE(luminance(p.color(QPalette::Window)) < 0.2, ab::ui::isDark(theme));
        ab::ui::MotionChart* chart = positionChart(shell.window());
        const ab::ui::SurfaceColours c = ab::ui::surfaceColours(theme);
        QCOMPARE(chart->backgroundBrush().color(), c.background);
        QCOMPARE(chart->titleBrush().color(), c.text);
        for (QAbstractAxis* axis : chart->axes())
            QCOMPARE(axis->labelsColor(), c.text);
        const double textContrast = contrast(p.color(QPalette::Text), p.color(QPalette::Base));
        const double chartContrast = contrast(c.text, c.background);
        const double required = ab::ui::isHighContrast(theme) ? 7.0 : 4.5; // WCAG AAA and AA
        QVERIFY2(textContrast >= required, qPrintable(QString::number(textContrast)));
        QVERIFY2(chartContrast >= required, qPrintable(QString::number(chartContrast)));
        shell.setTheme(Theme::Light);
    }

    void lectureModeScalesFontsAndLinesWithoutCompounding()
    {
        ab::ui::WindowShell shell;
        ab::ui::MotionChart* chart = positionChart(shell.window());
        const double appFont = QApplication::font().pointSizeF();
        const double titleFont = chart->titleFont().pointSizeF();
        const double labelFont = chart->axes().front()->labelsFont().pointSizeF();
        const double lineWidth = chart->line(1)->pen().widthF();
        for (int round = 0; round < 2; ++round) {
            shell.lecture().setActive(true);
            const double s = ab::ui::LectureMode::scale;
            const double f = ab::ui::chartFontScale(shell.appearance());
            QCOMPARE(shell.appearance().scale, s);
            QVERIFY(f > 1.3);
            QCOMPARE(QApplication::font().pointSizeF(), appFont * s);
            QCOMPARE(chart->titleFont().pointSizeF(), titleFont * f);
            QCOMPARE(chart->axes().front()->labelsFont().pointSizeF(), labelFont * f);
            QCOMPARE(chart->line(1)->pen().widthF(), lineWidth * s);
            shell.lecture().setActive(false);
            QCOMPARE(QApplication::font().pointSizeF(), appFont);
            QCOMPARE(chart->titleFont().pointSizeF(), titleFont);
            QCOMPARE(chart->line(1)->pen().widthF(), lineWidth);
        }
    }

    void colourBlindSafePaletteUsesOkabeItoColours()
    {
        ab::ui::WindowShell shell;
        shell.window().showScene(SceneId::Box3d); // x, y and z lines
        shell.setColourBlindSafe(true);
        const auto& okabe = ab::ui::okabeIto();
        std::set<QRgb> used;
        for (ab::ui::ChartKind kind : ab::ui::allChartKinds()) {
            ab::ui::MotionChart* chart = shell.window().charts()->chart(kind);
            for (int i = 0; i < 3; ++i) {
                // An Okabe-Ito hue; its lightness may be moved to hold 3:1 against the plot
                // (orange on white is 2.2:1).
                const QColor c = chart->line(i)->pen().color();
                const auto sameHue = [&c](const QColor& o) {
                    const float d = std::fabs(o.hslHueF() - c.hslHueF());
                    return o.hslSaturationF() > 0.2f && std::min(d, 1.0f - d) < 0.01f;
                };
                QVERIFY2(std::any_of(okabe.begin(), okabe.end(), sameHue), qPrintable(c.name()));
                QVERIFY2(contrast(c, ab::ui::surfaceColours(Theme::Light).plotArea) >= 3.0, qPrintable(c.name()));
                if (kind == ab::ui::ChartKind::Position)
                    used.insert(c.rgb());
            }
        }
        QCOMPARE(used.size(), std::size_t(3)); // x, y, z stay apart
        const std::vector<unsigned> balls = ab::ui::okabeItoBallColours(20, Theme::HighContrastDark);
        for (unsigned rgb : balls) {
            QVERIFY(std::find(okabe.begin(), okabe.end(), QColor(QRgb(rgb))) != okabe.end());
            QVERIFY(contrast(QColor(QRgb(rgb)), Qt::black) >= 3.0); // WCAG's figure for graphics
        }
        shell.setColourBlindSafe(false);
        QCOMPARE(positionChart(shell.window())->line(0)->pen().color(), QColor(0xd6, 0x27, 0x28));
    }
};

QTEST_MAIN(UiLecture)
#include "test_ui_lecture.moc"
