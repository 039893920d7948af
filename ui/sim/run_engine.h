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
// 4. Every step is checked by the core's health check (core/diagnostics/health.h) off the
//    GUI thread. Its worst finding so far is in the status; a new kind of failure (a ball
//    through a wall, balls through each other, energy gained by a method) pauses the run
//    at the state that showed it, so the moment can be looked at; Play goes on from there.
// 5. A run can fork back to any recorded step (resumeFrom): it drops what was recorded
//    from that step on and goes on from that step's exact state. The worker keeps whole
//    states ("keyframes", in double, counters included) before the steps on a stride that
//    doubles whenever they would pass a byte budget, and rebuilds the state of any step
//    by re-taking the steps from the keyframe before it: the rules are deterministic, so
//    the forked run is the one a fresh run would have taken to that step, bit for bit.
//    A street run ends at the step its last ball left at the open foot (emptiedAt): what
//    follows would show an empty street.
// 6. A comparison run follows another instead of the clock (follow): it steps, unpaced,
//    while its next state's time is not past the other run's, so both show one moment.
#pragma once

#include "recording.h"

#include "core/diagnostics/health.h"
#include "core/simulation.h"

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace ab::ui {

struct EngineStatus {
    long long steps = 0; // steps taken
    double t = 0.0;      // time of the current state
    bool playing = false;
    bool finished = false;                                // the planned steps are done, or the run failed
    double stepSeconds = 0.0;                             // wall time of one step, smoothed
    double energy = 0.0;                                  // total of the current state (ConservationMeter)
    bool energyPerUnitMass = true;                        // false: with the physical model's masses
    std::string warning;                                  // from the run's health check, empty when none
    std::string notice;                                   // from the model, e.g. the report's bounce limit reached
    diagnostics::Health health = diagnostics::Health::Ok; // the health check's worst finding so far
    std::string healthLine;                               // that finding: what happened, what to change
    diagnostics::HealthStatus worst;                      // the same as data (the window words it)
    std::optional<double> haltedAt;                       // when the report's counter stopped the motion (the notice)
    std::optional<double> emptiedAt; // the street's last ball left at its open foot then: the run ended there
    bool pausedOnHealth = false;     // the last pause was the health check's (cleared by play or a step)
    unsigned long long version = 0;  // changes whenever the snapshot does
};

class RunEngine {
public:
    // Takes the simulation; `maxSteps` ends the run. `rate` is simulated time per second.
    static constexpr std::size_t defaultKeyframeBudget = std::size_t(256) << 20;

    // Off: no health check at all (a comparison run, whose findings the window does not
    // show): status().health stays Ok.
    enum class HealthChecking { On, Off };

    RunEngine(std::unique_ptr<Simulation> sim, long long maxSteps, int trackedBall,
              std::size_t frameBudget = Recording::defaultFrameBudget,
              std::size_t keyframeBudget = defaultKeyframeBudget, HealthChecking checking = HealthChecking::On);
    ~RunEngine();
    RunEngine(const RunEngine&) = delete;
    RunEngine& operator=(const RunEngine&) = delete;

    void play(double rate);
    void pause();
    void stepOnce(); // pauses, then takes one step
    void setTrackedBall(int ball);
    // Forks the run back to recorded step `step` (0 to the current step) and pauses it
    // there; the worker rebuilds the state, so this returns at once and status().steps
    // becomes `step` when the fork is done. A later play() or stepOnce() waits for it.
    void resumeFrom(long long step);
    // Steps, as fast as the steps go, while the next state's time is at most `t` (to
    // rounding): the run follows another run's time instead of the clock. Pauses.
    void follow(double t);

    EngineStatus status() const;
    // Calls `f` with the recording and the current frame under the lock; keep it short.
    void read(const std::function<void(const Recording&, const Frame& current)>& f) const;

    const Simulation& simulation() const { return *sim_; }
    long long maxSteps() const { return maxSteps_; }

private:
    using Clock = std::chrono::steady_clock;

    void loop();
    bool mayStep() const;
    bool followDue() const; // a step is owed to the followed time (under the lock)
    // Waits until a paced step is due; false when woken by a command instead.
    bool waitForDueStep(std::unique_lock<std::mutex>& lock);
    void takeStep(std::unique_lock<std::mutex>& lock);
    // Checks the step that made state_ final (worker only, unlocked); true when it
    // showed a new kind of failure.
    bool checkHealth();
    // Carries out a pending resumeFrom (worker only; unlocks while it re-takes steps).
    void fork(std::unique_lock<std::mutex>& lock);
    // Keeps state_ (before its step) as a keyframe when its step falls on the stride.
    void keepKeyframe();
    // Under the lock: the health check's worst finding, and state_ as the current frame
    // of step status_.steps, into the shared snapshot.
    void publishHealth();
    void publishCurrent();
    // Failures among the health check's findings (0 without a check).
    std::size_t failuresFound() const;
    void finish(std::string warning);
    // The street's balls have all left at its open foot (false in the other stages).
    bool streetEmpty() const;

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
    std::optional<long long> forkTo_;
    std::optional<double> followT_;
    double rate_ = 1.0;
    Clock::time_point anchorTime_;
    long long anchorStep_ = 0;
    bool quit_ = false;
    // The worker's own. previous_ is the last final state before state_ (for the health
    // check); the three buffers rotate, so no state is copied.
    State state_, next_, previous_;
    bool havePrevious_ = false;
    std::optional<diagnostics::HealthCheck> health_;
    std::size_t failuresSeen_ = 0;
    static constexpr std::size_t kNoneYet = static_cast<std::size_t>(-1);
    std::size_t issuesPublished_ = kNoneYet; // health_->issues().size() when status_.health was last set
    struct Keyframe {
        long long step;
        State state; // before the step from it was taken
    };
    std::vector<Keyframe> keyframes_; // in step order; the start is always the first
    std::size_t maxKeyframes_;
    long long keyframeStride_ = 1;
    std::thread worker_;
};

} // namespace ab::ui
