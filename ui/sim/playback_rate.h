// SPDX-License-Identifier: MIT
// Simulated time per real second at 1x speed, shared by the window's playback and the
// animation export (a clip at 1x runs as the window plays): stages 2-3 count seconds;
// stage 1 counts steps of 0.1 s (report 2.2.1: g = 9.82 read with the step as 0.1 s);
// stage 4 counts frames of a 60 Hz display, as the report's WebGL program ran.
#pragma once

#include "core/scene.h"

namespace ab::ui {

inline double playbackRate(const SceneInfo& scene)
{
    if (scene.timeUnit == "step")
        return 10.0;
    if (scene.timeUnit == "frame")
        return 60.0;
    return 1.0;
}

} // namespace ab::ui
