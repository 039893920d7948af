// SPDX-License-Identifier: MIT
#include "physical_models.h"

namespace ab::physical {

std::unique_ptr<Simulation> makeBounce1d(const RunSpec& spec, double)
{
    throw InputError("--model physical: not available for " + sceneInfo(spec.scene).key + " in this build");
}

} // namespace ab::physical
