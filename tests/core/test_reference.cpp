// SPDX-License-Identifier: MIT
// The closed forms the accuracy study measures against: hand-worked values, the ODEs
// they solve (checked by finite differences and by a fine independent integration), the
// Zeno time, and textbook collision outcomes.
#include "core/reference/bounce_reference.h"
#include "core/reference/collision.h"
#include "core/reference/reference.h"
#include "support/sim_helpers.h"

#include <QtTest>

#include <cmath>

using namespace ab::reference;

namespace {

// dv/dt = -g - beta v - kappa |v| v by classical RK4 with a fine step: an independent
// check of the closed forms, good to ~1e-12 here.
std::pair<double, double> integrateFlight(double g, Drag d, double y, double v, double t)
{
    const int n = 200000;
    const double h = t / n;
    auto a = [&](double u) { return -g - d.beta * u - d.kappa * std::abs(u) * u; };
    for (int i = 0; i < n; ++i) {
        const double k1 = a(v), v2 = v + 0.5 * h * k1, k2 = a(v2), v3 = v + 0.5 * h * k2, k3 = a(v3), v4 = v + h * k3,
                     k4 = a(v4);
        y += h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
        v += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    return {y, v};
}

bool near(double a, double b, double tol)
{
    return std::abs(a - b) <= tol;
}

} // namespace

class ReferenceTest : public QObject {
    Q_OBJECT

private slots:
    void flightWithoutDragIsTheParabola()
    {
        // y = 20 + 5 t - 9.82 t^2 / 2; lands at t = (5 + sqrt(25 + 2 9.82 20)) / 9.82 = 2.58722... s.
        const VerticalFlight f(9.82, {}, 20.0, 5.0);
        QVERIFY(near(f.height(1.0), 20.0 + 5.0 - 4.91, 1e-13));
        QVERIFY(near(f.velocity(1.0), 5.0 - 9.82, 1e-13));
        QVERIFY(near(f.landing(0.0), (5.0 + std::sqrt(25.0 + 2.0 * 9.82 * 20.0)) / 9.82, 1e-13));
        QVERIFY(near(f.apex(), 20.0 + 25.0 / (2.0 * 9.82), 1e-13));
        // Thrown down: the other form of the root, still exact.
        const VerticalFlight down(9.82, {}, 20.0, -5.0);
        QVERIFY(near(down.landing(0.0), (-5.0 + std::sqrt(25.0 + 2.0 * 9.82 * 20.0)) / 9.82, 1e-13));
    }

    void flightWithDragSolvesItsOde_data()
    {
        QTest::addColumn<double>("beta");
        QTest::addColumn<double>("kappa");
        QTest::addColumn<double>("v0");
        QTest::newRow("quadratic, thrown up") << 0.0 << 0.01 << 20.0;
        QTest::newRow("quadratic, dropped") << 0.0 << 0.01 << 0.0;
        QTest::newRow("quadratic, thrown down slower than terminal") << 0.0 << 0.01 << -12.0;
        QTest::newRow("quadratic, thrown down faster than terminal") << 0.0 << 0.01 << -60.0;
        QTest::newRow("linear, thrown up") << 0.3 << 0.0 << 20.0;
        QTest::newRow("linear, thrown down") << 0.3 << 0.0 << -50.0;
    }

    void flightWithDragSolvesItsOde()
    {
        QFETCH(double, beta);
        QFETCH(double, kappa);
        QFETCH(double, v0);
        const double g = 9.82, y0 = 100.0;
        const Drag drag{beta, kappa};
        const VerticalFlight f(g, drag, y0, v0);
        QCOMPARE(f.height(0.0), y0);
        QVERIFY(near(f.velocity(0.0), v0, 1e-12 * std::abs(v0)));
        for (double t : {0.3, 1.0, 1.7, 2.5, 4.0, 6.0}) {
            // Against an independent fine integration of dv/dt = -g - beta v - kappa |v| v.
            const auto [y, v] = integrateFlight(g, drag, y0, v0, t);
            QVERIFY2(near(f.height(t), y, 1e-9 * y0),
                     qPrintable(QString("t %1: %2 vs %3").arg(t).arg(f.height(t)).arg(y)));
            QVERIFY2(near(f.velocity(t), v, 1e-9 * 50.0),
                     qPrintable(QString("t %1: v %2 vs %3").arg(t).arg(f.velocity(t)).arg(v)));
            // And dy/dt = v by a central difference.
            const double h = 1e-5;
            QVERIFY(near((f.height(t + h) - f.height(t - h)) / (2.0 * h), f.velocity(t), 1e-6 * 50.0));
        }
        const double land = f.landing(0.0);
        QVERIFY(near(f.height(land), 0.0, 1e-10 * y0));
        QVERIFY(f.velocity(land) < 0.0);
    }

