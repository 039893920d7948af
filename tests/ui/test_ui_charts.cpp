// SPDX-License-Identifier: MIT
// The window's data path without a window: downsampling keeps every extreme, the
// recording stays bounded and holds exactly the core's states, the charts draw only the
// scene's axes and the run's closed-form free fall, and the worker stops on a
// non-finite state without ever recording it.
#include "support/sim_helpers.h"

#include "core/diagnostics/conservation.h"
#include "ui/charts/chart_data_csv.h"
#include "ui/charts/downsample.h"
#include "ui/charts/motion_chart.h"
#include "ui/charts/scene_layout.h"
#include "ui/panels/chart_panel.h"
#include "ui/sim/recording.h"
#include "ui/sim/run_engine.h"

#include <QChartView>
#include <QGraphicsTextItem>
#include <QLineSeries>
#include <QValueAxis>
#include <QtTest>

#include <cmath>
#include <limits>

namespace {

// A rule that flies freely and then produces a NaN: a stand-in for a diverging model.
class Diverging final : public ab::Simulation {
public:
    explicit Diverging(long long badStep) : Simulation(ab::RunSpec(ab::SceneId::Box3d), 1.0), badStep_(badStep) {}
    ab::State initialState() const override
    {
        ab::State s;
        s.resize(1);
        s.p.col(0) = Eigen::Vector3d(1, 2, 3);
        return s;
    }
    void step(ab::State& s, ab::State& next) override
    {
        next = s;
        next.t = s.t + 1.0;
        next.p(0, 0) = s.p(0, 0) + 1.0;
        if (std::lround(next.t) == badStep_)
            next.p(1, 0) = std::numeric_limits<double>::quiet_NaN();
    }

private:
    long long badStep_;
};

} // namespace

class UiCharts : public QObject {
    Q_OBJECT

private slots:
    void downsamplingKeepsEveryPointOfAShortRun()
    {
        const std::vector<double> t{0, 1, 2, 3}, y{5, -1, 7, 2};
        const QList<QPointF> p = ab::ui::downsampleMinMax(t, y, 10);
        QCOMPARE(p.size(), 4);
        for (int i = 0; i < 4; ++i)
            QCOMPARE(p[i], QPointF(t[std::size_t(i)], y[std::size_t(i)]));
    }

    void downsamplingALongRunKeepsEndsPeaksAndOrderWithinBudget()
    {
        // A bouncing-like signal: 100,000 samples, one sharp spike (a single sample).
        const std::size_t n = 100000;
        std::vector<double> t(n), y(n);
        for (std::size_t i = 0; i < n; ++i) {
            t[i] = 0.01 * double(i);
            y[i] = std::sin(0.001 * double(i));
        }
        y[54321] = 40.0;
        y[77] = -40.0;
        const int columns = 300;
        const QList<QPointF> p = ab::ui::downsampleMinMax(t, y, columns);
        QVERIFY(p.size() <= 4 * columns);
        QCOMPARE(p.front(), QPointF(t.front(), y.front()));
        QCOMPARE(p.back(), QPointF(t.back(), y.back()));
        const auto [lo, hi] = std::minmax_element(p.begin(), p.end(), [](auto& a, auto& b) { return a.y() < b.y(); });
        QCOMPARE(hi->y(), 40.0);
        QCOMPARE(hi->x(), t[54321]);
        QCOMPARE(lo->y(), -40.0);
        for (int i = 1; i < p.size(); ++i)
            QVERIFY(p[i].x() > p[i - 1].x());
    }

