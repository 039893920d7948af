// SPDX-License-Identifier: MIT
// The window's charts without a window: they draw only the scene's axes, the run's
// closed-form free fall and what applies to the stage, and their CSV holds what they show.
// The data path under them: test_ui_data.cpp.
#include "support/sim_helpers.h"

#include "core/diagnostics/conservation.h"
#include "ui/charts/chart_data_csv.h"
#include "ui/charts/motion_chart.h"
#include "ui/charts/motion_track.h"
#include "ui/charts/nice_ticks.h"
#include "ui/panels/chart_panel.h"

#include <QApplication>
#include <QChartView>
#include <QContextMenuEvent>
#include <QGraphicsTextItem>
#include <QLineSeries>
#include <QMenu>
#include <QTabBar>
#include <QTimer>
#include <QValueAxis>
#include <QtTest>

#include <cmath>
#include <limits>

namespace {

// The texts a chart view draws (tick labels, axis titles, the chart's title), as drawn:
// Qt Charts' own cut to "..." included.
QStringList shownTexts(const QChartView& view)
{
    QStringList texts;
    for (const QGraphicsItem* item : view.scene()->items())
        if (const auto* t = dynamic_cast<const QGraphicsTextItem*>(item); t && t->isVisible())
            texts << t->toPlainText();
    return texts;
}

} // namespace

