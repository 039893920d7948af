// SPDX-License-Identifier: MIT
// Every theme meets WCAG 2.1 AA, measured with the standard's own relative-luminance
// formula (written out here, not the program's): text 4.5:1 against the background it
// is drawn on (every palette role pair, greyed-out text included, and the charts' titles,
// axis labels and legends); 3:1 for what is not text (field borders, the media icons as
// painted, every chart line and the time cursor, axis lines, a checked button against
// itself unchecked), in each theme with and
// without the colour-blind-safe palette, for every chart of every scene, compared and not.
#include "ui/charts/chart_style.h"
#include "ui/charts/motion_chart.h"
#include "ui/charts/scene_layout.h"
#include "ui/panels/transport_bar.h"
#include "ui/theme/appearance.h"
#include "ui/theme/theme.h"
#include "ui/theme/theme_style.h"
#include "ui/view/scene_geometry.h"
#include "ui/view/view_frame.h"

#include <QAbstractAxis>
#include <QApplication>
#include <QChart>
#include <QGraphicsScene>
#include <QImage>
#include <QLegend>
#include <QLineSeries>
#include <QPainter>
#include <QPushButton>
#include <QToolButton>
#include <QtTest>

#include <cmath>

using ab::ui::Theme;

namespace {

// WCAG 2.1 relative luminance (www.w3.org/TR/WCAG21/#dfn-relative-luminance) and
// contrast ratio (#dfn-contrast-ratio).
double luminance(const QColor& c)
{
    auto channel = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
}

double ratio(const QColor& a, const QColor& b)
{
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

QString why(const char* what, const QColor& fg, const QColor& bg)
{
    return QStringLiteral("%1: %2 on %3 is %4:1").arg(what, fg.name(), bg.name()).arg(ratio(fg, bg), 0, 'f', 2);
}

#define CHECK_CONTRAST(what, fg, bg, least) QVERIFY2(ratio(fg, bg) >= (least), qPrintable(why(what, fg, bg)))

void addThemeRows()
{
    QTest::addColumn<Theme>("theme");
    for (Theme t : ab::ui::allThemes())
        QTest::newRow(qPrintable(ab::ui::themeKey(t))) << t;
}

} // namespace

class UiContrast : public QObject {
    Q_OBJECT
private slots:
    void paletteTextIsAtLeastFourAndAHalfToOne_data() { addThemeRows(); }
    void paletteTextIsAtLeastFourAndAHalfToOne()
    {
        QFETCH(Theme, theme);
        const QPalette p = ab::ui::themePalette(theme);
        using R = QPalette;
        const std::pair<R::ColorRole, R::ColorRole> pairs[] = {
            {R::WindowText, R::Window},
            {R::Text, R::Base},
            {R::Text, R::AlternateBase},
            {R::ButtonText, R::Button},
            {R::HighlightedText, R::Highlight},
            {R::ToolTipText, R::ToolTipBase},
            {R::PlaceholderText, R::Base},
            {R::PlaceholderText, R::Window},
            {R::Link, R::Base},
            {R::Link, R::Window},
        };
        for (const auto& [fg, bg] : pairs) {
            CHECK_CONTRAST("active", p.color(R::Active, fg), p.color(R::Active, bg), 4.5);
            // Greyed-out fields (the report model's fixed integrator) are read too.
            CHECK_CONTRAST("disabled", p.color(R::Disabled, fg), p.color(R::Disabled, bg), 4.5);
        }
    }

    void fieldBordersAndFocusAreAtLeastThreeToOne_data() { addThemeRows(); }
    void fieldBordersAndFocusAreAtLeastThreeToOne()
    {
        QFETCH(Theme, theme);
        const QPalette p = ab::ui::themePalette(theme);
        const QColor border = ab::ui::fieldBorder(theme);
        CHECK_CONTRAST("border on window", border, p.color(QPalette::Window), 3.0);
        CHECK_CONTRAST("border on field", border, p.color(QPalette::Base), 3.0);
        CHECK_CONTRAST("focus frame on window", p.color(QPalette::Link), p.color(QPalette::Window), 3.0);
        CHECK_CONTRAST("focus frame on field", p.color(QPalette::Link), p.color(QPalette::Base), 3.0);
    }

