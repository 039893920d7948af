// SPDX-License-Identifier: MIT
// Compare: a second run of the same scene, constants and start, computed by another model
// or integrator, beside the first. On the offscreen platform (no 3D view) the comparison
// still runs and is charted: both runs start from one state, stay at one simulated time,
// the comparison's record is exactly a fresh run of its spec, its lines are overlaid and
// exported, switching it off removes them, and a comparison the core refuses changes
// nothing.
#include "ui/charts/motion_chart.h"
#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/panels/run_options_panel.h"
#include "ui/presets/preset_actions.h"

#include "core/io/preset.h"
#include "tests/support/sim_helpers.h"

#include <QComboBox>
#include <QFile>
#include <QLineSeries>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

using ab::SceneId;
using ab::ui::MainWindow;

namespace {

const ab::RunVariant physicalSymplectic{ab::ModelKind::Physical, ab::Integrator::SymplecticEuler,
                                        ab::ImpactMode::Located, std::nullopt};

bool compareWith(MainWindow& w, const std::optional<ab::RunVariant>& v)
{
    ab::ui::RunOptions o = w.options();
    o.compare = v;
    return w.applyOptions(o);
}

// Steps the main run `n` times and waits until the comparison has caught up with it: its
// next step would pass the main run's time.
bool stepBoth(MainWindow& w, long long n)
{
    ab::ui::RunController& c = w.controller();
    const long long target = c.status().steps + n;
    for (long long i = 0; i < n; ++i)
        c.stepOnce();
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 20000) {
        c.poll();
        if (c.status().steps == target &&
            (!c.comparing() || c.comparisonStatus().t + c.comparisonEngine()->simulation().dt() > c.status().t + 1e-9))
            return true;
        QTest::qWait(5);
    }
    return false;
}

ab::ui::MotionTrack trackOf(const ab::ui::RunEngine& e)
{
    ab::ui::MotionTrack copy;
    e.read([&](const ab::ui::Recording& rec, const ab::ui::Frame&) { copy = rec.track(); });
    return copy;
}

ab::ui::Frame currentOf(const ab::ui::RunEngine& e)
{
    ab::ui::Frame copy;
    e.read([&](const ab::ui::Recording&, const ab::ui::Frame& f) { copy = f; });
    return copy;
}

} // namespace

class UiCompare : public QObject {
    Q_OBJECT

private slots:
    void theCompareListComesFromTheCore()
    {
        MainWindow w;
        QComboBox* box = w.runOptions()->compareBox();
        // Off, then the report (one scheme per stage) and the physical model with each integrator.
        int expected = 1;
        for (ab::ModelKind m : ab::allModels())
            expected += m == ab::ModelKind::Report ? 1 : int(ab::allIntegrators().size());
        QCOMPARE(box->count(), expected);
        QCOMPARE(box->currentIndex(), 0);
        QVERIFY(!w.controller().comparing());
        for (ab::Integrator i : ab::allIntegrators())
            QVERIFY(w.runOptions()->compareIndex(ab::RunVariant{ab::ModelKind::Physical, i, {}, {}}) > 0);
        QVERIFY(box->toolTip().contains("ignores")); // says which constants each model reads
    }

    void choosingInTheListStartsTheComparison()
    {
        MainWindow w;
        QComboBox* box = w.runOptions()->compareBox();
        box->setCurrentIndex(w.runOptions()->compareIndex(physicalSymplectic));
        QVERIFY(w.controller().comparing());
        QVERIFY(w.controller().comparison() == physicalSymplectic);
        QCOMPARE(w.controller().comparisonEngine()->simulation().spec().model, ab::ModelKind::Physical);
        box->setCurrentIndex(0);
        QVERIFY(!w.controller().comparing());
    }

    void theComparisonStartsFromTheMainRunsStartState()
    {
        MainWindow w;
        w.showScene(SceneId::Box3d);
        QVERIFY(compareWith(w, physicalSymplectic));
        const ab::ui::Frame a = currentOf(w.controller().engine());
        const ab::ui::Frame b = currentOf(*w.controller().comparisonEngine());
        QCOMPARE(b.t, a.t);
        QVERIFY(a.p == b.p);
        QVERIFY(a.v == b.v);
        QCOMPARE(b.step, 0LL);
    }

