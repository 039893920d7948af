// SPDX-License-Identifier: MIT
// Stage 5's Simulation: the street engine behind the State interface, its settings from the
// scene's parameters, and the hopper's start.
#include "street_engine.h"

#include "../physical/engine_step.h"
#include "../random.h"

#include <cmath>

namespace ab::street {

Settings Settings::fromSpec(const RunSpec& spec, double dt)
{
    if (spec.integrator != Integrator::Event)
        throw InputError("--integrator: the street's flight is exact between events; " +
                         std::string(integratorKey(spec.integrator)) + " is not offered (use event)");
    if (spec.broadphase != Broadphase::Grid)
        throw InputError("--broadphase: the street finds its pairs in a grid; all-pairs is not offered");
    const ParamValues& v = spec.params;
    Settings s;
    s.n = static_cast<int>(v.integer("n"));
    s.radius = v.real("r");
    s.g = v.real("g");
    s.e = v.real("e");
    s.restHeight = v.real("rest_height");
    s.mu = v.real("mu");
    s.beta = v.real("beta");
    s.inertia = v.real("inertia");
    s.speed = v.real("speed");
    s.seed = static_cast<std::uint64_t>(v.integer("seed"));
    s.threads = spec.threads;
    s.dt = dt;
    return s;
}

State hopperStart(const Layout& layout, const Settings& s)
{
    const Hopper& h = layout.hopper;
    State start;
    start.resize(s.n);
    start.w.setZero(3, s.n);
    SplitMix64 rng(s.seed);
    const double jitter = 0.1 * s.radius; // sites 2.2 r apart: centres stay > 2 r apart
    const auto draw = [&](double bound) { return bound * (2.0 * rng.uniform() - 1.0); };
    for (int i = 0; i < s.n; ++i) {
        const int layer = i / (h.columns * h.rows), site = i % (h.columns * h.rows);
        const int column = h.columns - 1 - site / h.rows, row = site % h.rows; // downhill columns first
        const double x = h.x0 + (column + 0.5) * h.spacing + draw(jitter);
        const double z = h.z0 + (row + 0.5) * h.spacing + draw(jitter);
        const double y = layout.roadY(x) + s.radius + h.lift + layer * h.spacing + draw(jitter);
        start.p.col(i) = Eigen::Vector3d(x, y, z);
        for (int a = 0; a < 3; ++a)
            start.v(a, i) = draw(s.speed);
    }
    return start;
}

namespace {

class StreetSimulation final : public Simulation {
public:
    StreetSimulation(const RunSpec& spec, double dt)
        : Simulation(spec, dt), engine_(Layout::fromParams(spec.params), Settings::fromSpec(spec, dt))
    {
    }

    State initialState() const override { return hopperStart(engine_.layout(), engine_.settings()); }

    void step(State& s, State& next) override
    {
        // The engine keeps which balls rest on which face between steps; a state it did not
        // write itself (the first, a fork, an edit) is loaded and its contacts found again.
        if (!engine_.holds(s))
            engine_.load(s);
        physical::stepEngine(engine_, s, next, dt_);
    }

private:
    Engine engine_;
};

} // namespace

std::unique_ptr<Simulation> makeStreet(const RunSpec& spec, double dt)
{
    const Settings settings = Settings::fromSpec(spec, dt); // refuses what the street does not offer
    if (spec.init && spec.init->size() != settings.n)
        throw InputError("--init: the state has " + std::to_string(spec.init->size()) + " balls; n is " +
                         std::to_string(settings.n));
    return std::make_unique<StreetSimulation>(spec, dt);
}

} // namespace ab::street
