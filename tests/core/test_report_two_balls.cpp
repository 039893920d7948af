// SPDX-License-Identifier: MIT
// Stage 3, the report's rule (Appendix C): velocity swap x e, shared counter, listing.
#include "support/report_listings.h"
#include "support/sim_helpers.h"

#include <QtTest>

using ab::SceneId;

class ReportTwoBalls : public QObject {
    Q_OBJECT

private slots:
    void headOnBallsSwapVelocitiesScaledByE()
    {
        // Ball 2 starts at z = 297.95: along z the centres close at 0.30 per step from
        // 295.95 apart, so the gap 295.95 - 0.3 n is 2.25 at n = 979 and 1.95 < 2r at
        // n = 980. Both move the same in x and y, so the step-980 velocities are ball 2's
        // and ball 1's, swapped and scaled by 0.95.
        const auto s = testing::record(testing::spec(SceneId::TwoBalls, {"p2=2,20,297.95"}), 980);
        const ab::State& a = s[979];
        const ab::State& b = s[980];
        QVERIFY(std::abs(a.p(2, 1) - a.p(2, 0)) >= 2.0);
        QVERIFY(std::abs(b.p(2, 1) - b.p(2, 0)) < 2.0);
        QVERIFY(std::abs(b.v(2, 0) - 0.95 * -15.0) < 1e-12);
        QVERIFY(std::abs(b.v(2, 1) - 0.95 * 15.0) < 1e-12);
        QVERIFY(std::abs(b.v(0, 0) - 0.95 * 10.0) < 1e-12);
    }

    void propagationKeepsTheStoredContactState()
    {
        // Unlike Appendix B, propagation clamps a copy: the stored floor state stays below 0.
        const auto s = testing::record(testing::spec(SceneId::TwoBalls), 203);
        QVERIFY(s[202].p(1, 0) < 0.0);
        QVERIFY(s[203].p(1, 0) > 0.0);
    }

    void matchesTheListingStepForStep_data()
    {
        QTest::addColumn<QStringList>("set");
        QTest::newRow("report constants") << QStringList{};
        QTest::newRow("oblique meeting")
            << QStringList{"p1=100,30,100", "v1=12,2,8", "p2=160,30,140", "v2=-12,2,-8", "r=3"};
        QTest::newRow("low event limit") << QStringList{"max_events=12", "e=0.5"};
        QTest::newRow("overlapping start") << QStringList{"p1=50,10,50", "p2=50.5,10,50", "v1=1,0,0", "v2=-1,0,0"};
    }

    void matchesTheListingStepForStep()
    {
        QFETCH(QStringList, set);
        auto spec = testing::spec(SceneId::TwoBalls);
        for (const QString& a : set)
            spec.params.parseAssignment(a.toStdString());
        const auto& P = spec.params;
        auto v3 = [](const Eigen::Vector3d& v) { return listing::V3{v.x(), v.y(), v.z()}; };
        const int steps = 6000;
        const auto ref = listing::appendixC(-P.real("g"), P.real("k"), P.real("e"), P.real("r"), P.real("box"),
                                            v3(P.vector("p1")), v3(P.vector("v1")), v3(P.vector("p2")),
                                            v3(P.vector("v2")), static_cast<int>(P.integer("max_events")), steps);
        const auto s = testing::record(spec, steps);
        for (std::size_t i = 0; i < s.size(); ++i)
            for (int a = 0; a < 3; ++a) {
                const double tol = 1e-12 * std::max(1.0, std::abs(ref.b1.p[i][a]));
                if (std::abs(s[i].p(a, 0) - ref.b1.p[i][a]) > tol || std::abs(s[i].v(a, 0) - ref.b1.v[i][a]) > tol ||
                    std::abs(s[i].p(a, 1) - ref.b2.p[i][a]) > 1e-12 * std::max(1.0, std::abs(ref.b2.p[i][a])) ||
                    std::abs(s[i].v(a, 1) - ref.b2.v[i][a]) > 1e-12 * std::max(1.0, std::abs(ref.b2.v[i][a])))
                    QFAIL(qPrintable(QString("state %1 axis %2 differs from the listing").arg(i).arg(a)));
            }
    }

    void countLimitZeroesVelocitiesButPositionsGoOn()
    {
        // With max_events = 0 the first floor or wall contact stops both balls' velocities;
        // positions then move by -g dt^2 per step as the listing recomputes them.
        auto spec = testing::spec(SceneId::TwoBalls, {"max_events=0", "p1=10,0,10", "p2=200,50,200"});
        const auto s = testing::record(spec, 3);
        QVERIFY(s[0].v.isZero(0.0));
        QVERIFY(s[1].v.isZero(0.0));
        QVERIFY(std::abs((s[2].p(1, 1) - s[1].p(1, 1)) - -9.82 * 1e-4) < 1e-12);
    }
};

QTEST_GUILESS_MAIN(ReportTwoBalls)
#include "test_report_two_balls.moc"
