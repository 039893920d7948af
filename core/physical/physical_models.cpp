// SPDX-License-Identifier: MIT
#include "physical_models.h"

#include "../street/street_engine.h"

namespace ab::physical {

std::unique_ptr<Simulation> makeSimulation(const RunSpec& spec, double dt)
{
    switch (spec.scene) {
    case SceneId::Bounce1d:
        return makeBounce1d(spec, dt);
    case SceneId::Box3d:
        return makeBox3d(spec, dt);
    case SceneId::TwoBalls:
        return makeTwoBalls(spec, dt);
    case SceneId::ManyBalls:
        return makeManyBalls(spec, dt);
    case SceneId::Street:
        return street::makeStreet(spec, dt);
    }
    throw std::logic_error("scene without a physical model");
}

} // namespace ab::physical
