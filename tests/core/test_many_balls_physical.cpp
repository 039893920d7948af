// SPDX-License-Identifier: MIT
// Stage 4, physical model: a head-on and an oblique impact worked by hand (eqs 2.4-2.11),
// a wall impact located inside the step, momentum kept by ball-ball impulses, energy never
// gained, every centre inside the box, overlaps below a stated tolerance, a pile that comes
// to rest, fast balls that do not pass through each other, ball indices that stay put
// while the engine re-orders its arrays, bit-identical runs for any thread count, and the
// same bits from the AVX2 flight and grid as from the portable ones.
#include "support/many_balls_helpers.h"

#include "core/physical/many_balls_physical.h"
#include "core/random.h"

#include <QtTest>

#include <cmath>

using ab::Broadphase;
using ab::ImpactMode;
using ab::Integrator;
using ab::ModelKind;
using ab::SceneId;
using ab::State;
using Eigen::Vector3d;

Q_DECLARE_METATYPE(ab::Integrator)
Q_DECLARE_METATYPE(ab::ImpactMode)
Q_DECLARE_METATYPE(ab::Broadphase)

namespace {

constexpr auto physical = &testing::manyBallsPhysical; // the physical model with --set assignments and dt
constexpr auto balls = &testing::ballsAt;              // a start from (position, velocity) pairs

double kinetic(const State& s)
{
    return 0.5 * s.v.squaredNorm(); // unit masses
}

// Kinetic plus potential energy (unit masses, height measured from the origin).
double energy(const State& s, double g)
{
    return kinetic(s) + g * s.p.row(1).sum();
}

// The deepest overlap 2r - |pi - pj| over all pairs (0 when none touch).
double deepestOverlap(const State& s, double r)
{
    double deepest = 0.0;
    for (int i = 0; i < s.size(); ++i)
        for (int j = i + 1; j < s.size(); ++j)
            deepest = std::max(deepest, 2.0 * r - (s.p.col(i) - s.p.col(j)).norm());
    return deepest;
}

bool inside(const State& s, double box, double r)
{
    const double limit = box / 2.0 - r;
    return s.p.allFinite() && s.p.maxCoeff() <= limit && s.p.minCoeff() >= -limit;
}

long long rebounds(const State& s)
{
    long long sum = 0;
    for (int b : s.bounces)
        sum += b;
    return sum;
}

bool identical(const State& a, const State& b)
{
    return a.p == b.p && a.v == b.v && a.bounces == b.bounces;
}

// Tolerance on the deepest overlap after a step (see docs/performance.md): the contact
// passes leave at most this fraction of r in a settling pile under gravity.
constexpr double kOverlapTolerance = 0.05;

} // namespace

class PhysicalManyBalls : public QObject {
    Q_OBJECT

private slots:
    void headOnImpactReversesWithRestitution()
    {
        // Two balls 2.01 apart closing at 2: after one step of 0.01 they overlap by 0.01.
        // Eqs 2.4-2.7 with equal masses and e = 0.8: u = -2 becomes +1.6, so va = -0.8 and
        // vb = +0.8; the projection moves each 0.005 back, leaving them exactly touching.
        auto spec = physical({"n=2", "g=0", "secondary_loss=0.8"}, 0.01);
        spec.init = balls({{Vector3d(-1.005, 0, 0), Vector3d(1, 0, 0)}, {Vector3d(1.005, 0, 0), Vector3d(-1, 0, 0)}});
        const auto s = testing::record(spec, 1);
        QVERIFY((s[1].v.col(0) - Vector3d(-0.8, 0, 0)).norm() < 1e-14);
        QVERIFY((s[1].v.col(1) - Vector3d(0.8, 0, 0)).norm() < 1e-14);
        QVERIFY((s[1].p.col(0) - Vector3d(-1.0, 0, 0)).norm() < 1e-14);
        QVERIFY((s[1].p.col(1) - Vector3d(1.0, 0, 0)).norm() < 1e-14);
        QCOMPARE(rebounds(s[1]), 2LL);
    }

