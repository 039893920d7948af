// SPDX-License-Identifier: MIT
// Stage 4, physical model with rough balls (docs/spin.md): a ball sliding on the floor
// spins up and rolls at v0/(1 + q) from t* = q v0/((1 + q) mu g) (S2-S4, first order in
// the step); the superball's floor impact (Garwin: 3/7 u and r w = 2u/(1 + q), energy and
// the angular momentum about the contact point kept); two equal balls' oblique contact
// keeps the momentum and changes both spins alike, sticking to -beta times the slip or
// sliding at Coulomb's bound; mu = 0 or beta = -1 equals the smooth run bit for bit; and
// spin-on runs are bit-identical for any thread count and kernel.
#include "support/many_balls_helpers.h"

#include "core/physical/many_balls_physical.h"
#include "core/physical/physical_simulation.h"

#include <Eigen/Geometry> // cross products
#include <QtTest>

#include <cmath>

using ab::ImpactMode;
using ab::Integrator;
using ab::ModelKind;
using ab::SceneId;
using ab::State;
using Eigen::Vector3d;

Q_DECLARE_METATYPE(ab::Integrator)

namespace {

constexpr auto physical = &testing::manyBallsPhysical; // the physical model with --set assignments and dt
constexpr auto balls = &testing::ballsAt;              // a start from (position, velocity) pairs

bool identical(const State& a, const State& b)
{
    return a.p == b.p && a.v == b.v && a.w == b.w && a.bounces == b.bounces;
}

// The slip between two balls at their contact point, along the contact plane, n from a
// to b: g = v_b - v_a - r (w_a + w_b) x n, less its part along n (S11).
Vector3d pairSlip(const State& s, double r)
{
    const Vector3d n = (s.p.col(1) - s.p.col(0)).normalized();
    Vector3d g = s.v.col(1) - s.v.col(0) - r * (s.spin(0) + s.spin(1)).cross(n);
    return g - g.dot(n) * n;
}

} // namespace

class ManyBallsSpin : public QObject {
    Q_OBJECT

private slots:
    void slidingBallRollsAtOneOverOnePlusQ_data()
    {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<double>("q");
        QTest::addColumn<double>("dt");
        QTest::newRow("solid, symplectic-euler, dt 0.01") << Integrator::SymplecticEuler << 0.4 << 0.01;
        QTest::newRow("solid, symplectic-euler, dt 0.001") << Integrator::SymplecticEuler << 0.4 << 0.001;
        QTest::newRow("solid, verlet, dt 0.01") << Integrator::Verlet << 0.4 << 0.01;
        QTest::newRow("hollow, euler, dt 0.01") << Integrator::Euler << 2.0 / 3.0 << 0.01;
    }
    void slidingBallRollsAtOneOverOnePlusQ()
    {
        // A ball set down on the floor at v0 = 5 along x without spin, mu = 0.3, g = 9.82:
        // speed v0 - mu g t until t* = q v0/((1 + q) mu g) (0.485 for q = 2/5), then
        // rolling at v0/(1 + q) (5/7 v0) with r w_z = -v. Friction acts as an impulse at the
        // start of each step, so the speed is exact at the steps, the change to rolling comes
        // in the step that holds t*, and the position lags by mu g dt t/2 (first order).
        QFETCH(Integrator, integrator);
        QFETCH(double, q);
        QFETCH(double, dt);
        const double v0 = 5.0, mu = 0.3, g = 9.82, r = 1.0, x0 = -40.0;
        auto spec = physical({"n=1", "g=9.82", "mu=0.3"}, dt); // rests on the floor: rebounds of g dt stop
        spec.params.parseAssignment("inertia=" + QString::number(q, 'g', 17).toStdString());
        spec.integrator = integrator;
        spec.init = balls({{Vector3d(x0, -49.0, 0), Vector3d(v0, 0, 0)}});
        const double tStar = q * v0 / ((1.0 + q) * mu * g), roll = v0 / (1.0 + q);
        const auto s = testing::record(spec, static_cast<long long>(std::lround(1.0 / dt)));
        double rolledAt = -1.0;
        for (const State& st : s) {
            QCOMPARE(st.p(1, 0), -49.0); // on the floor throughout
            QCOMPARE(st.v(1, 0), 0.0);
            const double vx = st.v(0, 0), slip = vx + r * st.spin(0).z();
            if (rolledAt < 0.0 && st.t > 0.0 && slip == 0.0)
                rolledAt = st.t;
            if (st.t <= tStar - dt) { // sliding: v0 - mu g t, x0 + v0 t - mu g t^2/2 - mu g dt t/2
                QVERIFY(std::abs(vx - (v0 - mu * g * st.t)) <= 1e-12 * v0);
                const double x = x0 + v0 * st.t - 0.5 * mu * g * st.t * st.t;
                QVERIFY(std::abs(st.p(0, 0) - x - (-0.5 * mu * g * dt * st.t)) <= 1e-9 * std::abs(x0));
            }
        }
        QVERIFY2(rolledAt >= tStar && rolledAt < tStar + dt + 1e-12, qPrintable(QString::number(rolledAt)));
        const State& end = s.back();
        QVERIFY(std::abs(end.v(0, 0) - roll) <= 1e-9 * roll);              // v0/(1 + q)
        QVERIFY(std::abs(r * end.spin(0).z() + roll) <= 1e-9 * roll);      // r w = v, rolling sense
        QVERIFY(std::abs(end.v(2, 0)) + std::abs(end.spin(0).x()) == 0.0); // nothing across
        // Rolling from t*: x(t*) + v (t - t*), within the first-order lag and one step's slide.
        const double x = x0 + v0 * tStar - 0.5 * mu * g * tStar * tStar + roll * (end.t - tStar);
        QVERIFY(std::abs(end.p(0, 0) - x) <= (0.5 * mu * g * tStar + v0) * dt);
    }

