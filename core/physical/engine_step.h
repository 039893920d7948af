// SPDX-License-Identifier: MIT
// The Simulation::step of an engine that moves its balls in place (many-balls, the street):
// one step of the engine, its balls stored into `next` one dt after `s`, the scene's counter
// carried over and the step's impacts added to the run's.
#pragma once

#include "../state.h"

namespace ab::physical {

template <typename Engine> void stepEngine(Engine& engine, const State& s, State& next, double dt)
{
    engine.step();
    engine.store(next);
    next.t = s.t + dt;
    next.count = s.count;
    next.impacts = s.impacts + engine.impactsLastStep();
    next.halted = false;
}

} // namespace ab::physical