    void quadraticDragApproachesTheTerminalSpeed()
    {
        // vt = sqrt(g / kappa) = sqrt(982) = 31.34 m/s; after 100 s of falling g t / vt = 31
        // and tanh(31) is 1 to double precision.
        const VerticalFlight f(9.82, {0.0, 0.01}, 1e6, 0.0);
        QVERIFY(near(f.velocity(100.0), -std::sqrt(982.0), 1e-12));
        // Apex of a throw at 20 m/s: (vt^2 / 2g) ln(1 + v0^2/vt^2) = 50 ln(1 + 400/982) = 17.0842 m,
        // below the drag-free 20.367 m.
        const VerticalFlight up(9.82, {0.0, 0.01}, 0.0, 20.0);
        QVERIFY(near(up.apex(), 50.0 * std::log(1.0 + 400.0 / 982.0), 1e-12));
        QVERIFY(up.apex() < 400.0 / (2.0 * 9.82));
    }

    void zenoTimeIsT1TimesOnePlusKOverOneMinusK_data()
    {
        QTest::addColumn<double>("k");
        QTest::newRow("k 0") << 0.0;
        QTest::newRow("k 0.6 (report)") << 0.6;
        QTest::newRow("k 0.9") << 0.9;
        QTest::newRow("k 0.99") << 0.99;
    }

    void zenoTimeIsT1TimesOnePlusKOverOneMinusK()
    {
        QFETCH(double, k);
        const double g = 0.0982, h0 = 2000.0;
        const double t1 = std::sqrt(2.0 * h0 / g); // 201.82 steps
        const BounceReference b(g, k, h0, 0.0);
        const double tz = t1 * (1.0 + k) / (1.0 - k);
        QVERIFY(near(b.restTime(), tz, 1e-12 * tz));
        QCOMPARE(b.height(tz), 0.0);
        QCOMPARE(b.velocity(tz * 1.5), 0.0);
        const std::vector<double> t = b.impactTimes(tz);
        QVERIFY(near(t.front(), t1, 1e-12 * t1));
        // Each flight lasts k times the one before, and every impact is on the floor.
        for (std::size_t n = 2; n < std::min<std::size_t>(t.size(), 40); ++n)
            QVERIFY(near(t[n] - t[n - 1], k * (t[n - 1] - t[n - 2]), 1e-9 * t1));
        for (std::size_t n = 0; n < std::min<std::size_t>(t.size(), 40); ++n)
            QVERIFY(near(b.height(t[n]), 0.0, 1e-10 * h0));
        // Halfway through the second flight it is at its apex, k^2 h0.
        if (t.size() > 1)
            QVERIFY(near(b.height(0.5 * (t[0] + t[1])), k * k * h0, 1e-10 * h0));
    }

    void bounceWithDragRestsAndLosesHeight()
    {
        const double g = 0.0982;
        const BounceReference b(g, 0.6, 2000.0, 0.0, 0.0, {0.0, 0.001});
        const std::vector<double> t = b.impactTimes(1e9);
        QVERIFY(t.size() > 10);
        QVERIFY(std::isfinite(b.restTime()));
        // Drag makes every flight shorter than k times the one before.
        for (std::size_t n = 2; n < 10; ++n)
            QVERIFY(t[n] - t[n - 1] < 0.6 * (t[n - 1] - t[n - 2]));
        // Continuous through an impact, on the floor there.
        QVERIFY(near(b.height(t[1]), 0.0, 1e-9));
        QVERIFY(near(b.height(t[1] - 1e-7), 0.0, 1e-4));
    }

    void wallAxisBouncesBetweenItsWalls()
    {
        // x from 2 at 10 m/s: hits 300 at 29.8 s, comes back at 9 m/s, hits 0 at 29.8 + 300/9 s.
        const WallAxisReference x(2.0, 10.0, 0.0, 300.0, 0.9, 0.9, 1000.0);
        QVERIFY(near(x.position(10.0), 102.0, 1e-12));
        QVERIFY(near(x.position(40.0), 300.0 - 9.0 * 10.2, 1e-10));
        QCOMPARE(x.velocity(40.0), -9.0);
        const std::vector<double> t = x.impactTimes(70.0);
        QCOMPARE(t.size(), std::size_t(2));
        QVERIFY(near(t[0], 29.8, 1e-12));
        QVERIFY(near(t[1], 29.8 + 300.0 / 9.0, 1e-12));
    }

