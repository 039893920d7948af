// SPDX-License-Identifier: MIT
// The balls' orientations, which the 3D view's pattern turns by: equation O1 turns a ball
// spinning at a constant w by |w| t about w/|w| however many steps it takes, turns that
// follow each other compose in their order, and the recording keeps each frame's
// orientation, so looking back turns the balls back and a fork turns on from the frame
// kept before it. A run whose balls do not turn keeps none.
#include "ui/sim/recording.h"
#include "ui/view/ball_orientation.h"

#include "core/diagnostics/conservation.h"
#include "core/simulation.h"

#include <QtTest>

#include <Eigen/Geometry>

using ab::ui::BallOrientations;

namespace {

// The angle between two orientations (0 when they are the same rotation; q and -q are).
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.angularDistance(b);
}

Eigen::Quaterniond turn(double angle, const Eigen::Vector3d& axis)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

// One ball at time t spinning at w.
ab::State spinning(double t, const Eigen::Vector3d& w)
{
    ab::State s;
    s.resize(1);
    s.t = t;
    s.w.resize(3, 1);
    s.w.col(0) = w;
    return s;
}

Eigen::Quaterniond fromFloats(const std::vector<float>& q, int ball)
{
    const auto k = std::size_t(ab::ui::kOrientationFloats * ball);
    return Eigen::Quaterniond(q[k + 3], q[k], q[k + 1], q[k + 2]);
}

ab::ui::Recording recordingOfOneBall(std::size_t budgetFrames)
{
    ab::RunSpec spec(ab::SceneId::Box3d);
    spec.model = ab::ModelKind::Physical;
    // The meter keeps a pointer to the simulation's World: the simulation outlives every recording.
    static const std::unique_ptr<ab::Simulation> sim = ab::makeSimulation(spec);
    const std::size_t frameBytes = 13 * sizeof(float); // p, v, w and q of one ball
    return ab::ui::Recording(ab::ui::layoutFor(spec), ab::ConservationMeter(*sim), 0, budgetFrames * frameBytes);
}

} // namespace

class BallOrientation : public QObject {
    Q_OBJECT

private slots:
    void aConstantSpinTurnsTheBallByItsRateTimesTheTimeAboutItsAxis()
    {
        const Eigen::Vector3d w(0.3, -1.1, 0.7); // rad per time unit
        const double dt = 0.01;
        BallOrientations o;
        const int steps = 10'000;
        for (int k = 0; k <= steps; ++k)
            o.follow(spinning(k * dt, w));
        QVERIFY(o.active());
        const double t = steps * dt; // 100 time units: |w| t = 134 rad, many turns
        const Eigen::Quaterniond expected = turn(w.norm() * t, w);
        const double error = angleBetween(o[0], expected);
        QVERIFY2(error < 1e-9, qPrintable(QString("off by %1 rad").arg(error)));
        QVERIFY(std::abs(o[0].norm() - 1.0) < 1e-12);
    }

    void twoSpinsInTurnComposeInTheirOrder()
    {
        // 2 time units about x at 0.5, then 3 about y at 0.4: R = R_y(1.2) R_x(1.0). The
        // step in which the spin changes takes the mean of its two ends (O1).
        const Eigen::Vector3d wx(0.5, 0.0, 0.0), wy(0.0, 0.4, 0.0);
        BallOrientations o;
        for (int k = 0; k <= 200; ++k)
            o.follow(spinning(k * 0.01, wx));
        for (int k = 201; k <= 500; ++k)
            o.follow(spinning(k * 0.01, wy));
        const Eigen::Vector3d mean = 0.5 * (wx + wy);
        const Eigen::Quaterniond expected = turn(0.4 * 2.99, wy) * turn(mean.norm() * 0.01, mean) * turn(0.5 * 2.0, wx);
        const double error = angleBetween(o[0], expected);
        QVERIFY2(error < 1e-9, qPrintable(QString("off by %1 rad").arg(error)));
        // The other order is another orientation: the test tells them apart.
        const Eigen::Quaterniond swapped = turn(0.5 * 2.0, wx) * turn(mean.norm() * 0.01, mean) * turn(0.4 * 2.99, wy);
        QVERIFY(angleBetween(o[0], swapped) > 0.1);
    }

