// SPDX-License-Identifier: MIT
// Stage 4, the report's WebGL model (Appendix D): the fixed tangent and its degenerate
// case, the pair rule worked by hand, walls, rest, and the seeded start.
#include "support/sim_helpers.h"

#include "core/report/report_models.h"

#include <QtTest>

using ab::SceneId;
using Eigen::Vector3d;

namespace {

ab::State oneBall(const Vector3d& p, const Vector3d& v, int bounces = 0)
{
    ab::State s;
    s.resize(1);
    s.p.col(0) = p;
    s.v.col(0) = v;
    s.bounces[0] = bounces;
    return s;
}

bool near(const Vector3d& a, const Vector3d& b, double tol = 1e-12)
{
    return (a - b).norm() <= tol;
}

} // namespace

class ReportManyBalls : public QObject {
    Q_OBJECT

private slots:
    void fixedTangentFollowsEq224()
    {
        // n = (1, 2, 3)/sqrt(14): tz = -(0.3 + 0.6)/3 = -0.3, so t = (1, 1, -1)/sqrt(3).
        const Vector3d n = Vector3d(1, 2, 3).normalized();
        const Vector3d t = ab::report::fixedTangent(n);
        QVERIFY(near(t, Vector3d(1, 1, -1) / std::sqrt(3.0)));
        QVERIFY(std::abs(t.dot(n)) < 1e-15);
    }

    void fixedTangentWithZeroNormalZIsTheLimitDirection()
    {
        // n.z = 0: eq 2.24 divides by zero. As n.z -> 0 the tangent tends to (0, 0, +-1),
        // which is perpendicular to n; that limit is used.
        const Vector3d t = ab::report::fixedTangent(Vector3d(0.6, 0.8, 0.0));
        QVERIFY(near(t.cwiseAbs(), Vector3d(0, 0, 1)));
        const Vector3d nearly = ab::report::fixedTangent(Vector3d(0.6, 0.8, 1e-9).normalized());
        QVERIFY(near(nearly.cwiseAbs(), Vector3d(0, 0, 1), 1e-8));
        // Overflowing tz (n.z tiny) gives the same finite limit, never NaN.
        const Vector3d tiny = ab::report::fixedTangent(Vector3d(0.6, 0.8, 1e-300));
        QVERIFY(tiny.allFinite());
        QVERIFY(near(tiny.cwiseAbs(), Vector3d(0, 0, 1)));
    }

    void fixedTangentWhenEveryTzFitsIsTheDiagonal()
    {
        // n = (1, -1, 0)/sqrt(2): 0.3 n.x + 0.3 n.y = 0 and n.z = 0, so any tz satisfies
        // eq 2.24; tz = 0 is taken. The zero normal (coincident centres) falls here too.
        const Vector3d diag = Vector3d(1, 1, 0).normalized();
        QVERIFY(near(ab::report::fixedTangent(Vector3d(1, -1, 0).normalized()), diag));
        QVERIFY(near(ab::report::fixedTangent(Vector3d::Zero()), diag));
    }

    void headOnHitOnRestingBallHandsOverTheDampedSpeed()
    {
        // p1 - p2 along +z, n = (0, 0, 1), t = (1, 1, 0)/sqrt(2). Ball 1 moves (0, 0, -2)
        // into ball 2 at rest. Normalised: u1 = (0, 0, -1), u2 = 0. Eq 2.30:
        // u2n'' = (0.95 u1n + u1n)/2 = (0, 0, -0.975); eq 2.31: u1n'' = (0, 0, -0.025).
        // Swapped speeds: ball 1 gets 0.95 |v2| = 0, ball 2 gets 0.95 |v1| = 1.9.
        Vector3d v1(0, 0, -2), v2(0, 0, 0);
        ab::report::resolveReportPair(Vector3d(0, 0, 2), Vector3d(0, 0, 0), v1, v2, 0.95);
        QVERIFY(near(v1, Vector3d::Zero()));
        QVERIFY(near(v2, Vector3d(0, 0, -1.9)));
    }

    void obliqueHitSwapsDampedSpeeds()
    {
        Vector3d v1(0.3, -0.2, 0.5), v2(-0.1, 0.4, 0.2);
        const double s1 = v1.norm(), s2 = v2.norm();
        ab::report::resolveReportPair(Vector3d(1, 0.5, 1.2), Vector3d(0, 0, 0), v1, v2, 0.95);
        QVERIFY(std::abs(v1.norm() - 0.95 * s2) < 1e-14);
        QVERIFY(std::abs(v2.norm() - 0.95 * s1) < 1e-14);
    }