    void mediaIconsAreAtLeastThreeToOne_data() { addThemeRows(); }
    void mediaIconsAreAtLeastThreeToOne()
    {
        QFETCH(Theme, theme);
        ab::ui::applyToApplication({theme, false, 1.0});
        auto* style = qobject_cast<ab::ui::ThemeStyle*>(QApplication::style());
        QVERIFY(style);
        const QColor button = QApplication::palette().color(QPalette::Button);
        for (QStyle::StandardPixmap icon :
             {QStyle::SP_MediaPlay, QStyle::SP_MediaPause, QStyle::SP_MediaSkipForward, QStyle::SP_MediaSkipBackward}) {
            // The icon as painted on the button's colour: its most distinct pixel.
            QImage image(32, 32, QImage::Format_RGB32);
            image.fill(button);
            QPainter painter(&image);
            style->standardIcon(icon).paint(&painter, image.rect());
            painter.end();
            double best = 1.0;
            QColor strongest = button;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    if (const QColor c = image.pixelColor(x, y); ratio(c, button) > best) {
                        best = ratio(c, button);
                        strongest = c;
                    }
            CHECK_CONTRAST("icon", strongest, button, 3.0);
        }
        ab::ui::applyToApplication({Theme::Light, false, 1.0});
    }

    void theStreetsSpeedLinesStayApart_data() { addThemeRows(); }
    void theStreetsSpeedLinesStayApart()
    {
        // The percentiles and the fastest ball, told apart by colour as well as dashes: three
        // deepening blues met on the high-contrast white (the 10th percentile's light blue
        // darkened to #307dab beside the median's #2171b5) and were all lifted towards one
        // bright blue on the black.
        QFETCH(Theme, theme);
        ab::ui::MotionChart chart(ab::ui::ChartKind::Speeds);
        ab::ui::ChartUnits units;
        units.streetBlocks = 3;
        chart.configure(ab::sceneInfo(ab::SceneId::Street), 0, units);
        ab::ui::applyToChart(&chart, {theme, false, 1.0});
        std::vector<QColor> colours;
        for (int i = 0; i < 4; ++i)
            colours.push_back(chart.line(i)->pen().color());
        for (std::size_t i = 0; i < colours.size(); ++i)
            for (std::size_t j = i + 1; j < colours.size(); ++j) {
                const double d =
                    std::hypot(colours[i].red() - colours[j].red(), colours[i].green() - colours[j].green(),
                               colours[i].blue() - colours[j].blue());
                QVERIFY2(
                    d >= 60.0,
                    qPrintable(
                        QString("lines %1 and %2: %3 and %4").arg(i).arg(j).arg(colours[i].name(), colours[j].name())));
            }
    }

    void transportIconsFollowAThemeSetAfterTheBarWasBuilt()
    {
        // The window's bar is built before the theme's style is set: Step and Reset kept the
        // default style's dark grey icons on the high-contrast black (1.6:1 there).
        ab::ui::applyToApplication({Theme::Light, false, 1.0});
        QApplication::setStyle(QStringLiteral("Fusion")); // as before any theme
        ab::ui::TransportBar bar;
        ab::ui::applyToApplication({Theme::HighContrastDark, false, 1.0});
        const QColor button = QApplication::palette().color(QPalette::Button);
        for (QPushButton* b : {bar.playButton(), bar.stepButton(), bar.resetButton()}) {
            const QImage image = b->icon().pixmap(32, 32).toImage();
            double best = 1.0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    if (const QColor c = image.pixelColor(x, y); c.alpha() == 255)
                        best = std::max(best, ratio(c, button));
            QVERIFY2(best >= 3.0, qPrintable(QString("%1: %2:1").arg(b->objectName()).arg(best)));
        }
        ab::ui::applyToApplication({Theme::Light, false, 1.0});
    }

    void stageOnesHeightScaleStandsOutOnTheViewAtThreeToOne_data() { addThemeRows(); }
    void stageOnesHeightScaleStandsOutOnTheViewAtThreeToOne()
    {
        // The scale's line and ticks stand above the floor (y > 0), on the view's clear colour;
        // the grid lies on the floor, on the floor's own colour.
        QFETCH(Theme, theme);
        const QColor background = ab::ui::surfaceColours(theme).background;
        const ab::ui::SceneGeometry g =
            ab::ui::buildSceneGeometry(ab::ui::layoutFor(ab::RunSpec(ab::SceneId::Bounce1d)), "unit");
        int checked = 0;
        for (const ab::ui::FlatVertex& v : g.lines)
            if (v.y > 0.0f) {
                CHECK_CONTRAST("height scale", QColor::fromRgbF(v.r, v.g, v.b), background, 3.0);
                ++checked;
            }
        QVERIFY(checked >= 2);
    }

