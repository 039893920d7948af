// SPDX-License-Identifier: MIT
// The street's camera shots (stage 5): from the foot of the hill looking up the street,
// low on the road as the advert's camera stood; from the side and above, the whole street
// with the near houses cut away; and following the front of the flood down the hill.
#pragma once

#include "orbit_camera.h"

#include "core/street/street_layout.h"

#include <memory>
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

// How near the eye may come to the street's solid parts (m): beyond the near plane of the
// view's projection (OrbitCamera::projection, a quarter of a metre on the street), so a
// camera stopped at a wall or the road does not cut into it.
inline constexpr float kStreetEyeClearance = 0.5f;

// The street's solid parts as the view draws them (streetSolids), for the camera moved by
// hand: it keeps its eye out of them, and zooms towards the point of them under the pointer.
class StreetSolids {
public:
    explicit StreetSolids(std::shared_ptr<const street::Layout> street);

    // Whether an eye at `eye` stands clear: kStreetEyeClearance above the road's surface
    // (roadY: the ground under the houses and past the foot too) and as far from every box.
    bool clear(const QVector3D& eye) const;
    // The first point of a solid part, or of the flat street past the foot, on the ray from
    // `origin` along unit `direction`; none when the ray meets only the sky.
    std::optional<QVector3D> hit(const QVector3D& origin, const QVector3D& direction) const;

    // Whether a solid part stands between `eye` and `point`, more than half a metre before it
    // (a point on a surface, or just over it, is not hidden by that surface).
    bool hides(const QVector3D& eye, const QVector3D& point) const;

private:
    std::shared_ptr<const street::Layout> street_;
    std::vector<street::Box> boxes_;
};

// Whether the ball at x has left the run at the open foot and is not drawn.
bool ballHidden(const street::Layout& street, float x);

} // namespace ab::ui