    void sideWallReversesAndDampsWithGravityTwice()
    {
        // x = 48.5 moving +1: gravity first (vy = -0.00982), then x = 49.5 > 49, so vx =
        // -0.9, vy = 0.95 * -0.00982 - 0.00982, and x is put back to 49.
        auto spec = testing::spec(SceneId::ManyBalls, {"n=1"});
        spec.init = oneBall(Vector3d(48.5, 0, 0), Vector3d(1, 0, 0));
        const auto s = testing::record(spec, 1);
        QVERIFY(near(s[1].p.col(0), Vector3d(49, -0.00982, 0)));
        QVERIFY(near(s[1].v.col(0), Vector3d(-0.9, 0.95 * -0.00982 - 0.00982, 0)));
        QCOMPARE(s[1].bounces[0], 1);
    }

    void floorHitReversesAndStaysOnTheFloor()
    {
        // y = -48.9 moving -0.5: y = -49.40982 <= -49, so vy = 0.9 * 0.50982, y = -49.
        // From then on y > -49 is false and the report's update skips the ball for good.
        auto spec = testing::spec(SceneId::ManyBalls, {"n=1"});
        spec.init = oneBall(Vector3d(10, -48.9, 5), Vector3d(0.2, -0.5, 0.1));
        const auto s = testing::record(spec, 3);
        QVERIFY(near(s[1].v.col(0), Vector3d(0.19, 0.9 * 0.50982, 0.095)));
        QCOMPARE(s[1].p(1, 0), -49.0);
        QVERIFY(near(s[3].p.col(0), s[1].p.col(0)));
    }

    void ballPastTheBounceLimitNearTheFloorIsPutToRest()
    {
        auto sim = ab::makeSimulation(testing::spec(SceneId::ManyBalls, {"n=1"}));
        ab::State s = oneBall(Vector3d(3, -48.5, 3), Vector3d(0.1, 0.3, 0.1), 21);
        ab::State next;
        sim->step(s, next);
        QCOMPARE(next.p(1, 0), -49.0);
        QVERIFY(next.v.isZero(0.0));
        QVERIFY(near(next.p.col(0), Vector3d(3, -49, 3)));
    }

    void seededStartIsReproducibleAndInsideTheReportsCube()
    {
        auto a = ab::makeSimulation(testing::spec(SceneId::ManyBalls, {"seed=7"}))->initialState();
        auto b = ab::makeSimulation(testing::spec(SceneId::ManyBalls, {"seed=7"}))->initialState();
        auto c = ab::makeSimulation(testing::spec(SceneId::ManyBalls, {"seed=8"}))->initialState();
        QCOMPARE(a.size(), 150);
        QVERIFY(a.p == b.p && a.v == b.v);
        QVERIFY(a.p != c.p);
        QVERIFY(a.p.maxCoeff() < 9.0 && a.p.minCoeff() >= -9.0);
        QVERIFY(a.v.cwiseAbs().maxCoeff() <= 1.0);
    }

    void coincidentCentresEndTheFrameWithFiniteState()
    {
        // The zero normal pushes nothing apart, so the pair collides again and again; the
        // frame's shared repeat counter (100) ends it.
        auto spec = testing::spec(SceneId::ManyBalls, {"n=2"});
        ab::State s;
        s.resize(2);
        s.p.col(0) = s.p.col(1) = Vector3d(1, 2, 3);
        s.v.col(0) = Vector3d(0.1, 0, 0);
        spec.init = s;
        const auto states = testing::record(spec, 5);
        QVERIFY(states.back().p.allFinite() && states.back().v.allFinite());
    }

    void defaultRunStaysFiniteAndLosesEnergy()
    {
        // 500 frames of the report's 150 balls: every number finite, and the kinetic energy
        // never grows overall (walls and pairs only damp; gravity feeds falling balls, so
        // the check is on the total with potential energy m g y).
        const auto s = testing::record(testing::spec(SceneId::ManyBalls), 500);
        auto energy = [](const ab::State& st) {
            return 0.5 * st.v.squaredNorm() + 9.82 / 1000.0 * (st.p.row(1).array() + 49.0).sum();
        };
        for (const ab::State& st : s)
            QVERIFY(st.p.allFinite() && st.v.allFinite());
        QVERIFY(energy(s.back()) < energy(s.front()));
    }
};

QTEST_GUILESS_MAIN(ReportManyBalls)
#include "test_report_many_balls.moc"
