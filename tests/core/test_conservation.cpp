// SPDX-License-Identifier: MIT
// What the conservation meter reads from a state, checked against hand-computed physics:
// energy with the physical model's masses, per unit mass for the report, the spring
// floor's share, many-balls' rotation; momentum kept by the physical collision and not by the report's speed
// swap; impacts counted once per wall contact and once per pair, in both many-balls models.
#include "support/sim_helpers.h"

#include "core/diagnostics/conservation.h"

#include <QtTest>

#include <cmath>

namespace {

bool near(double a, double b, double relative)
{
    return std::abs(a - b) <= relative * std::max(std::abs(b), 1.0);
}

} // namespace

class Conservation : public QObject {
    Q_OBJECT

private slots:
    void energyWithUnequalMassesIsTheHandSum()
    {
        // E = 1/2 m1 |v1|^2 + 1/2 m2 |v2|^2 + m1 g y1 + m2 g y2, p = m1 v1 + m2 v2.
        const ab::RunSpec spec = testing::spec(ab::SceneId::TwoBalls, {"m1=2", "m2=5"}, ab::ModelKind::Physical);
        const auto sim = ab::makeSimulation(spec);
        ab::State s;
        s.resize(2);
        s.p.col(0) = Eigen::Vector3d(10, 30, 10);
        s.v.col(0) = Eigen::Vector3d(1, 2, 3); // |v1|^2 = 14
        s.p.col(1) = Eigen::Vector3d(50, 40, 60);
        s.v.col(1) = Eigen::Vector3d(-4, 0, 1); // |v2|^2 = 17
        const ab::ConservationSample c = ab::measureConservation(*sim, s);
        QVERIFY(near(c.energy.kinetic, 0.5 * 2 * 14 + 0.5 * 5 * 17, 1e-14));     // 56.5
        QVERIFY(near(c.energy.potential, 2 * 9.82 * 30 + 5 * 9.82 * 40, 1e-14)); // 2553.2
        QCOMPARE(c.energy.spring, 0.0);
        QVERIFY(near(c.energy.total(), 56.5 + 2553.2, 1e-14));
        QVERIFY((c.momentum - Eigen::Vector3d(-18, 4, 11)).norm() < 1e-13);
        QVERIFY(!ab::ConservationMeter(*sim).perUnitMass());
    }

    void reportEnergyIsPerUnitMassAboveTheFloor()
    {
        // One ball 10 m above the floor moving at (3, 4, 0) m/s: |v|^2/2 + g h = 12.5 + 98.2.
        const auto box = ab::makeSimulation(testing::spec(ab::SceneId::Box3d));
        ab::State s;
        s.resize(1);
        s.p.col(0) = Eigen::Vector3d(5, 10, 5);
        s.v.col(0) = Eigen::Vector3d(3, 4, 0);
        const ab::ConservationSample c = ab::measureConservation(*box, s);
        QVERIFY(near(c.energy.total(), 12.5 + 9.82 * 10.0, 1e-14));
        QVERIFY(ab::ConservationMeter(*box).perUnitMass());
        QVERIFY((c.momentum - Eigen::Vector3d(3, 4, 0)).norm() == 0.0);
        // Stage 4 measures height from its floor at -box/2: balls at rest on it have none.
        const auto many = ab::makeSimulation(testing::spec(ab::SceneId::ManyBalls, {"n=2"}));
        ab::State two;
        two.resize(2);
        two.p.row(1).setConstant(-50.0);
        const ab::ConservationSample rest = ab::measureConservation(*many, two);
        QCOMPARE(rest.energy.total(), 0.0);
        QCOMPARE(rest.moving, 0LL);
    }

    void manyBallsTurningBallsCountTheirRotation()
    {
        // Rough many-balls (physical, r = 2, q = 2/5): |v|^2/2 + q r^2 |w|^2/2 per unit mass,
        // 1/2 (1 + 4) + 0.4 x 4 x (9 + 16)/2 = 2.5 + 20 for one ball on the floor at rest's height.
        const auto many = ab::makeSimulation(
            testing::spec(ab::SceneId::ManyBalls, {"n=1", "r=2", "mu=0.5"}, ab::ModelKind::Physical));
        ab::State s;
        s.resize(1);
        s.p.col(0) = Eigen::Vector3d(0, -50, 0);
        s.v.col(0) = Eigen::Vector3d(1, 0, 2);
        s.w.setZero(3, 1);
        s.w.col(0) = Eigen::Vector3d(0, 3, -4);
        QVERIFY(near(ab::measureConservation(*many, s).energy.kinetic, 2.5 + 20.0, 1e-14));
        s.w.resize(3, 0); // a state without spins: translation only
        QVERIFY(near(ab::measureConservation(*many, s).energy.kinetic, 2.5, 1e-14));
    }

