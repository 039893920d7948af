// SPDX-License-Identifier: MIT
// The window's run on its worker thread: going back to a recorded step forks the run
// from that step's exact state (the forked run is, bit for bit, the run a fresh start
// takes), whether the state is kept or rebuilt from an earlier keyframe; the recording
// drops what came after and records the new course; and the window forks at the moment
// the time slider shows when Play or Step is pressed there.
#include "ui/main_window.h"
#include "ui/panels/transport_bar.h"
#include "ui/sim/run_engine.h"

#include "core/street/street_census.h"

#include "tests/support/sim_helpers.h"
#include "tests/support/window_helpers.h"

#include <QSlider>
#include <QStatusBar>
#include <QtTest>

using ab::SceneId;
using ab::ui::RunEngine;

namespace {

// Steps `engine` until it has taken `steps` steps (single steps: no pacing).
void stepTo(RunEngine& engine, long long steps)
{
    while (engine.status().steps < steps) {
        const long long before = engine.status().steps;
        engine.stepOnce();
        QTRY_VERIFY(engine.status().steps > before);
    }
}

// The tracked ball's recorded positions and velocities equal those of a fresh run of
// the same spec, exactly, at every recorded step up to `upTo`.
void expectTrackIsAFreshRun(const RunEngine& engine, const ab::RunSpec& spec, long long upTo)
{
    const std::vector<ab::State> fresh = testing::record(spec, upTo);
    engine.read([&](const ab::ui::Recording& rec, const ab::ui::Frame&) {
        const ab::ui::MotionTrack& track = rec.track();
        QCOMPARE(track.steps().back(), upTo);
        for (std::size_t i = 0; i < track.size(); ++i) {
            const auto& s = fresh[static_cast<std::size_t>(track.steps()[i])];
            // Exact equality: QCOMPARE's fuzzy compare of doubles would allow 1e-12.
            for (int a = 0; a < 3; ++a) {
                QVERIFY2(track.p(a)[i] == s.p(a, 0), qPrintable(QString("position at step %1").arg(track.steps()[i])));
                QVERIFY2(track.v(a)[i] == s.v(a, 0), qPrintable(QString("velocity at step %1").arg(track.steps()[i])));
            }
            QVERIFY(track.t()[i] == s.t);
        }
    });
}

} // namespace