    void superballBounceOffTheFloorKeepsEnergyAndAngularMomentum_data()
    {
        QTest::addColumn<Integrator>("integrator");
        QTest::newRow("verlet") << Integrator::Verlet;
        QTest::newRow("symplectic-euler") << Integrator::SymplecticEuler;
    }
    void superballBounceOffTheFloorKeepsEnergyAndAngularMomentum()
    {
        // k = 1, beta = 1, friction that sticks (mu = 10): meeting the floor with tangential
        // speed u = 2 and no spin, the ball leaves with u (1 - q)/(1 + q) = 6/7 and
        // r w_z = -2u/(1 + q) = -20/7 (Garwin 1969); the kinetic energy of translation and
        // rotation is kept exactly, and so is r n x v + q r^2 w about the contact point (S13).
        QFETCH(Integrator, integrator);
        const double q = 0.4, r = 1.0, u = 2.0;
        auto spec = physical({"n=1", "g=0", "mu=10", "beta=1", "primary_loss=1", "rest_height=0"}, 0.1);
        spec.integrator = integrator;
        spec.init = balls({{Vector3d(0, -49.0 + 0.15, 0), Vector3d(u, -3.0, 0)}});
        const auto s = testing::record(spec, 1);
        const State& after = s[1];
        QVERIFY(std::abs(after.v(0, 0) - u * (1.0 - q) / (1.0 + q)) <= 1e-12);
        QVERIFY(std::abs(after.v(1, 0) - 3.0) <= 1e-12);
        QVERIFY(std::abs(r * after.spin(0).z() + 2.0 * u / (1.0 + q)) <= 1e-12);
        const auto energy = [&](const State& st) {
            return 0.5 * st.v.col(0).squaredNorm() + 0.5 * q * r * r * st.spin(0).squaredNorm();
        };
        QVERIFY(std::abs(energy(after) - energy(s[0])) <= 1e-12 * energy(s[0]));
        const Vector3d n = Vector3d::UnitY();
        const auto angular = [&](const State& st) {
            return Vector3d(r * n.cross(st.v.col(0)) + q * r * r * st.spin(0));
        };
        QVERIFY((angular(after) - angular(s[0])).norm() <= 1e-12 * u);
        QCOMPARE(after.bounces[0], 1);
    }

