// SPDX-License-Identifier: MIT
#include "run_controller.h"

#include "playback_rate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace ab::ui {

RunController::RunController(QObject* parent) : QObject(parent)
{
    frameTimer_.setInterval(16);
    frameTimer_.setTimerType(Qt::PreciseTimer);
    connect(&frameTimer_, &QTimer::timeout, this, &RunController::poll);
    frameTimer_.start();
}

namespace {

// The comparison's simulation, checked against the main run's: the same scene is counted
// in the same units by both models (SceneInfo::timeUnit and lengthUnit are the scene's,
// and defaultDt gives both models the report's step: bounce1d counts steps, with g in
// length per step^2, in the physical model too), so both runs share one time axis when
// they start at the same time with the same balls.
std::unique_ptr<Simulation> makeComparison(const RunSpec& main, const Simulation& mainSim, const RunVariant& variant)
{
    const std::string who = variantLabel(variant);
    std::unique_ptr<Simulation> sim;
    try {
        sim = makeSimulation(variantOf(main, variant));
    } catch (const InputError& e) {
        // The core's reason, quoted inside; translated with it where it is a Refusal.
        Refusal r{refusal::compareWith, {who}};
        if (e.refusal())
            r.detail = e.shared();
        else
            r.args.emplace_back(e.what());
        throw InputError(std::move(r));
    }
    const State a = mainSim.start(), b = sim->start();
    if (a.t != b.t || a.size() != b.size())
        throw InputError(Refusal{refusal::compareStart, {who}});
    return sim;
}

int engineThreadCount = 0; // 0: defaultEngineThreads(); read and set on the GUI thread only

} // namespace

int RunController::defaultEngineThreads()
{
    const int cores = static_cast<int>(std::thread::hardware_concurrency()); // 0 where unknown
    return std::clamp(cores - 1, 1, 8);
}

int RunController::engineThreads()
{
    return engineThreadCount > 0 ? engineThreadCount : defaultEngineThreads();
}

void RunController::setEngineThreads(int threads)
{
    if (threads < 1 || threads > kMaxThreads)
        throw std::invalid_argument("RunController::setEngineThreads: outside [1, kMaxThreads]");
    engineThreadCount = threads;
}

RunController::~RunController()
{
    retireEngine(engine_);
    retireEngine(compare_);
    for (std::future<void>& f : retiring_)
        f.wait();
}

void RunController::retireEngine(std::unique_ptr<RunEngine>& engine)
{
    if (!engine)
        return;
    std::erase_if(retiring_, [](const std::future<void>& f) {
        return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
    });
    retiring_.push_back(std::async(std::launch::async, [old = std::move(engine)]() mutable { old.reset(); }));
}

double RunController::realTimeRate(const SceneInfo& scene)
{
    return playbackRate(scene);
}

const RunSpec& RunController::spec() const
{
    if (!spec_)
        throw std::logic_error("RunController: no run yet");
    return *spec_;
}

double RunController::plannedEnd() const
{
    if (!engine_)
        return 1.0;
    const Simulation& sim = engine_->simulation();
    return sim.start().t + sim.dt() * static_cast<double>(std::max<long long>(steps_, 1));
}

void RunController::setRun(const RunSpec& asked, long long steps, const std::optional<RunVariant>& compare)
{
    RunSpec spec = asked;
    spec.threads = engineThreads();                         // the pace only: the balls are the same for any count
    std::unique_ptr<Simulation> sim = makeSimulation(spec); // throws InputError: nothing changes
    std::unique_ptr<Simulation> other = compare ? makeComparison(spec, *sim, *compare) : nullptr;
    spec_ = std::make_unique<RunSpec>(spec);
    variant_ = compare;
    compareSpec_ = other ? std::make_unique<RunSpec>(other->spec()) : nullptr;
    steps_ = steps;
    layout_ = layoutFor(spec);
    startEngine(std::move(sim), std::move(other));
}

