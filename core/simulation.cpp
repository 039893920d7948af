// SPDX-License-Identifier: MIT
#include "simulation.h"

#include "physical/physical_models.h"
#include "report/report_models.h"

#include <cmath>

namespace ab {

double defaultDt(SceneId scene, ModelKind model)
{
    (void)model; // both models start from the report's step, so they are compared like for like
    return sceneInfo(scene).reportDt;
}

RunSpec variantOf(const RunSpec& base, const RunVariant& variant)
{
    RunSpec spec = base;
    spec.model = variant.model;
    spec.integrator = variant.integrator;
    spec.impacts = variant.impacts;
    spec.dt = variant.dt ? variant.dt : base.dt;
    return spec;
}

std::string variantLabel(const RunVariant& variant)
{
    std::string label(modelKey(variant.model));
    if (variant.model == ModelKind::Report)
        return label; // one scheme per stage: the integrator and impacts do not apply
    label += " ";
    label += integratorKey(variant.integrator);
    if (variant.impacts == ImpactMode::StepEnd && variant.integrator != Integrator::Event)
        label += " step-end";
    return label;
}

long long defaultSteps(SceneId scene, ModelKind model)
{
    (void)model;
    return sceneInfo(scene).reportSteps;
}

namespace {

void checkInitialState(const RunSpec& spec, const State& s)
{
    const SceneInfo& info = sceneInfo(spec.scene);
    if (info.ballCount != 0 && s.size() != info.ballCount)
        throw InputError("--init: the state has " + std::to_string(s.size()) + " ball(s); " + info.key + " has " +
                         std::to_string(info.ballCount));
    if (!s.p.allFinite() || !s.v.allFinite() || !std::isfinite(s.t))
        throw InputError("--init: the state holds a non-finite number");
}

} // namespace

bool integratorOffered(SceneId scene, Integrator integrator)
{
    switch (scene) {
    case SceneId::Street:
        return integrator == Integrator::Event;
    case SceneId::ManyBalls:
        return integrator != Integrator::Event && integrator != Integrator::ImplicitEuler &&
               integrator != Integrator::ImplicitMidpoint;
    case SceneId::Bounce1d:
    case SceneId::Box3d:
    case SceneId::TwoBalls:
        return true;
    }
    return true;
}

std::unique_ptr<Simulation> makeSimulation(const RunSpec& spec)
{
    const SceneInfo& info = sceneInfo(spec.scene);
    if (&spec.params.table() != &info.params)
        throw std::logic_error("parameter values of another scene");
    if (info.crossCheck)
        info.crossCheck(spec.params);
    if (spec.threads < 1 || spec.threads > kMaxThreads)
        throw InputError("--threads: " + std::to_string(spec.threads) + " is outside [1, " +
                         std::to_string(kMaxThreads) + "]");
    const double dt = spec.dt.value_or(defaultDt(spec.scene, spec.model));
    if (!std::isfinite(dt) || dt <= 0.0)
        throw InputError("--dt: " + formatNumber(dt) + " must be a positive finite step");
    if (spec.init)
        checkInitialState(spec, *spec.init);

    if (spec.model == ModelKind::Physical)
        return physical::makeSimulation(spec, dt);

    switch (spec.scene) {
    case SceneId::Bounce1d:
        return report::makeBounce1d(spec, dt);
    case SceneId::Box3d:
        return report::makeBox3d(spec, dt);
    case SceneId::TwoBalls:
        return report::makeTwoBalls(spec, dt);
    case SceneId::ManyBalls:
        if (dt != 1.0)
            throw InputError("--dt: the report's many-balls model advances one frame per step; its step is 1 frame");
        return report::makeManyBalls(spec);
    case SceneId::Street:
        throw InputError("--model: the report's rules stop at the box (report 3.1); the street is the physical "
                         "model's: use --model physical");
    }
    throw std::logic_error("scene without a report model");
}

State Simulation::start() const
{
    if (!spec_.init)
        return initialState();
    State s = *spec_.init;
    s.bounces.assign(static_cast<std::size_t>(s.size()), 0);
    s.count = 0;
    s.halted = false;
    return s;
}

State runRecorded(Simulation& sim, State start, long long steps, long long every,
                  const std::function<void(const State&)>& record, const std::function<bool()>& cancelled)
{
    State s = std::move(start);
    State next;
    for (long long i = 0; i < steps; ++i) {
        if (cancelled && cancelled())
            return s;
        sim.step(s, next); // may correct s: it is final only now
        if (i % every == 0)
            record(s);
        std::swap(s, next);
    }
    if (steps % every == 0)
        record(s);
    return s;
}

} // namespace ab