    void theViewsLabelsStandSevenToOneOnAHaloOfTheViewsSide_data() { addThemeRows(); }
    void theViewsLabelsStandSevenToOneOnAHaloOfTheViewsSide()
    {
        // A label is read from the back of a lecture hall: its text 7:1 against its halo as drawn,
        // over the view and over the lightest or darkest scene under it (5.6:1 before). The
        // halo is of the view's own side, dark on a dark view: a white one over black read as a
        // pale box round grey text (stage 1's scale in high-contrast dark, 3.9:1 within it).
        QFETCH(Theme, theme);
        const QColor background = ab::ui::surfaceColours(theme).background;
        std::vector<QColor> colours = {QColor(0x20, 0x20, 0x20), QColor(0x4b, 0x00, 0x82), QColor(Qt::red)};
        for (const ab::SceneId scene : {ab::SceneId::Bounce1d, ab::SceneId::Box3d, ab::SceneId::Street})
            for (const ab::ui::SceneLabel& l :
                 ab::ui::buildSceneGeometry(ab::ui::layoutFor(ab::RunSpec(scene)), "m").labels)
                colours.push_back(l.colour);
        QVERIFY(colours.size() >= 10);
        for (const QColor& colour : colours) {
            const ab::ui::LabelInk ink = ab::ui::labelInk(colour, background);
            QColor opaque = ink.halo;
            opaque.setAlpha(255);
            const double a = ink.halo.alphaF();
            // The halo as drawn over whatever the scene has under it, its lightest (white, under a
            // dark halo) or darkest (black, under a light one), and over the view's background.
            const double under = opaque.lightnessF() < 0.5 ? 1.0 : 0.0;
            const QColor worst =
                QColor::fromRgbF(a * opaque.redF() + (1 - a) * under, a * opaque.greenF() + (1 - a) * under,
                                 a * opaque.blueF() + (1 - a) * under);
            CHECK_CONTRAST("label on its halo over the brightest scene", ink.text, worst, 7.0);
            const QColor over = QColor::fromRgbF(a * opaque.redF() + (1 - a) * background.redF(),
                                                 a * opaque.greenF() + (1 - a) * background.greenF(),
                                                 a * opaque.blueF() + (1 - a) * background.blueF());
            QVERIFY2(ratio(over, background) < 1.5, qPrintable(why("halo over the view", over, background)));
            CHECK_CONTRAST("label on its halo over the view", ink.text, over, 7.0);
        }
    }

    void aCheckedButtonStandsApartAtThreeToOne_data() { addThemeRows(); }
    void aCheckedButtonStandsApartAtThreeToOne()
    {
        // The stage buttons and the street's camera shots say which is down: the same push
        // and tool button drawn up and down differ somewhere by 3:1 (WCAG 1.4.11).
        QFETCH(Theme, theme);
        ab::ui::applyToApplication({theme, false, 1.0});
        QPushButton push(QStringLiteral("5  street"));
        QToolButton tool;
        tool.setText(QStringLiteral("Flood"));
        for (QAbstractButton* button : {static_cast<QAbstractButton*>(&push), static_cast<QAbstractButton*>(&tool)}) {
            button->setCheckable(true);
            button->resize(160, 36);
            button->setChecked(false);
            const QImage up = button->grab().toImage();
            button->setChecked(true);
            const QImage down = button->grab().toImage();
            QCOMPARE(up.size(), down.size());
            double best = 1.0;
            for (int y = 0; y < up.height(); ++y)
                for (int x = 0; x < up.width(); ++x)
                    best = std::max(best, ratio(up.pixelColor(x, y), down.pixelColor(x, y)));
            QVERIFY2(best >= 3.0, qPrintable(QStringLiteral("%1: up and down differ by %2:1 at most")
                                                 .arg(button->metaObject()->className())
                                                 .arg(best, 0, 'f', 2)));
        }
        ab::ui::applyToApplication({Theme::Light, false, 1.0});
    }

