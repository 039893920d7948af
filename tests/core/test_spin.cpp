// SPDX-License-Identifier: MIT
// Rotation in the physical model (docs/spin.md): a sliding ball that starts to roll at
// t* = q v0 / ((1 + q) mu g), the superball's bounce, angular momentum about the contact
// point across any floor impact, two rough balls, energy kept with beta = 1, and smooth
// contacts (mu = 0 or beta = -1) that leave every run as it is without rotation.
#include "core/io/trajectory_csv.h"
#include "core/physical/impacts.h"
#include "core/physical/physical_simulation.h"
#include "core/random.h"
#include "core/reference/spin_reference.h"
#include "support/physical_spec.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>

using ab::ImpactMode;
using ab::Integrator;
using ab::ModelKind;
using ab::SceneId;

using testing::physical;

namespace {

double energyOf(const ab::Simulation& sim, const ab::State& s)
{
    return dynamic_cast<const ab::physical::PhysicalSimulation&>(sim).energy(s);
}

double relative(double got, double want)
{
    return std::abs(got - want) / std::max(std::abs(want), 1e-300);
}

const char* name(Integrator i)
{
    return ab::integratorKey(i).data();
}

// The largest relative error of x, v and r w against the closed form, over a run of the
// issue's ball (mu 0.3, 5 m/s along x on the floor of box3d, r = 1).
struct SlideErrors {
    double x = 0.0, v = 0.0, rw = 0.0;
};

SlideErrors slideErrors(Integrator integrator, double dt, double tEnd, const QStringList& extra = {})
{
    QStringList set{"mu=0.3", "p0=10,0,150", "v0=5,0,0"};
    set += extra;
    const ab::RunSpec spec = physical(SceneId::Box3d, integrator, dt, set);
    const double q = spec.params.real("inertia"), g = spec.params.real("g");
    SlideErrors e;
    for (const ab::State& s : testing::record(spec, std::llround(tEnd / dt))) {
        const ab::reference::SlidingBall want = ab::reference::slidingBall(q, 0.3, g, 5.0, s.t);
        if (s.t > 0.0)
            e.x = std::max(e.x, relative(s.p(0, 0) - 10.0, want.x));
        e.v = std::max(e.v, std::abs(s.v(0, 0) - want.v) / 5.0);
        e.rw = std::max(e.rw, std::abs(-s.w(2, 0) - want.rw) / 5.0);
        if (s.p(1, 0) != 0.0 || s.v(1, 0) != 0.0 || s.p(2, 0) != 150.0 || s.w(0, 0) != 0.0 || s.w(1, 0) != 0.0)
            e.x = 1.0; // it left the floor or turned off its line: fails any tolerance
    }
    return e;
}

Eigen::Vector3d randomVector(ab::SplitMix64& rng, double size)
{
    return {size * (2.0 * rng.uniform() - 1.0), size * (2.0 * rng.uniform() - 1.0), size * (2.0 * rng.uniform() - 1.0)};
}

} // namespace

