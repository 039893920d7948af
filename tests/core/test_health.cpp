// SPDX-License-Identifier: MIT
// The health check on hand-worked steps: the report's stage-1 energy gain of g^2 dt^2 / 2
// per flight step, a late impact against an escape, the stage-3 swap losing 1 - e of the
// momentum and repeating, balls passing through or grazing each other (and a street ball a
// contact pass moved, which did not fly free), the spring's compression,
// the stage-4 failures of the report's own rules, and the angular momentum of a rough ball
// about its contact point at the floor.
#include "core/diagnostics/health.h"
#include "core/street/street_layout.h"
#include "support/sim_helpers.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace ab;
using diagnostics::Health;
using diagnostics::HealthCheck;

namespace {

// Runs `steps` steps, checking every pair of consecutive final states.
struct Checked {
    std::unique_ptr<Simulation> sim;
    std::unique_ptr<HealthCheck> health;
};

Checked runChecked(const RunSpec& spec, long long steps)
{
    Checked c{makeSimulation(spec), nullptr};
    State s = c.sim->start();
    c.health = std::make_unique<HealthCheck>(*c.sim, s);
    State next, previous;
    bool first = true;
    for (long long i = 0; i <= steps; ++i) {
        if (i < steps)
            c.sim->step(s, next);
        if (!first)
            c.health->check(previous, s);
        previous = s;
        first = false;
        std::swap(s, next);
    }
    return c;
}

bool mentions(const HealthCheck& h, const std::string& text)
{
    for (const diagnostics::HealthStatus& s : h.issues())
        if (s.line().find(text) != std::string::npos)
            return true;
    return false;
}

State oneBall(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double t = 0.0)
{
    State s;
    s.resize(1);
    s.p.col(0) = p;
    s.v.col(0) = v;
    s.t = t;
    return s;
}

State balls(const std::vector<Eigen::Vector3d>& p)
{
    State s;
    s.resize(static_cast<int>(p.size()));
    for (std::size_t i = 0; i < p.size(); ++i)
        s.p.col(static_cast<int>(i)) = p[i];
    return s;
}

} // namespace

class HealthChecks : public QObject {
    Q_OBJECT

private slots:
    void reportStage1GainsHalfGSquaredDtSquaredPerFlightStep()
    {
        // E' - E = (v - g)^2 / 2 - v^2 / 2 + g v = g^2 / 2 when the position moves with the
        // old velocity (eq 2.16): after 10 steps the gain is 5 g^2 against E0 = g h0.
        const Checked c = runChecked(testing::spec(SceneId::Bounce1d), 10);
        const double g = 0.0982;
        QVERIFY(std::abs(c.health->figures().maxEnergyGain - 5.0 * g / 2000.0) <= 1e-12);
        QCOMPARE(c.health->worst().level, Health::Warning);
        QVERIFY(mentions(*c.health, "eq 2.16"));
    }

    void nonFiniteStateFailsAndStopsTheCount()
    {
        auto sim = makeSimulation(testing::spec(SceneId::Box3d));
        const State start = sim->start();
        HealthCheck h(*sim, start);
        State bad = start;
        bad.p(0, 0) = std::numeric_limits<double>::quiet_NaN();
        QCOMPARE(h.check(start, bad), Health::Failed);
        QVERIFY(h.figures().nonfinite);
        QVERIFY(h.worst().what.find("non-finite") != std::string::npos);
        // A speed whose energy overflows is as unusable as a NaN.
        HealthCheck h2(*sim, start);
        QCOMPARE(h2.check(start, oneBall({2, 20, 2}, {0, -2e154, 0})), Health::Failed);
        QVERIFY(h2.figures().nonfinite);
    }