    void aBallAtRestKeepsItsOrientation()
    {
        BallOrientations o;
        o.follow(spinning(0.0, Eigen::Vector3d(0.0, 0.0, 2.0)));
        o.follow(spinning(0.5, Eigen::Vector3d(0.0, 0.0, 2.0)));
        const Eigen::Quaterniond before = o[0];
        for (int k = 1; k <= 100; ++k)
            o.follow(spinning(0.5 + k, Eigen::Vector3d(0.0, 0.0, 0.0)));
        // The step from spinning to rest turns it by the mean, 1 rad a unit, for 1 unit.
        QVERIFY(angleBetween(o[0], turn(1.0, Eigen::Vector3d::UnitZ()) * before) < 1e-12);
    }

    void lookingBackShowsThatFramesOrientationAndAForkTurnsOnFromIt()
    {
        // Ten frames at most: the stride doubles, and the steps between frames are not kept.
        ab::ui::Recording rec = recordingOfOneBall(10);
        const Eigen::Vector3d w1(0.0, 0.0, 0.1), w2(0.2, 0.0, 0.0); // rad per step
        for (long long step = 0; step <= 100; ++step)
            rec.add(step, spinning(double(step), w1));
        QVERIFY(rec.frameStride() > 1);
        const ab::ui::Frame* f = rec.frameAt(40.0);
        QVERIFY(f && f->step <= 40);
        QCOMPARE(f->q.size(), std::size_t(4));
        QVERIFY(angleBetween(fromFloats(f->q, 0), turn(0.1 * f->t, w1)) < 1e-5);
        QCOMPARE(f->bytes(), 13 * sizeof(float));

        // Fork back at step 70 (between kept frames): the ball turns on from the last
        // frame kept before it, at w2 from there.
        const long long forkAt = 70;
        rec.truncateFrom(forkAt);
        const ab::ui::Frame kept = rec.frames().back();
        QVERIFY(kept.step < forkAt);
        for (long long step = forkAt; step <= 100; ++step)
            rec.add(step, spinning(double(step), w2));
        const ab::ui::Frame& last = rec.frames().back();
        QCOMPARE(last.step, 96LL);
        const Eigen::Vector3d mean = 0.5 * (w1 + w2); // over the gap from the kept frame to the fork
        const Eigen::Quaterniond expected = turn(0.2 * double(last.step - forkAt), w2) *
                                            turn(mean.norm() * double(forkAt - kept.step), mean) *
                                            turn(0.1 * kept.t, w1);
        const double error = angleBetween(fromFloats(last.q, 0), expected);
        QVERIFY2(error < 1e-5, qPrintable(QString("off by %1 rad").arg(error)));
        // Looking back before the fork still shows the orientation kept then.
        QVERIFY(angleBetween(fromFloats(rec.frameAt(40.0)->q, 0), turn(0.1 * rec.frameAt(40.0)->t, w1)) < 1e-5);

        // The frame drawn while playing is one step ahead of the recording.
        const std::vector<float> ahead = rec.orientationsAt(spinning(101.0, w2));
        const Eigen::Quaterniond expectedAhead = turn(0.2 * double(101 - forkAt), w2) *
                                                 turn(mean.norm() * double(forkAt - kept.step), mean) *
                                                 turn(0.1 * kept.t, w1);
        QVERIFY(angleBetween(fromFloats(ahead, 0), expectedAhead) < 1e-5);
    }

    void aRunWhoseBallsDoNotTurnKeepsNoOrientation()
    {
        ab::ui::Recording rec = recordingOfOneBall(10);
        for (long long step = 0; step <= 5; ++step) {
            ab::State s;
            s.resize(1);
            s.t = double(step);
            rec.add(step, s);
        }
        for (const ab::ui::Frame& f : rec.frames())
            QVERIFY(f.q.empty());
        ab::State s;
        s.resize(1);
        QVERIFY(rec.orientationsAt(s).empty());
    }
};

QTEST_GUILESS_MAIN(BallOrientation)
#include "test_ball_orientation.moc"
