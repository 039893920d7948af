// SPDX-License-Identifier: MIT
// Textbook rigid-ball physics for the four scenes (the `physical` model): impulses with
// restitution that conserve momentum for any masses, contact normals from the geometry,
// a physical rest rule, and any of the integrators. One builder per scene, each in the
// file named after its scene.
#pragma once

#include "../simulation.h"

#include <memory>

namespace ab::physical {

std::unique_ptr<Simulation> makeSimulation(const RunSpec& spec, double dt);

std::unique_ptr<Simulation> makeBounce1d(const RunSpec& spec, double dt);
std::unique_ptr<Simulation> makeBox3d(const RunSpec& spec, double dt);
std::unique_ptr<Simulation> makeTwoBalls(const RunSpec& spec, double dt);
std::unique_ptr<Simulation> makeManyBalls(const RunSpec& spec, double dt);

} // namespace ab::physical