class UiCharts : public QObject {
    Q_OBJECT

private slots:
    void positionChartDrawsOnlyTheScenesAxes()
    {
        ab::ui::MotionChart vertical(ab::ui::ChartKind::Position);
        vertical.configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0);
        QCOMPARE(vertical.shownAxes(), std::vector<int>{1});
        QVERIFY(!vertical.line(0)->isVisible());
        QVERIFY(vertical.line(1)->isVisible());
        QVERIFY(!vertical.line(2)->isVisible());
        ab::ui::MotionChart box(ab::ui::ChartKind::Velocity);
        box.configure(ab::sceneInfo(ab::SceneId::Box3d), 0);
        QCOMPARE(box.shownAxes(), (std::vector<int>{0, 1, 2}));
        QCOMPARE(box.line(0)->name(), QString("vx"));
    }

    void velocityChartOfStage1IsTheReportsFreeFall()
    {
        // Appendix A before the first bounce: v[n] = -0.0982 n (eq 2.15), p[n] from eq 2.16.
        const ab::RunSpec spec = testing::spec(ab::SceneId::Bounce1d);
        ab::ui::MotionTrack track;
        const auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        long long i = 0;
        for (const ab::State& s : testing::record(spec, 150))
            track.add(i++, s.t, s.p.col(0), s.v.col(0), meter.measure(s));
        ab::ui::MotionChart chart(ab::ui::ChartKind::Velocity);
        chart.configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0);
        chart.setTimeSpan(2000);
        chart.showTrack(track, 600);
        const QList<QPointF> points = chart.line(1)->points();
        QCOMPARE(points.size(), 151);
        for (const QPointF& p : points)
            QVERIFY(std::abs(p.y() - (-0.0982 * p.x())) < 1e-12);
    }

    void tickLabelsNeverShowRoundOff()
    {
        // A velocity falling from 0 to -0.49 (stage 1's first five steps): the axis runs
        // from -0.5 to 0 in steps of 0.1, and its top tick reads "0", not "-2.77556e-17".
        const ab::RunSpec spec = testing::spec(ab::SceneId::Bounce1d);
        ab::ui::MotionTrack track;
        const auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        long long i = 0;
        for (const ab::State& s : testing::record(spec, 5))
            track.add(i++, s.t, s.p.col(0), s.v.col(0), meter.measure(s));
        auto* chart = new ab::ui::MotionChart(ab::ui::ChartKind::Velocity);
        chart->configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0);
        chart->setTimeSpan(6);
        chart->showTrack(track, 600);
        QChartView view(chart); // owns the chart
        view.resize(600, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QCoreApplication::processEvents();
        const QStringList labels = shownTexts(view);
        QVERIFY2(labels.contains(QStringLiteral("0")), qPrintable(labels.join(" | ")));
        QVERIFY2(labels.contains(QStringLiteral("-0.5")), qPrintable(labels.join(" | ")));
        for (const QString& l : labels)
            QVERIFY2(!l.contains(QLatin1String("e-")), qPrintable(l));
    }

    void referenceSeamDrawsTheClosedFormDashedAndCanBeRemoved()
    {
        // Free fall from 2000 under g = 9.82: y = 2000 - g t^2 / 2, vy = -g t.
        ab::ui::ReferenceMotion fall{
            "closed form", [](double t) -> std::optional<ab::ui::Kinematics> {
                if (t > 20.0)
                    return std::nullopt;
                return ab::ui::Kinematics{Eigen::Vector3d(0, 2000 - 4.91 * t * t, 0), Eigen::Vector3d(0, -9.82 * t, 0)};
            }};
        ab::ui::MotionChart chart(ab::ui::ChartKind::Position);
        chart.configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0);
        chart.setTimeSpan(40.0);
        chart.setReference(&fall, 100);
        QVERIFY(chart.hasReference());
        const QList<QPointF> points = chart.referenceLine(1)->points();
        QCOMPARE(points.size(), 101); // t in [0, 20] of the 201 samples over [0, 40]
        for (const QPointF& p : points)
            QVERIFY(std::abs(p.y() - (2000 - 4.91 * p.x() * p.x())) < 1e-9);
        QCOMPARE(chart.referenceLine(1)->pen().style(), Qt::DashLine);
        QVERIFY(chart.referenceLine(0)->points().isEmpty()); // bounce1d has no x
        chart.setReference(nullptr);
        QVERIFY(chart.referenceLine(1)->points().isEmpty());
    }

    void aNewSceneForgetsThePreviousClosedFormAndItsRange()
    {
        // Stage 1's fall from 2000 stretched the value axis; stage 2's ball stays below
        // 300, so once the chart is configured for it the axis must end near 300, not 2000.
        ab::ui::ReferenceMotion fall{
            "closed form", [](double t) -> std::optional<ab::ui::Kinematics> {
                return ab::ui::Kinematics{Eigen::Vector3d(0, 2000 - 4.91 * t * t, 0), Eigen::Vector3d(0, -9.82 * t, 0)};
            }};
        ab::ui::MotionChart chart(ab::ui::ChartKind::Position);
        chart.configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0);
        chart.setTimeSpan(20.0);
        chart.setReference(&fall, 100);
        chart.configure(ab::sceneInfo(ab::SceneId::Box3d), 0);
        QVERIFY(!chart.hasReference());
        ab::ui::ReferenceMotion inBox{
            "closed form", [](double t) -> std::optional<ab::ui::Kinematics> {
                return ab::ui::Kinematics{Eigen::Vector3d(2 + 5 * t, 20, 2 + 5 * t), Eigen::Vector3d(5, 0, 5)};
            }};
        chart.setReference(&inBox, 100);
        auto* axis = qobject_cast<QValueAxis*>(chart.axes(Qt::Vertical).front());
        QVERIFY(axis);
        QVERIFY2(axis->max() >= 52.0 && axis->max() < 300.0, qPrintable(QString::number(axis->max())));
    }

    void cursorMarksTheShownTime()
    {
        ab::ui::MotionChart chart(ab::ui::ChartKind::Position);
        chart.configure(ab::sceneInfo(ab::SceneId::Box3d), 0);
        chart.setCursorTime(12.5);
        const QList<QPointF> c = chart.cursorLine()->points();
        QCOMPARE(c.size(), 2);
        QCOMPARE(c[0].x(), 12.5);
        QCOMPARE(c[1].x(), 12.5);
        chart.setCursorTime(std::numeric_limits<double>::quiet_NaN());
        QVERIFY(chart.cursorLine()->points().isEmpty());
    }

    void chartsAreOfferedOnlyWhereTheyApply()
    {
        using ab::SceneId;
        using ab::ui::ChartKind;
        QVERIFY(!ab::ui::chartApplies(ChartKind::Momentum, SceneId::Bounce1d));
        QVERIFY(!ab::ui::chartApplies(ChartKind::Momentum, SceneId::Box3d));
        QVERIFY(ab::ui::chartApplies(ChartKind::Momentum, SceneId::TwoBalls));
        QVERIFY(!ab::ui::chartApplies(ChartKind::Activity, SceneId::TwoBalls));
        QVERIFY(ab::ui::chartApplies(ChartKind::Activity, SceneId::ManyBalls));
        for (ChartKind kind : ab::ui::allChartKinds())
            QCOMPARE(ab::ui::parseChartKind(ab::ui::chartKey(kind)), std::optional<ChartKind>(kind));
        // The panel hides what does not apply and keeps the View menu's wish for later.
        ab::ui::ChartPanel panel;
        panel.configure(ab::sceneInfo(SceneId::Bounce1d), 1, 0, 100.0);
        QVERIFY(panel.chartView(ChartKind::Momentum)->isHidden());
        QVERIFY(panel.chartView(ChartKind::Activity)->isHidden());
        QVERIFY(!panel.chartView(ChartKind::Energy)->isHidden());
        QVERIFY(panel.chartShown(ChartKind::Momentum)); // wished for, shown where it applies
        panel.configure(ab::sceneInfo(SceneId::ManyBalls), 150, 0, 1000.0);
        QVERIFY(!panel.chartView(ChartKind::Momentum)->isHidden());
        QVERIFY(!panel.chartView(ChartKind::Activity)->isHidden());
        panel.setChartShown(ChartKind::Activity, false);
        panel.configure(ab::sceneInfo(SceneId::TwoBalls), 2, 0, 100.0);
        panel.configure(ab::sceneInfo(SceneId::ManyBalls), 150, 0, 1000.0);
        QVERIFY(panel.chartView(ChartKind::Activity)->isHidden());
        QVERIFY(!panel.chartShown(ChartKind::Activity));
    }

    void aChartsMenuOffersPdfForAReportBesidePngSvgAndCsv()
    {
        // The right-click menu offered PNG, SVG and CSV: a report's vector figure was reached
        // only by typing ".pdf" into the file dialog.
        using ab::ui::ExportFormat;
        ab::ui::ChartPanel panel;
        panel.resize(600, 800);
        panel.configure(ab::sceneInfo(ab::SceneId::Box3d), 1, 0, 60.0);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        std::vector<std::pair<ab::ui::ChartKind, ExportFormat>> asked;
        connect(&panel, &ab::ui::ChartPanel::exportRequested,
                [&](ab::ui::ChartKind kind, ExportFormat format) { asked.emplace_back(kind, format); });
        QStringList offered;
        QTimer::singleShot(0, [&] {
            QWidget* popup = QApplication::activePopupWidget();
            auto* menu = qobject_cast<QMenu*>(popup);
            if (!menu)
                return;
            for (QAction* a : menu->actions())
                if (!a->isSeparator())
                    offered << a->text();
            for (QAction* a : menu->actions())
                if (a->text().contains("PDF"))
                    a->trigger();
            menu->close();
        });
        QWidget* viewport = panel.chartView(ab::ui::ChartKind::Velocity)->viewport();
        QContextMenuEvent event(QContextMenuEvent::Mouse, QPoint(50, 50), viewport->mapToGlobal(QPoint(50, 50)));
        QApplication::sendEvent(viewport, &event);
        QCOMPARE(offered, (QStringList{"Export this chart as PNG...", "Export this chart as SVG...",
                                       "Export this chart as PDF...", "Export the chart data as CSV..."}));
        QCOMPARE(asked.size(), std::size_t(1));
        QVERIFY(asked[0].first == ab::ui::ChartKind::Velocity && asked[0].second == ExportFormat::Pdf);
    }

    void stackedChartsPutOneTimeAtOneX()
    {
        using ab::SceneId;
        using ab::ui::ChartKind;
        // The street's charts in one column: the energy's labels ("2000000") are far wider
        // than the speeds' ("40"), which put the speeds' plot, and its cursor, 40 px further
        // left. Each plot now starts and ends where the others do: a time is at one x.
        ab::ui::ChartPanel panel;
        panel.resize(600, 4000); // every chart on one page
        ab::ui::ChartUnits units;
        units.streetBlocks = 3;
        panel.configure(ab::sceneInfo(SceneId::Street), 10, 0, 30.0, units);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.chart(ChartKind::Energy)->valueAxis()->setRange(0.0, 2e6);
        panel.chart(ChartKind::Speeds)->valueAxis()->setRange(0.0, 40.0);
        const std::vector<ChartKind> column = panel.shownCharts();
        QVERIFY(column.size() >= 5); // position, velocity, energy, foot rate, speeds
        // Where t = 17.7 s is drawn in each chart's view.
        auto xAt = [&](ChartKind kind) {
            ab::ui::MotionChart* c = panel.chart(kind);
            return c->mapToPosition(QPointF(17.7, 0.0), c->line(0)).x() + c->pos().x();
        };
        auto spread = [&](auto edge) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (ChartKind kind : column) {
                lo = std::min(lo, edge(kind));
                hi = std::max(hi, edge(kind));
            }
            return hi - lo;
        };
        QTRY_VERIFY2(spread(xAt) < 1.0, qPrintable(QString::number(spread(xAt))));
        QVERIFY(spread([&](ChartKind k) { return panel.chart(k)->plotArea().right(); }) < 1.0);
        // The charts' own plots would start apart: the energy's labels are the wider.
        const double unaligned =
            spread([&](ChartKind k) { return panel.chart(k)->plotArea().left() - panel.chart(k)->plotInsetLeft(); });
        QVERIFY2(unaligned > 20.0, qPrintable(QString::number(unaligned)));
        // A chart alone on its page has no inset.
        panel.resize(600, 330); // one chart a page
        QTRY_VERIFY(panel.pages()->count() > 2);
        QTRY_COMPARE(panel.chart(panel.currentChart())->plotInsetLeft(), 0);
    }

    void energyChartDrawsKineticPotentialAndTotal()
    {
        // Stage 1's free fall: kinetic g^2 t^2 / 2 and potential g (h0 - g t^2 / 2) per unit
        // mass, their sum constant at g h0 while the ball flies (eqs 2.1-2.2; the report's
        // scheme conserves it to within g^2 dt^2 / 2 per step, at most 0.005 here).
        const ab::RunSpec spec = testing::spec(ab::SceneId::Bounce1d);
        const auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        ab::ui::MotionTrack track;
        long long i = 0;
        for (const ab::State& s : testing::record(spec, 150))
            track.add(i++, s.t, s.p.col(0), s.v.col(0), meter.measure(s));
        ab::ui::MotionChart chart(ab::ui::ChartKind::Energy);
        chart.configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0);
        QCOMPARE(chart.shownAxes(), (std::vector<int>{0, 1, 2}));
        QCOMPARE(chart.line(2)->name(), QString("total"));
        QVERIFY(!chart.line(3)->isVisible()); // no spring floor
        chart.setTimeSpan(150);
        chart.showTrack(track, 600);
        const double g = spec.params.real("g"), h0 = spec.params.real("h0");
        const QList<QPointF> total = chart.line(2)->points();
        QCOMPARE(total.size(), 151);
        for (const QPointF& p : total)
            QVERIFY(std::abs(p.y() - g * h0) <= 0.005 * g * h0);
        for (const QPointF& p : chart.line(0)->points()) // v = -g t exactly (eq 2.15)
            QVERIFY(std::abs(p.y() - 0.5 * g * g * p.x() * p.x()) <= 1e-9 * (1.0 + p.y()));
        ab::ui::MotionChart spring(ab::ui::ChartKind::Energy);
        spring.configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0, ab::ui::ChartUnits{false, true});
        QVERIFY(spring.line(3)->isVisible());
        QVERIFY2(spring.title().startsWith("Energy (kg"), qPrintable(spring.title())); // one ball: no sum
    }

    void millionsOnAnAxisAreWrittenOutNotInENotation()
    {
        // The street's 10,000 balls 70 m up hold E/m = 10,000 x 9.82 x 61.5 = 6.04e6 m^2/s^2:
        // the axis reads 0, 2000000, ... 8000000 ("%g" wrote "6e+06"); small values keep "%g".
        QCOMPARE(QString(ab::ui::tickLabelFormat(2e6, 8e6)), QString("%.0f"));
        QCOMPARE(QString(ab::ui::tickLabelFormat(0.5, 2.5)), QString("%g"));
        QCOMPARE(QString(ab::ui::tickLabelFormat(5e5, 9e5)), QString("%g"));
        auto* chart = new ab::ui::MotionChart(ab::ui::ChartKind::Energy);
        chart->configure(ab::sceneInfo(ab::SceneId::Street), 0, ab::ui::ChartUnits{true, false, true});
        chart->setTimeSpan(30);
        ab::ui::MotionTrack track;
        for (int k = 0; k <= 10; ++k) {
            ab::ConservationSample sample;
            sample.energy.potential = 6.04e6 - 1e5 * k; // m g h falling as the flood comes down
            sample.energy.kinetic = 1e5 * k;
            track.add(k, double(k), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), sample);
        }
        chart->showTrack(track, 600);
        QChartView view(chart); // owns the chart
        view.resize(700, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QCoreApplication::processEvents();
        QCOMPARE(chart->valueAxis()->labelFormat(), QString("%.0f"));
        const QStringList labels = shownTexts(view);
        QVERIFY2(labels.contains("6000000"), qPrintable(labels.join(" | ")));
        for (const QString& l : labels)
            QVERIFY2(!l.contains("e+"), qPrintable(l));
    }

    void aNarrowChartShortensItsTitleRatherThanCutIt()
    {
        // Stage 4's energy title with its long units ("unit²/frame²") is wider than a
        // chart panel a third of a 1280-pixel window: a shorter form is drawn whole, never a
        // title Qt Charts cut to "...".
        auto* chart = new ab::ui::MotionChart(ab::ui::ChartKind::Energy);
        chart->configure(ab::sceneInfo(ab::SceneId::ManyBalls), 0);
        QChartView view(chart); // owns the chart
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QStringList seen;
        for (int width = 900; width >= 240; width -= 7) {
            view.resize(width, 400);
            QCoreApplication::processEvents();
            const QStringList texts = shownTexts(view);
            QVERIFY2(texts.contains(chart->title()), qPrintable(chart->title() + " among " + texts.join(" | ")));
            for (const QString& text : texts)
                QVERIFY2(!text.contains(QChar(0x2026)) && !text.contains("..."), qPrintable(text));
            if (!seen.contains(chart->title()))
                seen << chart->title();
        }
        // Of 150 balls the chart draws the sum, and its title says so.
        QCOMPARE(seen.front(), QString::fromUtf8("Energy per unit mass, sum over all balls (unit\u00b2/frame\u00b2)"));
        QCOMPARE(chart->valueAxis()->titleText(), QString::fromUtf8("\u03a3 E/m"));
        QVERIFY2(seen.size() >= 3, qPrintable(seen.join(" | "))); // each shorter form had its turn
    }

    void impactRateIsTheCountOverTheWindow()
    {
        // Impacts since the start at t = 0..6: 0, 0, 1, 1, 3, 3, 4. Over a window of 2:
        // at t = 4, (3 - 1) / 2 = 1; at t = 6, (4 - 3) / 2 = 0.5; at t = 1 the run is
        // younger than the window: (0 - 0) / 1.
        const long long counts[] = {0, 0, 1, 1, 3, 3, 4};
        ab::ui::MotionTrack track;
        for (long long i = 0; i < 7; ++i) {
            ab::ConservationSample c;
            c.impacts = counts[i];
            track.add(i, double(i), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), c);
        }
        const std::vector<double> rate = ab::ui::impactRate(track, 2.0);
        QCOMPARE(rate[1], 0.0);
        QCOMPARE(rate[2], 0.5); // (1 - 0) / 2
        QCOMPARE(rate[4], 1.0);
        QCOMPARE(rate[6], 0.5);
    }

    void manyBallsActivityShowsMovingBallsAndImpacts()
    {
        const ab::RunSpec spec = testing::spec(ab::SceneId::ManyBalls, {"n=150"});
        const auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        ab::ui::MotionTrack track;
        long long i = 0;
        for (const ab::State& s : testing::record(spec, 1000))
            track.add(i++, s.t, s.p.col(0), s.v.col(0), meter.measure(s));
        ab::ui::MotionChart chart(ab::ui::ChartKind::Activity);
        chart.configure(ab::sceneInfo(ab::SceneId::ManyBalls), 0);
        chart.setTimeSpan(1000);
        chart.showTrack(track, 600);
        QVERIFY(chart.rateAxis());
        QCOMPARE(chart.line(0)->points().front().y(), 150.0); // all move at the start
        double peak = 0.0;
        for (const QPointF& p : chart.line(1)->points())
            peak = std::max(peak, p.y());
        QVERIFY(peak > 0.0); // the balls reach the floor (50 units below) within 1000 frames
        QVERIFY(chart.rateAxis()->max() >= peak);
        // The grid is the left axis's alone: two scales' lines fell between each other.
        QVERIFY(chart.valueAxis()->isGridLineVisible());
        QVERIFY(!chart.rateAxis()->isGridLineVisible());
    }

    void chartCsvHasUnitsTheShownAxesEverySampleAndOneBasedBalls()
    {
        ab::ConservationSample scene;
        scene.energy = {3.0, 4.0, 0.0}; // kinetic, potential, spring: total 7
        scene.momentum = Eigen::Vector3d(0.5, -1, 2);
        scene.moving = 2;
        scene.impacts = 9;
        ab::ui::MotionTrack track;
        track.add(0, 0.0, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6), scene);
        track.add(1, 0.5, Eigen::Vector3d(1, 2.5, 3), Eigen::Vector3d(4, 5, 6), scene);
        std::ostringstream vertical, full;
        ab::ui::ChartData data;
        data.run = &track;
        data.axes = 1;
        data.ball = 0;
        data.comments = {"made by hand"};
        ab::ui::writeChartCsv(vertical, data);
        const std::string header =
            "energy_total [m^2/s^2],energy_kinetic [m^2/s^2],energy_potential [m^2/s^2],energy_spring [m^2/s^2],"
            "momentum_x [m/s],momentum_y [m/s],momentum_z [m/s],moving [balls],impacts [1]\n";
        QCOMPARE(QString::fromStdString(vertical.str()),
                 QString::fromStdString("# made by hand\nt [s],ball,y [m],vy [m/s]," + header +
                                        "0,1,2,5,7,3,4,0,0.5,-1,2,2,9\n" + "0.5,1,2.5,5,7,3,4,0,0.5,-1,2,2,9\n"));
        data.axes = 3;
        data.ball = 1;
        data.comments.clear();
        data.perUnitMass = false;
        ab::ui::writeChartCsv(full, data);
        QVERIFY(full.str().rfind("t [s],ball,x [m],y [m],z [m],vx [m/s],vy [m/s],vz [m/s],energy_total [kg m^2/s^2],",
                                 0) == 0);
        QVERIFY(full.str().find("\n0,2,1,2,3,4,5,6,7,") != std::string::npos); // the second ball is ball 2
    }

    void chartCsvWritesTheClosedFormAndTheComparisonAtEachRowsTime()
    {
        ab::ConservationSample scene;
        ab::ui::MotionTrack run, other;
        for (int i = 0; i < 3; ++i) {
            run.add(i, 0.5 * i, Eigen::Vector3d(0, 10.0 - i, 0), Eigen::Vector3d(0, -1, 0), scene);
            other.add(i, 0.5 * i, Eigen::Vector3d(0, 10.0 - 2 * i, 0), Eigen::Vector3d(0, -2, 0), scene);
        }
        // A closed form y = 10 - t^2, vy = -2 t, by hand.
        const ab::ui::ReferenceMotion closed{
            "closed form", [](double t) -> std::optional<ab::ui::Kinematics> {
                return ab::ui::Kinematics{Eigen::Vector3d(0, 10 - t * t, 0), Eigen::Vector3d(0, -2 * t, 0)};
            }};
        ab::ui::ChartData data;
        data.run = &run;
        data.axes = 1;
        data.comparison = &other;
        data.closedForm = &closed;
        std::ostringstream out;
        ab::ui::writeChartCsv(out, data);
        const QStringList lines = QString::fromStdString(out.str()).split('\n', Qt::SkipEmptyParts);
        const QStringList header = lines.front().split(',');
        QCOMPARE(lines.size(), 4);
        const int y = int(header.indexOf("y_closed_form [m]")), vy = int(header.indexOf("vy_closed_form [m/s]"));
        const int cy = int(header.indexOf("compare_y [m]")), ct = int(header.indexOf("compare_t [s]"));
        QVERIFY(y > 0 && vy > 0 && cy > 0 && ct > 0);
        const QStringList last = lines[3].split(','); // t = 1
        QCOMPARE(last.size(), header.size());
        QCOMPARE(last[y].toDouble(), 9.0);
        QCOMPARE(last[vy].toDouble(), -2.0);
        QCOMPARE(last[ct].toDouble(), 1.0);
        QCOMPARE(last[cy].toDouble(), 6.0);
    }
};

QTEST_MAIN(UiCharts)
#include "test_ui_charts.moc"