    void obliqueImpactChangesOnlyTheNormalParts()
    {
        // Eqs 2.8-2.11: tangential parts kept, the normal relative velocity becomes -e times
        // itself, the momentum is kept. n is the line of centres after the flight.
        const double e = 0.7, dt = 0.01;
        auto spec = physical({"n=2", "g=0", "secondary_loss=0.7"}, dt);
        const Vector3d pa(-1.0, 0.3, 0.1), pb(0.9, -0.2, 0.3), va(1.0, 0.4, -0.2), vb(-0.5, 0.3, 0.6);
        spec.init = balls({{pa, va}, {pb, vb}});
        const auto s = testing::record(spec, 1);
        const Vector3d n = ((pb + vb * dt) - (pa + va * dt)).normalized();
        const Vector3d dva = s[1].v.col(0) - va, dvb = s[1].v.col(1) - vb;
        QVERIFY((dva - dva.dot(n) * n).norm() < 1e-14); // only along n
        QVERIFY((dvb - dvb.dot(n) * n).norm() < 1e-14);
        QVERIFY((dva + dvb).norm() < 1e-14); // momentum
        const double before = (vb - va).dot(n), after = (s[1].v.col(1) - s[1].v.col(0)).dot(n);
        QVERIFY(before < 0.0);
        QVERIFY(std::abs(after + e * before) < 1e-14);
    }

    void wallImpactIsLocatedInsideTheStep()
    {
        // Without gravity, 0.075 from the wall at speed 1 with dt = 0.25 (one substep): the
        // impact comes at t = 0.075 and the ball goes back 0.175 k (k = 0.9) in what is left
        // of the step. At the step end instead the ball is only put back on the wall.
        for (ImpactMode mode : {ImpactMode::Located, ImpactMode::StepEnd}) {
            auto spec = physical({"n=1", "g=0", "box=100", "primary_loss=0.9"}, 0.25);
            spec.impacts = mode;
            spec.init = balls({{Vector3d(49.0 - 0.075, 0, 0), Vector3d(1, 0, 0)}});
            const auto s = testing::record(spec, 1);
            const double x = mode == ImpactMode::Located ? 49.0 - 0.175 * 0.9 : 49.0;
            QVERIFY(std::abs(s[1].p(0, 0) - x) < 1e-12);
            QVERIFY(std::abs(s[1].v(0, 0) + 0.9) < 1e-12);
        }
    }

    void fallOnTheFloorMatchesTheParabola()
    {
        // Verlet flies the exact parabola, so a located floor impact gives the closed form:
        // dropped from 2 above the floor with g = 9.82, it lands at T = sqrt(2 * 2 / g) with
        // speed g T and leaves with k g T; at t = 1 (one step) it is at floor + k g T (t - T)
        // - g (t - T)^2 / 2.
        const double g = 9.82, k = 0.8, T = std::sqrt(4.0 / g);
        auto spec = physical({"n=1", "g=9.82", "primary_loss=0.8", "rest_height=0"}, 0.1);
        spec.integrator = Integrator::Verlet;
        spec.init = balls({{Vector3d(0, -49.0 + 2.0, 0), Vector3d::Zero()}});
        const auto s = testing::record(spec, 10);
        const double t = s.back().t, after = t - T;
        QVERIFY(after > 0.0 && after < 0.5);
        QVERIFY(std::abs(s.back().p(1, 0) - (-49.0 + k * g * T * after - 0.5 * g * after * after)) < 1e-9);
        QVERIFY(std::abs(s.back().v(1, 0) - (k * g * T - g * after)) < 1e-9);
    }

    void droppedBallComesToRestOnTheFloor()
    {
        // The rest rule ends the Zeno bounces: once a rebound would rise less than
        // rest_height, the ball stays on the floor, exactly, with zero velocity.
        auto spec = physical({"n=1", "g=9.82", "primary_loss=0.8", "rest_height=0.02"}, 1.0 / 240.0);
        spec.init = balls({{Vector3d(3, -45.0, -2), Vector3d(0.2, 0, 0.1)}}); // Zeno time about 8 s
        const auto s = testing::record(spec, 2400);
        QCOMPARE(s.back().p(1, 0), -49.0);
        QVERIFY(s.back().v.isZero(0.0));
        QVERIFY(rebounds(s.back()) > 5);
    }

