// SPDX-License-Identifier: MIT
// The street of stage 5 as the 3D view draws it: every box of the core's layout
// (core/street/street_layout.h) as a shaded block, the road asphalt grey with a dashed
// centre line, the crossings paler with zebra stripes, the sidewalks concrete, the parked
// cars in colours, and a terrace of painted house fronts along both sides whose roofs
// follow the road. The houses on the near side (+z) go to their own list, so that the side
// shot can leave them out and see the road over them.
#pragma once

#include "scene_geometry.h"

namespace ab::ui {

// How far over the top crossing's far end the label "top, H m above the foot" stands: high
// enough that from the foot it is drawn over the houses, not over the hopper where the balls
// start (at 8 m it hid them in lecture mode's large text).
constexpr double kTopLabelHeight = 18.0;

// Fills `g` (floor: opaque triangles; cutaway: the +z houses; lines; labels; the framed
// region) for `street`, labels in `lengthUnit`.
void addStreetGeometry(SceneGeometry& g, const street::Layout& street, const QString& lengthUnit);

// The street's solid parts as the view draws them: the layout's boxes, its tall house fronts
// replaced by the terrace of houses drawn in their place (the camera keeps out of these).
std::vector<street::Box> streetSolids(const street::Layout& street);

} // namespace ab::ui
