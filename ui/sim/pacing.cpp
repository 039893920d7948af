// SPDX-License-Identifier: MIT
#include "pacing.h"

namespace ab::ui {

double defaultSpeed(SceneId scene)
{
    switch (scene) {
    case SceneId::Bounce1d:
    case SceneId::Box3d:
        return 10.0;
    case SceneId::TwoBalls:
        return 5.0;
    case SceneId::ManyBalls:
    case SceneId::Street:
        return 1.0;
    }
    return 1.0;
}

} // namespace ab::ui