    void downsamplingNeverDrawsANonFiniteSample()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const std::vector<double> t{0, 1, 2, 3, 4}, y{1, nan, 3, std::numeric_limits<double>::infinity(), 5};
        const QList<QPointF> p = ab::ui::downsampleMinMax(t, y, 10);
        QCOMPARE(p.size(), 3);
        for (const QPointF& q : p)
            QVERIFY(std::isfinite(q.y()));
    }

    void trackThinsEvenlyPastItsCapacityAndKeepsTheStart()
    {
        ab::ui::MotionTrack track(8);
        for (long long step = 0; step <= 100; ++step)
            track.add(step, 0.5 * double(step), Eigen::Vector3d(double(step), 0, 0), Eigen::Vector3d::Zero(),
                      ab::ConservationSample{});
        QVERIFY(track.size() <= 8);
        QCOMPARE(track.steps().front(), 0LL);
        QCOMPARE(track.stride(), 16LL); // 101 samples into 8: stride 1 -> 16
        for (std::size_t i = 0; i < track.size(); ++i) {
            QCOMPARE(track.steps()[i] % track.stride(), 0LL);
            QCOMPARE(track.p(0)[i], double(track.steps()[i])); // samples kept whole, not averaged
            QCOMPARE(track.t()[i], 0.5 * double(track.steps()[i]));
        }
    }

    void layoutFollowsTheScenesSize()
    {
        ab::RunSpec box(ab::SceneId::Box3d);
        box.params.parseAssignment("box=120");
        const ab::ui::SceneLayout l = ab::ui::layoutFor(box);
        QCOMPARE(l.region.max().x(), 120.0);
        QCOMPARE(l.region.min().y(), 0.0);
        ab::RunSpec drop(ab::SceneId::Bounce1d);
        drop.params.parseAssignment("h0=500");
        drop.params.parseAssignment("v0=10");
        drop.params.parseAssignment("g=2");
        // Thrown up at 10 from 500 under g = 2: the top is 500 + 10^2 / (2 * 2) = 525.
        QCOMPARE(ab::ui::layoutFor(drop).region.max().y(), 525.0);
        QCOMPARE(ab::ui::layoutFor(drop).axes, 1);
    }

    void recordingKeepsFramesWithinItsBudgetAndFindsThemByTime()
    {
        ab::RunSpec spec(ab::SceneId::ManyBalls);
        spec.params.parseAssignment("n=10");
        const ab::ui::SceneLayout layout = ab::ui::layoutFor(spec);
        const std::size_t frameBytes = 6 * sizeof(float) * 10;
        const auto sim = ab::makeSimulation(spec);
        ab::ui::Recording rec(layout, ab::ConservationMeter(*sim), 0, 20 * frameBytes);
        QCOMPARE(rec.maxFrames(), std::size_t(20));
        for (long long step = 0; step <= 100; ++step) {
            ab::State s;
            s.t = double(step);
            s.resize(10);
            s.p.row(0).setConstant(double(step));
            rec.add(step, s);
        }
        QVERIFY(rec.frames().size() <= 20);
        QCOMPARE(rec.frameStride(), 8LL);
        QCOMPARE(rec.frames().front().step, 0LL);
        const ab::ui::Frame* f = rec.frameAt(50.0); // frames at 0, 8, ..., 48, 56: 48 is the last at or before 50
        QVERIFY(f);
        QCOMPARE(f->t, 48.0);
        QCOMPARE(f->p[0], 48.0f);
        QVERIFY(rec.frameAt(-1.0) == nullptr);
        QCOMPARE(rec.track().size(), std::size_t(101)); // the followed ball: every step
    }

    void followingAnotherBallRebuildsItsTrackFromTheFrames()
    {
        ab::RunSpec spec(ab::SceneId::TwoBalls);
        const auto sim = ab::makeSimulation(spec);
        ab::ui::Recording rec(ab::ui::layoutFor(spec), ab::ConservationMeter(*sim), 0);
        for (long long step = 0; step < 5; ++step) {
            ab::State s;
            s.t = double(step);
            s.resize(2);
            s.p(2, 0) = 1.0;
            s.p(2, 1) = 100.0 + double(step);
            rec.add(step, s);
        }
        rec.setTrackedBall(1);
        QCOMPARE(rec.track().size(), std::size_t(5));
        for (std::size_t i = 0; i < 5; ++i)
            QCOMPARE(rec.track().p(2)[i], 100.0 + double(i));
    }

    void engineRecordsExactlyTheStatesTheCoreComputes()
    {
        const ab::RunSpec spec = testing::spec(ab::SceneId::Box3d);
        const std::vector<ab::State> expected = testing::record(spec, 40);
        ab::ui::RunEngine engine(ab::makeSimulation(spec), 40, 0);
        engine.play(1e6); // as fast as it goes
        QTRY_VERIFY_WITH_TIMEOUT(engine.status().finished, 20000);
        QCOMPARE(engine.status().steps, 40LL);
        engine.read([&](const ab::ui::Recording& rec, const ab::ui::Frame& current) {
            const ab::ui::MotionTrack& track = rec.track();
            QCOMPARE(track.size(), expected.size());
            for (std::size_t i = 0; i < expected.size(); ++i)
                for (int a = 0; a < 3; ++a) {
                    QCOMPARE(track.p(a)[i], expected[i].p(a, 0));
                    QCOMPARE(track.v(a)[i], expected[i].v(a, 0));
                }
            QCOMPARE(current.t, expected.back().t);
        });
    }

    void engineStepsOnceAndPauses()
    {
        ab::ui::RunEngine engine(ab::makeSimulation(testing::spec(ab::SceneId::Bounce1d)), 2000, 0);
        engine.stepOnce();
        engine.stepOnce();
        QTRY_COMPARE(engine.status().steps, 2LL);
        QCOMPARE(engine.status().t, 2.0); // dt = 1 step
        QVERIFY(!engine.status().playing);
        // Free fall from rest, eq 2.15: v = -g t exactly for the report's scheme.
        engine.read([](const ab::ui::Recording& rec, const ab::ui::Frame& current) {
            QCOMPARE(rec.track().size(), std::size_t(2));
            QVERIFY(std::abs(current.v[1] - float(-0.0982 * 2)) < 1e-6f);
        });
    }

    void engineStopsAtANonFiniteStateAndNeverRecordsIt()
    {
        ab::ui::RunEngine engine(std::make_unique<Diverging>(5), 100, 0);
        engine.play(1e6);
        QTRY_VERIFY_WITH_TIMEOUT(engine.status().finished, 20000);
        const ab::ui::EngineStatus st = engine.status();
        QVERIFY(!st.playing);
        QVERIFY(st.warning.find("non-finite") != std::string::npos);
        engine.read([](const ab::ui::Recording& rec, const ab::ui::Frame& current) {
            QCOMPARE(rec.track().size(), std::size_t(5)); // t = 0..4; t = 5 held the NaN
            for (double y : rec.track().p(1))
                QVERIFY(std::isfinite(y));
            for (float x : current.p)
                QVERIFY(std::isfinite(x));
        });
    }

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
        QStringList labels;
        for (const QGraphicsItem* item : view.scene()->items())
            if (const auto* t = dynamic_cast<const QGraphicsTextItem*>(item))
                labels << t->toPlainText();
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
        QVERIFY(spring.title().startsWith("Energy, all balls (kg"));
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
