// SPDX-License-Identifier: MIT
// The physical model's time stepping: each integrator's energy behaviour in free flight
// (worked out by hand), exact located impacts, conservation of momentum in every pair
// collision, energy that never rises with located impacts, Walton's friction, the rest
// rule, and the contact geometry (no sinking, no overlap).
#include "core/physical/impacts.h"
#include "core/physical/physical_simulation.h"
#include "core/random.h"
#include "core/reference/collision.h"
#include "support/physical_spec.h"

#include <QtTest>

#include <cmath>

using ab::ImpactMode;
using ab::Integrator;
using ab::ModelKind;
using ab::SceneId;

Q_DECLARE_METATYPE(ab::Integrator)
Q_DECLARE_METATYPE(ab::ImpactMode)

using testing::physical;

namespace {

struct Run {
    std::vector<ab::State> states;
    std::vector<ab::physical::Impact> impacts;
    std::unique_ptr<ab::Simulation> sim;

    const ab::physical::PhysicalSimulation& physics() const
    {
        return dynamic_cast<const ab::physical::PhysicalSimulation&>(*sim);
    }
};

Run record(const ab::RunSpec& spec, long long steps)
{
    Run run;
    run.sim = ab::makeSimulation(spec);
    dynamic_cast<ab::physical::PhysicalSimulation&>(*run.sim).setImpactLog(&run.impacts);
    ab::runRecorded(*run.sim, run.sim->start(), steps, 1, [&](const ab::State& s) { run.states.push_back(s); });
    return run;
}

const std::vector<Integrator> stepIntegrators = {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet,
                                                 Integrator::Rk4};

} // namespace

class PhysicalStepping : public QObject {
    Q_OBJECT

private slots:
    void explicitEulerGainsHalfMG2Dt2EveryFlightStep_data()
    {
        QTest::addColumn<double>("g");
        QTest::addColumn<double>("dt");
        QTest::addColumn<double>("m");
        QTest::newRow("report gravity, dt 1 step") << 0.0982 << 1.0 << 1.0;
        QTest::newRow("report gravity, dt 0.25, m 2") << 0.0982 << 0.25 << 2.0;
        QTest::newRow("g 9.82, dt 0.1") << 9.82 << 0.1 << 1.0;
    }

    void explicitEulerGainsHalfMG2Dt2EveryFlightStep()
    {
        // y' = y + v dt, v' = v - g dt: E' = m (v - g dt)^2 / 2 + m g (y + v dt)
        //                                 = E + m g^2 dt^2 / 2, every step, exactly.
        QFETCH(double, g);
        QFETCH(double, dt);
        QFETCH(double, m);
        const auto spec = physical(SceneId::Bounce1d, Integrator::Euler, dt,
                                   {"g=" + QString::number(g, 'g', 17), "m=" + QString::number(m, 'g', 17)});
        const Run run = record(spec, 40);
        const double gain = 0.5 * m * g * g * dt * dt;
        const double e0 = run.physics().energy(run.states[0]);
        for (std::size_t n = 1; n < run.states.size(); ++n) {
            QVERIFY(run.states[n].p(1, 0) > 0.0); // still in flight
            const double step = run.physics().energy(run.states[n]) - run.physics().energy(run.states[n - 1]);
            QVERIFY2(std::abs(step - gain) <= 1e-9 * gain + 1e-13 * e0,
                     qPrintable(QString("step %1 gained %2, expected %3").arg(n).arg(step).arg(gain)));
        }
    }

    void symplecticEulerLosesHalfMG2Dt2EveryFlightStep()
    {
        // v' = v - g dt, y' = y + v' dt: E' = E - m g^2 dt^2 / 2.
        const double g = 0.0982, dt = 1.0;
        const Run run = record(physical(SceneId::Bounce1d, Integrator::SymplecticEuler, dt), 40);
        for (std::size_t n = 1; n < run.states.size(); ++n) {
            const double step = run.physics().energy(run.states[n]) - run.physics().energy(run.states[n - 1]);
            QVERIFY(std::abs(step + 0.5 * g * g * dt * dt) <= 1e-12);
        }
    }

