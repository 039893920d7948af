// SPDX-License-Identifier: MIT
#include "physical_models.h"
#include "spring_contact.h"

namespace ab::physical {

std::unique_ptr<Simulation> makeBounce1d(const RunSpec& spec, double dt)
{
    if (contactLawOf(spec) != ContactLaw::Impulse)
        return makeSpringBounce1d(spec, dt); // the floor as a spring (report 1.2)
    throw InputError("--model physical: not available for " + sceneInfo(spec.scene).key + " in this build");
}

} // namespace ab::physical