class RunEngineFork : public QObject {
    Q_OBJECT

private slots:
    void forkedRunIsTheFreshRunBitForBit_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<int>("model");
        QTest::addColumn<qulonglong>("keyframeBudget");
        // A budget for two keyframes only: the fork rebuilds its state by re-taking up to
        // 64 steps from an earlier keyframe. The report's stage 4 carries per-ball bounce
        // counters and a seeded start, stage 1 its shared counter and the bounce limit.
        const auto tiny = qulonglong(2 * (6 * sizeof(double) + sizeof(int)) * 30);
        QTest::newRow("many-balls report, rebuilt") << int(SceneId::ManyBalls) << int(ab::ModelKind::Report) << tiny;
        QTest::newRow("bounce1d report, rebuilt")
            << int(SceneId::Bounce1d) << int(ab::ModelKind::Report) << qulonglong(2 * 52);
        QTest::newRow("box3d physical, every state kept")
            << int(SceneId::Box3d) << int(ab::ModelKind::Physical) << qulonglong(RunEngine::defaultKeyframeBudget);
    }

    void forkedRunIsTheFreshRunBitForBit()
    {
        QFETCH(int, scene);
        QFETCH(int, model);
        QFETCH(qulonglong, keyframeBudget);
        const auto id = static_cast<SceneId>(scene);
        ab::RunSpec spec = testing::spec(id,
                                         id == SceneId::ManyBalls ? std::initializer_list<std::string>{"n=30"}
                                                                  : std::initializer_list<std::string>{},
                                         static_cast<ab::ModelKind>(model));
        RunEngine engine(ab::makeSimulation(spec), 1000, 0, ab::ui::Recording::defaultFrameBudget,
                         std::size_t(keyframeBudget));
        stepTo(engine, 120);
        engine.resumeFrom(77);
        QTRY_COMPARE(engine.status().steps, 77LL);
        engine.read([](const ab::ui::Recording& rec, const ab::ui::Frame& current) {
            // What came after is dropped: the track ends at the state shown, step 77's.
            QCOMPARE(rec.track().steps().back(), 77LL);
            QVERIFY(rec.frames().back().step < 77);
            QCOMPARE(current.step, 77LL);
        });
        stepTo(engine, 90);
        // The track reaches the state shown, step 90's, final only after its step.
        expectTrackIsAFreshRun(engine, spec, 90);
        QVERIFY(!engine.status().finished);
    }

    void goingBackToTheStartRestartsTheSameRun()
    {
        const ab::RunSpec spec = testing::spec(SceneId::TwoBalls);
        RunEngine engine(ab::makeSimulation(spec), 1000, 1);
        stepTo(engine, 40);
        engine.resumeFrom(0);
        QTRY_COMPARE(engine.status().steps, 0LL);
        QCOMPARE(engine.status().t, 0.0);
        engine.read([](const ab::ui::Recording& rec, const ab::ui::Frame&) {
            QVERIFY(rec.frames().empty());                // no state final yet
            QCOMPARE(rec.track().size(), std::size_t(1)); // the start, shown
            QCOMPARE(rec.track().steps().back(), 0LL);
        });
        stepTo(engine, 41);
        engine.read([&](const ab::ui::Recording& rec, const ab::ui::Frame&) {
            const std::vector<ab::State> fresh = testing::record(spec, 41);
            QVERIFY(rec.track().p(2).back() == fresh.back().p(2, 1));
        });
    }

    void goingBackKeepsTheFindingsBeforeTheMomentShown()
    {
        // The report's stage 1 gains energy with every flight step (explicit Euler): a
        // warning from the first steps on. Going back to step 50 keeps it, at its own time,
        // and does not find it anew.
        const ab::RunSpec spec = testing::spec(SceneId::Bounce1d);
        RunEngine engine(ab::makeSimulation(spec), 1000, 0);
        stepTo(engine, 100);
        QCOMPARE(engine.status().health, ab::diagnostics::Health::Warning);
        const std::string line = engine.status().healthLine;
        QVERIFY(line.find("energy") != std::string::npos);
        engine.resumeFrom(50);
        QTRY_COMPARE(engine.status().steps, 50LL);
        QCOMPARE(engine.status().health, ab::diagnostics::Health::Warning);
        QCOMPARE(engine.status().healthLine, line);
        QVERIFY(!engine.status().pausedOnHealth);
    }

    void aRunWithoutHealthCheckingNeverPausesOnAFinding()
    {
        // Two balls at 10,000 m/s each way swap sides within one step: a failure that
        // pauses a checked run at once. The comparison's engine checks nothing: it plays
        // on to its end with its health left Ok.
        const ab::RunSpec spec = testing::spec(
            SceneId::TwoBalls, {"g=0", "p1=150,20,100", "p2=150,20,200", "v1=0,0,10000", "v2=0,0,-10000"});
        RunEngine checked(ab::makeSimulation(spec), 20, 0);
        checked.play(1e6);
        QTRY_VERIFY(checked.status().pausedOnHealth);
        QCOMPARE(checked.status().health, ab::diagnostics::Health::Failed);
        RunEngine unchecked(ab::makeSimulation(spec), 20, 0, ab::ui::Recording::defaultFrameBudget,
                            RunEngine::defaultKeyframeBudget, RunEngine::HealthChecking::Off);
        unchecked.play(1e6);
        QTRY_VERIFY(unchecked.status().finished);
        QCOMPARE(unchecked.status().steps, 20LL);
        QVERIFY(!unchecked.status().pausedOnHealth);
        QCOMPARE(unchecked.status().health, ab::diagnostics::Health::Ok);
    }

    void aFinishedRunGoesOnAfterGoingBack()
    {
        const ab::RunSpec spec = testing::spec(SceneId::Bounce1d);
        RunEngine engine(ab::makeSimulation(spec), 30, 0);
        stepTo(engine, 30);
        QTRY_VERIFY(engine.status().finished);
        engine.resumeFrom(10);
        QTRY_COMPARE(engine.status().steps, 10LL);
        QVERIFY(!engine.status().finished);
        engine.play(1e6);
        QTRY_VERIFY(engine.status().finished);
        expectTrackIsAFreshRun(engine, spec, 30);
    }

    void aStreetRunEndsAtTheStepItsLastBallLeaves()
    {
        // Twenty balls down one short block (10 m at 30 deg): all have passed the open foot
        // within about 2.5 s of the 10 s planned. The run ends at the first step whose state
        // has every centre beyond the foot (found here from a fresh run, ball by ball), not
        // 7 s of an empty street later; going back before it plays to the same end.
        const ab::RunSpec spec =
            testing::spec(SceneId::Street, {"n=20", "blocks=1", "block_length=10", "crossing=2", "slope=30"},
                          ab::ModelKind::Physical);
        constexpr long long planned = 600;
        const std::vector<ab::State> fresh = testing::record(spec, planned);
        const auto street = ab::street::Layout::fromParams(spec.params);
        long long emptied = -1;
        for (std::size_t k = 0; k < fresh.size() && emptied < 0; ++k) {
            bool all = true;
            for (int i = 0; i < fresh[k].size(); ++i)
                all = all && ab::street::hasLeft(street, fresh[k].p(0, i));
            emptied = all ? static_cast<long long>(k) : -1;
        }
        QVERIFY2(emptied > 60 && emptied < planned / 2, qPrintable(QString::number(emptied)));
        RunEngine engine(ab::makeSimulation(spec), planned, 0);
        QVERIFY(!engine.status().emptiedAt);
        engine.play(1e6);
        QTRY_VERIFY_WITH_TIMEOUT(engine.status().finished, 30000);
        QCOMPARE(engine.status().steps, emptied);
        QVERIFY(engine.status().emptiedAt && *engine.status().emptiedAt == fresh[std::size_t(emptied)].t);
        QVERIFY(engine.status().warning.empty());
        engine.resumeFrom(emptied - 5);
        QTRY_COMPARE(engine.status().steps, emptied - 5);
        QVERIFY(!engine.status().finished && !engine.status().emptiedAt);
        engine.play(1e6);
        QTRY_VERIFY(engine.status().finished);
        QCOMPARE(engine.status().steps, emptied);
        QVERIFY(engine.status().emptiedAt && *engine.status().emptiedAt == fresh[std::size_t(emptied)].t);
        expectTrackIsAFreshRun(engine, spec, emptied); // the empty street's state is recorded as the last
    }

    void theWindowsStreetOnThreeThreadsIsTheOneThreadRunBitForBit()
    {
        // 3000 balls: three flight chunks and two pair-search chunks, so that the three
        // threads share the flight and the pair search (core/street's tests share the
        // contact passes too, with more balls). 40 steps take the hopper's balls into contact.
        QVERIFY(ab::ui::RunController::defaultEngineThreads() >= 1);
        QVERIFY(ab::ui::RunController::defaultEngineThreads() <= 8);
        ab::ui::RunController::setEngineThreads(3);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ab::ui::RunController::setEngineThreads(0));
        QCOMPARE(ab::ui::RunController::engineThreads(), 3); // a refused count changes nothing
        ab::RunSpec spec = testing::spec(SceneId::Street, {"n=3000"}, ab::ModelKind::Physical);
        ab::ui::RunController controller;
        controller.setRun(spec, 1000);
        QCOMPARE(controller.spec().threads, 3);
        QCOMPARE(controller.engine().simulation().spec().threads, 3);
        const ab::ui::RunEngine& engine = controller.engine();
        constexpr long long steps = 40;
        while (engine.status().steps < steps) { // the window's Step button, once a step
            const long long before = engine.status().steps;
            controller.stepOnce();
            QTRY_VERIFY(engine.status().steps > before);
        }
        QCOMPARE(spec.threads, 1);
        expectTrackIsAFreshRun(engine, spec, steps);
        const ab::State fresh = testing::record(spec, steps).back();
        QVERIFY(fresh.impacts > 0); // the balls have met by then: the threads share contact passes
        engine.read([&](const ab::ui::Recording&, const ab::ui::Frame& current) {
            QCOMPARE(current.step, steps);
            long long differing = 0;
            for (int i = 0; i < fresh.size(); ++i)
                for (int a = 0; a < 3; ++a)
                    differing += current.p[std::size_t(3 * i + a)] != float(fresh.p(a, i));
            QCOMPARE(differing, 0LL);
        });
        ab::ui::RunController::setEngineThreads(1);
    }

    void pressingStepWhileLookingBackForksAtTheMomentShown()
    {
        ab::ui::MainWindow w;
        w.show();
        w.showScene(SceneId::Bounce1d);
        const std::optional<double> shown = testing::stepThenLookBack(w, 100, 3, 10); // stage 1 counts steps: t = 30
        QVERIFY(shown.has_value());
        const double looked = *shown;
        QTest::keyClick(&w, Qt::Key_Right);
        // The frame shown is the last one at or before the slider's time: step floor(t).
        const auto expected = static_cast<long long>(std::floor(looked)) + 1;
        QTRY_COMPARE(w.controller().status().steps, expected);
        QVERIFY(!w.transport()->viewTime().has_value()); // live again, at the fork
        QVERIFY(w.statusBar()->currentMessage().contains("Went back"));
        QVERIFY(std::abs(w.controller().status().t - double(expected)) < 1e-12);
    }
};

QTEST_MAIN(RunEngineFork)
#include "test_run_engine.moc"
