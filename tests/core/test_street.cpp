// SPDX-License-Identifier: MIT
// Stage 5, the street (docs/street.md), against closed forms: a ball rolling down a block
// accelerates at g sin(theta) / (1 + q) with r w = v (St1); below St3's friction it slides at
// g (sin(theta) - mu cos(theta)) while its spin grows at mu g cos(theta) / (q r) (St2); a ball
// leaving a crossing's edge flies a parabola and lands where St5's root puts it, to 1e-9; an
// elastic superball (e = beta = 1, friction sticking) keeps its energy; nothing goes through a
// kerb or the road at any speed; balls leave at the open foot; runs are the same for any
// thread count; the report model and other integrators are refused with one line.
#include "core/diagnostics/conservation.h"
#include "core/diagnostics/health.h"
#include "core/street/street_census.h"
#include "core/street/street_engine.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>

using ab::RunSpec;
using ab::SceneId;
using ab::State;
using Eigen::Vector3d;

namespace {

RunSpec streetSpec(const QStringList& assignments, double dt = 1.0 / 60.0)
{
    RunSpec s(SceneId::Street);
    for (const QString& a : assignments)
        s.params.parseAssignment(a.toStdString());
    s.dt = dt;
    return s;
}

State oneBall(const Vector3d& p, const Vector3d& v, const Vector3d& w = Vector3d::Zero())
{
    State s;
    s.resize(1);
    s.w.setZero(3, 1);
    s.p.col(0) = p;
    s.v.col(0) = v;
    s.w.col(0) = w;
    return s;
}

State runFor(ab::Simulation& sim, State s, long long steps)
{
    State next;
    for (long long k = 0; k < steps; ++k) {
        sim.step(s, next);
        std::swap(s, next);
    }
    return s;
}

// A run of `steps` steps under the health check: the last state, and the worst the check met.
struct CheckedRun {
    State end;
    ab::diagnostics::HealthStatus worst;
};
CheckedRun runChecked(ab::Simulation& sim, State s, long long steps)
{
    State next;
    ab::diagnostics::HealthCheck health(sim, s);
    for (long long k = 0; k < steps; ++k) {
        sim.step(s, next);
        health.check(s, next);
        std::swap(s, next);
    }
    return {s, health.worst()};
}

double radians(double degrees)
{
    return degrees * std::numbers::pi / 180.0;
}

// The highest point of the street's solid on the vertical line through (x, z): each box meets
// the line in the y interval where all three slabs |R^T (p - c)|_j <= h_j hold, each slab
// linear in y along the column (R^T e_y)_j.
double solidTop(const ab::street::Layout& layout, double x, double z)
{
    double top = -std::numeric_limits<double>::infinity();
    for (const ab::street::Box& b : layout.boxes) {
        const Vector3d base = b.toLocal(Vector3d(x, 0.0, z)), dir = b.rotateIn(Vector3d::UnitY());
        double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
        for (int j = 0; j < 3 && lo <= hi; ++j) {
            if (dir[j] == 0.0) {
                if (std::abs(base[j]) > b.half[j])
                    hi = -hi;
                continue;
            }
            const double y0 = (-b.half[j] - base[j]) / dir[j], y1 = (b.half[j] - base[j]) / dir[j];
            lo = std::max(lo, std::min(y0, y1));
            hi = std::min(hi, std::max(y0, y1));
        }
        if (lo <= hi)
            top = std::max(top, hi);
    }
    return top;
}

bool near(const Vector3d& a, const Vector3d& b, double relative)
{
    return (a - b).norm() <= relative * std::max(1.0, b.norm());
}

} // namespace