    void mediaIconPixmapsHoldOnlyTheirShape()
    {
        // A button draws its icon from QIcon::pixmap(), not paint(): every pixel of it is
        // either transparent or the button text's colour (antialiased edges only lower the
        // alpha), whatever the memory the pixmap was given held before.
        ab::ui::applyToApplication({Theme::Light, false, 1.0});
        const QColor text = QApplication::palette().color(QPalette::ButtonText);
        for (QStyle::StandardPixmap icon :
             {QStyle::SP_MediaPlay, QStyle::SP_MediaPause, QStyle::SP_MediaSkipForward, QStyle::SP_MediaSkipBackward}) {
            for (int k = 0; k < 8; ++k) { // memory of the pixmap's size, left dirty when freed
                QImage junk(24, 24, QImage::Format_ARGB32_Premultiplied);
                junk.fill(QColor(255, 0, 255));
            }
            const QImage image = QApplication::style()
                                     ->standardIcon(icon)
                                     .pixmap(QSize(24, 24))
                                     .toImage()
                                     .convertToFormat(QImage::Format_ARGB32);
            int stray = 0, opaque = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    opaque += c.alpha() == 255 ? 1 : 0;
                    const bool shape = std::abs(c.red() - text.red()) <= 2 && std::abs(c.green() - text.green()) <= 2 &&
                                       std::abs(c.blue() - text.blue()) <= 2;
                    stray += c.alpha() > 0 && !shape ? 1 : 0;
                }
            QVERIFY2(stray == 0,
                     qPrintable(QStringLiteral("icon %1: %2 pixels of another colour").arg(icon).arg(stray)));
            QVERIFY2(opaque >= 24, qPrintable(QStringLiteral("icon %1: %2 opaque pixels").arg(icon).arg(opaque)));
            QCOMPARE(image.pixelColor(0, 0).alpha(), 0);
        }
    }

    void chartTextAndLinesMeetAa_data()
    {
        QTest::addColumn<Theme>("theme");
        QTest::addColumn<bool>("safe");
        for (Theme t : ab::ui::allThemes())
            for (bool safe : {false, true})
                QTest::newRow(qPrintable(ab::ui::themeKey(t) + (safe ? " colour-blind-safe" : ""))) << t << safe;
    }
    void chartTextAndLinesMeetAa()
    {
        QFETCH(Theme, theme);
        QFETCH(bool, safe);
        const ab::ui::SurfaceColours c = ab::ui::surfaceColours(theme);
        CHECK_CONTRAST("chart text", c.text, c.background, 4.5);
        CHECK_CONTRAST("chart text on plot", c.text, c.plotArea, 4.5);
        CHECK_CONTRAST("axis line", c.axisLine, c.plotArea, 3.0);
        for (const ab::SceneInfo* scene : ab::allScenes())
            for (ab::ui::ChartKind kind : ab::ui::allChartKinds()) {
                ab::ui::MotionChart chart(kind);
                chart.configure(*scene, 0, {true, scene->id == ab::SceneId::Bounce1d});
                chart.setComparison("report", "physical rk4");
                chart.setCursorTime(1.0);
                ab::ui::applyToChart(&chart, {theme, safe, 1.0});
                CHECK_CONTRAST("title", chart.titleBrush().color(), c.background, 4.5);
                CHECK_CONTRAST("legend", chart.legend()->labelColor(), c.background, 4.5);
                for (QAbstractAxis* axis : chart.axes()) {
                    CHECK_CONTRAST("tick labels", axis->labelsColor(), c.background, 4.5);
                    CHECK_CONTRAST("axis title", axis->titleBrush().color(), c.background, 4.5);
                    CHECK_CONTRAST("axis line", axis->linePen().color(), c.plotArea, 3.0);
                }
                for (QAbstractSeries* s : chart.series()) {
                    auto* line = qobject_cast<QLineSeries*>(s);
                    QVERIFY(line);
                    // A projector's high-contrast lines as text: 4.5:1.
                    CHECK_CONTRAST(
                        qPrintable(QStringLiteral("%1 line '%2'")
                                       .arg(QString::fromLatin1(ab::ui::chartKey(kind).data()), line->name())),
                        line->pen().color(), c.plotArea, ab::ui::isHighContrast(theme) ? 4.5 : 3.0);
                }
                CHECK_CONTRAST("cursor", chart.cursorLine()->pen().color(), c.plotArea, 3.0);
            }
    }