class TestSpin : public QObject {
    Q_OBJECT

private slots:
    void slidingBallRollsFromTStarAtFiveSevenths()
    {
        // The run: t* = 0.4 5 / (1.4 0.3 9.82) = 0.485 s, then 5/7 of 5 m/s.
        const double ts = ab::reference::rollStart(0.4, 0.3, 9.82, 5.0);
        QVERIFY(std::abs(ts - 0.485) < 5e-4);
        const SlideErrors e = slideErrors(Integrator::Event, 0.01, 4.0);
        qInfo("event: max relative error x %.2e, v %.2e, r w %.2e", e.x, e.v, e.rw);
        QVERIFY(e.x <= 1e-9 && e.v <= 1e-9 && e.rw <= 1e-9);
        // Verlet and rk4 are exact under the constant friction force, and located steps end
        // at t*: the same tolerance, even with a coarse step.
        for (Integrator i : {Integrator::Verlet, Integrator::Rk4}) {
            const SlideErrors s = slideErrors(i, 0.05, 4.0);
            qInfo("%s dt 0.05: x %.2e, v %.2e, r w %.2e", name(i), s.x, s.v, s.rw);
            QVERIFY2(s.x <= 1e-9 && s.v <= 1e-9 && s.rw <= 1e-9, name(i));
        }
        // Euler and symplectic Euler update v and w exactly under a constant force, and miss
        // the position by mu g h / 2 per step of the sliding phase: at most mu g dt t* / 2.
        for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler}) {
            for (double dt : {0.05, 0.005}) {
                const SlideErrors s = slideErrors(i, dt, 4.0);
                QVERIFY2(s.v <= 1e-9 && s.rw <= 1e-9, name(i));
                const double bound = 0.5 * 0.3 * 9.82 * dt * ts * (1.0 + 1e-9);
                const ab::RunSpec spec = physical(SceneId::Box3d, i, dt, {"mu=0.3", "p0=10,0,150", "v0=5,0,0"});
                const ab::State end = testing::record(spec, std::llround(4.0 / dt)).back();
                const double want = 10.0 + ab::reference::slidingBall(0.4, 0.3, 9.82, 5.0, end.t).x;
                const double err = std::abs(end.p(0, 0) - want);
                qInfo("%s dt %g: x error at 4 s %.3e (bound mu g dt t*/2 = %.3e)", name(i), dt, err, bound);
                QVERIFY2(err <= bound && err >= 0.5 * bound, name(i)); // first order, and no better
            }
        }
    }

    void backSpinRollsBackwards()
    {
        // 2 m/s forward with back-spin w_z = +10 rad/s (r = 1): slip u = 2 + 10 = 12 m/s,
        // t* = q 12 / ((1 + q) mu g), then v = (2 - q r w) / (1 + q) = -2/1.4 m/s (S4).
        const double q = 0.4, mu = 0.5, g = 9.82;
        const double ts = q * 12.0 / ((1.0 + q) * mu * g), roll = (2.0 - q * 10.0) / (1.0 + q);
        const ab::RunSpec spec =
            physical(SceneId::Box3d, Integrator::Event, 0.01, {"mu=0.5", "p0=150,0,150", "v0=2,0,0", "w0=0,0,10"});
        for (const ab::State& s : testing::record(spec, 200)) {
            const double v = s.t < ts ? 2.0 - mu * g * s.t : roll;
            const double w = s.t < ts ? 10.0 - mu * g * s.t / q : -roll; // w_z: rolling backwards is +z
            QVERIFY2(std::abs(s.v(0, 0) - v) <= 1e-9 * 12.0, qPrintable(QString::number(s.t)));
            QVERIFY2(std::abs(s.w(2, 0) - w) <= 1e-9 * 12.0, qPrintable(QString::number(s.t)));
        }
    }

    void superballBounceKeepsEnergyAndSpinsUp()
    {
        // e = 1, beta = 1, no spin, tangential u = 3 m/s: after the floor u (1 - q)/(1 + q)
        // = 9/7, r w = 2 u / (1 + q) = 30/7, energy kept exactly. The ball falls 20 m.
        const double u = 3.0, q = 0.4;
        const ab::reference::Bounce want = ab::reference::stickingBounce(q, 1.0, u);
        QVERIFY(std::abs(want.vt - 9.0 / 7.0) < 1e-15 && std::abs(want.rw - 30.0 / 7.0) < 1e-15);
        for (Integrator i : {Integrator::Event, Integrator::Verlet, Integrator::Rk4}) {
            const ab::RunSpec spec =
                physical(SceneId::Box3d, i, 0.05, {"k=1", "beta=1", "mu=10", "p0=20,20,150", "v0=3,0,0"});
            auto sim = ab::makeSimulation(spec);
            const ab::State start = sim->start();
            const double e0 = energyOf(*sim, start);
            double drift = 0.0;
            ab::State at3;
            ab::runRecorded(*sim, start, 60, 1, [&](const ab::State& s) {
                drift = std::max(drift, relative(energyOf(*sim, s), e0));
                if (std::abs(s.t - 3.0) < 1e-9)
                    at3 = s; // after the impact at 2.018 s, before the next at 6.05 s
            });
            qInfo("%s: v_x %.17g (9/7), r w %.17g (30/7), energy drift %.2e", name(i), at3.v(0, 0), -at3.w(2, 0),
                  drift);
            QVERIFY2(relative(at3.v(0, 0), want.vt) <= 1e-9, name(i));
            QVERIFY2(relative(-at3.w(2, 0), want.rw) <= 1e-9, name(i));
            QVERIFY2(drift <= 1e-12, name(i));
        }
    }

    void floorImpactKeepsAngularMomentumAboutTheContactPoint()
    {
        // Any impact on any face: L = m r n x v + I w, about the contact point, is kept,
        // whether friction sticks or slides; and energy never rises.
        ab::SplitMix64 rng(17);
        double worst = 0.0;
        for (int n = 0; n < 2000; ++n) {
            ab::physical::World w;
            w.g = 9.82;
            w.mass = {0.1 + 5.0 * rng.uniform()};
            w.spinRadius = 0.1 + 2.0 * rng.uniform();
            w.inertia = (2.0 / 3.0) * rng.uniform();
            w.beta = 2.0 * rng.uniform() - 1.0;
            const std::vector<ab::physical::Wall> walls =
                ab::physical::boxWalls(0.0, 10.0, rng.uniform(), 2.0 * rng.uniform());
            const ab::physical::Wall& wall = walls[static_cast<std::size_t>(n % 5)];
            const Eigen::Vector3d nrm = wall.normal();
            Eigen::Vector3d v = randomVector(rng, 10.0), spin = randomVector(rng, 10.0);
            if (wall.normalSpeed(v) > 0.0)
                v[wall.axis] = -v[wall.axis]; // approaching
            const double m = w.mass[0], r = w.spinRadius, inertia = w.inertia * m * r * r;
            auto momentum = [&] { return Eigen::Vector3d(m * r * nrm.cross(v) + inertia * spin); };
            auto energy = [&] { return 0.5 * m * v.squaredNorm() + 0.5 * inertia * spin.squaredNorm(); };
            const Eigen::Vector3d before = momentum();
            const double e0 = energy();
            ab::physical::resolveWallImpact(w, wall, v, spin, 0.0);
            const double err = (momentum() - before).norm() / before.norm();
            worst = std::max(worst, err);
            QVERIFY(err <= 1e-13);
            QVERIFY(energy() <= e0 * (1.0 + 1e-14));
        }
        qInfo("largest relative change of m r n x v + I w: %.2e", worst);
    }

    void twoEqualRoughBallsShareTheirSpinChange()
    {
        // Equal balls, oblique impact with mu > 0: total momentum kept, both spins change by
        // the same vector (equal and opposite impulses at one contact point, equal levers),
        // and the angular momentum about the origin, sum m p x v + I w, is kept too.
        ab::SplitMix64 rng(5);
        for (int n = 0; n < 1000; ++n) {
            ab::physical::World w;
            w.mass = {2.0, 2.0};
            w.radius = w.spinRadius = 1.0;
            w.e = rng.uniform();
            w.pairMu = 0.05 + rng.uniform();
            w.beta = 2.0 * rng.uniform() - 1.0;
            w.inertia = 0.4;
            const Eigen::Vector3d dir = randomVector(rng, 1.0).normalized();
            const Eigen::Vector3d p1(5, 5, 5), p2 = p1 - 2.0 * dir;
            Eigen::Vector3d v1 = randomVector(rng, 9.0), v2 = randomVector(rng, 9.0);
            Eigen::Vector3d w1 = randomVector(rng, 5.0), w2 = randomVector(rng, 5.0);
            const Eigen::Vector3d w1a = w1, w2a = w2;
            const double inertia = 0.4 * 2.0;
            auto linear = [&] { return Eigen::Vector3d(2.0 * (v1 + v2)); };
            auto angular = [&] { return Eigen::Vector3d(2.0 * (p1.cross(v1) + p2.cross(v2)) + inertia * (w1 + w2)); };
            const Eigen::Vector3d l0 = linear(), a0 = angular();
            if (ab::physical::resolvePairImpact(w, 0, 1, p1, p2, v1, v2, {w1, w2}) == 0.0)
                continue; // not approaching: nothing happened
            QVERIFY((linear() - l0).norm() <= 1e-13 * (1.0 + l0.norm()));
            QVERIFY((angular() - a0).norm() <= 1e-12 * (1.0 + a0.norm()));
            QVERIFY(((w1 - w1a) - (w2 - w2a)).norm() <= 1e-14 * (1.0 + (w1 - w1a).norm()));
        }
        // Through a run: ball 2 offset by 1 m in x meets ball 1 head-on along z, no gravity.
        const ab::RunSpec spec =
            physical(SceneId::TwoBalls, Integrator::Event, 0.1,
                     {"g=0", "mu=0.5", "p1=150,20,100", "v1=0,0,10", "p2=151,20,200", "v2=0,0,-10"});
        const std::vector<ab::State> states = testing::record(spec, 100);
        const ab::State& a = states.front();
        const ab::State& b = states[60]; // after the meeting at about 4.9 s, before any wall
        QVERIFY((b.v.col(0) + b.v.col(1) - a.v.col(0) - a.v.col(1)).norm() <= 1e-12);
        QVERIFY(b.w.col(0).norm() > 0.1);
        QVERIFY((b.w.col(0) - b.w.col(1)).norm() <= 1e-12 * b.w.col(0).norm());
    }

    void smoothContactsEqualTheRunWithoutRotation()
    {
        // mu = 0 is the model without rotation; beta = -1 (or mu = 0 with any beta), with
        // any start spin, must give its positions and velocities bit for bit, and keep the
        // start spin exactly (free rotation). Checked on runs with floor, wall and pair
        // impacts for every integrator and both impact modes.
        struct Case {
            SceneId scene;
            QStringList base, smooth;
        };
        const std::vector<Case> cases = {
            {SceneId::Box3d, {"k=0.8"}, {"mu=0.7", "beta=-1", "w0=1,-2,3"}},
            {SceneId::Box3d, {"k=0.8"}, {"beta=1", "w0=0,0,-4"}},
            {SceneId::TwoBalls, {"e=0.8", "p2=4,21,298"}, {"mu=0.4", "beta=-1", "w1=2,0,0", "w2=0,5,1"}},
            {SceneId::Bounce1d, {}, {"w0=3", "inertia=0.6"}},
        };
        for (const Case& c : cases) {
            for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4,
                                 Integrator::Event}) {
                for (ImpactMode mode : {ImpactMode::Located, ImpactMode::StepEnd}) {
                    if (i == Integrator::Event && mode == ImpactMode::StepEnd)
                        continue;
                    const double dt = c.scene == SceneId::Bounce1d ? 1.0 : 0.02;
                    const ab::RunSpec plain = physical(c.scene, i, dt, c.base, mode);
                    const ab::RunSpec smooth = physical(c.scene, i, dt, c.base + c.smooth, mode);
                    const std::vector<ab::State> a = testing::record(plain, 1500), b = testing::record(smooth, 1500);
                    QCOMPARE(a.size(), b.size());
                    const ab::State start = ab::makeSimulation(smooth)->start();
                    for (std::size_t n = 0; n < a.size(); ++n) {
                        QVERIFY2(a[n].p == b[n].p && a[n].v == b[n].v && a[n].t == b[n].t, name(i));
                        QVERIFY2(b[n].w == start.w, name(i));
                    }
                    // ... and the lone ball's run is the closed form's: with no friction its speed
                    // along x stays exactly what it was until it reaches the wall x = 300 (at
                    // 29.8 s; in bounce1d it is 0).
                    if (c.scene == SceneId::TwoBalls)
                        continue;
                    for (const ab::State& s : a)
                        if (s.t < 29.0)
                            QVERIFY2(s.v(0, 0) == a.front().v(0, 0), name(i));
                }
            }
        }
    }

    void frictionNeverCreatesEnergy()
    {
        // Rough contacts with |beta| <= 1 and k, e <= 1 lose energy or keep it (beta = 1,
        // k = e = 1 with friction that sticks): never gain it. Two rough balls in the box.
        for (Integrator i : {Integrator::Verlet, Integrator::Rk4, Integrator::Event}) {
            for (const QStringList& set : {QStringList{"mu=0.3", "beta=0.5", "p2=4,22,298", "w1=5,0,0"},
                                           QStringList{"mu=0.8", "beta=1", "k=1", "e=1", "p2=3,21,298", "w2=0,0,3"}}) {
                const ab::RunSpec spec = physical(SceneId::TwoBalls, i, 0.02, set);
                auto sim = ab::makeSimulation(spec);
                const ab::State start = sim->start();
                const double e0 = energyOf(*sim, start);
                ab::runRecorded(*sim, start, 2000, 1, [&](const ab::State& s) {
                    QVERIFY2(energyOf(*sim, s) <= e0 * (1.0 + 1e-12), name(i));
                });
            }
        }
    }

    void trajectoryCsvCarriesSpinAndInitReadsIt()
    {
        const ab::RunSpec spec = physical(SceneId::Box3d, Integrator::Event, 0.1, {"mu=0.3", "w0=0.5,-1,2"});
        auto sim = ab::makeSimulation(spec);
        const ab::State start = sim->start();
        QVERIFY(ab::physical::hasRotation(*sim, start));
        const auto plain = ab::makeSimulation(physical(SceneId::Box3d, Integrator::Event, 0.1));
        QVERIFY(!ab::physical::hasRotation(*plain, plain->start()));
        QTemporaryDir dir;
        const std::string path = dir.filePath("spin.csv").toStdString();
        {
            std::ofstream out(path);
            ab::writeTrajectoryHeader(out, true);
            ab::writeTrajectoryRows(out, start, true);
        }
        std::ifstream in(path);
        std::string header;
        std::getline(in, header);
        QCOMPARE(header, std::string("t,ball,x,y,z,vx,vy,vz,wx,wy,wz"));
        const ab::State back = ab::readFirstState(path);
        QVERIFY(back.spins());
        QCOMPARE(back.w, start.w);
        QCOMPARE(back.v, start.v);
        // A file without the columns reads as no spin.
        {
            std::ofstream out(path);
            ab::writeTrajectoryHeader(out);
            ab::writeTrajectoryRows(out, start);
        }
        QVERIFY(!ab::readFirstState(path).spins());
    }
};

QTEST_GUILESS_MAIN(TestSpin)
#include "test_spin.moc"
