// SPDX-License-Identifier: MIT
// The window's data path without a window: downsampling keeps every extreme, the
// recording stays bounded and holds exactly the core's states, the scene's layout follows
// its size, and the worker stops on a non-finite state without ever recording it.
#include "support/sim_helpers.h"

#include "core/diagnostics/conservation.h"
#include "ui/charts/downsample.h"
#include "ui/charts/scene_layout.h"
#include "ui/sim/recording.h"
#include "ui/sim/run_engine.h"
#include "ui/view/orbit_camera.h"
#include "ui/view/scene_geometry.h"
#include "ui/view/view_frame.h"

#include <QPainter>
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

class UiData : public QObject {
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

    // Stages 1 and 2 model the ball as a point that meets the floor at y = 0, but draw it
    // as a sphere: the floor is drawn one drawn radius lower, so the ball at rest touches it
    // with its underside instead of sitting half sunk in it. The drawn floor's triangles
    // all lie at y = -R; stage 4's balls have a contact radius and their floor is the box's.
    void aPointBallAtRestIsDrawnStandingOnTheFloor()
    {
        for (ab::SceneId id : {ab::SceneId::Bounce1d, ab::SceneId::Box3d}) {
            const ab::ui::SceneLayout l = ab::ui::layoutFor(ab::RunSpec(id));
            QVERIFY(l.ballRadius > 0.0);
            QCOMPARE(l.drawnInset, l.ballRadius);
            const ab::ui::SceneGeometry g = ab::ui::buildSceneGeometry(l, "m");
            QVERIFY(!g.floor.empty());
            for (const ab::ui::FlatVertex& v : g.floor)
                QCOMPARE(v.y, float(l.floorY - l.ballRadius));
        }
        const ab::ui::SceneLayout box = ab::ui::layoutFor(ab::RunSpec(ab::SceneId::ManyBalls));
        QCOMPARE(box.drawnInset, 0.0);
    }

    // Stage 1 labels its ball with its height beside the ball as drawn: the text's first inked
    // pixel on the ball's row lies at least the ball's projected radius and a third of a line
    // from its centre (at 0.9 of a line from the centre, "y = 0.0" touched a ball drawn larger).
    void theHeightLabelStandsClearOfTheBall()
    {
        const ab::ui::SceneLayout l = ab::ui::layoutFor(ab::RunSpec(ab::SceneId::Bounce1d));
        const ab::ui::SceneGeometry g = ab::ui::buildSceneGeometry(l, "unit");
        const QSize size(480, 990); // the window's view at 1920x1080
        ab::ui::OrbitCamera camera;
        ab::ui::frameSceneCamera(camera, g, l, float(size.width()) / float(size.height()));
        const std::vector<float> ball{0.0f, 1000.0f, 0.0f};
        QPointF centre, rim;
        QVERIFY(camera.project(QVector3D(0.0f, 1000.0f, 0.0f), size, centre));
        QVERIFY(camera.project(QVector3D(0.0f, 1000.0f + float(l.ballRadius), 0.0f), size, rim));
        const double radius =
            std::max(QLineF(centre, rim).length(), double(ab::ui::smallestBallPixels(l, size.height(), 1.0)));
        QVERIFY(radius > 5.0);
        QImage image(size, QImage::Format_RGB32);
        image.fill(Qt::white);
        QFont font;
        font.setPixelSize(13); // 10 pt
        {
            QPainter p(&image);
            ab::ui::SceneGeometry unlabelled = g;
            unlabelled.labels.clear(); // the scale's numbers lie left of the ball; only the ball's label
            ab::ui::paintSceneLabels(p, camera, size, unlabelled, l, ball, font, Qt::white);
        }
        const int row = int(std::lround(centre.y()));
        int first = -1;
        for (int x = int(centre.x()); x < size.width() && first < 0; ++x)
            for (int dy = -3; dy <= 3 && first < 0; ++dy)
                if (qGray(image.pixel(x, row + dy)) < 100)
                    first = x;
        QVERIFY2(first > 0, "no label drawn");
        QVERIFY2(first - centre.x() >= radius + 13.0 / 3.0,
                 qPrintable(QString("text at %1 px from the centre, ball %2 px").arg(first - centre.x()).arg(radius)));
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
            // The start, step 1 and the state shown, step 2's (the paused run's charts and
            // their CSV reach the moment on screen).
            QCOMPARE(rec.track().size(), std::size_t(3));
            QCOMPARE(rec.track().steps().back(), 2LL);
            QCOMPARE(rec.track().v(1).back(), -0.0982 * 2);
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
};

QTEST_MAIN(UiData)
#include "test_ui_data.moc"
