// SPDX-License-Identifier: MIT
#include "run_engine.h"

#include "core/params.h"
#include "core/street/street_census.h"

#include <algorithm>

#include <cmath>

#ifdef __linux__
#include <pthread.h>
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace ab::ui {

namespace {

bool finiteState(const State& s)
{
    return std::isfinite(s.t) && s.p.allFinite() && s.v.allFinite();
}

// The window's drawing comes first: on a busy machine a long step (10,000 balls) must
// not take the core the window and software OpenGL need. On Linux the stepping thread
// runs at nice 8 (about a tenth of a normal thread's share when both want the core). Not
// SCHED_IDLE: that starves the run outright whenever anything else is busy (a compile
// in the background froze the window's run at t = 0); elsewhere it keeps the default.
void lowerThisThreadsPriority()
{
#ifdef __linux__
    (void)setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 8);
    pthread_setname_np(pthread_self(), "ab-stepper"); // named for profilers and --measure-frames
#endif
}

// Beyond this many balls the health check looks at ball pairs on every 10th step: at
// 10,000 balls checking every pair costs about as much as the report's step, and the
// window keeps the run in real time beside the drawing.
constexpr int kPairsSampledAbove = 2'000;

} // namespace

RunEngine::RunEngine(std::unique_ptr<Simulation> sim, long long maxSteps, int trackedBall, std::size_t frameBudget,
                     std::size_t keyframeBudget, HealthChecking checking)
    : sim_(std::move(sim)), maxSteps_(maxSteps), layout_(layoutFor(sim_->spec())), meter_(*sim_),
      recording_(layout_, meter_, trackedBall, frameBudget), state_(sim_->start())
{
    if (checking == HealthChecking::On)
        health_.emplace(*sim_, state_, kPairsSampledAbove);
    // A keyframe holds two 3-vectors of doubles and a counter per ball.
    const std::size_t keyframeBytes =
        (6 * sizeof(double) + sizeof(int)) * static_cast<std::size_t>(std::max(state_.size(), 1));
    maxKeyframes_ = std::max<std::size_t>(keyframeBudget / keyframeBytes, 2); // the start is always kept
    publishCurrent();                                                         // no other thread yet
    status_.energyPerUnitMass = meter_.perUnitMass();
    status_.finished = maxSteps_ <= 0;
    if (!finiteState(state_))
        finish("the start state holds a non-finite number");
    worker_ = std::thread([this] { loop(); });
}

RunEngine::~RunEngine()
{
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

void RunEngine::play(double rate)
{
    {
        std::lock_guard lock(mutex_);
        if (!(std::isfinite(rate) && rate > 0.0))
            throw std::logic_error("play: the rate must be positive");
        rate_ = rate;
        anchorTime_ = Clock::now();
        anchorStep_ = status_.steps;
        if (!status_.finished) {
            status_.playing = true;
            status_.pausedOnHealth = false;
        }
        ++status_.version;
    }
    wake_.notify_all();
}

void RunEngine::pause()
{
    std::lock_guard lock(mutex_);
    if (status_.playing) {
        status_.playing = false;
        ++status_.version;
    }
}

void RunEngine::stepOnce()
{
    {
        std::lock_guard lock(mutex_);
        status_.playing = false;
        status_.pausedOnHealth = false;
        if (!status_.finished)
            ++pendingSteps_;
        ++status_.version;
    }
    wake_.notify_all();
}

void RunEngine::setTrackedBall(int ball)
{
    std::lock_guard lock(mutex_);
    if (ball < 0 || ball >= current_.balls())
        throw std::logic_error("setTrackedBall: no such ball");
    recording_.setTrackedBall(ball);
    recording_.showCurrent(status_.steps, state_, current_.scene);
    ++status_.version;
}

void RunEngine::resumeFrom(long long step)
{
    {
        std::lock_guard lock(mutex_);
        if (step < 0 || step > status_.steps)
            throw std::logic_error("resumeFrom: no such recorded step");
        status_.playing = false;
        pendingSteps_ = 0;
        forkTo_ = step;
        followT_.reset(); // a followed run that goes back is told its new time afterwards
        ++status_.version;
    }
    wake_.notify_all();
}

void RunEngine::follow(double t)
{
    {
        std::lock_guard lock(mutex_);
        if (!std::isfinite(t))
            throw std::logic_error("follow: the time must be finite");
        if (followT_ == t && !status_.playing)
            return;
        status_.playing = false;
        followT_ = t;
    }
    wake_.notify_all();
}

bool RunEngine::followDue() const
{
    if (!followT_)
        return false;
    // The next state is at t + dt. Both runs add their steps to the same start time, so
    // with equal steps their times are equal bit for bit; with different steps a rounding
    // allowance of 1e-9 of a step keeps t = 3 * 0.1 from missing a followed 0.3.
    const double dt = sim_->dt();
    return status_.t + dt <= *followT_ + 1e-9 * dt;
}

EngineStatus RunEngine::status() const
{
    std::lock_guard lock(mutex_);
    return status_;
}

void RunEngine::read(const std::function<void(const Recording&, const Frame&)>& f) const
{
    std::lock_guard lock(mutex_);
    f(recording_, current_);
}

bool RunEngine::mayStep() const
{
    return forkTo_ || (!status_.finished && (status_.playing || pendingSteps_ > 0 || followDue()));
}

void RunEngine::loop()
{
    lowerThisThreadsPriority();
    std::unique_lock lock(mutex_);
    while (!quit_) {
        if (!mayStep()) {
            wake_.wait(lock);
            continue;
        }
        if (forkTo_) {
            fork(lock);
            continue;
        }
        if (pendingSteps_ > 0)
            --pendingSteps_;
        else if (!followDue() && !waitForDueStep(lock)) // a step owed to the followed time is not paced
            continue;
        takeStep(lock);
    }
}

bool RunEngine::waitForDueStep(std::unique_lock<std::mutex>& lock)
{
    const double dt = sim_->dt();
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - anchorTime_).count();
    const double due = static_cast<double>(anchorStep_) + std::floor(elapsed * rate_ / dt) - status_.steps;
    if (due >= 1.0) {
        // More than a quarter second behind: the steps cannot keep up, so stop owing them.
        if (due * dt / rate_ > 0.25) {
            anchorTime_ = now;
            anchorStep_ = status_.steps;
        }
        return true;
    }
    const auto next = anchorTime_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                                        static_cast<double>(status_.steps + 1 - anchorStep_) * dt / rate_));
    const unsigned long long version = status_.version;
    wake_.wait_until(lock, next, [&] { return quit_ || status_.version != version; });
    return false; // re-check commands and the clock
}