    void verletAndRk4FlyTheParabolaExactly()
    {
        for (Integrator i : {Integrator::Verlet, Integrator::Rk4}) {
            const Run run = record(physical(SceneId::Bounce1d, i, 1.0), 200);
            for (const ab::State& s : run.states)
                QVERIFY(std::abs(s.p(1, 0) - (2000.0 - 0.5 * 0.0982 * s.t * s.t)) <= 1e-12 * 2000.0);
        }
    }

    void locatedImpactIsAtTheExactTimeStepEndOneStepLate()
    {
        // First impact of bounce1d: t1 = sqrt(2 h0 / g) = 201.8185 steps.
        const double t1 = std::sqrt(2.0 * 2000.0 / 0.0982);
        for (Integrator i : {Integrator::Verlet, Integrator::Rk4}) {
            const Run located = record(physical(SceneId::Bounce1d, i, 1.0), 250);
            QVERIFY(!located.impacts.empty());
            QVERIFY(std::abs(located.impacts.front().t - t1) <= 1e-12 * t1);
            const Run late = record(physical(SceneId::Bounce1d, i, 1.0, {}, ImpactMode::StepEnd), 250);
            QCOMPARE(late.impacts.front().t, 202.0); // detected at the end of the step it happened in
        }
    }

    void energyNeverRisesWithLocatedImpacts_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<double>("dt");
        QTest::addColumn<long long>("steps");
        const int b = int(SceneId::Bounce1d), x = int(SceneId::Box3d), t = int(SceneId::TwoBalls);
        QTest::newRow("bounce1d, dt 1") << b << QStringList{} << 1.0 << 2000LL;
        QTest::newRow("bounce1d, dt 7") << b << QStringList{} << 7.0 << 300LL;
        QTest::newRow("bounce1d, elastic k 1") << b << QStringList{"k=1"} << 0.5 << 3000LL;
        QTest::newRow("bounce1d, quadratic drag") << b << QStringList{"c=0.001"} << 1.0 << 2000LL;
        QTest::newRow("bounce1d, linear drag") << b << QStringList{"b=0.01"} << 1.0 << 2000LL;
        QTest::newRow("box3d, report") << x << QStringList{} << 0.01 << 6000LL;
        QTest::newRow("box3d, friction, dt 0.05") << x << QStringList{"mu=0.3", "k=0.8"} << 0.05 << 2000LL;
        QTest::newRow("two-balls, report") << t << QStringList{} << 0.01 << 6000LL;
        QTest::newRow("two-balls, unequal masses, oblique, friction")
            << t << QStringList{"m2=3.7", "e=0.8", "mu=0.2", "p2=4,22,298"} << 0.02 << 3000LL;
        QTest::newRow("two-balls, elastic") << t << QStringList{"k=1", "e=1", "p2=3,21,298"} << 0.02 << 2000LL;
    }

    void energyNeverRisesWithLocatedImpacts()
    {
        QFETCH(int, scene);
        QFETCH(QStringList, assignments);
        QFETCH(double, dt);
        QFETCH(long long, steps);
        for (Integrator i : {Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4, Integrator::Event}) {
            ab::RunSpec spec = physical(SceneId(scene), i, dt, assignments);
            if (i == Integrator::Event && (spec.params.real("b") > 0.0 || spec.params.real("c") > 0.0))
                continue; // the event integrator refuses drag
            const Run run = record(spec, steps);
            const double e0 = run.physics().energy(run.states[0]);
            for (const ab::State& s : run.states) {
                const double e = run.physics().energy(s);
                if (e > e0 + 1e-12 * std::abs(e0))
                    QFAIL(qPrintable(QString("%1: energy %2 at t = %3 exceeds the start %4")
                                         .arg(QString::fromStdString(std::string(ab::integratorKey(i))))
                                         .arg(e, 0, 'g', 17)
                                         .arg(s.t)
                                         .arg(e0, 0, 'g', 17)));
            }
        }
    }

    void momentumIsConservedInEveryPairCollision()
    {
        // No gravity, walls far away: total momentum must not change at all, whatever
        // the integrator, through a glancing collision of unequal masses.
        const QStringList set{"g=0",           "m1=1",      "m2=3.7",        "e=0.8",
                              "p1=100,50,100", "v1=10,1,5", "p2=110,51,104", "v2=-4,0,2"};
        for (ImpactMode mode : {ImpactMode::Located, ImpactMode::StepEnd}) {
            for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4,
                                 Integrator::Event}) {
                if (i == Integrator::Event && mode == ImpactMode::StepEnd)
                    continue;
                const Run run = record(physical(SceneId::TwoBalls, i, 0.01, set, mode), 300);
                const auto momentum = [](const ab::State& s) { return Eigen::Vector3d(s.v.col(0) + 3.7 * s.v.col(1)); };
                const Eigen::Vector3d p0 = momentum(run.states[0]);
                QVERIFY(run.states.back().bounces[0] >= 1 && run.states.back().bounces[1] >= 1);
                for (const ab::State& s : run.states)
                    QVERIFY2((momentum(s) - p0).norm() <= 1e-12 * p0.norm(),
                             qPrintable(QString("%1: momentum off by %2").arg(int(i)).arg((momentum(s) - p0).norm())));
            }
        }
    }

    void pairImpulseIsTheTextbookOutcome()
    {
        // The simulation's impulse form against the head-on decomposition of
        // reference/collision.h, for random masses, geometries and velocities.
        ab::SplitMix64 rng(7);
        auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
        for (int n = 0; n < 1000; ++n) {
            ab::physical::World w;
            w.mass = {uniform(0.1, 10.0), uniform(0.1, 10.0)};
            w.radius = 1.0;
            w.e = uniform(0.0, 1.0);
            const Eigen::Vector3d dir = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
            const Eigen::Vector3d p1(5, 5, 5), p2 = p1 - 2.0 * dir;
            Eigen::Vector3d v1(uniform(-9, 9), uniform(-9, 9), uniform(-9, 9)),
                v2(uniform(-9, 9), uniform(-9, 9), uniform(-9, 9));
            const auto [r1, r2] = ab::reference::obliqueOutcome(w.mass[0], w.mass[1], p1, p2, v1, v2, w.e);
            const Eigen::Vector3d before = w.mass[0] * v1 + w.mass[1] * v2;
            Eigen::Vector3d w1 = Eigen::Vector3d::Zero(), w2 = Eigen::Vector3d::Zero();
            ab::physical::resolvePairImpact(w, 0, 1, p1, p2, v1, v2, {w1, w2});
            const double scale = std::max(1.0, v1.norm() + v2.norm());
            QVERIFY((v1 - r1).norm() <= 1e-13 * scale);
            QVERIFY((v2 - r2).norm() <= 1e-13 * scale);
            QVERIFY((w.mass[0] * v1 + w.mass[1] * v2 - before).norm() <= 1e-12 * before.norm() + 1e-300);
        }
    }

    void wallImpactWithWaltonFriction()
    {
        // v = (3, -4, 0) onto the floor, k = 0.5, a solid ball (q = 0.4) without spin: the
        // normal part goes -4 -> 2 (impulse 6 per unit mass). Sticking with beta = 0 would
        // take (1 + beta) q / (1 + q) 3 = 6/7 from the 3 m/s along the floor.
        ab::physical::World w;
        w.g = 9.82;
        w.mass = {1.0};
        w.spinRadius = 1.0;
        w.beta = 0.0;
        ab::physical::Wall floor = ab::physical::floorWall(0.0, 0.5, 0.1);
        // mu = 0.1: sliding, bounded by mu 6 = 0.6, which also gives r w = 0.6 / q = 1.5
        // about -z (the rolling sense of motion along +x).
        Eigen::Vector3d v(3, -4, 0), spin = Eigen::Vector3d::Zero();
        QCOMPARE(ab::physical::resolveWallImpact(w, floor, v, spin, 0.0), 4.0);
        QVERIFY((v - Eigen::Vector3d(3 - 0.6, 2, 0)).norm() < 1e-15);
        QVERIFY((spin - Eigen::Vector3d(0, 0, -1.5)).norm() < 1e-15);
        // mu = 1: sticking, the contact point stops: v_x = 3 - 6/7 = 15/7 = r |w|.
        floor.mu = 1.0;
        v = {3, -4, 0};
        spin.setZero();
        ab::physical::resolveWallImpact(w, floor, v, spin, 0.0);
        QVERIFY((v - Eigen::Vector3d(15.0 / 7.0, 2, 0)).norm() < 1e-15);
        QVERIFY((spin - Eigen::Vector3d(0, 0, -15.0 / 7.0)).norm() < 1e-15);
        // A wall's tangent is the slip's own: along y and z for the wall x = 0, where
        // mu = 0.05 of the normal impulse 20 bounds the change to 1 along (3, 4)/5 (sticking
        // would take 2/7 of the 5 m/s, 1.43).
        ab::physical::Wall wall{0, 0.0, 1.0, 1.0, 0.05, "wall x = 0"};
        v = {-10, 3, 4};
        spin.setZero();
        ab::physical::resolveWallImpact(w, wall, v, spin, 0.0);
        QVERIFY((v - Eigen::Vector3d(10, 3 * (1 - 1.0 / 5.0), 4 * (1 - 1.0 / 5.0))).norm() < 1e-14);
        // A smooth contact (beta = -1) changes nothing along the wall, whatever mu.
        w.beta = -1.0;
        v = {-10, 3, 4};
        spin = {1, 2, 3};
        ab::physical::resolveWallImpact(w, wall, v, spin, 0.0);
        QCOMPARE(v, Eigen::Vector3d(10, 3, 4));
        QCOMPARE(spin, Eigen::Vector3d(1, 2, 3));
    }

    void restSpeedCutsTheReboundForLocatedImpactsToo()
    {
        // As in the event test: the sixth rebound (0.92 unit/step) is slower than 1 and is cut.
        const double g = 0.0982, u1 = std::sqrt(2.0 * g * 2000.0);
        double t6 = u1 / g;
        for (int n = 1; n <= 5; ++n)
            t6 += 2.0 * u1 * std::pow(0.6, n) / g;
        const Run run = record(physical(SceneId::Bounce1d, Integrator::Verlet, 1.0, {"rest_speed=1"}), 1000);
        QCOMPARE(run.impacts.size(), std::size_t(6));
        QVERIFY(std::abs(run.impacts.back().t - t6) < 1e-9 * t6);
        QCOMPARE(run.states.back().p(1, 0), 0.0);
        QCOMPARE(run.states.back().v(1, 0), 0.0);
    }

    void neverSinksAndComesToRest_data()
    {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<ImpactMode>("impacts");
        for (Integrator i : stepIntegrators)
            for (ImpactMode m : {ImpactMode::Located, ImpactMode::StepEnd})
                QTest::newRow(qPrintable(QString::fromStdString(std::string(ab::integratorKey(i)) + " " +
                                                                std::string(ab::impactModeKey(m)))))
                    << i << m;
    }

    void neverSinksAndComesToRest()
    {
        QFETCH(Integrator, integrator);
        QFETCH(ImpactMode, impacts);
        const Run run = record(physical(SceneId::Bounce1d, integrator, 1.0, {}, impacts), 4000);
        for (const ab::State& s : run.states)
            QVERIFY(s.p(1, 0) >= 0.0);
        if (integrator == Integrator::Euler)
            return; // explicit Euler gains m g^2 dt^2 / 2 in every step of flight: it never settles
        QCOMPARE(run.states.back().p(1, 0), 0.0);
        QCOMPARE(run.states.back().v(1, 0), 0.0);
    }

    void twoBallsKeepTheirDistance_data()
    {
        neverSinksAndComesToRest_data();
        QTest::newRow("event") << Integrator::Event << ImpactMode::Located;
    }

    void twoBallsKeepTheirDistance()
    {
        // Centres stay r from every wall and 2r from each other (r = 1.5 here), through
        // a glancing collision, wall hits and resting on the floor.
        QFETCH(Integrator, integrator);
        QFETCH(ImpactMode, impacts);
        const QStringList set{"r=1.5", "box=40", "p1=3,10,5", "v1=8,2,9", "p2=30,12,30", "v2=-7,0,-6", "m2=2"};
        const Run run = record(physical(SceneId::TwoBalls, integrator, 0.02, set, impacts), 2000);
        QVERIFY(run.states.back().count > 10);
        for (const ab::State& s : run.states) {
            QVERIFY((s.p.col(0) - s.p.col(1)).norm() >= 3.0 - 1e-9);
            QVERIFY(s.p.minCoeff() >= 1.5 - 1e-9);
            QVERIFY(s.p.row(0).maxCoeff() <= 38.5 + 1e-9 && s.p.row(2).maxCoeff() <= 38.5 + 1e-9);
        }
    }

    void aBallWedgedAgainstAWallDoesNotCollapse()
    {
        // A heavy ball pushes a light one into the wall x = r, both inelastic: without care
        // they collide infinitely often in finite time (inelastic collapse). Every
        // integrator must get through it, keep the geometry and never gain energy.
        const QStringList set{"g=0", "k=0.5", "e=0.5", "m2=10", "p1=3,20,150", "v1=0,0,0", "p2=6,20,150", "v2=-2,0,0"};
        for (Integrator i :
             {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4, Integrator::Event}) {
            const Run run = record(physical(SceneId::TwoBalls, i, 0.01, set), 400);
            const double e0 = run.physics().energy(run.states[0]);
            for (const ab::State& s : run.states) {
                QVERIFY(run.physics().energy(s) <= e0 * (1.0 + 1e-12));
                QVERIFY((s.p.col(0) - s.p.col(1)).norm() >= 2.0 - 1e-9);
                QVERIFY(s.p(0, 0) >= 1.0 - 1e-12);
            }
            QVERIFY(run.states.back().count < 1000);
        }
    }

    void aBallRestingOnAnotherStaysOnItOrStopsTheEventIntegrator()
    {
        // Dropped exactly onto a ball resting on the floor, a ball comes to rest on top of
        // it: a lasting contact between balls, which the impulse model does not have. The
        // step integrators keep both apart and above the floor; the event integrator stops
        // with a message naming what to use instead.
        const QStringList set{"e=0.5", "p1=50,1,50", "v1=0,0,0", "p2=50,5,50", "v2=0,0,0"};
        for (Integrator i : {Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4}) {
            const Run run = record(physical(SceneId::TwoBalls, i, 0.01, set), 400);
            for (const ab::State& s : run.states) {
                QVERIFY((s.p.col(0) - s.p.col(1)).norm() >= 2.0 - 1e-9);
                QVERIFY(s.p.row(1).minCoeff() >= 1.0);
            }
            QVERIFY(std::abs(run.states.back().p(1, 1) - 3.0) < 1e-3);
        }
        try {
            record(physical(SceneId::TwoBalls, Integrator::Event, 0.01, set), 400);
            QFAIL("the event integrator went on");
        } catch (const ab::InputError& e) {
            QVERIFY2(std::string(e.what()).find("choose a step integrator") != std::string::npos, e.what());
        }
    }

    void refusesTheSpringContactIntegratorsAndBadStarts()
    {
        for (Integrator i : {Integrator::ImplicitEuler, Integrator::ImplicitMidpoint}) {
            try {
                ab::makeSimulation(physical(SceneId::Bounce1d, i, 1.0));
                QFAIL("accepted an implicit integrator");
            } catch (const ab::InputError& e) {
                QVERIFY2(std::string(e.what()).find("spring-dashpot") != std::string::npos, e.what());
            }
        }
        const auto refused = [](const QStringList& set, const char* named) {
            try {
                ab::makeSimulation(physical(SceneId::TwoBalls, Integrator::Verlet, 0.01, set));
                return false;
            } catch (const ab::InputError& e) {
                return std::string(e.what()).rfind(named, 0) == 0;
            }
        };
        QVERIFY(refused({"p1=0.5,20,2"}, "p1:"));        // closer than r to the wall x = 0
        QVERIFY(refused({"p2=2,20,299.5"}, "p2:"));      // beyond the wall z = box - r
        QVERIFY(refused({"p2=2,20.5,3"}, "p1 and p2:")); // overlapping balls
    }
};

QTEST_GUILESS_MAIN(PhysicalStepping)
#include "test_physical_stepping.moc"
