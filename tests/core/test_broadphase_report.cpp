// SPDX-License-Identifier: MIT
// The report's stage 4 gives the same frames, to the last bit, whichever broadphase finds
// each ball's partner: its rule (the lowest-index ball within c r, again and again, with
// one repeat counter per frame) does not depend on how the partner is found.
#include "support/sim_helpers.h"

#include "core/physical/many_balls_physical.h"

#include <QtTest>

using ab::Broadphase;
using ab::SceneId;

namespace {

std::vector<ab::State> recordWith(ab::RunSpec spec, Broadphase b, long long steps)
{
    spec.broadphase = b;
    return testing::record(spec, steps);
}

long long contacts(const std::vector<ab::State>& states)
{
    long long sum = 0;
    for (const ab::State& s : states)
        for (int b : s.bounces)
            sum += b;
    return sum;
}

} // namespace

class ReportBroadphase : public QObject {
    Q_OBJECT

private slots:
    void gridAndAllPairsGiveIdenticalFrames_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<int>("frames");
        QTest::newRow("the report's 150 balls") << QStringList{} << 1000;
        QTest::newRow("seed 7") << QStringList{"seed=7"} << 600;
        // 400 balls in a 24-wide box: crowded, so the shared repeat counter runs out.
        QTest::newRow("crowded box") << QStringList{"n=400", "box=24", "seed=3"} << 300;
        QTest::newRow("wide contact") << QStringList{"n=300", "box=30", "contact_factor=4", "seed=5"} << 200;
        QTest::newRow("big balls") << QStringList{"n=200", "r=3", "box=60", "seed=11"} << 300;
    }
    void gridAndAllPairsGiveIdenticalFrames()
    {
        QFETCH(QStringList, assignments);
        QFETCH(int, frames);
        ab::RunSpec spec(SceneId::ManyBalls);
        for (const QString& a : assignments)
            spec.params.parseAssignment(a.toStdString());
        const auto grid = recordWith(spec, Broadphase::Grid, frames);
        const auto all = recordWith(spec, Broadphase::AllPairs, frames);
        QCOMPARE(grid.size(), all.size());
        for (std::size_t k = 0; k < grid.size(); ++k) {
            QVERIFY2(grid[k].p == all[k].p && grid[k].v == all[k].v && grid[k].bounces == all[k].bounces,
                     qPrintable(QString("frame %1 differs").arg(k)));
        }
        QVERIFY(contacts(all) > 0); // the run had collisions to agree on
    }

    void benchmarkWorkloadGivesIdenticalFrames()
    {
        // The benchmark's start (a jittered lattice filling the box) in the report's units.
        const ab::RunSpec spec = ab::physical::benchmarkSpec(1500, ab::ModelKind::Report, Broadphase::Grid, 1);
        const auto grid = recordWith(spec, Broadphase::Grid, 40);
        const auto all = recordWith(spec, Broadphase::AllPairs, 40);
        QVERIFY(grid.back().p == all.back().p && grid.back().v == all.back().v);
        QVERIFY(grid.back().bounces == all.back().bounces);
        QVERIFY(contacts(all) > 0);
    }
};

QTEST_GUILESS_MAIN(ReportBroadphase)
#include "test_broadphase_report.moc"