    void aDenseSolidLineIsDrawnInItsPensColour()
    {
        // The contrast above is the pen's; the pixels must carry it. A track thinned to its
        // least and greatest per pixel column is a zigzag of segments shorter than a pixel,
        // which Qt Charts draws one by one: with flat ends they blended to 0.7 of the pen's
        // colour (the total energy's violet #8e44ad drawn as #b17ec7 on white).
        const QPen pen =
            ab::ui::linePen(ab::ui::ChartKind::Energy, 2, 0, ab::ui::LineFamily::Run, ab::ui::ChartLook::window());
        QChart chart;
        chart.legend()->hide();
        chart.setBackgroundBrush(Qt::white);
        chart.setPlotAreaBackgroundVisible(false);
        auto* series = new QLineSeries;
        for (int i = 0; i < 2000; ++i) // 4 points a pixel column, 0.3 px apart up and down
            series->append(i / 4.0, 10.0 + ((i % 4 == 1 || i % 4 == 2) ? 0.01 : -0.01));
        series->setPen(pen);
        chart.addSeries(series);
        chart.createDefaultAxes();
        for (QAbstractAxis* axis : chart.axes())
            axis->hide();
        chart.axes(Qt::Vertical).front()->setRange(0.0, 20.0);
        chart.resize(600, 300);
        QImage image(600, 300, QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        QGraphicsScene scene;
        scene.addItem(&chart);
        scene.render(&painter, QRectF(0, 0, 600, 300), QRectF(0, 0, 600, 300));
        painter.end();
        scene.removeItem(&chart);
        // The pixels of the line's core: as many as the line is long, in the pen's colour.
        int exact = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                exact += image.pixelColor(x, y).rgb() == pen.color().rgb() ? 1 : 0;
        QVERIFY2(exact > 300, qPrintable(QString("%1 pixels in %2").arg(exact).arg(pen.color().name())));
    }

    void comparisonLinesStandApartFromTheirRunOnDarkPlots()
    {
        // On a dark plot the comparison's darkened family sank into the background as a
        // faint grey: there each comparison line is saturated and of another colour than
        // the run line it shadows (RGB distance, 0-441).
        for (Theme theme : ab::ui::allThemes()) {
            if (!ab::ui::isDark(theme))
                continue;
            for (ab::ui::ChartKind kind : ab::ui::allChartKinds()) {
                ab::ui::MotionChart chart(kind);
                chart.configure(ab::sceneInfo(ab::SceneId::Box3d), 0, {true, false});
                chart.setComparison("report", "physical rk4");
                ab::ui::applyToChart(&chart, {theme, false, 1.0});
                int pairs = 0;
                for (QAbstractSeries* s : chart.series()) {
                    const QVariant of = s->property(ab::ui::comparisonOfProperty);
                    if (!of.isValid())
                        continue;
                    const QColor comparison = static_cast<QLineSeries*>(s)->pen().color();
                    QVERIFY2(comparison.hslSaturationF() >= 0.5f, qPrintable(comparison.name()));
                    for (QAbstractSeries* r : chart.series()) {
                        const QVariant base = r->property("ab_basePen");
                        if (r == s || r->property(ab::ui::comparisonOfProperty).isValid() || !base.isValid() ||
                            base.value<QPen>().color() != of.value<QColor>())
                            continue;
                        const QColor run = static_cast<QLineSeries*>(r)->pen().color();
                        const double d = std::hypot(run.red() - comparison.red(), run.green() - comparison.green(),
                                                    run.blue() - comparison.blue());
                        QVERIFY2(d >= 80.0, qPrintable(QStringLiteral("%1: run %2, comparison %3")
                                                           .arg(QString::fromLatin1(ab::ui::chartKey(kind).data()),
                                                                run.name(), comparison.name())));
                        ++pairs;
                    }
                }
                if (kind == ab::ui::ChartKind::Position)
                    QVERIFY(pairs >= 3); // x, y and z each met their comparison
            }
        }
    }
};

QTEST_MAIN(UiContrast)
#include "test_ui_contrast.moc"
