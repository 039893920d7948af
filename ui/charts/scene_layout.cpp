// SPDX-License-Identifier: MIT
#include "scene_layout.h"

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

// Stage 1: a column above the floor, as tall as the highest point of the flight:
// h0 + v0^2 / (2 g) when thrown upwards (energy conservation, eqs 2.1-2.2).
SceneLayout bounce1dLayout(const ParamValues& v)
{
    SceneLayout l;
    l.axes = 1;
    l.walls = false;
    l.gravity = v.real("g");
    const double h0 = v.real("h0");
    const double v0 = v.real("v0");
    double top = h0;
    if (v0 > 0.0)
        top = l.gravity > 0.0 ? h0 + v0 * v0 / (2.0 * l.gravity) : h0 + std::abs(v0) * 100.0;
    top = std::max(top, 1.0);
    const double half = 0.2 * top;
    l.region = Eigen::AlignedBox3d(Eigen::Vector3d(-half, 0.0, -half), Eigen::Vector3d(half, top, half));
    l.ballRadius = top / 60.0;   // a point for contact; drawn at a readable size
    l.drawnInset = l.ballRadius; // the floor drawn a radius down: the ball at y = 0 rests on it
    return l;
}

// Stages 2-3: the box has a corner at the origin and side `box`, y up, no ceiling.
SceneLayout cornerBoxLayout(const ParamValues& v, double radius, int balls)
{
    SceneLayout l;
    l.gravity = v.real("g");
    const double side = v.real("box");
    l.region = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(side));
    l.ballRadius = radius;
    l.balls = balls;
    return l;
}

// Stage 4: the box is centred at the origin (Appendix D), floor at -box/2.
SceneLayout centredBoxLayout(const ParamValues& v)
{
    SceneLayout l;
    l.gravity = v.real("g");
    const double half = v.real("box") / 2.0;
    l.region = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-half), Eigen::Vector3d::Constant(half));
    l.floorY = -half;
    l.ballRadius = v.real("r");
    l.balls = static_cast<int>(v.integer("n"));
    return l;
}

// Stage 5: the street, x down it from the top crossing's upper end to the open foot, y
// up from the foot's road (y = 0) to the top's (`height`), z across the roadway and both
// sidewalks. The floor is the foot's road; the houses and hopper stand above the region.
SceneLayout streetLayout(const ParamValues& v)
{
    SceneLayout l;
    auto street = std::make_shared<const street::Layout>(street::Layout::fromParams(v));
    const double across = 0.5 * street->width + street->sidewalk;
    l.region = Eigen::AlignedBox3d(Eigen::Vector3d(street->xTop, 0.0, -across),
                                   Eigen::Vector3d(street->xFoot, street->height + 2.0, across));
    l.walls = false;
    l.gravity = v.real("g");
    l.ballRadius = v.real("r");
    l.balls = static_cast<int>(v.integer("n"));
    l.street = std::move(street);
    return l;
}

} // namespace

SceneLayout layoutFor(const RunSpec& spec)
{
    const ParamValues& v = spec.params;
    switch (spec.scene) {
    case SceneId::Bounce1d:
        return bounce1dLayout(v);
    case SceneId::Box3d: {
        SceneLayout l = cornerBoxLayout(v, v.real("box") / 80.0, 1); // a point for contact; drawn at 1/80 of the box
        l.drawnInset = l.ballRadius;
        l.pathEndsAtHalt = spec.model == ModelKind::Report;
        return l;
    }
    case SceneId::TwoBalls:
        return cornerBoxLayout(v, v.real("r"), 2);
    case SceneId::ManyBalls:
        return centredBoxLayout(v);
    case SceneId::Street:
        return streetLayout(v);
    }
    throw std::logic_error("scene without a layout");
}

} // namespace ab::ui
