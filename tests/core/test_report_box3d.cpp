// SPDX-License-Identifier: MIT
// Stage 2, the report's rule (Appendix B with eqs 2.17-2.22): hand-worked contacts and
// the listing, step for step.
#include "support/report_listings.h"
#include "support/sim_helpers.h"

#include <QtTest>

using ab::SceneId;

namespace {

bool near(double a, double b, double tol = 1e-12)
{
    return std::abs(a - b) <= tol * std::max(1.0, std::abs(b));
}

} // namespace

class ReportBox3d : public QObject {
    Q_OBJECT

private slots:
    void freeFlightIsSemiImplicitEuler()
    {
        // v1 = v0 + g dt = (10, -0.0982, 15); p1 = p0 + v1 dt = (2.1, 19.999018, 2.15).
        const auto s = testing::record(testing::spec(SceneId::Box3d), 1);
        QVERIFY(near(s[1].v(1, 0), -0.0982));
        QVERIFY(near(s[1].p(0, 0), 2.1));
        QVERIFY(near(s[1].p(1, 0), 20.0 - 0.000982));
        QVERIFY(near(s[1].p(2, 0), 2.15));
    }

    void firstFloorContactIsStep202()
    {
        // y_n = 20 - 0.000491 n (n + 1): 0.0876 left at n = 201, below the floor at 202.
        // The floor step: y restarts at 0, vy = -0.9 vy - g dt = 0.9 * 19.8364 - 0.0982.
        const auto s = testing::record(testing::spec(SceneId::Box3d), 203);
        QVERIFY(s[201].p(1, 0) > 0.0);
        QCOMPARE(s[202].p(1, 0), 0.0); // the clamp is stored (Appendix B)
        QVERIFY(near(s[202].v(1, 0), -202 * 0.0982));
        QVERIFY(near(s[203].v(1, 0), 0.9 * 202 * 0.0982 - 0.0982));
        QVERIFY(near(s[203].p(1, 0), (0.9 * 202 * 0.0982 - 0.0982) * 0.01));
        QVERIFY(near(s[203].v(0, 0), 10.0));
        QCOMPARE(s[203].count, 1LL);
    }

    void firstWallHitIsTheFarZWallAtStep1987()
    {
        // z_n = 2 + 0.15 n passes 300 first at n = 1987 (300.05), x is at 200.7 then and
        // the ball is in the air: the z = box branch clamps z to 300 and reverses vz.
        const auto s = testing::record(testing::spec(SceneId::Box3d), 1988);
        QVERIFY(s[1986].p(2, 0) < 300.0);
        QVERIFY(s[1987].p(1, 0) > 0.0);
        QCOMPARE(s[1987].p(2, 0), 300.0);
        QVERIFY(near(s[1988].v(2, 0), -13.5));
        QVERIFY(near(s[1988].p(2, 0), 300.0 - 0.135));
        QVERIFY(near(s[1988].v(0, 0), 10.0));
        QCOMPARE(s[1988].count, 8LL); // seven floor contacts before it
    }

    void stopsAfterTheFiftyFirstContact()
    {
        const auto s = testing::record(testing::spec(SceneId::Box3d), 6000);
        QVERIFY(!s[3532].halted);
        for (std::size_t i = 3533; i < s.size(); ++i)
            QVERIFY(s[i].p.isZero(0.0) && s[i].v.isZero(0.0));
    }

    void matchesTheListingStepForStep_data()
    {
        QTest::addColumn<QStringList>("set");
        QTest::newRow("report constants") << QStringList{};
        QTest::newRow("k 0.7, another start")
            << QStringList{"k=0.7", "p0=150,40,20", "v0=-30,5,12", "max_bounces=80"};
        QTest::newRow("small box, strong gravity")
            << QStringList{"box=50", "g=30", "p0=25,10,25", "v0=40,0,-35", "max_bounces=200"};
        QTest::newRow("x walls first") << QStringList{"p0=299,50,150", "v0=20,0,0"};
        QTest::newRow("weightless") << QStringList{"g=0", "p0=10,5,10", "v0=-7,0,3"};
    }

    void matchesTheListingStepForStep()
    {
        QFETCH(QStringList, set);
        auto spec = testing::spec(SceneId::Box3d);
        for (const QString& a : set)
            spec.params.parseAssignment(a.toStdString());
        const auto& P = spec.params;
        auto v3 = [](const Eigen::Vector3d& v) { return listing::V3{v.x(), v.y(), v.z()}; };
        const int steps = 6000;
        const auto ref = listing::appendixB(-P.real("g"), P.real("k"), P.real("box"), v3(P.vector("p0")),
                                            v3(P.vector("v0")), static_cast<int>(P.integer("max_bounces")), steps);
        const auto s = testing::record(spec, steps);
        QCOMPARE(s.size(), ref.p.size());
        for (std::size_t i = 0; i < s.size(); ++i)
            for (int a = 0; a < 3; ++a)
                if (!near(s[i].p(a, 0), ref.p[i][a]) || !near(s[i].v(a, 0), ref.v[i][a]))
                    QFAIL(qPrintable(QString("state %1 axis %2 differs from the listing").arg(i).arg(a)));
    }
};

QTEST_GUILESS_MAIN(ReportBox3d)
#include "test_report_box3d.moc"