    void afterNStepsBothRunsAreAtTheSameSimulatedTime()
    {
        // Stage 1 counts time in steps in both models (dt = 1, g in length per step^2).
        MainWindow w;
        QVERIFY(compareWith(w, physicalSymplectic));
        QCOMPARE(w.controller().comparisonEngine()->simulation().dt(), w.controller().engine().simulation().dt());
        QVERIFY(stepBoth(w, 37));
        QCOMPARE(w.controller().status().t, 37.0);
        QCOMPARE(w.controller().comparisonStatus().t, 37.0); // exactly: the same steps added to the same start
        QCOMPARE(w.controller().comparisonStatus().steps, 37LL);
    }

    void aComparisonWithAFinerStepIsSteppedToTheMainRunsTime()
    {
        MainWindow w;
        w.showScene(SceneId::Box3d); // dt = 0.01 s
        ab::RunVariant finer = physicalSymplectic;
        finer.dt = 0.0025; // four comparison steps a main step
        QVERIFY(compareWith(w, finer));
        QVERIFY(stepBoth(w, 10));
        // 40 steps of 0.0025 s reach 0.1 s to rounding: 1e-12 s is far below one step.
        QCOMPARE(w.controller().comparisonStatus().steps, 40LL);
        QVERIFY(std::abs(w.controller().comparisonStatus().t - w.controller().status().t) < 1e-12);
    }

    void theComparisonsRecordEqualsAFreshRunOfItsSpec()
    {
        MainWindow w;
        QVERIFY(compareWith(w, physicalSymplectic));
        const long long n = 300; // past the first impact, at t = 201.8 steps
        QVERIFY(stepBoth(w, n));
        const ab::RunSpec spec = ab::variantOf(w.controller().spec(), physicalSymplectic);
        const std::vector<ab::State> fresh = testing::record(spec, n);
        const ab::ui::MotionTrack track = trackOf(*w.controller().comparisonEngine());
        QCOMPARE(track.size(), std::size_t(n + 1)); // the start and each step's state, the last the one shown
        for (std::size_t i = 0; i < track.size(); ++i) {
            QCOMPARE(track.t()[i], fresh[i].t);
            QCOMPARE(track.p(1)[i], fresh[i].p(1, 0)); // bit for bit: the same rules from the same state
            QCOMPARE(track.v(1)[i], fresh[i].v(1, 0));
        }
    }

    void chartsOverlayTheComparisonAndTurningItOffRemovesIt()
    {
        MainWindow w;
        w.show();
        QVERIFY(compareWith(w, physicalSymplectic));
        QVERIFY(stepBoth(w, 50));
        w.controller().pause(); // panels redraw at once when not playing
        ab::ui::MotionChart* energy = w.charts()->chart(ab::ui::ChartKind::Energy);
        QTRY_VERIFY(energy->comparisonLine(2)->count() > 0);
        QVERIFY(energy->hasComparison());
        QVERIFY(energy->comparisonLine(2)->isVisible());
        QVERIFY(energy->comparisonLine(2)->name().contains("physical symplectic-euler"));
        QVERIFY(energy->line(2)->name().contains("report"));
        ab::ui::MotionChart* position = w.charts()->chart(ab::ui::ChartKind::Position);
        QTRY_VERIFY(position->comparisonLine(1)->count() > 0);
        QVERIFY(position->comparisonLine(1)->pen().style() != position->line(1)->pen().style());

        QVERIFY(compareWith(w, std::nullopt));
        QVERIFY(!w.controller().comparing());
        for (ab::ui::ChartKind kind : ab::ui::allChartKinds()) {
            ab::ui::MotionChart* c = w.charts()->chart(kind);
            QVERIFY(!c->hasComparison());
            for (int a = 0; a < 4; ++a) {
                QCOMPARE(c->comparisonLine(a)->count(), 0);
                QVERIFY(!c->comparisonLine(a)->isVisible());
                QVERIFY(!c->line(a)->name().contains("report"));
            }
        }
    }

    void aComparisonTheCoreRefusesChangesNothing()
    {
        MainWindow w;
        w.showScene(SceneId::ManyBalls);
        ab::ui::RunOptions o = w.options();
        o.model = ab::ModelKind::Physical;
        o.dt = 0.5;
        QVERIFY(w.applyOptions(o));
        const ab::RunSpec before = w.controller().spec();
        // The report's stage 4 advances one frame per step: it refuses the main run's 0.5.
        QVERIFY(!compareWith(w, ab::RunVariant{ab::ModelKind::Report, {}, {}, {}}));
        QVERIFY(w.runOptions()->errorText().contains("compare with report"));
        QVERIFY(w.runOptions()->errorText().contains("one frame"));
        QVERIFY(w.statusBar()->currentMessage().contains("compare with report"));
        QVERIFY(!w.controller().comparing());
        QVERIFY(!w.options().compare);
        QCOMPARE(w.controller().spec().model, before.model);
        QCOMPARE(w.controller().spec().dt, before.dt);
        QCOMPARE(w.runOptions()->compareBox()->currentIndex(), 0); // the list shows what runs
    }

