// SPDX-License-Identifier: MIT
// Runs one Simulation on a worker thread, so the window never waits for a step (a step of
// 10,000 balls takes longer than a frame). The window reads a snapshot each frame under
// a short lock; commands (play, pause, one step, follow a ball) take effect between steps.
//
// 1. Playing is paced: the simulated time follows the wall clock times `rate`; when the
//    steps cannot keep up the run goes as fast as it can and stops trying to catch up.
// 2. A state is recorded once the step from it has been taken (the report's rules may
//    still correct it during that step), so the recording holds final states only; the
//    state about to be stepped is shown live as the "current" frame.
// 3. A step that leaves a non-finite number, or throws, ends the run with a warning; the
//    bad state is never recorded or shown.
#pragma once

#include "recording.h"

#include "core/simulation.h"

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace ab::ui {

struct EngineStatus {
    long long steps = 0; // steps taken
    double t = 0.0;      // time of the current state
    bool playing = false;
    bool finished = false;          // the planned steps are done, or the run failed
    double stepSeconds = 0.0;       // wall time of one step, smoothed
    double energy = 0.0;            // total of the current state (ConservationMeter)
    bool energyPerUnitMass = true;  // false: with the physical model's masses
    std::string warning;            // from the run's health check, empty when none
    std::string notice;             // from the model, e.g. the report's bounce limit reached
    unsigned long long version = 0; // changes whenever the snapshot does
};

class RunEngine {
public:
    // Takes the simulation; `maxSteps` ends the run. `rate` is simulated time per second.
    RunEngine(std::unique_ptr<Simulation> sim, long long maxSteps, int trackedBall,
              std::size_t frameBudget = Recording::defaultFrameBudget);
    ~RunEngine();
    RunEngine(const RunEngine&) = delete;
    RunEngine& operator=(const RunEngine&) = delete;

    void play(double rate);
    void pause();
    void stepOnce(); // pauses, then takes one step
    void setTrackedBall(int ball);

    EngineStatus status() const;
    // Calls `f` with the recording and the current frame under the lock; keep it short.
    void read(const std::function<void(const Recording&, const Frame& current)>& f) const;

    const Simulation& simulation() const { return *sim_; }
    long long maxSteps() const { return maxSteps_; }

private:
    using Clock = std::chrono::steady_clock;

    void loop();
    bool mayStep() const;
    // Waits until a paced step is due; false when woken by a command instead.
    bool waitForDueStep(std::unique_lock<std::mutex>& lock);
    void takeStep(std::unique_lock<std::mutex>& lock);
    void finish(std::string warning);

    std::unique_ptr<Simulation> sim_;
    const long long maxSteps_;
    const SceneLayout layout_;
    const ConservationMeter meter_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    // Shared with the window, under mutex_.
    Recording recording_;
    Frame current_;
    EngineStatus status_;
    int pendingSteps_ = 0;
    double rate_ = 1.0;
    Clock::time_point anchorTime_;
    long long anchorStep_ = 0;
    bool quit_ = false;
    // The worker's own.
    State state_, next_;
    std::thread worker_;
};

} // namespace ab::ui