    void headOnOutcomes()
    {
        // 1 kg at 4 m/s hits 3 kg at rest, elastic: -2 and 2 m/s (v1 = (m1 - m2) u1 / (m1 + m2)).
        auto [a, b] = headOnOutcome(1.0, 3.0, 4.0, 0.0, 1.0);
        QVERIFY(near(a, -2.0, 1e-15) && near(b, 2.0, 1e-15));
        // e = 0.5: -0.5 and 1.5 m/s (separation 2 = 0.5 * 4, momentum 4).
        std::tie(a, b) = headOnOutcome(1.0, 3.0, 4.0, 0.0, 0.5);
        QVERIFY(near(a, -0.5, 1e-15) && near(b, 1.5, 1e-15));
        // Equal masses: eq 2.6 v2 = (e (v1 - v2) + v1 + v2) / 2, eq 2.7 v1 = v1 + v2 - v2''.
        std::tie(a, b) = headOnOutcome(2.0, 2.0, 15.0, -15.0, 0.95);
        QVERIFY(near(b, (0.95 * 30.0 + 0.0) / 2.0, 1e-13));
        QVERIFY(near(a, 0.0 - b, 1e-13));
    }

    void obliqueOutcomeKeepsTheTangentialParts()
    {
        // Ball 1 at the origin moving (1, 1, 0) hits ball 2 at rest at (2, 0, 0), equal
        // masses, elastic: the parts along x are exchanged, the part along y stays.
        const auto [v1, v2] = obliqueOutcome(1.0, 1.0, {0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {0, 0, 0}, 1.0);
        QVERIFY((v1 - Eigen::Vector3d(0, 1, 0)).norm() < 1e-15);
        QVERIFY((v2 - Eigen::Vector3d(1, 0, 0)).norm() < 1e-15);
        // Separating balls do not collide.
        const auto [w1, w2] = obliqueOutcome(1.0, 1.0, {0, 0, 0}, {2, 0, 0}, {-1, 0, 0}, {0, 0, 0}, 1.0);
        QCOMPARE(w1, Eigen::Vector3d(-1, 0, 0));
        QCOMPARE(w2, Eigen::Vector3d(0, 0, 0));
    }

    void headOnMeetingOfTheReportIsAtPoint8Seconds()
    {
        // Default two-balls: z from 2 and 298 at +-15 m/s, r = 1: they touch at z = 149 and
        // 151 after (149 - 2) / 15 = 9.8 s, then each leaves at e 15 = 14.25 m/s.
        auto spec = testing::spec(ab::SceneId::TwoBalls, {}, ab::ModelKind::Physical);
        const auto ref = makeReference(spec, 30.0);
        QVERIFY(near(ref->position(0, 9.8).z(), 149.0, 1e-12));
        QVERIFY(near(ref->position(1, 9.8).z(), 151.0, 1e-12));
        QVERIFY(near(ref->velocity(0, 10.0).z(), -14.25, 1e-12));
        QVERIFY(near(ref->velocity(1, 10.0).z(), 14.25, 1e-12));
        QVERIFY(near(ref->position(0, 5.0).x(), 52.0, 1e-12));
    }

    void uncoveredParametersAreRefused_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<QString>("assignment");
        QTest::addColumn<QString>("named");
        QTest::newRow("box3d with drag") << int(ab::SceneId::Box3d) << "c=0.1"
                                         << "c:";
        QTest::newRow("box3d with friction") << int(ab::SceneId::Box3d) << "mu=0.2"
                                             << "mu:";
        QTest::newRow("bounce1d with a rest speed") << int(ab::SceneId::Bounce1d) << "rest_speed=0.1"
                                                    << "rest_speed:";
        QTest::newRow("two-balls not mirrored") << int(ab::SceneId::TwoBalls) << "p2=5,20,298"
                                                << "p2, v2:";
        QTest::newRow("two-balls unequal masses") << int(ab::SceneId::TwoBalls) << "m2=2"
                                                  << "m2:";
        QTest::newRow("many balls") << int(ab::SceneId::ManyBalls) << "n=3"
                                    << "many-balls:";
    }

    void uncoveredParametersAreRefused()
    {
        QFETCH(int, scene);
        QFETCH(QString, assignment);
        QFETCH(QString, named);
        auto spec = testing::spec(ab::SceneId(scene), {assignment.toStdString()}, ab::ModelKind::Physical);
        try {
            makeReference(spec, 10.0);
            QFAIL("no error");
        } catch (const ab::InputError& e) {
            QVERIFY2(std::string(e.what()).rfind(named.toStdString(), 0) == 0, e.what());
        }
    }

    void bothDragsAtOnceAreRefused()
    {
        auto spec = testing::spec(ab::SceneId::Bounce1d, {"b=0.1", "c=0.1"}, ab::ModelKind::Physical);
        QVERIFY_THROWS_EXCEPTION(ab::InputError, makeReference(spec, 10.0));
    }
};

QTEST_GUILESS_MAIN(ReferenceTest)
#include "test_reference.moc"
