// SPDX-License-Identifier: MIT
// The window's handle on a run: builds it from a RunSpec (keeping the previous one when
// the spec is refused), plays it at a speed relative to real time, steps, resets, follows
// the selected ball, and polls the worker each frame, signalling only when something
// changed. 1x speed is real time in the scene's own units (see realTimeRate()).
// A comparison run (the same scene, constants and start computed another way: RunVariant)
// runs on a second engine that follows the main run's simulated time, so both always
// show the same moment; play, pause, step, reset, speed, going back and the followed
// ball drive both.
#pragma once

#include "run_engine.h"

#include <QObject>
#include <QTimer>

#include <future>
#include <memory>
#include <optional>
#include <vector>

namespace ab::ui {

class RunController : public QObject {
    Q_OBJECT
public:
    explicit RunController(QObject* parent = nullptr);
    ~RunController() override;

    // Validates and builds the run; throws InputError (and keeps the current run) when
    // the core refuses the spec. The new run starts paused at its start state.
    // With `compare`, the comparison run is built too; when the core refuses it the
    // InputError names the comparison ("compare with report: ...") and nothing changes.
    void setRun(const RunSpec& spec, long long steps, const std::optional<RunVariant>& compare = std::nullopt);
    // Takes `other`'s run as it stands (its recording, time, comparison, speed and the
    // followed ball; playing on if it played): a window rebuilt in another language goes
    // on with the same run. `other` is left without a run. Emits runReplaced.
    void takeOver(RunController& other);
    bool hasRun() const { return engine_ != nullptr; }
    const RunSpec& spec() const;
    bool comparing() const { return compare_ != nullptr; }
    const std::optional<RunVariant>& comparison() const { return variant_; }
    const RunEngine* comparisonEngine() const { return compare_.get(); }
    EngineStatus comparisonStatus() const { return compareStatus_; }
    const SceneLayout& layout() const { return layout_; }
    long long plannedSteps() const { return steps_; }
    double plannedEnd() const;
    const RunEngine& engine() const { return *engine_; }
    EngineStatus status() const { return status_; }

    bool playing() const { return status_.playing; }
    double speed() const { return speed_; }
    int selectedBall() const { return selected_; }

    // Simulated time per real second at 1x: stages 2-3 count seconds; stage 1 counts
    // steps of 0.1 s (report 2.2.1: g = 9.82 read with the step as 0.1 s); stage 4 counts
    // frames of a 60 Hz display, as the report's WebGL program ran.
    static double realTimeRate(const SceneInfo& scene);

    // Threads that step the physical model's many balls (stages 4 and 5) in every run the
    // window builds from now on, 1 to kMaxThreads: the engines give the same balls for any count,
    // so this changes the pace only. By default one fewer than the processor's cores (the
    // window's own thread draws), at least 1 and at most 8 (more cores than the grid's
    // slabs of a few thousand balls each stay idle at the sizes the window plays).
    static int engineThreads();
    static void setEngineThreads(int threads);
    static int defaultEngineThreads();

public slots:
    void play();
    void pause();
    void togglePlay();
    void stepOnce();
    void reset();
    void setSpeed(double factor);
    void selectBall(int ball);
    // Forks the run back to recorded step `step`, paused there (RunEngine::resumeFrom).
    void resumeFrom(long long step);
    // Polls the worker now (the frame timer does it every 16 ms).
    void poll();

signals:
    void runReplaced(); // a new run or a reset: the view and charts start over
    void advanced();    // the run's snapshot changed
    void playingChanged(bool playing);
    void selectionChanged(int ball);
    void speedChanged(double factor);

private:
    void startEngine(std::unique_ptr<Simulation> sim, std::unique_ptr<Simulation> compare);
    // Keeps the comparison at the main run's time: forks it back when it is ahead (the
    // main run went back), then has it follow.
    void keepComparisonInStep();
    // Ends the current engine off the GUI thread: its worker may be inside a long step.
    void retireEngine(std::unique_ptr<RunEngine>& engine);

    std::unique_ptr<RunSpec> spec_;
    long long steps_ = 0;
    SceneLayout layout_;
    std::unique_ptr<RunEngine> engine_;
    std::optional<RunVariant> variant_;
    std::unique_ptr<RunSpec> compareSpec_;
    std::unique_ptr<RunEngine> compare_;
    EngineStatus compareStatus_;
    std::optional<long long> compareForkTo_;
    std::vector<std::future<void>> retiring_; // joined at the latest in the destructor
    EngineStatus status_;
    double speed_ = 1.0;
    int selected_ = 0;
    QTimer frameTimer_;
};

} // namespace ab::ui
