// SPDX-License-Identifier: MIT
// Where a scene's balls live, read from its parameters: the region the view frames, the
// floor, the walls, gravity and the radius a ball is drawn with. Shared by the window's
// 3D view and the charts' energy, so both agree on the floor the height is measured from.
#pragma once

#include "core/simulation.h"

#include <Eigen/Geometry>

namespace ab::ui {

struct SceneLayout {
    int axes = 3;               // 1: vertical only (bounce1d)
    Eigen::AlignedBox3d region; // what the camera frames (the box, or the flight column)
    double floorY = 0.0;        // the floor plane
    bool walls = true;          // five faces of a box at region's x and z limits
    double gravity = 0.0;       // magnitude, down is -y
    double ballRadius = 1.0;    // drawn radius in length units (contact radius where the model has one)
    int balls = 1;
};

SceneLayout layoutFor(const RunSpec& spec);

// Kinetic plus potential energy per unit mass, summed over the balls (the report's balls
// have equal masses): sum of |v|^2 / 2 + g (y - floor), in length^2/time^2. Finite states only.
double energyPerMass(const State& s, const SceneLayout& layout);

} // namespace ab::ui