    void obliqueContactKeepsMomentumAndTurnsBothBallsAlike_data()
    {
        QTest::addColumn<double>("mu");
        QTest::newRow("sticking, mu 10") << 10.0;
        QTest::newRow("sliding, mu 0.1") << 0.1;
    }
    void obliqueContactKeepsMomentumAndTurnsBothBallsAlike()
    {
        // Two equal balls meet obliquely without gravity (e = 0.8, beta = 0.5): the momentum
        // is kept, the spins change by the same vector (equal and opposite impulses at one
        // point, S12). Sticking (mu 10) turns the slip into -beta times itself (S9); sliding
        // (mu 0.1) moves each ball along the contact plane by mu times its normal change (S10).
        QFETCH(double, mu);
        const double beta = 0.5, r = 1.0;
        auto spec = physical({"n=2", "g=0", "secondary_loss=0.8", "beta=0.5", "mu=" + std::to_string(mu)}, 0.01);
        const Vector3d pa(-1.0, 0.3, 0.1), pb(0.9, -0.2, 0.3), va(1.0, 0.4, -0.2), vb(-0.5, 0.3, 0.6);
        State start = balls({{pa, va}, {pb, vb}});
        start.w.setZero(3, 2);
        start.w.col(0) = Vector3d(0.3, -0.2, 0.5);
        start.w.col(1) = Vector3d(-0.1, 0.4, 0.2);
        spec.init = start;
        const auto s = testing::record(spec, 1);
        const State& after = s[1];
        QVERIFY((after.v.col(0) + after.v.col(1) - va - vb).norm() < 1e-14); // momentum
        const Vector3d dwa = after.spin(0) - start.spin(0), dwb = after.spin(1) - start.spin(1);
        QVERIFY(dwa.norm() > 1e-3);
        QVERIFY((dwa - dwb).norm() < 1e-14 * dwa.norm() + 1e-16);
        // The slip before, at the impact's normal (the flight moves the centres straight,
        // and the projection moves them along n).
        State before = start;
        before.p.col(0) = pa + va * 0.01;
        before.p.col(1) = pb + vb * 0.01;
        const Vector3d n = (after.p.col(1) - after.p.col(0)).normalized();
        QVERIFY((n - (before.p.col(1) - before.p.col(0)).normalized()).norm() < 1e-14);
        const Vector3d slip0 = pairSlip(before, r), slip1 = pairSlip(after, r);
        const Vector3d dva = after.v.col(0) - va;
        const double normal = std::abs(dva.dot(n));
        const Vector3d tangential = dva - dva.dot(n) * n;
        if (mu > 1.0) {
            QVERIFY((slip1 + beta * slip0).norm() < 1e-13 * slip0.norm());
        } else {
            QVERIFY(std::abs(tangential.norm() - mu * normal) < 1e-13 * normal);
            QVERIFY(tangential.dot(slip0) > 0.0); // a pulled along the slip of b against a
        }
    }

    void smoothContactsEqualTheRunWithoutSpin_data()
    {
        QTest::addColumn<QString>("setting");
        QTest::newRow("mu 0, beta 0.5") << "mu=0,beta=0.5";
        QTest::newRow("mu 0.5, beta -1") << "mu=0.5,beta=-1";
        QTest::newRow("mu 0, start spins 0.3") << "mu=0,spin=0.3";
    }
    void smoothContactsEqualTheRunWithoutSpin()
    {
        // With mu = 0 or beta = -1 no tangential impulse acts: positions, velocities and
        // rebounds are those of the smooth engine bit for bit (2000 balls falling into a pile),
        // and start spins stay as they were drawn.
        QFETCH(QString, setting);
        auto base = physical({"n=2000", "g=9.82", "box=40", "seed=3"}, 1.0 / 240.0);
        auto rough = base;
        for (const QString& a : setting.split(','))
            rough.params.parseAssignment(a.toStdString());
        const State plain = testing::record(base, 200).back();
        const auto run = testing::record(rough, 200);
        const State& turned = run.back();
        QVERIFY(plain.p == turned.p && plain.v == turned.v && plain.bounces == turned.bounces);
        QVERIFY(plain.w.cols() == 0);
        if (setting.contains("spin")) {
            QCOMPARE(turned.w.cols(), 2000);
            QVERIFY(turned.w == run.front().w);
            QVERIFY(turned.w.cwiseAbs().maxCoeff() <= 0.3 && turned.w.cwiseAbs().maxCoeff() > 0.29);
        }
    }

