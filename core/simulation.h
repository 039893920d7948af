// SPDX-License-Identifier: MIT
// What every front end drives: a Simulation built from a RunSpec (scene, model,
// integrator, parameters, step). It is a rule set over State, with no clock, thread or
// drawing of its own; the CLI, the tests and the app step it the same way.
#pragma once

#include "scene.h"
#include "state.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace ab {

struct RunSpec {
    // The street has no report model (its stage is the physical model's), and its flight is
    // exact between events: its runs start physical, `event`.
    explicit RunSpec(SceneId id)
        : scene(id), model(id == SceneId::Street ? ModelKind::Physical : ModelKind::Report),
          integrator(id == SceneId::Street ? Integrator::Event : Integrator::SymplecticEuler),
          params(sceneInfo(id).defaults())
    {
    }

    SceneId scene;
    ModelKind model;
    Integrator integrator;
    ImpactMode impacts = ImpactMode::Located;
    Broadphase broadphase = Broadphase::Grid;
    int threads = 1;          // 1 to kMaxThreads
    std::optional<double> dt; // unset: the model's default for the scene
    ParamValues params;
    std::optional<State> init; // start here instead of the parameters' start values
};

// The most threads a run may ask for (--threads, in the CLI and the window).
inline constexpr int kMaxThreads = 256;

// Another way to compute the same scene: a model, an integrator and impact finding, and
// optionally its own step. A comparison run is `variantOf` the main run: the same scene,
// constants and start, computed this way.
struct RunVariant {
    ModelKind model = ModelKind::Report;
    Integrator integrator = Integrator::SymplecticEuler;
    ImpactMode impacts = ImpactMode::Located;
    std::optional<double> dt; // unset: the main run's step

    friend bool operator==(const RunVariant&, const RunVariant&) = default;
};

// `base` computed as `variant` says; scene, parameters, start state, broadphase and
// threads stay `base`'s. Not validated: makeSimulation does that.
RunSpec variantOf(const RunSpec& base, const RunVariant& variant);
// A few words naming the variant: "report", "physical symplectic-euler", "physical
// rk4 step-end" (impacts are named only when found at the step's end; `event` has none).
std::string variantLabel(const RunVariant& variant);

class Simulation {
public:
    virtual ~Simulation() = default;

    // The start the parameters describe (ball positions, velocities, seeded draws).
    virtual State initialState() const = 0;
    // The state a run starts from: the spec's `init` when given, else initialState().
    State start() const;

    // Computes `next` from `s`, one step of dt() later. The report's rules may first
    // correct `s` itself (they clamp a position at a contact and zero the state at the
    // bounce limit), so `s` is final only once the step from it has been taken: record a
    // state after the step that leaves it.
    virtual void step(State& s, State& next) = 0;

    double dt() const { return dt_; }
    const RunSpec& spec() const { return spec_; }
    const SceneInfo& scene() const { return sceneInfo(spec_.scene); }

protected:
    Simulation(RunSpec spec, double dt) : spec_(std::move(spec)), dt_(dt) {}

    RunSpec spec_;
    double dt_;
};

// Validates the whole spec (parameters, cross-checks, step, model/integrator fit) and
// builds the simulation; throws InputError naming what is wrong.
std::unique_ptr<Simulation> makeSimulation(const RunSpec& spec);

// Whether the physical model of `scene` steps with `integrator` at all, whatever its
// constants: the street's flight is exact between events (event only); many-balls resolves
// its contacts at each substep's end (no event) and has no spring contacts (no implicit
// integrators). makeSimulation still refuses what constants rule out (event with drag).
bool integratorOffered(SceneId scene, Integrator integrator);

double defaultDt(SceneId scene, ModelKind model);
long long defaultSteps(SceneId scene, ModelKind model);

// Steps `sim` `steps` times from `start`, handing every `every`-th state (the start
// included) to `record` in time order, each only once it is final. Returns the last
// state. `cancelled`, when given, is polled between steps; a cancelled run returns the
// state reached so far.
State runRecorded(Simulation& sim, State start, long long steps, long long every,
                  const std::function<void(const State&)>& record, const std::function<bool()>& cancelled = {});

} // namespace ab