class Street : public QObject {
    Q_OBJECT

private slots:
    void aBallRollingDownABlockAcceleratesAtGSinThetaOverOnePlusQ_data()
    {
        QTest::addColumn<double>("slope");
        QTest::addColumn<double>("q");
        QTest::addColumn<double>("mu");
        QTest::newRow("17 deg, solid ball") << 17.0 << 0.4 << 0.5;
        QTest::newRow("30 deg, solid ball") << 30.0 << 0.4 << 0.5;
        QTest::newRow("45 deg, hollow shell") << 45.0 << 2.0 / 3.0 << 1.0;
    }
    void aBallRollingDownABlockAcceleratesAtGSinThetaOverOnePlusQ()
    {
        QFETCH(double, slope);
        QFETCH(double, q);
        QFETCH(double, mu);
        const double th = radians(slope), g = 9.82, r = 0.03, height = 3 * 80.0 * std::sin(th);
        const Vector3d along(std::cos(th), -std::sin(th), 0.0), n(std::sin(th), std::cos(th), 0.0);
        QVERIFY(mu >= q * std::tan(th) / (1.0 + q)); // St3: friction holds it
        const Vector3d p0 = Vector3d(0.0, height, 0.0) + 5.0 * along + r * n;
        RunSpec spec = streetSpec({"n=1", QString("slope=%1").arg(slope), QString("inertia=%1").arg(q, 0, 'g', 17),
                                   QString("mu=%1").arg(mu)});
        spec.init = oneBall(p0, Vector3d::Zero());
        auto sim = ab::makeSimulation(spec);
        const State end = runFor(*sim, sim->start(), 180);               // 3 s
        const double t = 180.0 / 60.0, a = g * std::sin(th) / (1.0 + q); // St1
        QVERIFY2(near(end.p.col(0), p0 + 0.5 * a * t * t * along, 1e-9),
                 qPrintable(QString("x = %1, expected %2")
                                .arg(end.p(0, 0), 0, 'g', 17)
                                .arg((p0 + 0.5 * a * t * t * along).x(), 0, 'g', 17)));
        QVERIFY(near(end.v.col(0), a * t * along, 1e-9));
        // Rolling without slipping: r w = n x v, so |r w| = |v| (St1).
        QVERIFY(near(r * Vector3d(end.w.col(0)), n.cross(Vector3d(end.v.col(0))), 1e-9));
    }

    void aBallSlidingDownABlockSpinsUpAtMuGCosThetaOverQR()
    {
        const double th = radians(30.0), g = 9.82, r = 0.03, q = 0.4, mu = 0.1;
        QVERIFY(mu < q * std::tan(th) / (1.0 + q)); // below St3: it slides
        const double height = 3 * 80.0 * std::sin(th);
        const Vector3d along(std::cos(th), -std::sin(th), 0.0), n(std::sin(th), std::cos(th), 0.0);
        const Vector3d p0 = Vector3d(0.0, height, 0.0) + 5.0 * along + r * n;
        RunSpec spec = streetSpec({"n=1", "slope=30", "mu=0.1"});
        spec.init = oneBall(p0, Vector3d::Zero());
        auto sim = ab::makeSimulation(spec);
        const State end = runFor(*sim, sim->start(), 120);                // 2 s
        const double t = 2.0, a = g * (std::sin(th) - mu * std::cos(th)); // St2
        QVERIFY(near(end.p.col(0), p0 + 0.5 * a * t * t * along, 1e-9));
        QVERIFY(near(end.v.col(0), a * t * along, 1e-9));
        const double spinRate = mu * g * std::cos(th) / (q * r); // St2
        QVERIFY(near(end.w.col(0), spinRate * t * n.cross(along), 1e-9));
    }

