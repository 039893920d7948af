// SPDX-License-Identifier: MIT
// The window's figures: the same chart and data as `amazeballs-cli chart` for the same
// run (one recipe, two front ends); no time cursor in an export though the window shows
// one; with a comparison the difference chart is in the panel, and its lines are the run
// minus the comparison; the closed form stays beside a comparison, named once in the legend.
#include "support/cli_runner.h"

#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/sim/recording.h"
#include "ui/sim/run_engine.h"

#include <QChartView>
#include <QFile>
#include <QLineSeries>
#include <QTemporaryDir>
#include <QtTest>

using ab::SceneId;
using ab::ui::ChartKind;
using ab::ui::MainWindow;

namespace {

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Steps the run (and its comparison) `n` times and waits until both have caught up.
bool stepBoth(MainWindow& w, long long n)
{
    ab::ui::RunController& c = w.controller();
    const long long target = c.status().steps + n;
    for (long long i = 0; i < n; ++i)
        c.stepOnce();
    return QTest::qWaitFor(
        [&] {
            c.poll();
            return c.status().steps == target &&
                   (!c.comparing() ||
                    c.comparisonStatus().t + c.comparisonEngine()->simulation().dt() > c.status().t + 1e-9);
        },
        60000);
}

bool compareWith(MainWindow& w, const std::optional<ab::RunVariant>& v)
{
    ab::ui::RunOptions o = w.options();
    o.compare = v;
    return w.applyOptions(o);
}

ab::ui::MotionTrack trackOf(const ab::ui::RunEngine& e)
{
    ab::ui::MotionTrack t;
    e.read([&](const ab::ui::Recording& rec, const ab::ui::Frame&) { t = rec.track(); });
    return t;
}

} // namespace

class UiFigureWindow : public QObject {
    Q_OBJECT

private slots:
    void theWindowAndTheCommandLineDrawTheSameChartAndData()
    {
        // Stage 2's velocity chart at report-column, the whole planned run (6000 steps).
        MainWindow w;
        w.show();
        w.showScene(SceneId::Box3d);
        const long long steps = w.controller().plannedSteps();
        QCOMPARE(steps, 6000LL);
        QVERIFY(stepBoth(w, steps));
        QTemporaryDir dir;
        ab::ui::ChartExportChoice how;
        how.options.size = ab::ui::FigureSize::reportColumn();
        w.exportChartTo(ChartKind::Velocity, dir.filePath("window.svg"), how);
        w.exportDataTo(dir.filePath("window.csv"));
        const testing::CliResult r =
            testing::cli({"chart", "box3d", "--chart", "velocity", "--size", "report-column", "--out",
                          dir.filePath("cli.svg").toStdString(), "--data", dir.filePath("cli.csv").toStdString()});
        QCOMPARE(r.status, 0);
        const QByteArray windowSvg = readAll(dir.filePath("window.svg")), cliSvg = readAll(dir.filePath("cli.svg"));
        QVERIFY(windowSvg.size() > 10000);
        // The same series with the same points (every polyline), the same legend and axes.
        QCOMPARE(windowSvg.count("<polyline"), cliSvg.count("<polyline"));
        QVERIFY(windowSvg == cliSvg);
        const QByteArray windowCsv = readAll(dir.filePath("window.csv")), cliCsv = readAll(dir.filePath("cli.csv"));
        QCOMPARE(windowCsv.count('\n'), cliCsv.count('\n'));
        QVERIFY(windowCsv == cliCsv);
        QVERIFY(windowCsv.contains("vy_closed_form [m/s]"));
    }

    void anExportLeavesTheWindowsCursorOut()
    {
        MainWindow w;
        w.show();
        w.showScene(SceneId::Box3d);
        QVERIFY(stepBoth(w, 200));
        QVERIFY(!w.charts()->chart(ChartKind::Position)->cursorLine()->points().isEmpty()); // shown in the window
        QTemporaryDir dir;
        w.exportChartTo(ChartKind::Position, dir.filePath("plain.svg"));
        ab::ui::ChartExportChoice how;
        how.cursor = true;
        how.caption = true;
        w.exportChartTo(ChartKind::Position, dir.filePath("asked.svg"), how);
        const QByteArray plain = readAll(dir.filePath("plain.svg")), asked = readAll(dir.filePath("asked.svg"));
        QVERIFY(!plain.contains("#606066")); // the cursor's grey
        QVERIFY(asked.contains("#606066"));
        QVERIFY(!plain.contains("Stage 2 (box3d)"));
        QVERIFY(asked.contains("Stage 2 (box3d)"));
        QVERIFY(!w.charts()->chart(ChartKind::Position)->cursorLine()->points().isEmpty()); // still in the window
    }

    void aComparisonBringsTheDifferenceChartAndDistinctLegendEntries()
    {
        MainWindow w;
        w.show();
        w.showScene(SceneId::Box3d);
        QVERIFY(compareWith(
            w, ab::RunVariant{ab::ModelKind::Physical, ab::Integrator::Rk4, ab::ImpactMode::Located, std::nullopt}));
        QVERIFY(stepBoth(w, 300));
        w.controller().poll();
        QTRY_VERIFY(!w.charts()->chartView(ChartKind::Difference)->isHidden());
        ab::ui::MotionChart* velocity = w.charts()->chart(ChartKind::Velocity);
        QTRY_VERIFY(velocity->comparisonLine(1)->count() > 0);
        const auto& entries = velocity->legendEntries();
        // "report:", vx, vy, vz, the closed form (kept beside the comparison), the comparison.
        QCOMPARE(int(entries.size()), 6);
        QCOMPARE(entries.back().text, QString("physical rk4"));
        for (int a = 1; a <= 3; ++a) {
            QVERIFY(entries.back().pen.color() != entries[std::size_t(a)].pen.color());
            QVERIFY(entries.back().pen.style() != entries[std::size_t(a)].pen.style());
        }
        // The difference chart: the run minus the comparison at the run's sample times.
        ab::ui::MotionChart* difference = w.charts()->chart(ChartKind::Difference);
        QTRY_VERIFY(difference->line(1)->count() > 0);
        const ab::ui::MotionTrack run = trackOf(w.controller().engine());
        const ab::ui::MotionTrack other = trackOf(*w.controller().comparisonEngine());
        const QList<QPointF> points = difference->line(1)->points();
        int checked = 0;
        for (const QPointF& p : points) {
            const auto i = std::size_t(std::lround(p.x() / 0.01)); // both runs step 0.01 s
            if (i >= run.size() || i >= other.size())
                continue;
            QCOMPARE(run.t()[i], p.x());
            QCOMPARE(other.t()[i], p.x());
            QCOMPARE(p.y(), run.p(1)[i] - other.p(1)[i]);
            ++checked;
        }
        QVERIFY(checked > 100);
        // Without the comparison it gives way to the closed form; the panel keeps it.
        QVERIFY(compareWith(w, std::nullopt));
        QVERIFY(!w.charts()->chartView(ChartKind::Difference)->isHidden()); // box3d has a closed form
    }
};

QTEST_MAIN(UiFigureWindow)
#include "test_ui_figure_window.moc"
