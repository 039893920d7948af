// SPDX-License-Identifier: MIT
// How fast each stage plays when it is opened: fast enough that what it is about shows
// within a few seconds of Play (a lecture cannot wait 20 s for the first bounce), and
// said on screen in words. 1x is real time in the stage's own units
// (RunController::realTimeRate: 10 steps a second in stage 1, seconds in stages 2-3, 60
// frames a second in stage 4).
#pragma once

#include "core/scene.h"

namespace ab::ui {

// The longest wait, in seconds of wall time, from Play to the first thing a stage or a
// built-in preset is about (its first impact, or the preset's event).
inline constexpr double kLessonWait = 3.0;

// The speed a stage opens at:
//  stage 1: the first bounce comes after sqrt(2 h0 / g) = sqrt(2 * 2000 / 0.0982) = 201.8
//           steps, 20.2 s at 1x (10 steps a second): 10x brings it to 2.0 s;
//  stage 2: the first wall (z = 300 at vz = 15 m/s from z = 2) after 19.9 s: 10x, 2.0 s;
//  stage 3: the balls 296 m apart close at 30 m/s and touch after (296 - 2 r) / 30 = 9.8 s:
//           5x, 2.0 s;
//  stage 4: the balls start packed in a cube 18 wide and collide in the first frames: 1x;
//  stage 5: the hopper's lowest layer lands on the top crossing from 0.5 m in
//           sqrt(2 * 0.5 / 9.82) = 0.32 s, and the first balls roll onto the first block
//           within a second or two: 1x (real time, as the advert was filmed).
double defaultSpeed(SceneId scene);

} // namespace ab::ui
