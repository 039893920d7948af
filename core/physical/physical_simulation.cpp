// SPDX-License-Identifier: MIT
#include "physical_simulation.h"

#include "many_balls_physical.h"

#include "../params.h"

namespace ab::physical {

namespace {

void checkIntegrator(const RunSpec& spec, const World& w)
{
    const std::string key(integratorKey(spec.integrator));
    switch (spec.integrator) {
    case Integrator::Euler:
    case Integrator::SymplecticEuler:
    case Integrator::Verlet:
    case Integrator::Rk4:
        return;
    case Integrator::Event:
        if (spec.impacts == ImpactMode::StepEnd)
            throw InputError(
                "--impacts step-end: the event integrator finds every impact exactly; leave --impacts out");
        if (w.hasDrag())
            throw InputError("--integrator event: flight with air drag has no closed form; set b and c to 0 or "
                             "choose euler, symplectic-euler, verlet or rk4");
        return;
    case Integrator::ImplicitEuler:
    case Integrator::ImplicitMidpoint:
        throw InputError("--integrator " + key +
                         ": only for the spring-dashpot contact model, which this build does not have; choose euler, "
                         "symplectic-euler, verlet, rk4 or event");
    }
    throw std::logic_error("integrator without a physical model");
}

std::string ballName(const std::vector<std::string>& names, int i, bool fromInit)
{
    if (fromInit)
        return "--init: ball " + std::to_string(i);
    return names.at(static_cast<std::size_t>(i));
}

void checkStart(const World& w, const State& s, const std::vector<std::string>& names, bool fromInit)
{
    for (int i = 0; i < s.size(); ++i) {
        for (const Wall& wall : w.walls) {
            if (wall.gap(s.p.col(i)) < 0.0) {
                const std::string reach =
                    w.radius > 0.0 ? " (centres stay at least r = " + formatNumber(w.radius) + " from every wall)" : "";
                throw InputError(ballName(names, i, fromInit) + ": " + formatNumber(s.p(0, i)) + "," +
                                 formatNumber(s.p(1, i)) + "," + formatNumber(s.p(2, i)) + " lies beyond the " +
                                 wall.name + reach);
            }
        }
        for (int j = i + 1; j < s.size(); ++j) {
            const double d = (s.p.col(i) - s.p.col(j)).norm();
            if (d < 2.0 * w.radius)
                throw InputError(ballName(names, i, fromInit) + " and " +
                                 (fromInit ? "ball " + std::to_string(j) : names.at(static_cast<std::size_t>(j))) +
                                 ": the balls overlap (centres " + formatNumber(d) +
                                 " apart, less than 2 r = " + formatNumber(2.0 * w.radius) + ")");
        }
    }
}

} // namespace

bool hasRotation(const Simulation& sim, const State& start)
{
    const World* w = worldOf(sim);
    if (!w) { // the many-balls engine: rough balls, or a start with spins
        const RunSpec& spec = sim.spec();
        if (spec.scene == SceneId::Street) // the street's balls always carry spins
            return spec.model == ModelKind::Physical;
        if (spec.scene != SceneId::ManyBalls || spec.model != ModelKind::Physical)
            return false;
        return ManyBallsSettings::fromSpec(spec, sim.dt()).rough() || start.spins();
    }
    if (!(w->spinRadius > 0.0))
        return false;
    return w->anyRough() || (start.spins() && !start.w.isZero(0.0));
}

std::unique_ptr<Simulation> makePhysicalSimulation(const RunSpec& spec, double dt, World world, State initial,
                                                   const std::vector<std::string>& names)
{
    checkIntegrator(spec, world);
    checkStart(world, initial, names, false);
    if (!initial.spins())
        initial.w.setZero(3, initial.size());
    if (spec.init)
        checkStart(world, *spec.init, names, true);
    if (spec.integrator == Integrator::Event)
        return makeEventSimulation(spec, dt, std::move(world), std::move(initial));
    return makeSteppedSimulation(spec, dt, std::move(world), std::move(initial));
}

} // namespace ab::physical