    void springFloorEnergyIsItsOwnPart()
    {
        // Linear spring per unit mass k_s = 100, ball of m = 2 pressed 0.1 into the floor:
        // spring m k_s d^2 / 2 = 1, gravity m g y = -2 g 0.1 (below the floor's zero;
        // stage 1's g is the report's 0.0982 per step^2).
        const ab::RunSpec spec =
            testing::spec(ab::SceneId::Bounce1d, {"contact=1", "stiffness=100", "m=2"}, ab::ModelKind::Physical);
        const auto sim = ab::makeSimulation(spec);
        QVERIFY(ab::ConservationMeter(*sim).hasSpring());
        ab::State s;
        s.resize(1);
        s.p(1, 0) = -0.1;
        s.v(1, 0) = 3.0;
        const ab::ConservationSample c = ab::measureConservation(*sim, s);
        QVERIFY(near(c.energy.spring, 1.0, 1e-12));
        QVERIFY(near(c.energy.potential, -2 * spec.params.real("g") * 0.1, 1e-12));
        QVERIFY(near(c.energy.kinetic, 0.5 * 2 * 9.0, 1e-14));
    }

    void twoBallsWithoutGravityOrLossKeepMomentumAndEnergy()
    {
        // Head-on along z, m1 = 1 at +10, m2 = 3 at -10, e = 1, g = 0: p_z = 10 - 30 = -20
        // and E = 50 + 150 = 200 before and after (ball 1 leaves at -20, ball 2 stops,
        // eqs 2.4-2.7). They meet near t = 14.8 s; ball 1 reaches the wall after t = 22 s.
        const ab::RunSpec spec =
            testing::spec(ab::SceneId::TwoBalls, {"g=0", "e=1", "k=1", "m1=1", "m2=3", "v1=0,0,10", "v2=0,0,-10"},
                          ab::ModelKind::Physical);
        ab::RunSpec stepped = spec;
        stepped.dt = 0.01;
        const auto sim = ab::makeSimulation(stepped);
        const ab::ConservationMeter meter(*sim);
        const ab::ConservationSample start = meter.measure(sim->start());
        QVERIFY(near(start.momentum.z(), -20.0, 1e-15));
        QVERIFY(near(start.energy.total(), 200.0, 1e-15));
        ab::State last;
        ab::runRecorded(*sim, sim->start(), 2000, 1, [&](const ab::State& s) {
            const ab::ConservationSample c = meter.measure(s);
            for (int a = 0; a < 3; ++a)
                QVERIFY(std::abs(c.momentum[a] - start.momentum[a]) <= 1e-12 * 20.0);
            QVERIFY(std::abs(c.energy.total() - 200.0) <= 1e-12 * 200.0);
            last = s;
        });
        QVERIFY(near(last.v(2, 0), -20.0, 1e-12)); // the collision did happen
        QVERIFY(std::abs(last.v(2, 1)) < 1e-12);
    }

    void reportSpeedSwapLosesEnergyAndMomentum()
    {
        // Appendix D, g = 0: ball 1 at (-1.5, 0, 0) moving (1, 0, 0) lands at -0.5, within
        // c r = 2.2 of ball 2 at 1.5: one swap. The swap keeps each speed times 0.95 and
        // exchanges them, so E = 1/2 (|v1|^2 + |v2|^2) falls by exactly 0.95^2; the
        // momentum (0.5, 0.3, 0) is not kept (the directions come from the fixed tangent).
        ab::RunSpec spec = testing::spec(ab::SceneId::ManyBalls, {"n=2", "g=0", "primary_loss=1"});
        ab::State s;
        s.resize(2);
        s.p.col(0) = Eigen::Vector3d(-1.5, 0, 0);
        s.v.col(0) = Eigen::Vector3d(1, 0, 0);
        s.p.col(1) = Eigen::Vector3d(1.5, 0, 0);
        s.v.col(1) = Eigen::Vector3d(-0.5, 0.3, 0);
        spec.init = s;
        const auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        const std::vector<ab::State> states = testing::record(spec, 1);
        const ab::ConservationSample before = meter.measure(states[0]);
        const ab::ConservationSample after = meter.measure(states[1]);
        QCOMPARE(after.impacts, 1LL);
        QVERIFY(near(after.energy.kinetic, 0.95 * 0.95 * before.energy.kinetic, 1e-12));
        QVERIFY((after.momentum - before.momentum).norm() > 0.05);
    }