    void lateImpactIsAWarningAndACrossingBeyondOneStepAnEscape()
    {
        // box3d, dt 0.01: at 2000 m/s a step travels 20 m (+ g dt^2).
        auto sim = makeSimulation(testing::spec(SceneId::Box3d));
        const State before = oneBall({290, 20, 150}, {2000, 0, 0});
        HealthCheck h(*sim, before);
        QCOMPARE(h.check(before, oneBall({305, 20, 150}, {2000, 0, 0}, 0.01)), Health::Warning);
        QCOMPARE(h.figures().maxPenetration, 5.0);
        QCOMPARE(h.figures().escaped, 0);
        QCOMPARE(h.check(before, oneBall({330, 20, 150}, {2000, 0, 0}, 0.01)), Health::Failed);
        QCOMPARE(h.figures().escaped, 1);
        QVERIFY(h.worst().what.find("x = 300 wall") != std::string::npos);
    }

    void reportBallOnTheFloorNeverMeetsAWall()
    {
        // A ball sliding on the floor takes the floor branch every step (Appendix B checks
        // the floor first), so it rolls through the wall at x = 300.
        const Checked c = runChecked(
            testing::spec(SceneId::Box3d, {"p0=290,0,150", "v0=50,0,0", "k=0.5", "max_bounces=1000000"}), 100);
        QCOMPARE(c.health->figures().escaped, 1);
        QCOMPARE(c.health->worst().level, Health::Failed);
        QVERIFY(mentions(*c.health, "the floor first (Appendix B)"));
    }

    void reportSwapLosesOneMinusEOfTheMomentumAndRepeats()
    {
        // Without gravity: z1 = 100 + 0.3, z2 = 102.01 - 0.1, 1.61 apart: swap to -9.5 and
        // 28.5 (e = 0.95), so the momentum 20 becomes 19: |dp| / (|v1| + |v2|) = 1 / 40.
        // Next step they are 1.99 apart, still overlapping: the swap repeats.
        const Checked c = runChecked(
            testing::spec(SceneId::TwoBalls, {"g=0", "p1=150,20,100", "p2=150,20,102.01", "v1=0,0,30", "v2=0,0,-10"}),
            2);
        const auto& f = c.health->figures();
        QVERIFY(f.maxMomentumError && std::abs(*f.maxMomentumError - 1.0 / 40.0) <= 1e-12);
        QVERIFY(f.maxOverlap && std::abs(*f.maxOverlap - 0.39) <= 1e-9);
        QVERIFY(mentions(*c.health, "swap repeats"));
        QVERIFY(mentions(*c.health, "scales both swapped velocities by e"));
    }

    void ballsPassingThroughEachOtherFail()
    {
        // 100 m per step each way: the centres swap sides without ever being closer than
        // 2 r at a step's end.
        const Checked c = runChecked(testing::spec(SceneId::TwoBalls, {"g=0", "p1=150,20,100", "p2=150,20,200",
                                                                       "v1=0,0,10000", "v2=0,0,-10000"}),
                                     1);
        QCOMPARE(c.health->worst().level, Health::Failed);
        QVERIFY(mentions(*c.health, "passed through each other"));
    }

    void aHeavyBallStrikingALightOneGainsNoEnergy()
    {
        // m1 = 100 at 5 m/s onto m2 = 1 at rest, elastic, head on: eqs 2.4-2.7 give
        // v1' = (m1 - m2) / (m1 + m2) v = 4.90 and v2' = 2 m1 / (m1 + m2) v = 9.90 m/s.
        // The kinetic energy m v^2 / 2 is kept (1250 J), but the energy per unit mass of
        // the two balls, v^2 / 2 summed, grows from 12.5 to 61.0: the check must weigh
        // each ball by its mass, or it reports a gain the physics does not make.
        RunSpec spec =
            testing::spec(SceneId::TwoBalls,
                          {"g=0", "m1=100", "m2=1", "e=1", "p1=150,20,100", "p2=150,20,110", "v1=0,0,5", "v2=0,0,0"},
                          ModelKind::Physical);
        const Checked c = runChecked(spec, 400);
        QCOMPARE(c.health->worst().level, Health::Ok);
        QVERIFY(!mentions(*c.health, "energy"));
        // The collision did happen: ball 2 moves off at 2 m1 v / (m1 + m2).
        State s = c.sim->start(), next;
        for (int k = 0; k < 400; ++k) {
            c.sim->step(s, next);
            std::swap(s, next);
        }
        QVERIFY(std::abs(s.v(2, 1) - 2.0 * 100.0 * 5.0 / 101.0) < 1e-6);
    }

