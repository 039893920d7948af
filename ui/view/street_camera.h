// SPDX-License-Identifier: MIT
// The street's camera shots (stage 5): from the foot of the hill looking up the street,
// low on the road as the advert's camera stood; from the side and above, the whole street
// with the near houses cut away; and following the front of the flood down the hill.
#pragma once

#include "orbit_camera.h"

#include "core/street/street_layout.h"

#include <optional>
#include <vector>

namespace ab::ui {

enum class StreetShot { Foot, Side, Flood };

// The pose of `shot` for a view of aspect `aspect` (width / height); the flood shot looks at
// `front` (floodFront), or at the hopper before the balls are known.
CameraPose streetPose(const street::Layout& street, StreetShot shot, float aspect, std::optional<float> front = {});

// The front of the flood: the x that only one ball in 200 of those still on the street
// passes (a lone runaway ball does not drag the camera away), from centres x y z per ball;
// nothing when no ball is on the street.
std::optional<float> floodFront(const street::Layout& street, const std::vector<float>& xyz);

// Whether the ball at x has left the run at the open foot and is not drawn.
bool ballHidden(const street::Layout& street, float x);

} // namespace ab::ui