    void aBallLeavingACrossingFliesAParabolaAndLandsWhereTheRootSays()
    {
        // A smooth ball (mu = 0) sliding at v0 over the flat crossing below block 1 leaves its
        // lower edge E, flies p(t) = p_E + v0 t - g t^2 / 2 (St4) and meets block 2's plane
        // when n.(p - E) = r (St5): -(g cos th / 2) t^2 + v0 sin th t + r (cos th - 1) = 0,
        // the larger root. With e = 1 it leaves the plane mirrored: v' = v - 2 (n.v) n.
        const double th = radians(17.0), g = 9.82, r = 0.03, v0 = 6.0;
        const ab::street::Layout layout(th, 3, 80.0, 14.0, 12.0, 0.15, 3.0, 0, r, 1);
        const double xe = layout.blockStartX[1], ye = layout.roadY(xe);
        const Vector3d n(std::sin(th), std::cos(th), 0.0), gv(0.0, -g, 0.0);
        const double lead = 0.5; // the ball starts 0.5 m before the edge
        RunSpec spec = streetSpec({"n=1", "mu=0", "e=1", "rest_height=0"}, 1.0 / 240.0);
        spec.init = oneBall(Vector3d(xe - lead, ye + r, 1.0), Vector3d(v0, 0.0, 0.0));
        auto sim = ab::makeSimulation(spec);
        const double tEdge = lead / v0;
        const double A = 0.5 * g * std::cos(th), B = v0 * std::sin(th), C = r * (1.0 - std::cos(th));
        const double tLand = (B + std::sqrt(B * B - 4.0 * A * C)) / (2.0 * A); // after the edge
        const Vector3d pE(xe, ye + r, 1.0), vE(v0, 0.0, 0.0);
        const Vector3d pLand = pE + tLand * vE + 0.5 * tLand * tLand * gv;
        const Vector3d vLand = vE + tLand * gv, vOut = vLand - 2.0 * vLand.dot(n) * n;
        QCOMPARE_LT(std::abs(n.dot(pLand - Vector3d(xe, ye, 1.0)) - r), 1e-12); // the root is a root
        State s = sim->start(), next;
        int checkedBefore = 0, checkedAfter = 0;
        for (int k = 0; k < 240; ++k) {
            sim->step(s, next);
            std::swap(s, next);
            const double t = s.t - tEdge;
            Vector3d expected, velocity;
            if (t <= 0.0) {
                expected = pE + t * vE, velocity = vE;
            } else if (t < tLand) {
                expected = pE + t * vE + 0.5 * t * t * gv, velocity = vE + t * gv;
                ++checkedBefore;
            } else {
                const double u = t - tLand;
                expected = pLand + u * vOut + 0.5 * u * u * gv, velocity = vOut + u * gv;
                ++checkedAfter;
                if (u > 0.2)
                    break; // before the bounce lands again
            }
            QVERIFY2(near(s.p.col(0), expected, 1e-9),
                     qPrintable(QString("t = %1: off by %2 m").arg(s.t).arg((Vector3d(s.p.col(0)) - expected).norm())));
            QVERIFY(near(s.v.col(0), velocity, 1e-9));
        }
        QVERIFY(checkedBefore >= 10);
        QVERIFY(checkedAfter >= 10);
    }

    void anElasticSuperballKeepsItsEnergyDownTheStreet_data()
    {
        QTest::addColumn<double>("slope");
        QTest::newRow("17 deg") << 17.0;
        QTest::newRow("45 deg") << 45.0;
    }
    void anElasticSuperballKeepsItsEnergyDownTheStreet()
    {
        // e = beta = 1 with friction that always sticks (mu = 10): every impact keeps the
        // energy (S9 with beta = 1 reverses the slip), and the flight is exact.
        QFETCH(double, slope);
        RunSpec spec =
            streetSpec({"n=1", QString("slope=%1").arg(slope), "e=1", "beta=1", "mu=10", "rest_height=0", "speed=3"});
        auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        State s = sim->start();
        const double e0 = meter.measure(s).energy.total();
        long long impacts = 0;
        for (int k = 0; k < 600; ++k) {
            State next;
            sim->step(s, next);
            std::swap(s, next);
            if (ab::street::hasLeft(ab::street::Layout::fromParams(spec.params), s.p(0, 0)))
                break;
            impacts = s.impacts;
            const double e = meter.measure(s).energy.total();
            QVERIFY2(
                std::abs(e - e0) <= 1e-9 * e0,
                qPrintable(QString("t = %1: energy %2 against %3").arg(s.t).arg(e, 0, 'g', 17).arg(e0, 0, 'g', 17)));
        }
        QVERIFY(impacts >= 3); // it bounced on the way
    }