    void resetAndGoingBackKeepTheComparisonAtTheMainRunsTime()
    {
        MainWindow w;
        QVERIFY(compareWith(w, physicalSymplectic));
        QVERIFY(stepBoth(w, 40));
        w.controller().resumeFrom(15);
        QTRY_COMPARE(w.controller().status().steps, 15LL);
        QTRY_COMPARE(w.controller().comparisonStatus().t, w.controller().status().t);
        QCOMPARE(w.controller().comparisonStatus().steps, 15LL);
        w.controller().reset();
        QCOMPARE(w.controller().status().steps, 0LL);
        QVERIFY(w.controller().comparing());
        QCOMPARE(w.controller().comparisonStatus().steps, 0LL);
    }

    void theComparisonFollowsTheSelectedBall()
    {
        MainWindow w;
        w.showScene(SceneId::TwoBalls);
        QVERIFY(compareWith(w, physicalSymplectic));
        QVERIFY(stepBoth(w, 5));
        w.controller().selectBall(1);
        w.controller().poll();
        const ab::ui::MotionTrack main = trackOf(w.controller().engine());
        const ab::ui::MotionTrack other = trackOf(*w.controller().comparisonEngine());
        QVERIFY(!other.empty());
        // Both start at ball 2's start position (p2 = (2, 20, 298) m): the tracks show ball 2.
        QCOMPARE(other.p(2).front(), main.p(2).front());
        QCOMPARE(other.p(2).front(), 298.0);
    }

    void csvExportHasTheComparisonsColumnsAndTheChartsItsLines()
    {
        MainWindow w;
        w.show();
        QVERIFY(compareWith(w, physicalSymplectic));
        QVERIFY(stepBoth(w, 30));
        QTemporaryDir dir;
        const QString csv = dir.filePath("c.csv");
        w.exportDataTo(csv);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        QVERIFY(lines.front().startsWith("# Amazeballs "));
        QVERIFY(lines
                    .filter(QRegularExpression("^# comparison \\(compare_ columns\\): model physical, integrator "
                                               "symplectic-euler"))
                    .size() == 1);
        while (lines.front().startsWith('#')) // the settings
            lines.removeFirst();
        const QStringList header = lines.front().split(',');
        QVERIFY(header.contains("compare_t [step]"));
        const int y = int(header.indexOf("compare_y [unit]"));
        QVERIFY(y > 0);
        QVERIFY(header.contains("compare_energy_total [unit^2/step^2]"));
        QCOMPARE(lines.size(), 32); // the header, the start and the 30 steps' states
        const ab::ui::MotionTrack other = trackOf(*w.controller().comparisonEngine());
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList cells = lines[i].split(',');
            QCOMPARE(cells.size(), header.size());
            QCOMPARE(cells[header.indexOf("compare_t [step]")].toDouble(), cells[0].toDouble()); // the same moment
            QCOMPARE(cells[y].toDouble(), other.p(1)[std::size_t(i - 1)]);                       // shortest round trip
        }
        const QString svg = dir.filePath("e.svg");
        w.exportChartTo(ab::ui::ChartKind::Energy, svg);
        QFile s(svg);
        QVERIFY(s.open(QIODevice::ReadOnly));
        QVERIFY(s.readAll().contains("physical symplectic-euler")); // the overlay's legend is in the export
    }

    void theBuiltinComparePresetRunsReportBesidePhysical()
    {
        MainWindow w;
        ab::ui::applyPresetToWindow(w, ab::loadPreset("bounce1d-compare-report-physical"));
        QCOMPARE(w.controller().spec().model, ab::ModelKind::Report);
        QVERIFY(w.controller().comparing());
        QVERIFY(*w.controller().comparison() == physicalSymplectic);
        QCOMPARE(w.runOptions()->compareBox()->currentIndex(), w.runOptions()->compareIndex(physicalSymplectic));
        // With the comparison comes the chart of report minus physical.
        QVERIFY(w.charts()->chartShown(ab::ui::ChartKind::Difference));
        const ab::Preset captured = ab::ui::capturePreset(w, "x", "y");
        QVERIFY(captured.view.compare == physicalSymplectic);
        ab::ui::applyPresetToWindow(w, ab::loadPreset("bounce1d-report")); // an older preset: no comparison
        QVERIFY(!w.controller().comparing());
    }
};

QTEST_MAIN(UiCompare)
#include "test_ui_compare.moc"