    void ballsGrazingWithinAStepWarnWithoutFailing()
    {
        // As above, but 1.99 apart sideways (along y, so that the report's distance, which
        // counts dy twice, also stays above 2 r at both step ends): the straight path
        // comes within 1.99 of contact at 2, 0.01 r inside it, less than the tenth of a
        // radius that counts as passing through.
        const Checked c = runChecked(testing::spec(SceneId::TwoBalls, {"g=0", "p1=150,20,100", "p2=150,21.99,200",
                                                                       "v1=0,0,10000", "v2=0,0,-10000"}),
                                     1);
        QCOMPARE(c.health->worst().level, Health::Warning);
        QVERIFY(mentions(*c.health, "grazed within one step"));
        QVERIFY(!mentions(*c.health, "passed through each other"));
    }

    void twoProjectilesGrazingOnTheStreetWarnButABallAContactPassMovedDoesNot()
    {
        // Two balls 2 m above the road fly across it towards each other at 2.4 m/s, 2 r - 0.01 r
        // apart along the street, from 4 cm apart across it to 4 cm past: the straight path
        // between their step ends comes 0.01 r inside contact. Both follow the exact projectile
        // x1 = x0 + v0 dt - g dt^2 / 2 e_y, v1 = v0 - g dt e_y, so the step missed a graze.
        // (The check's grid holds the step ends in cells 2 r wide: each ball moves 4 cm, so the
        // two end in neighbouring cells.)
        RunSpec spec = testing::spec(SceneId::Street, {"n=2"}, ModelKind::Physical);
        const double dt = 1.0 / 60.0; // the scene's step
        spec.dt = dt;
        const street::Layout layout = street::Layout::fromParams(spec.params);
        const double r = 0.03, g = spec.params.real("g");
        const double x = 20.0, y = layout.roadY(x) + 2.0;
        State before;
        before.resize(2);
        before.w.setZero(3, 2);
        before.p.col(0) = Eigen::Vector3d(x, y, -0.02);
        before.p.col(1) = Eigen::Vector3d(x + 1.99 * r, y, 0.02);
        before.v.col(0) = Eigen::Vector3d(0.0, 0.0, 2.4);
        before.v.col(1) = Eigen::Vector3d(0.0, 0.0, -2.4);
        State after = before;
        after.t = dt;
        for (int i = 0; i < 2; ++i) {
            after.v.col(i) = before.v.col(i) - Eigen::Vector3d(0.0, g * dt, 0.0);
            after.p.col(i) = before.p.col(i) + before.v.col(i) * dt - Eigen::Vector3d(0.0, 0.5 * g * dt * dt, 0.0);
        }
        auto sim = makeSimulation(spec);
        HealthCheck grazed(*sim, before);
        grazed.check(before, after);
        QCOMPARE(grazed.worst().level, Health::Warning);
        QVERIFY2(mentions(grazed, "grazed within one step"), grazed.worst().line().c_str());

        // The same step, but a contact pass parted ball 0 from a third ball by 1 mm downwards,
        // its velocity untouched (street_pairs.cpp point 4): it touched a ball, its path was not
        // the straight one, and nothing about a graze follows from its step ends.
        after.p(1, 0) -= 1e-3;
        HealthCheck parted(*sim, before);
        parted.check(before, after);
        QVERIFY2(!mentions(parted, "grazed"), parted.worst().line().c_str());
        QCOMPARE(parted.worst().level, Health::Ok);
    }

