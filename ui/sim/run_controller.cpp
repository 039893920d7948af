// SPDX-License-Identifier: MIT
#include "run_controller.h"

#include <algorithm>
#include <chrono>

namespace ab::ui {

RunController::RunController(QObject* parent) : QObject(parent)
{
    frameTimer_.setInterval(16);
    frameTimer_.setTimerType(Qt::PreciseTimer);
    connect(&frameTimer_, &QTimer::timeout, this, &RunController::poll);
    frameTimer_.start();
}

RunController::~RunController()
{
    retireEngine();
    for (std::future<void>& f : retiring_)
        f.wait();
}

void RunController::retireEngine()
{
    if (!engine_)
        return;
    std::erase_if(retiring_, [](const std::future<void>& f) {
        return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
    });
    retiring_.push_back(std::async(std::launch::async, [old = std::move(engine_)]() mutable { old.reset(); }));
}

double RunController::realTimeRate(const SceneInfo& scene)
{
    if (scene.timeUnit == "step")
        return 10.0;
    if (scene.timeUnit == "frame")
        return 60.0;
    return 1.0;
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

void RunController::setRun(const RunSpec& spec, long long steps)
{
    std::unique_ptr<Simulation> sim = makeSimulation(spec); // throws InputError: nothing changes
    spec_ = std::make_unique<RunSpec>(spec);
    steps_ = steps;
    layout_ = layoutFor(spec);
    startEngine(std::move(sim));
}

void RunController::startEngine(std::unique_ptr<Simulation> sim)
{
    const bool wasPlaying = status_.playing;
    retireEngine();
    const int balls = sim->start().size();
    selected_ = std::clamp(selected_, 0, std::max(balls - 1, 0));
    engine_ = std::make_unique<RunEngine>(std::move(sim), steps_, selected_);
    status_ = engine_->status();
    emit runReplaced();
    if (wasPlaying)
        emit playingChanged(false);
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
    startEngine(makeSimulation(*spec_)); // the same spec built before: it is valid
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
    emit selectionChanged(ball);
    poll();
}

void RunController::poll()
{
    if (!engine_)
        return;
    const EngineStatus s = engine_->status();
    if (s.version == status_.version)
        return;
    const bool playingChange = s.playing != status_.playing;
    status_ = s;
    if (playingChange)
        emit playingChanged(s.playing);
    emit advanced();
}

} // namespace ab::ui