    void reportImpactsAreCountedByHand()
    {
        // One ball from x = 0 at 1 unit/frame, walls at +-(box/2 - r) = +-4: past 4 in
        // frame 5 (the first wall), back past -4 in frame 14 (the second).
        ab::RunSpec spec = testing::spec(ab::SceneId::ManyBalls, {"n=1", "g=0", "box=10", "primary_loss=1"});
        ab::State s;
        s.resize(1);
        s.v(0, 0) = 1.0;
        spec.init = s;
        QCOMPARE(testing::record(spec, 4).back().impacts, 0LL);
        QCOMPARE(testing::record(spec, 5).back().impacts, 1LL);
        QCOMPARE(testing::record(spec, 13).back().impacts, 1LL);
        QCOMPARE(testing::record(spec, 14).back().impacts, 2LL);
    }

    void physicalImpactsAreCountedOncePerWallAndPair()
    {
        // g = 0, e = k = 1, walls where a centre touches at +-4. Balls at -2 and 2 close
        // at 1 each: they touch at t = 1 (one pair impact) and swap velocities, reach the
        // walls at t = 4 (two impacts), meet again at t = 7 (the fourth).
        ab::RunSpec spec = testing::spec(
            ab::SceneId::ManyBalls, {"n=2", "g=0", "box=10", "primary_loss=1", "secondary_loss=1", "rest_height=0"},
            ab::ModelKind::Physical);
        spec.dt = 0.1;
        ab::State s;
        s.resize(2);
        s.p(0, 0) = -2.0;
        s.v(0, 0) = 1.0;
        s.p(0, 1) = 2.0;
        s.v(0, 1) = -1.0;
        spec.init = s;
        const std::vector<ab::State> states = testing::record(spec, 80);
        QCOMPARE(states[5].impacts, 0LL);  // t = 0.5
        QCOMPARE(states[25].impacts, 1LL); // t = 2.5
        QCOMPARE(states[55].impacts, 3LL); // t = 5.5
        QCOMPARE(states[80].impacts, 4LL); // t = 8
    }

    void aReportBallOnTheFloorIsNotMovingWhateverItsSpeed()
    {
        // Appendix D updates only centres above -(L/2 - r) = -49: a ball there with a speed
        // from a collision never moves again; the same speed above the floor moves.
        const auto sim = ab::makeSimulation(testing::spec(ab::SceneId::ManyBalls, {"n=2"}));
        const ab::ConservationMeter meter(*sim);
        ab::State s = sim->start();
        s.p.col(0) = Eigen::Vector3d(0, -49, 0);
        s.p.col(1) = Eigen::Vector3d(10, 0, 0);
        s.v.col(0) = s.v.col(1) = Eigen::Vector3d(0.5, 0, 0);
        const auto sample = meter.measure(s);
        QCOMPARE(sample.moving, 1LL);
        QVERIFY(std::abs(sample.energy.kinetic - 2 * 0.5 * 0.25) < 1e-15); // both still hold energy
    }

    void manyBallsCountImpactsOnceBallsReachTheFloor()
    {
        for (ab::ModelKind model : {ab::ModelKind::Report, ab::ModelKind::Physical}) {
            const ab::RunSpec spec = testing::spec(ab::SceneId::ManyBalls, {"n=150"}, model);
            const auto sim = ab::makeSimulation(spec);
            const ab::ConservationMeter meter(*sim);
            const std::vector<ab::State> states = testing::record(spec, 600);
            QCOMPARE(states.front().impacts, 0LL);
            QVERIFY(states.back().impacts > 0);
            QVERIFY(meter.measure(states.front()).moving == 150); // every start velocity is far above rest
        }
    }
};

QTEST_MAIN(Conservation)
#include "test_conservation.moc"