    void theStreetsGridFindsTwoBallsOverlappingAcrossEveryCellBoundary()
    {
        // The street's check holds the balls in cells 2 r wide. Two balls 1.7 r apart (an
        // overlap of 0.3 r) along each of the 26 directions to a neighbouring cell, ball A near
        // the cell's face, corner or edge in that direction, so that B lies in the neighbour;
        // A numbered first and then second. The check must find the overlap every time.
        RunSpec spec = testing::spec(SceneId::Street, {"n=2"}, ModelKind::Physical);
        const street::Layout layout = street::Layout::fromParams(spec.params);
        const double r = 0.03, cell = 2.0 * r, overlap = 0.3 * r;
        const Eigen::Vector3d base(std::floor(20.0 / cell), std::floor((layout.roadY(20.0) + 0.5) / cell), 0.0);
        auto sim = makeSimulation(spec);
        int checked = 0;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const Eigen::Vector3d d(dx, dy, dz);
                    if (d.squaredNorm() == 0.0)
                        continue;
                    const Eigen::Vector3d a = (base + Eigen::Vector3d::Constant(0.5) + 0.45 * d) * cell;
                    const Eigen::Vector3d b = a + (2.0 * r - overlap) * d.normalized();
                    for (int k = 0; k < 3; ++k) // B in the neighbouring cell along d
                        QCOMPARE(std::floor(b[k] / cell) - std::floor(a[k] / cell), d[k]);
                    for (bool aFirst : {true, false}) {
                        State s = aFirst ? balls({a, b}) : balls({b, a});
                        s.w.setZero(3, 2);
                        HealthCheck h(*sim, s);
                        h.check(s, s);
                        const std::optional<double> found = h.figures().maxOverlap;
                        QVERIFY2(found && std::abs(*found - overlap) <= 1e-9 * r,
                                 qPrintable(QStringLiteral("direction (%1, %2, %3), A %4: overlap %5")
                                                .arg(dx)
                                                .arg(dy)
                                                .arg(dz)
                                                .arg(aFirst ? "first" : "second")
                                                .arg(found.value_or(-1.0))));
                        QVERIFY(mentions(h, "balls 0 and 1 overlap"));
                        ++checked;
                    }
                }
        QCOMPARE(checked, 52);
    }

    void springCompressionIsTheClosedForm()
    {
        // Undamped (k = 1), no gravity, entering at speed 1: deepest point u / omega0 = 0.1
        // for k_s = 100; the energy stays that of the start.
        RunSpec s = testing::spec(SceneId::Bounce1d, {"contact=1", "stiffness=100", "k=1", "g=0", "h0=0.5", "v0=-1"},
                                  ModelKind::Physical);
        s.integrator = Integrator::Verlet;
        s.dt = 1e-4;
        const Checked c = runChecked(s, 10'000);
        QVERIFY(std::abs(c.health->figures().maxPenetration - 0.1) <= 1e-6);
        QCOMPARE(c.health->worst().level, Health::Ok);
        QVERIFY(c.health->figures().maxEnergyGain <= 1e-9);
    }

    void explicitEulerOnTheSpringFailsWithAdvice()
    {
        RunSpec s = testing::spec(SceneId::Bounce1d, {"contact=1", "h0=10"}, ModelKind::Physical);
        s.integrator = Integrator::Euler;
        const Checked c = runChecked(s, 2000);
        QCOMPARE(c.health->worst().level, Health::Failed);
        QVERIFY(c.health->worst().advice.find("explicit Euler gains energy") != std::string::npos);
    }

    void aSpringStepBeyondItsLimitIsStoppedAtTheBackstopNotThroughTheFloor()
    {
        // Linear spring k_s = 1e3 (omega0 = 31.6), undamped, no gravity, in at speed 1:
        // the exact motion reaches d = u / omega0 = 0.0316 at most. Verlet at dt omega0 =
        // 2.5 (limit 2) stepped blindly across the contact grows without bound; the
        // backstop holds it at 1.5 d, and the run fails on the energy it gained instead.
        RunSpec s = testing::spec(SceneId::Bounce1d, {"contact=1", "stiffness=1000", "k=1", "g=0", "h0=0.5", "v0=-1"},
                                  ModelKind::Physical);
        s.integrator = Integrator::Verlet;
        s.impacts = ab::ImpactMode::StepEnd;
        s.dt = 2.5 / std::sqrt(1000.0);
        const double d = 1.0 / std::sqrt(1000.0);
        auto sim = ab::makeSimulation(s);
        double deepest = 0.0;
        ab::runRecorded(*sim, sim->start(), 2000, 1,
                        [&](const ab::State& st) { deepest = std::min(deepest, st.p(1, 0)); });
        QVERIFY2(std::abs(deepest + 1.5 * d) <= 1e-12, qPrintable(QString::number(deepest)));
        const Checked c = runChecked(s, 2000);
        QCOMPARE(c.health->figures().escaped, 0);
        QCOMPARE(c.health->worst().level, Health::Failed);
        QVERIFY(c.health->figures().maxEnergyGain > 0.1);
        QVERIFY(mentions(*c.health, "backstop held the ball"));
    }

    void startAtRestIsMeasuredAgainstTheSceneSize()
    {
        // No energy at the start: a gain of 1/2 (speed 1) against g x 1 (the scale of a
        // ball raised by one unit) is 0.5 / 0.0982.
        auto sim = makeSimulation(testing::spec(SceneId::Bounce1d, {"h0=0"}));
        const State start = sim->start();
        HealthCheck h(*sim, start);
        QCOMPARE(h.check(start, oneBall({0, 0, 0}, {0, 1, 0}, 1.0)), Health::Failed);
        QVERIFY(std::abs(h.figures().maxEnergyGain - 0.5 / 0.0982) <= 1e-12);
    }

    void reportStage4BallOnTheFloorIsStuck()
    {
        // Appendix D updates only balls above the floor (y > -49): one on it never moves.
        RunSpec s = testing::spec(SceneId::ManyBalls, {"n=1"});
        s.init = oneBall({0, -49, 0}, {1, 0, 0});
        const Checked c = runChecked(s, 3);
        QCOMPARE(c.health->worst().level, Health::Warning);
        QVERIFY(mentions(*c.health, "Appendix D updates only balls above the floor"));
    }

    void reportStage4PushLeavesABallBeyondTheWall()
    {
        // Ball 0 at x = 48.9 and ball 1 at 47.5 are within 2.2 r: ball 0 is pushed one
        // radius along the normal (+x) to 49.9, 0.9 beyond the limit of 49.
        RunSpec s = testing::spec(SceneId::ManyBalls, {"n=2", "g=0"});
        State init;
        init.resize(2);
        init.p.col(0) = Eigen::Vector3d(48.9, 0, 0);
        init.p.col(1) = Eigen::Vector3d(47.5, 0, 0);
        s.init = init;
        const Checked c = runChecked(s, 1);
        QVERIFY(std::abs(c.health->figures().maxPenetration - 0.9) <= 1e-12);
        QCOMPARE(c.health->figures().escaped, 0);
        QVERIFY(mentions(*c.health, "pushes a colliding ball one radius"));
    }

    void gridFindsTheOverlapsAllPairsWould()
    {
        // 300 balls on a lattice 3 apart (no overlap), then ball 5 moved to 1.3 from ball
        // 6 across a cell boundary: the deepest overlap is 2 - 1.3 = 0.7.
        auto sim = makeSimulation(testing::spec(SceneId::ManyBalls, {"n=300"}));
        std::vector<Eigen::Vector3d> p;
        for (int i = 0; i < 300; ++i)
            p.emplace_back(3.0 * (i % 7) - 9.0, 3.0 * ((i / 7) % 7) - 9.0, 3.0 * (i / 49) - 9.0);
        p[5] = p[6] - Eigen::Vector3d(1.3, 0.0, 0.0);
        const State s = balls(p);
        HealthCheck h(*sim, s);
        h.check(s, s);
        QVERIFY(h.figures().maxOverlap && std::abs(*h.figures().maxOverlap - 0.7) <= 1e-12);
        QVERIFY(mentions(h, "balls 5 and 6 overlap"));
    }
    void roughFloorImpactsKeepTheAngularMomentumAboutTheContactPoint_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<int>("integrator");
        for (Integrator i :
             {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4, Integrator::Event})
            QTest::newRow(("box3d, " + std::string(integratorKey(i))).c_str())
                << static_cast<int>(SceneId::Box3d) << static_cast<int>(i);
        QTest::newRow("many-balls, symplectic-euler")
            << static_cast<int>(SceneId::ManyBalls) << static_cast<int>(Integrator::SymplecticEuler);
    }
    void roughFloorImpactsKeepTheAngularMomentumAboutTheContactPoint()
    {
        // A rough ball thrown with spin bounces on the floor, slides and rolls (mu 0.5,
        // beta 0.6): r n x v + q r^2 w never changes at the floor (S13, S4), to round-off.
        QFETCH(int, scene);
        QFETCH(int, integrator);
        RunSpec spec =
            scene == static_cast<int>(SceneId::Box3d)
                ? testing::spec(SceneId::Box3d, {"mu=0.5", "beta=0.6", "p0=100,30,150", "v0=8,0,3", "w0=3,20,-40"},
                                ModelKind::Physical)
                : testing::spec(SceneId::ManyBalls,
                                {"n=1", "mu=0.5", "beta=0.6", "spin=0.5", "g=0.05", "rest_height=0"},
                                ModelKind::Physical);
        spec.integrator = static_cast<Integrator>(integrator);
        const Checked c = runChecked(spec, 3000);
        QVERIFY(c.health->figures().maxAngularMomentumError.has_value());
        QVERIFY2(*c.health->figures().maxAngularMomentumError < 1e-12,
                 qPrintable(QString::number(*c.health->figures().maxAngularMomentumError)));
        QVERIFY(!mentions(*c.health, "angular momentum"));
    }

    void spinChangedAtTheFloorWithoutTheTranslationWarns()
    {
        // Set down at 5 m/s without spin, a solid ball rolls at 5/7 of it with r w = v (S4):
        // the same angular momentum about the contact point, no finding. The same ball
        // spun up without slowing down gained 2/7 of r m v of it: a warning.
        auto sim = makeSimulation(testing::spec(SceneId::Box3d, {"mu=0.3"}, ModelKind::Physical));
        State before = oneBall({150, 0, 150}, {5, 0, 0});
        before.w.setZero(3, 1);
        State rolled = oneBall({150.05, 0, 150}, {5.0 / 1.4, 0, 0}, 0.01);
        rolled.w.setZero(3, 1);
        rolled.w(2, 0) = -5.0 / 1.4; // r = 1
        HealthCheck kept(*sim, before);
        QCOMPARE(kept.check(before, rolled), Health::Ok);
        QVERIFY(kept.figures().maxAngularMomentumError && *kept.figures().maxAngularMomentumError < 1e-15);
        State spun = rolled;
        spun.v(0, 0) = 5.0;
        HealthCheck gained(*sim, before);
        gained.check(before, spun);
        QVERIFY(mentions(gained, "angular momentum of ball 0 about its contact point changed by"));
        QVERIFY(mentions(gained, "energy")); // the spin's energy came from nowhere too
        const auto found = std::find_if(gained.issues().begin(), gained.issues().end(), [](const auto& s) {
            return s.finding.kind == diagnostics::FindingKind::AngularMomentum;
        });
        QVERIFY(found != gained.issues().end());
        // 2/7 r v of the 5 r before, over the scale r |v| + q r^2 |w| = 5 + 0.4 x 5/1.4.
        QVERIFY(std::abs(found->finding.amount - 100.0 * (2.0 / 1.4) / (5.0 + 2.0 / 1.4)) < 1e-9);
    }
};

QTEST_GUILESS_MAIN(HealthChecks)
#include "test_health.moc"
