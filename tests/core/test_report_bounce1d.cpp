// SPDX-License-Identifier: MIT
// Stage 1, the report's rule (Appendix A): hand-worked steps and the listing, step for step.
#include "support/report_listings.h"
#include "support/sim_helpers.h"

#include <QtTest>

using ab::SceneId;

class ReportBounce1d : public QObject {
    Q_OBJECT

private slots:
    void firstStepsFallWithTheOldVelocity()
    {
        // p1 = p0 + v0 dt = 2000 (v0 = 0), v1 = -0.0982; p2 = 2000 - 0.0982, v2 = -0.1964.
        const auto s = testing::record(testing::spec(SceneId::Bounce1d), 2);
        QCOMPARE(s.size(), std::size_t(3));
        QCOMPARE(s[0].p(1, 0), 2000.0);
        QCOMPARE(s[1].p(1, 0), 2000.0);
        QVERIFY(std::abs(s[1].v(1, 0) - -0.0982) < 1e-15);
        QVERIFY(std::abs(s[2].p(1, 0) - 1999.9018) < 1e-12);
        QVERIFY(std::abs(s[2].v(1, 0) - -0.1964) < 1e-15);
    }

    void firstFloorContactIsStep203()
    {
        // Free fall gives p_n = 2000 - 0.0982 n(n-1)/2: 1993.56 fallen at n = 202,
        // 2013.39 at n = 203, so state 203 is the first with p <= 0. The bounce step sets
        // that state's position to 0 and leaves with v = 0.6 * 203 * 0.0982, no gravity.
        const auto s = testing::record(testing::spec(SceneId::Bounce1d), 204);
        QVERIFY(s[202].p(1, 0) > 0.0);
        QCOMPARE(s[203].p(1, 0), 0.0);
        QVERIFY(std::abs(s[203].v(1, 0) - -203 * 0.0982) < 1e-12);
        QCOMPARE(s[203].count, 0LL);
        QVERIFY(std::abs(s[204].v(1, 0) - 0.6 * 203 * 0.0982) < 1e-12);
        QVERIFY(std::abs(s[204].p(1, 0) - 0.6 * 203 * 0.0982) < 1e-12);
        QCOMPARE(s[204].count, 1LL);
    }

    void comesToRestAtTheEleventhContact()
    {
        // Contacts at states 203, 450, 603, ..., 886, 898 (worked through Appendix A);
        // the 11th makes count > 10, and state 898 and all later ones are zero.
        const auto s = testing::record(testing::spec(SceneId::Bounce1d), 2000);
        QCOMPARE(s.size(), std::size_t(2001));
        QVERIFY(s[897].p(1, 0) != 0.0 || s[897].v(1, 0) != 0.0);
        for (std::size_t i = 898; i < s.size(); ++i) {
            QCOMPARE(s[i].p(1, 0), 0.0);
            QCOMPARE(s[i].v(1, 0), 0.0);
        }
        QVERIFY(s[898].halted);
        QVERIFY(!s[897].halted);
    }

    void matchesTheListingStepForStep_data()
    {
        QTest::addColumn<double>("g");
        QTest::addColumn<double>("k");
        QTest::addColumn<double>("h0");
        QTest::addColumn<double>("v0");
        QTest::addColumn<int>("maxBounces");
        QTest::addColumn<int>("steps");
        QTest::newRow("report constants") << 0.0982 << 0.6 << 2000.0 << 0.0 << 10 << 2000;
        QTest::newRow("bouncier k 0.85") << 0.0982 << 0.85 << 2000.0 << 0.0 << 10 << 2000;
        QTest::newRow("lower start, thrown up") << 0.0982 << 0.6 << 500.0 << 3.5 << 10 << 2000;
        QTest::newRow("stronger gravity") << 0.5 << 0.6 << 2000.0 << 0.0 << 10 << 1500;
        QTest::newRow("three-bounce limit") << 0.0982 << 0.7 << 1200.0 << 0.0 << 3 << 3000;
        QTest::newRow("starts on the floor") << 0.0982 << 0.6 << 0.0 << 0.0 << 10 << 50;
        QTest::newRow("perfectly elastic") << 0.0982 << 1.0 << 100.0 << 0.0 << 1000 << 4000;
    }

    void matchesTheListingStepForStep()
    {
        QFETCH(double, g);
        QFETCH(double, k);
        QFETCH(double, h0);
        QFETCH(double, v0);
        QFETCH(int, maxBounces);
        QFETCH(int, steps);
        const auto ref = listing::appendixA(-g, k, h0, v0, maxBounces, steps);
        auto spec = testing::spec(SceneId::Bounce1d, {"g=" + std::to_string(g), "k=" + std::to_string(k),
                                                      "h0=" + std::to_string(h0), "v0=" + std::to_string(v0),
                                                      "max_bounces=" + std::to_string(maxBounces)});
        const auto s = testing::record(spec, steps);
        QCOMPARE(s.size(), ref.p.size());
        for (std::size_t i = 0; i < s.size(); ++i) {
            const double scale = std::max(1.0, h0);
            if (std::abs(s[i].p(1, 0) - ref.p[i]) > 1e-12 * scale || std::abs(s[i].v(1, 0) - ref.v[i]) > 1e-12 * scale)
                QFAIL(qPrintable(QString("state %1: (%2, %3) but the listing gives (%4, %5)")
                                     .arg(i)
                                     .arg(s[i].p(1, 0), 0, 'g', 17)
                                     .arg(s[i].v(1, 0), 0, 'g', 17)
                                     .arg(ref.p[i], 0, 'g', 17)
                                     .arg(ref.v[i], 0, 'g', 17)));
            QCOMPARE(s[i].p(0, 0), 0.0);
            QCOMPARE(s[i].p(2, 0), 0.0);
        }
    }
};

QTEST_GUILESS_MAIN(ReportBounce1d)
#include "test_report_bounce1d.moc"