void RunController::startEngine(std::unique_ptr<Simulation> sim, std::unique_ptr<Simulation> compare)
{
    const bool wasPlaying = status_.playing;
    retireEngine(engine_);
    retireEngine(compare_);
    const int balls = sim->start().size();
    selected_ = std::clamp(selected_, 0, std::max(balls - 1, 0));
    if (compare) {
        // As many steps as reach the main run's planned end: steps dt / dt_c of them,
        // rounded up (the allowance keeps 2000 * 1 / 1 from becoming 2001).
        const double ratio = sim->dt() / compare->dt();
        const auto compareSteps =
            static_cast<long long>(std::ceil(static_cast<double>(steps_) * ratio - 1e-9 * std::max(ratio, 1.0)));
        // The window shows the main run's health only: the comparison runs without a check.
        compare_ =
            std::make_unique<RunEngine>(std::move(compare), compareSteps, selected_, Recording::defaultFrameBudget,
                                        RunEngine::defaultKeyframeBudget, RunEngine::HealthChecking::Off);
        compareStatus_ = compare_->status();
    } else {
        compareStatus_ = {};
    }
    compareForkTo_.reset();
    engine_ = std::make_unique<RunEngine>(std::move(sim), steps_, selected_);
    status_ = engine_->status();
    emit runReplaced();
    if (wasPlaying)
        emit playingChanged(false);
    emit advanced();
}

void RunController::takeOver(RunController& other)
{
    retireEngine(engine_);
    retireEngine(compare_);
    spec_ = std::move(other.spec_);
    steps_ = other.steps_;
    layout_ = other.layout_;
    engine_ = std::move(other.engine_);
    variant_ = std::move(other.variant_);
    compareSpec_ = std::move(other.compareSpec_);
    compare_ = std::move(other.compare_);
    compareStatus_ = other.compareStatus_;
    compareForkTo_ = other.compareForkTo_;
    speed_ = other.speed_;
    selected_ = other.selected_;
    other.status_ = {};
    status_ = engine_ ? engine_->status() : EngineStatus{};
    emit runReplaced();
    emit speedChanged(speed_);
    emit playingChanged(status_.playing);
    emit advanced();
}

void RunController::play()
{
    if (!engine_)
        return;
    if (status_.finished)
        reset(); // play at the end starts the run again
    engine_->play(speed_ * realTimeRate(engine_->simulation().scene()));
    poll();
}

void RunController::pause()
{
    if (!engine_)
        return;
    engine_->pause();
    poll();
}

void RunController::togglePlay()
{
    if (status_.playing)
        pause();
    else
        play();
}

void RunController::stepOnce()
{
    if (engine_)
        engine_->stepOnce();
}

void RunController::resumeFrom(long long step)
{
    if (!engine_)
        return;
    engine_->resumeFrom(step);
    poll();
}

void RunController::reset()
{
    if (!spec_)
        return;
    // The same specs built before: they are valid.
    startEngine(makeSimulation(*spec_), compareSpec_ ? makeSimulation(*compareSpec_) : nullptr);
}

void RunController::setSpeed(double factor)
{
    factor = std::clamp(factor, 0.1, 10.0);
    if (factor == speed_)
        return;
    speed_ = factor;
    if (engine_ && status_.playing)
        engine_->play(speed_ * realTimeRate(engine_->simulation().scene()));
    emit speedChanged(speed_);
}

void RunController::selectBall(int ball)
{
    if (!engine_ || ball == selected_ || ball < 0 || ball >= layout_.balls)
        return;
    selected_ = ball;
    engine_->setTrackedBall(ball);
    if (compare_)
        compare_->setTrackedBall(ball);
    emit selectionChanged(ball);
    poll();
}

void RunController::poll()
{
    if (!engine_)
        return;
    const EngineStatus s = engine_->status();
    bool changed = s.version != status_.version;
    const bool playingChange = s.playing != status_.playing;
    status_ = s;
    if (compare_) {
        keepComparisonInStep();
        const EngineStatus c = compare_->status();
        changed = changed || c.version != compareStatus_.version;
        compareStatus_ = c;
    }
    if (!changed)
        return;
    if (playingChange)
        emit playingChanged(s.playing);
    emit advanced();
}

void RunController::keepComparisonInStep()
{
    const EngineStatus c = compare_->status();
    if (compareForkTo_) {
        if (c.steps != *compareForkTo_)
            return; // still going back
        compareForkTo_.reset();
    }
    const double dt = compare_->simulation().dt();
    if (c.t > status_.t + 1e-9 * dt) {
        // Ahead: the main run went back. The comparison's step k is at t0 + k dt_c, so
        // the last one not past the main run's time is k = floor((t - t0) / dt_c).
        const double t0 = compare_->simulation().start().t;
        const double k = std::floor((status_.t - t0) / dt + 1e-9);
        compareForkTo_ = std::clamp(static_cast<long long>(k), 0LL, c.steps);
        compare_->resumeFrom(*compareForkTo_);
        return;
    }
    compare_->follow(status_.t);
}

} // namespace ab::ui