    void momentumIsKeptByBallBallImpulses_data()
    {
        QTest::addColumn<Broadphase>("broadphase");
        QTest::addColumn<int>("threads");
        QTest::newRow("grid, 1 thread") << Broadphase::Grid << 1;
        QTest::newRow("grid, 3 threads") << Broadphase::Grid << 3;
        QTest::newRow("all pairs, 2 threads") << Broadphase::AllPairs << 2;
    }
    void momentumIsKeptByBallBallImpulses()
    {
        // No gravity, walls far away (box 2000, balls within 60 of the centre after the
        // run): only ball-ball impulses change velocities, so the total momentum stays.
        QFETCH(Broadphase, broadphase);
        QFETCH(int, threads);
        auto spec = physical({"n=400", "g=0", "box=2000", "secondary_loss=0.9", "seed=4"}, 1.0);
        spec.broadphase = broadphase;
        spec.threads = threads;
        const auto s = testing::record(spec, 30);
        const Vector3d p0 = s.front().v.rowwise().sum();
        const double scale = s.front().v.cwiseAbs().sum();
        for (const State& st : s) {
            QVERIFY((st.v.rowwise().sum() - p0).norm() <= 1e-13 * scale);
            QVERIFY(st.p.cwiseAbs().maxCoeff() < 100.0);
        }
        QVERIFY(rebounds(s.back()) > 100); // plenty of impacts
    }

