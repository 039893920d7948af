// SPDX-License-Identifier: MIT
// The physical model's entry: one builder per scene, each in the file named after it.
#include "physical_models.h"

namespace ab::physical {

std::unique_ptr<Simulation> makeSimulation(const RunSpec& spec, double dt)
{
    (void)dt;
    throw InputError("--model physical: not available for " + sceneInfo(spec.scene).key + " in this build");
}

} // namespace ab::physical
