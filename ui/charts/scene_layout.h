// SPDX-License-Identifier: MIT
// Where a scene's balls live, read from its parameters: the region the view frames, the
// floor, the walls, gravity and the radius a ball is drawn with. Shared by the window's
// 3D view and the recording; the charts' energy comes from core/diagnostics/conservation.h,
// which measures height from the same floor.
#pragma once

#include "core/simulation.h"
#include "core/street/street_layout.h"

#include <Eigen/Geometry>

#include <memory>

namespace ab::ui {

struct SceneLayout {
    int axes = 3;               // 1: vertical only (bounce1d)
    Eigen::AlignedBox3d region; // what the camera frames (the box, or the flight column)
    double floorY = 0.0;        // the floor plane
    bool walls = true;          // five faces of a box at region's x and z limits
    double gravity = 0.0;       // magnitude, down is -y
    double ballRadius = 1.0;    // drawn radius in length units (contact radius where the model has one)
    // Where the ball is a point for contact (stages 1 and 2): the floor and walls are drawn this
    // far beyond the faces its centre meets, so that the drawn ball touches them with its
    // surface (rests on the floor, rolls on it) instead of sinking half into them. 0
    // where the balls have a contact radius.
    double drawnInset = 0.0;
    // The report's bounce limit sets the ball's position to zero (Appendices A and B): the
    // drawn path ends where the ball was when it was stopped, instead of a straight line to
    // the origin that reads as motion.
    bool pathEndsAtHalt = false;
    int balls = 1;
    // The street of stage 5 (road blocks, crossings, sidewalks, houses, cars), built once
    // from the parameters; null in the other stages. Its region is the road's extent.
    std::shared_ptr<const street::Layout> street;
};

SceneLayout layoutFor(const RunSpec& spec);

} // namespace ab::ui
