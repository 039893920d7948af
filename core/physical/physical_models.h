// SPDX-License-Identifier: MIT
// Textbook rigid-ball physics for the four scenes (the `physical` model).
#pragma once

#include "../simulation.h"

#include <memory>

namespace ab::physical {

std::unique_ptr<Simulation> makeSimulation(const RunSpec& spec, double dt);

} // namespace ab::physical