    void anElasticSuperballOffAKerbsEdgeGainsNoEnergy()
    {
        // The kerb's top edge is met by closest point at the substep's end: the push out lifts
        // the centre, and the ball pays that potential energy from its speed (payForRise), so
        // with e = beta = 1 and sticking friction the energy stays as it was.
        RunSpec spec = streetSpec({"n=1", "e=1", "beta=1", "mu=10", "rest_height=0"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        const double x = 20.0, edgeZ = -0.5 * layout.width;
        // Falling and moving across at 3 m/s each way towards the edge's line, from 0.3 m above
        // the kerb's top and 0.25 m inside the roadway.
        spec.init = oneBall(Vector3d(x, layout.roadY(x) + layout.kerb + 0.3, edgeZ + 0.25), Vector3d(0.0, -3.0, -3.0));
        auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        State s = sim->start(), next;
        const double e0 = meter.measure(s).energy.total();
        bool turnedAcross = false, reboundUp = false;
        for (int k = 0; k < 30; ++k) {
            sim->step(s, next);
            std::swap(s, next);
            turnedAcross = turnedAcross || std::abs(s.v(2, 0) + 3.0) > 0.1;
            reboundUp = reboundUp || s.v(1, 0) > 0.0;
            const double e = meter.measure(s).energy.total();
            QVERIFY2(
                e <= e0 * (1.0 + 1e-9),
                qPrintable(QString("t = %1: energy %2 against %3").arg(s.t).arg(e, 0, 'g', 17).arg(e0, 0, 'g', 17)));
        }
        // It met the kerb's top at its edge (at t = 5/60 s): thrown up, its motion across changed.
        QVERIFY(reboundUp);
        QVERIFY(turnedAcross);
    }

    void nothingGoesThroughAKerbOrTheRoadAtAnySpeed_data()
    {
        QTest::addColumn<Vector3d>("velocity");
        QTest::newRow("across into the kerb at 300 m/s") << Vector3d(0.0, 0.0, 300.0);
        QTest::newRow("down into the road at 500 m/s") << Vector3d(20.0, -500.0, 0.0);
        QTest::newRow("into a parked car at 200 m/s") << Vector3d(200.0, -5.0, -40.0);
    }
    void nothingGoesThroughAKerbOrTheRoadAtAnySpeed()
    {
        QFETCH(Vector3d, velocity);
        RunSpec spec = streetSpec({"n=1", "cars=6", "e=0.9"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        spec.init = oneBall(Vector3d(20.0, layout.roadY(20.0) + 1.0, 0.0), velocity);
        auto sim = ab::makeSimulation(spec);
        State s = sim->start(), next;
        ab::diagnostics::HealthCheck health(*sim, s);
        for (int k = 0; k < 120; ++k) {
            sim->step(s, next);
            QCOMPARE(health.check(s, next), ab::diagnostics::Health::Ok);
            std::swap(s, next);
            if (ab::street::hasLeft(layout, s.p(0, 0)))
                break;
            // Between the house fronts, above the road under it.
            QVERIFY(std::abs(s.p(2, 0)) <= 0.5 * layout.width + layout.sidewalk - 0.03 + 1e-9);
            QVERIFY(s.p(1, 0) >= layout.roadY(s.p(0, 0)) + 0.03 - 1e-9 ||
                    std::abs(s.p(0, 0) - layout.blockFootX[0]) < 1.0);
        }
        QCOMPARE(health.figures().escaped, 0);
    }

    void theSidewalksMeetWithoutANotchWhereACrossingTipsIntoABlock_data()
    {
        QTest::addColumn<double>("slope");
        QTest::newRow("17 degrees") << 17.0;
        QTest::newRow("45 degrees") << 45.0;
    }
    void theSidewalksMeetWithoutANotchWhereACrossingTipsIntoABlock()
    {
        // Across each junction the sidewalk's top is the road's surface raised by the kerb: flat
        // y_c + k over the crossing, y_c + k / cos a - tan a (x - x_c) over the block (the
        // block's road through (x_c, y_c), raised k along its normal), whichever is lower, with
        // no gap between two box edges where a ball could wedge.
        QFETCH(double, slope);
        const RunSpec spec = streetSpec({QStringLiteral("slope=%1").arg(slope), "blocks=3"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        const double a = layout.slope, k = layout.kerb, z = 0.5 * layout.width + 0.5 * layout.sidewalk;
        for (double xc : layout.blockStartX) {
            const double yc = layout.roadY(xc);
            for (int step = -100; step <= 100; ++step) {
                const double x = xc + 1e-3 * step;
                const double expected = std::min(yc + k, yc + k / std::cos(a) - std::tan(a) * (x - xc));
                QVERIFY2(std::abs(solidTop(layout, x, z) - expected) <= 1e-9,
                         qPrintable(QStringLiteral("x - x_c = %1 m: top %2 m, expected %3 m")
                                        .arg(x - xc)
                                        .arg(solidTop(layout, x, z) - yc)
                                        .arg(expected - yc)));
            }
        }
    }

    void aPointsDistanceFromATurnedBoxIsMeasuredInTheBoxsFrame()
    {
        // Box half extents (1, 2, 3) turned 30 degrees about z. A point at local (3, 0.5, -5) is
        // beyond the edge x = 1, z = -3: its distance is |(2, 0, -2)| = sqrt(8); a point inside
        // is at distance 0.
        const ab::street::Box box(ab::street::ItemKind::Car, -1, Vector3d(4.0, -1.0, 2.0), std::numbers::pi / 6,
                                  Vector3d(1.0, 2.0, 3.0));
        const Vector3d beyond = box.outside(box.toLocal(box.toWorld(Vector3d(3.0, 0.5, -5.0))));
        QVERIFY((beyond - Vector3d(2.0, 0.0, -2.0)).norm() <= 1e-12);
        QVERIFY(std::abs(beyond.norm() - std::sqrt(8.0)) <= 1e-12);
        QCOMPARE(box.outside(box.toLocal(box.toWorld(Vector3d(0.9, -1.9, 2.9)))).norm(), 0.0);
    }

    void aBallDroppedOnTheSidewalksCreaseRestsOutsideBothBoxes()
    {
        // Dropped onto the sidewalk where the top crossing tips into block 1: it bounces,
        // comes to rest, and is never found inside a box (the health check's depth, 1e-9 r).
        RunSpec spec = streetSpec({"n=1", "e=0.5", "mu=0.5"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        const double r = layout.radius, k = layout.kerb;
        const double x = k * std::tan(0.5 * layout.slope), z = 0.5 * layout.width + 0.5 * layout.sidewalk;
        spec.init = oneBall(Vector3d(x, layout.roadY(0.0) + k + r + 0.05, z), Vector3d::Zero());
        auto sim = ab::makeSimulation(spec);
        const CheckedRun run = runChecked(*sim, sim->start(), 180);
        QVERIFY2(run.worst.level == ab::diagnostics::Health::Ok, run.worst.line().c_str());
        QVERIFY(run.end.p(1, 0) >= layout.roadY(0.0) + k); // on the sidewalk, not down in a notch
    }

    void ballsLeaveTheRunAtTheOpenFoot()
    {
        RunSpec spec = streetSpec({"n=1", "blocks=1", "block_length=20", "mu=0.5"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        spec.init =
            oneBall(Vector3d(layout.xFoot - 1.0, layout.roadY(layout.xFoot - 1.0) + 0.2, 0.0), Vector3d(8.0, 0.0, 0.0));
        auto sim = ab::makeSimulation(spec);
        const State end = runFor(*sim, sim->start(), 60);
        QVERIFY(ab::street::hasLeft(layout, end.p(0, 0)));
        QCOMPARE(end.v.col(0).norm(), 0.0); // at rest, out of the run
        const ab::street::Census c = ab::street::census(layout, end);
        QCOMPARE(c.left, 1);
        QCOMPARE(c.onStreet, 0);
        QCOMPARE(c.pastFoot.front(), 1);
    }

    void anOverlapOnTheStreetIsPutDownToItsContactsNotToTheStep()
    {
        // The street's substeps follow its fastest ball, whatever --dt: the advice for two balls
        // found inside each other names the contact passes and the pile's depth instead.
        RunSpec spec = streetSpec({"n=2"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        const double r = 0.03, y = layout.roadY(20.0) + r;
        State before;
        before.resize(2);
        before.w.setZero(3, 2);
        before.p.col(0) = Vector3d(20.0, y, 0.0);
        before.p.col(1) = Vector3d(20.0, y, 2.0 * r); // touching, side by side across the road
        State after = before;
        after.t = 1.0 / 60.0;
        after.p(2, 1) -= 0.2 * r; // now a fifth of r inside each other
        auto sim = ab::makeSimulation(spec);
        ab::diagnostics::HealthCheck health(*sim, before);
        health.check(before, after);
        bool found = false;
        for (const ab::diagnostics::HealthStatus& s : health.issues()) {
            if (s.finding.kind != ab::diagnostics::FindingKind::Overlap)
                continue;
            found = true;
            QCOMPARE(s.finding.remedy, ab::diagnostics::Remedy::StreetContacts);
            QVERIFY2(s.advice.find("contact passes") != std::string::npos, s.advice.c_str());
            QVERIFY2(s.advice.find("use a smaller --dt") == std::string::npos, s.advice.c_str());
        }
        QVERIFY(found);
    }

    void manyBallsLeavingAtTheFootStayHealthy()
    {
        // The balls that left rest where they left, out of the run: the health check does not
        // take them for balls inside each other.
        RunSpec spec = streetSpec({"n=400", "blocks=1", "block_length=12"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        auto sim = ab::makeSimulation(spec);
        const CheckedRun run = runChecked(*sim, sim->start(), 300);
        QVERIFY2(run.worst.level == ab::diagnostics::Health::Ok, run.worst.line().c_str());
        const ab::street::Census c = ab::street::census(layout, run.end);
        QCOMPARE_GT(c.left, 200);
        QCOMPARE(c.left + c.onStreet, 400);
    }

    void aFloodIsTheSameBitForBitOnOneOrTwoThreads()
    {
        // 12,000 balls in 6 chunks of pairs list some 16,000 pairs of each colour every substep
        // after the landing, enough for the two threads to share every phase of the contact
        // passes, the settling of the moved balls included.
        RunSpec one = streetSpec({"n=12000", "mu=0.4", "beta=0.3"});
        RunSpec two = one;
        two.threads = 2;
        auto a = ab::makeSimulation(one), b = ab::makeSimulation(two);
        const State sa = runFor(*a, a->start(), 40), sb = runFor(*b, b->start(), 40);
        QVERIFY(sa.impacts > 0); // the balls met each other and the road
        QVERIFY(sa.p == sb.p);
        QVERIFY(sa.v == sb.v);
        QVERIFY(sa.w == sb.w);
    }

    void smoothBallsKeepTheirOwnSpinsUnderTheirOwnNumbers()
    {
        // Without friction nothing turns a ball's spin (eqs 2.4-2.7 act along the line of
        // centres, impacts with the street along the face's normal): each ball must come back
        // with the spin it was given, however the engine re-orders its balls in memory.
        RunSpec spec = streetSpec({"n=2000", "mu=0"});
        State start = ab::makeSimulation(spec)->start();
        start.w.resize(3, start.size());
        for (int i = 0; i < start.size(); ++i)
            start.w.col(i) = Vector3d(0.5 * i, -1.0, 1e-3 * i);
        spec.init = start;
        auto sim = ab::makeSimulation(spec);
        const State end = runFor(*sim, sim->start(), 120);
        QCOMPARE_GT(end.impacts, 1000); // they met each other and the road
        for (int i = 0; i < end.size(); ++i)
            QVERIFY2(end.w.col(i) == start.w.col(i), qPrintable(QString("ball %1").arg(i)));
    }

    void aFloodStaysHealthyAndLosesEnergy()
    {
        RunSpec spec = streetSpec({"n=2000", "mu=0.5", "beta=0.2"});
        auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        const double e0 = meter.measure(sim->start()).energy.total();
        const CheckedRun run = runChecked(*sim, sim->start(), 150);
        QVERIFY2(run.worst.level == ab::diagnostics::Health::Ok, run.worst.line().c_str());
        QVERIFY(meter.measure(run.end).energy.total() < e0);
        QCOMPARE_GT(run.end.impacts, 100);
    }

    void theStreetRefusesTheReportModelAndOtherIntegrators()
    {
        RunSpec report = streetSpec({});
        report.model = ab::ModelKind::Report;
        try {
            ab::makeSimulation(report);
            QFAIL("the report model was accepted");
        } catch (const ab::InputError& e) {
            QVERIFY(QString(e.what()).contains("report 3.1"));
        }
        RunSpec euler = streetSpec({});
        euler.integrator = ab::Integrator::Euler;
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::makeSimulation(euler));
        RunSpec narrow = streetSpec({"width=0.1", "r=0.03"});
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::makeSimulation(narrow));
        RunSpec cars = streetSpec({"cars=2000", "blocks=1"});
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::makeSimulation(cars));
    }
};

QTEST_APPLESS_MAIN(Street)
#include "test_street.moc"