    void trajectoryCarriesSpinsWhenTheBallsTurn()
    {
        // The CSV's wx,wy,wz (physical::hasRotation): rough balls, even from an --init
        // start without spins, or start spins; never smooth balls without them.
        const auto turns = [](std::initializer_list<std::string> set, bool init) {
            auto spec = physical(set, 1.0);
            if (init)
                spec.init = balls({{Vector3d(0, -49, 0), Vector3d(1, 0, 0)}});
            const auto sim = ab::makeSimulation(spec);
            return ab::physical::hasRotation(*sim, sim->start());
        };
        QVERIFY(turns({"n=1", "mu=0.5"}, true));
        QVERIFY(turns({"n=1", "mu=0.5"}, false));
        QVERIFY(turns({"n=1", "spin=0.3"}, false));
        QVERIFY(!turns({"n=1"}, true));
        QVERIFY(!turns({"n=1", "mu=0.5", "beta=-1"}, false));
    }

    void roughRunsAreBitIdenticalForAnyThreadCount()
    {
        // 20000 rough balls (mu 0.5, beta 0.3, start spins up to 0.2) touching on their
        // lattice, falling under gravity: 1, 2 and 4 threads agree in every bit of p, v, w.
        auto run = [](int threads) {
            auto spec =
                physical({"n=20000", "g=9.82", "box=56", "seed=12", "mu=0.5", "beta=0.3", "spin=0.2"}, 1.0 / 240.0);
            spec.threads = threads;
            return testing::record(spec, 60).back();
        };
        const State one = run(1), two = run(2), four = run(4);
        QCOMPARE(one.w.cols(), 20000);
        QVERIFY(identical(one, two));
        QVERIFY(identical(one, four));
    }

    void roughAvx2FlightGivesThePortableNumbers()
    {
        // The vector flight leaves spins alone and sends every ball near a wall through the
        // scalar flight with its friction: the same bits as the portable engine.
        if (!ab::broadphase::UniformGrid::runs(ab::broadphase::UniformGrid::Kernel::Avx2))
            QSKIP("this processor has no AVX2: only the portable kernels run");
        auto spec = physical({"n=3000", "g=9.82", "box=40", "rest_height=0.05", "mu=0.4", "beta=0.2"}, 1.0 / 240.0);
        ab::physical::ManyBallsSettings settings = ab::physical::ManyBallsSettings::fromSpec(spec, 1.0 / 240.0);
        State start = ab::physical::jitteredGridStart(3000, 1.0, 38.0, 25.0, 4);
        ab::physical::randomSpins(start, 1.0, 4);
        auto run = [&](ab::broadphase::UniformGrid::Kernel kernel) {
            settings.kernel = kernel;
            ab::physical::ManyBallsEngine engine(settings);
            engine.load(start);
            for (int k = 0; k < 300; ++k)
                engine.step();
            State end = start;
            engine.store(end);
            return end;
        };
        const State portable = run(ab::broadphase::UniformGrid::Kernel::Portable);
        QVERIFY(identical(portable, run(ab::broadphase::UniformGrid::Kernel::Avx2)));
        QVERIFY(!(portable.w - start.w).isZero(0.0));
    }
};

QTEST_GUILESS_MAIN(ManyBallsSpin)
#include "test_many_balls_spin.moc"