void RunEngine::takeStep(std::unique_lock<std::mutex>& lock)
{
    lock.unlock();
    keepKeyframe();
    const auto begin = Clock::now();
    std::string failure;
    try {
        sim_->step(state_, next_); // may correct state_: it is final only now
        if (!finiteState(next_))
            failure = "the step from t = " + formatSignificant(state_.t, 6) +
                      " produced a non-finite number; try a smaller step or another integrator";
    } catch (const std::exception& e) {
        failure = "the step from t = " + formatSignificant(state_.t, 6) + " failed: " + e.what();
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    const bool finalOk = finiteState(state_);
    const bool newFailure = finalOk && checkHealth();
    lock.lock();

    if (finalOk)
        recording_.add(status_.steps, state_);
    publishHealth();
    if (health_ && health_->figures().nonfinite && failure.empty())
        failure = status_.healthLine; // an overflowing energy: nothing after it can be drawn
    if (!failure.empty() || !finalOk) {
        finish(failure.empty() ? "the state became non-finite" : failure);
        return;
    }
    if (state_.halted && !status_.haltedAt)
        status_.haltedAt = state_.t;
    if (state_.halted && status_.notice.empty())
        status_.notice = "the report's bounce limit stopped the motion at t = " + formatSignificant(state_.t, 6);
    // Rotate: the final state becomes the previous one, the new state the current one.
    std::swap(previous_, state_);
    std::swap(state_, next_);
    havePrevious_ = true;
    ++status_.steps;
    status_.stepSeconds = status_.stepSeconds == 0.0 ? seconds : 0.9 * status_.stepSeconds + 0.1 * seconds;
    publishCurrent();
    if (newFailure && status_.playing) {
        status_.playing = false; // stop where the failure showed: the state just recorded
        status_.pausedOnHealth = true;
        pendingSteps_ = 0;
    }
    ++status_.version;
    const bool emptied = streetEmpty();
    if (emptied)
        status_.emptiedAt = state_.t;
    if (status_.steps >= maxSteps_ || emptied) {
        recording_.add(status_.steps, state_); // the last state, as runRecorded records it
        finish({});
    }
}

bool RunEngine::streetEmpty() const
{
    if (!layout_.street)
        return false;
    for (int i = 0; i < state_.size(); ++i)
        if (!street::hasLeft(*layout_.street, state_.p(0, i)))
            return false;
    return true;
}

bool RunEngine::checkHealth()
{
    if (!health_ || !havePrevious_)
        return false; // no check, or the start: nothing to compare with yet
    health_->check(previous_, state_);
    const std::size_t failures = failuresFound();
    const bool grew = failures > failuresSeen_;
    failuresSeen_ = failures;
    return grew;
}

std::size_t RunEngine::failuresFound() const
{
    std::size_t failures = 0;
    if (health_)
        for (const diagnostics::HealthStatus& s : health_->issues())
            failures += s.level == diagnostics::Health::Failed ? 1 : 0;
    return failures;
}

void RunEngine::publishHealth()
{
    // The worst finding changes only with a new kind of finding: its line is built then.
    if (!health_ || health_->issues().size() == issuesPublished_)
        return;
    issuesPublished_ = health_->issues().size();
    const diagnostics::HealthStatus worst = health_->worst();
    status_.health = worst.level;
    status_.healthLine = worst.level == diagnostics::Health::Ok ? std::string() : worst.line();
    status_.worst = worst;
}

void RunEngine::publishCurrent()
{
    current_ = makeFrame(status_.steps, state_, meter_);
    current_.q = recording_.orientationsAt(state_); // state_ is recorded at the next step
    recording_.showCurrent(status_.steps, state_, current_.scene);
    status_.t = state_.t;
    status_.energy = current_.scene.energy.total();
}

void RunEngine::keepKeyframe()
{
    // status_.steps changes only on this thread, so it is read here without the lock.
    const long long step = status_.steps;
    if (step % keyframeStride_ != 0 || (!keyframes_.empty() && keyframes_.back().step >= step))
        return;
    keyframes_.push_back({step, state_});
    if (keyframes_.size() <= maxKeyframes_)
        return;
    keyframeStride_ *= 2; // thin to every other one, as the recording thins its frames
    const auto off = [this](const Keyframe& k) { return k.step % keyframeStride_ != 0; };
    keyframes_.erase(std::remove_if(keyframes_.begin(), keyframes_.end(), off), keyframes_.end());
}

void RunEngine::fork(std::unique_lock<std::mutex>& lock)
{
    const long long target = *forkTo_;
    forkTo_.reset();
    // The last keyframe at or before the target; the start's is always there.
    auto key = std::upper_bound(keyframes_.begin(), keyframes_.end(), target,
                                [](long long s, const Keyframe& k) { return s < k.step; });
    if (key == keyframes_.begin()) {
        keyframes_.insert(keyframes_.begin(), {0, sim_->start()});
        key = keyframes_.begin() + 1;
    }
    const Keyframe& from = *std::prev(key);
    lock.unlock();

    // Re-take the steps from the keyframe to the target, health check included: each
    // state is final once the step from it is taken, as in takeStep.
    State cur = from.state, nxt, prev;
    bool havePrev = false;
    if (health_) {
        // A check from the start, holding what the first pass found up to the keyframe:
        // the steps from there are checked again below.
        diagnostics::HealthCheck again(*sim_, sim_->start(), kPairsSampledAbove);
        again.keepFindings(*health_, from.state.t);
        *health_ = std::move(again);
    }
    std::string failure;
    try {
        for (long long step = from.step; step < target; ++step) {
            sim_->step(cur, nxt);
            if (havePrev && health_)
                health_->check(prev, cur);
            std::swap(prev, cur);
            std::swap(cur, nxt);
            havePrev = true;
        }
    } catch (const std::exception& e) { // these steps were taken before: only memory can fail
        failure = std::string("going back failed: ") + e.what();
    }
    const std::size_t failures = failuresFound();

    lock.lock();
    if (!failure.empty()) {
        finish(failure);
        return;
    }
    keyframes_.erase(std::upper_bound(keyframes_.begin(), keyframes_.end(), target,
                                      [](long long s, const Keyframe& k) { return s < k.step; }),
                     keyframes_.end());
    state_ = std::move(cur);
    previous_ = std::move(prev);
    havePrevious_ = havePrev;
    failuresSeen_ = failures;
    recording_.truncateFrom(target);
    status_.steps = target;
    status_.pausedOnHealth = false; // playing stays as resumeFrom and any later play() left it
    status_.warning.clear();
    status_.notice.clear();
    status_.haltedAt.reset();
    status_.emptiedAt.reset();
    if (streetEmpty())
        status_.emptiedAt = state_.t;
    status_.finished = target >= maxSteps_ || status_.emptiedAt;
    issuesPublished_ = kNoneYet; // the re-taken steps' findings are published anew
    publishHealth();
    publishCurrent();
    anchorTime_ = Clock::now();
    anchorStep_ = target;
    ++status_.version;
}

void RunEngine::finish(std::string warning)
{
    status_.finished = true;
    status_.playing = false;
    pendingSteps_ = 0;
    if (!warning.empty())
        status_.warning = std::move(warning);
    ++status_.version;
}

} // namespace ab::ui