    void energyIsNeverGainedWithoutGravity_data()
    {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<ImpactMode>("impacts");
        QTest::addColumn<double>("e");
        QTest::addColumn<double>("k");
        for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4})
            for (ImpactMode m : {ImpactMode::Located, ImpactMode::StepEnd}) {
                const std::string name = std::string(ab::integratorKey(i)) + ", " + std::string(ab::impactModeKey(m));
                QTest::newRow((name + ", elastic").c_str()) << i << m << 1.0 << 1.0;
                QTest::newRow((name + ", lossy").c_str()) << i << m << 0.9 << 0.95;
                QTest::newRow((name + ", plastic").c_str()) << i << m << 0.0 << 0.5;
            }
    }
    void energyIsNeverGainedWithoutGravity()
    {
        // A crowded box (400 balls in 28^3, 8% full) with k, e <= 1: every step keeps or
        // loses kinetic energy; with k = e = 1 it keeps it to round-off.
        QFETCH(Integrator, integrator);
        QFETCH(ImpactMode, impacts);
        QFETCH(double, e);
        QFETCH(double, k);
        auto spec = physical({"n=400", "g=0", "box=28", "seed=9"}, 1.0);
        spec.params.set("secondary_loss", Vector3d(e, 0, 0));
        spec.params.set("primary_loss", Vector3d(k, 0, 0));
        spec.integrator = integrator;
        spec.impacts = impacts;
        const auto s = testing::record(spec, 150);
        const double e0 = kinetic(s.front());
        for (std::size_t i = 1; i < s.size(); ++i) {
            QVERIFY(kinetic(s[i]) <= kinetic(s[i - 1]) * (1.0 + 1e-12));
            if (e == 1.0 && k == 1.0)
                QVERIFY(std::abs(kinetic(s[i]) - e0) <= 1e-11 * e0);
        }
        QVERIFY(rebounds(s.back()) > 200);
    }

    void energyWithGravityNeverRisesAboveTheStart_data()
    {
        QTest::addColumn<Integrator>("integrator");
        // Explicit Euler gains g^2 h^2 / 2 per substep in flight by itself; the others do not.
        QTest::newRow("symplectic-euler") << Integrator::SymplecticEuler;
        QTest::newRow("verlet") << Integrator::Verlet;
        QTest::newRow("rk4") << Integrator::Rk4;
    }
    void energyWithGravityNeverRisesAboveTheStart()
    {
        QFETCH(Integrator, integrator);
        auto spec = physical({"n=400", "g=9.82", "box=20", "seed=2"}, 1.0 / 240.0);
        spec.integrator = integrator;
        const auto s = testing::record(spec, 1200);
        const double e0 = energy(s.front(), 9.82);
        for (const State& st : s)
            QVERIFY(energy(st, 9.82) <= e0 + 1e-9 * std::abs(e0));
    }

    void pileStaysInsideWithSmallOverlapsAndComesToRest()
    {
        // 500 balls fall into a 20-wide box and pile up four or five deep. After every step
        // each centre is inside the box and no two overlap by more than the tolerance; after
        // 10 s the pile is at rest (what is left is about one step of gravity, g dt, a ball).
        auto spec = physical({"n=500", "g=9.82", "box=20", "seed=1"}, 1.0 / 240.0);
        auto sim = ab::makeSimulation(spec);
        State s = sim->start(), next;
        double deepest = 0.0;
        for (int i = 0; i < 2400; ++i) {
            sim->step(s, next);
            std::swap(s, next);
            QVERIFY(inside(s, 20.0, 1.0));
            if (i % 10 == 0)
                deepest = std::max(deepest, deepestOverlap(s, 1.0));
        }
        QVERIFY2(deepest <= kOverlapTolerance, qPrintable(QString("deepest overlap %1").arg(deepest)));
        const double gdt = 9.82 / 240.0;
        QVERIFY(kinetic(s) < 500 * 0.5 * (3 * gdt) * (3 * gdt));
    }

    void fastBallsDoNotPassThroughEachOther()
    {
        // Closing at 20 per step with dt = 1, r = 1: the step is cut into substeps in which no
        // ball moves more than r/4, so they meet instead of jumping past each other.
        auto spec = physical({"n=2", "g=0", "secondary_loss=1"}, 1.0);
        spec.init = balls({{Vector3d(-5, 0, 0), Vector3d(10, 0, 0)}, {Vector3d(5, 0, 0), Vector3d(-10, 0, 0)}});
        const auto s = testing::record(spec, 1);
        QVERIFY(s[1].p(0, 0) < s[1].p(0, 1));
        QVERIFY(s[1].v(0, 0) < 0.0 && s[1].v(0, 1) > 0.0);
    }

    void ballIndicesStayPutWhileTheArraysAreReordered()
    {
        // No gravity, no contact (a 7^3 lattice 40 apart, speeds below sqrt(3)): every ball
        // flies straight, p(t) = p0 + v0 t, for 100 steps of 0.05 while the engine re-orders
        // its arrays by cell every 32 substeps: ball i stays ball i.
        State start;
        start.resize(343);
        ab::SplitMix64 rng(6);
        for (int i = 0; i < 343; ++i) {
            // x varies slowest here, fastest in the grid: the re-ordering moves every ball.
            start.p.col(i) = Vector3d(i / 49, (i / 7) % 7, i % 7) * 40.0 - Vector3d::Constant(120.0);
            for (int a = 0; a < 3; ++a)
                start.v(a, i) = 2.0 * rng.uniform() - 1.0;
        }
        auto spec = physical({"n=343", "g=0", "box=400"}, 0.05);
        spec.init = start;
        const auto s = testing::record(spec, 100);
        QCOMPARE(rebounds(s.back()), 0LL);
        for (int i = 0; i < 343; ++i)
            QVERIFY((s.back().p.col(i) - (start.p.col(i) + start.v.col(i) * s.back().t)).norm() < 1e-10);
    }

    void runsAreBitIdenticalForAnyThreadCount()
    {
        // The same run on 1, 2 and 3 threads, and twice on 2: the slabs resolve their
        // contacts in a fixed order, so every bit agrees. 20000 balls start on a lattice 2r
        // apart, touching, so that each worker has several blocks of balls and the contacts
        // are many enough to be shared out too.
        auto run = [](int threads) {
            auto spec = physical({"n=20000", "g=9.82", "box=56", "seed=12"}, 1.0 / 240.0);
            spec.threads = threads;
            return testing::record(spec, 60).back();
        };
        const State one = run(1), two = run(2), again = run(2), three = run(3);
        QVERIFY(identical(two, again));
        QVERIFY(identical(one, two));
        QVERIFY(identical(one, three));
        QVERIFY(rebounds(one) > 0);
    }

    void avx2FlightAndGridGiveThePortableNumbers_data()
    {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<ImpactMode>("impacts");
        QTest::newRow("symplectic-euler, located") << Integrator::SymplecticEuler << ImpactMode::Located;
        QTest::newRow("symplectic-euler, step-end") << Integrator::SymplecticEuler << ImpactMode::StepEnd;
        QTest::newRow("euler, located") << Integrator::Euler << ImpactMode::Located;
        QTest::newRow("verlet, step-end") << Integrator::Verlet << ImpactMode::StepEnd;
        QTest::newRow("rk4, located") << Integrator::Rk4 << ImpactMode::Located;
    }
    void avx2FlightAndGridGiveThePortableNumbers()
    {
        // The vector flight takes four balls at a time only when all four end strictly
        // inside the box, with the scalar operations in the same order; the vector grid lists
        // the same pairs in the same order. So the two engines agree bit for bit: 3000 fast
        // balls in a box of 40 meet the walls, each other and the floor in 400 steps.
        if (!ab::broadphase::UniformGrid::runs(ab::broadphase::UniformGrid::Kernel::Avx2))
            QSKIP("this processor has no AVX2: only the portable kernels run");
        QFETCH(Integrator, integrator);
        QFETCH(ImpactMode, impacts);
        auto spec = physical({"n=3000", "g=9.82", "box=40", "rest_height=0.05"}, 1.0 / 240.0);
        spec.integrator = integrator;
        spec.impacts = impacts;
        ab::physical::ManyBallsSettings settings = ab::physical::ManyBallsSettings::fromSpec(spec, 1.0 / 240.0);
        const State start = ab::physical::jitteredGridStart(3000, 1.0, 38.0, 25.0, 4);
        auto run = [&](ab::broadphase::UniformGrid::Kernel kernel, long long& impactsSeen) {
            settings.kernel = kernel;
            ab::physical::ManyBallsEngine engine(settings);
            engine.load(start);
            impactsSeen = 0;
            for (int k = 0; k < 400; ++k) {
                engine.step();
                impactsSeen += engine.impactsLastStep();
            }
            State end = start;
            engine.store(end);
            return end;
        };
        long long portableImpacts = 0, vectorImpacts = 0;
        const State portable = run(ab::broadphase::UniformGrid::Kernel::Portable, portableImpacts);
        const State vector = run(ab::broadphase::UniformGrid::Kernel::Avx2, vectorImpacts);
        QVERIFY(identical(portable, vector));
        QCOMPARE(vectorImpacts, portableImpacts);
        QVERIFY(rebounds(portable) > 3000); // every ball met something, most several times
        QVERIFY(inside(portable, 40.0, 1.0));
    }

    void startLatticeHasNoOverlapsAndFitsTheBox()
    {
        for (const auto& [n, box] : {std::pair{150, 100.0}, {1000, 100.0}, {8000, 50.0}}) {
            auto spec = physical({"n=" + std::to_string(n), "box=" + ab::formatNumber(box)}, 1.0);
            const State s = ab::makeSimulation(spec)->initialState();
            QCOMPARE(s.size(), n);
            QVERIFY(inside(s, box, 1.0));
            QVERIFY(deepestOverlap(s, 1.0) <= 1e-12);
            QVERIFY(s.v.cwiseAbs().maxCoeff() <= 1.0);
        }
        const State bench = *ab::physical::benchmarkSpec(5000, ModelKind::Physical, Broadphase::Grid, 1).init;
        QVERIFY(inside(bench, ab::physical::benchmarkBoxSide(5000), 1.0));
        QVERIFY(deepestOverlap(bench, 1.0) <= 1e-12);
    }

    void refusesWhatItCannotDo()
    {
        for (Integrator i : {Integrator::Event, Integrator::ImplicitEuler, Integrator::ImplicitMidpoint}) {
            auto spec = physical({}, 1.0);
            spec.integrator = i;
            QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::makeSimulation(spec));
        }
        // 200000 balls of radius 1 need a lattice 118 wide; the box is 100.
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::makeSimulation(physical({"n=200000"}, 1.0)));
    }
};

QTEST_GUILESS_MAIN(PhysicalManyBalls)
#include "test_many_balls_physical.moc"
