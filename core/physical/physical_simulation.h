// SPDX-License-Identifier: MIT
// What the physical model's simulations have beyond Simulation: their World, energy, and
// an optional log of every impact with its time (the accuracy study compares the k-th
// impact time with the closed form). A scene builder describes its World and start
// state and calls makePhysicalSimulation, which picks the time stepping or the
// event-driven motion from the spec's integrator.
#pragma once

#include "../simulation.h"
#include "world.h"

#include <memory>
#include <vector>

namespace ab::physical {

struct Impact {
    double t = 0.0; // when: exact for located and event, the step's end for step-end
    int ball = 0;
    int other = -1;     // the other ball of a pair, or -1
    int wall = -1;      // index into World::walls, or -1
    double speed = 0.0; // approach speed along the normal
};

class PhysicalSimulation : public Simulation {
public:
    const World& world() const { return world_; }
    State initialState() const override { return initial_; }
    // Translation, rotation and potential energy.
    double energy(const State& s) const { return physical::energy(world_, s); }

    // Every later impact is appended to `log` (not owned; nullptr stops logging).
    void setImpactLog(std::vector<Impact>* log) { log_ = log; }

protected:
    PhysicalSimulation(const RunSpec& spec, double dt, World world, State initial)
        : Simulation(spec, dt), world_(std::move(world)), initial_(std::move(initial))
    {
    }

    bool logging() const { return log_ != nullptr; }
    // Gives a state without spins (one made by hand, or read from a file without them)
    // the zero spins of balls that do not turn.
    static void withSpin(State& s)
    {
        if (!s.spins())
            s.w.setZero(3, s.size());
    }
    void logImpact(const Impact& impact)
    {
        if (log_)
            log_->push_back(impact);
    }

    World world_;
    State initial_;

private:
    std::vector<Impact>* log_ = nullptr;
};

// The World of a physical simulation (its masses, walls, contact constants); nullptr for
// any other simulation (the report's, many-balls', the spring floor's).
inline const World* worldOf(const Simulation& sim)
{
    const auto* physical = dynamic_cast<const PhysicalSimulation*>(&sim);
    return physical ? &physical->world() : nullptr;
}

// The run turns its balls: a physical simulation of stages 1-3 whose contacts have
// friction, or whose start state spins; a physical many-balls run with rough balls or a
// start with spins (a `spin` bound, or spins from --init). Its trajectory CSV carries wx,wy,wz.
bool hasRotation(const Simulation& sim, const State& start);

// Validates the integrator and impact mode for the physical model and the start state
// against the world (every centre on the free side of every wall, pairs at least 2 r
// apart; InputError naming `where`, e.g. "p1" or "--init"), then builds the simulation.
// `names` names each ball's start position parameter for messages ("p0", "p1", "p2").
std::unique_ptr<Simulation> makePhysicalSimulation(const RunSpec& spec, double dt, World world, State initial,
                                                   const std::vector<std::string>& names);

// The builders behind makePhysicalSimulation, one per integrator family.
std::unique_ptr<Simulation> makeSteppedSimulation(const RunSpec& spec, double dt, World world, State initial);
std::unique_ptr<Simulation> makeEventSimulation(const RunSpec& spec, double dt, World world, State initial);

} // namespace ab::physical
