// SPDX-License-Identifier: MIT
// One step of each time-stepping integrator for one ball, as a map from the state at the
// start of a step to the state h later. Located impacts evaluate this same map at a
// shortened step, so the time of impact is found on the integrator's own trajectory.
#pragma once

#include "../scene.h"
#include "world.h"

namespace ab::physical {

struct Kinematics {
    Eigen::Vector3d p, v;
    Eigen::Vector3d w = Eigen::Vector3d::Zero(); // spin
};

// Advances ball i by h with `integrator` (euler, symplectic-euler, verlet or rk4;
// anything else is a logic error). `support` is the wall it rests on, or null. The spin
// follows dw/dt = alpha (rolling.h) with the same scheme as the velocity: in flight alpha
// is zero, so every integrator keeps w exactly (free rotation of a sphere).
Kinematics advance(Integrator integrator, const World& w, int i, const Wall* support, const Kinematics& s, double h);

// Under a constant acceleration a every integrator's step is a polynomial in h:
// p(h) = p + v h + alpha a h^2, with alpha = 0 (euler: the position moves with the old
// velocity), 1 (symplectic Euler: with the new one) or 1/2 (verlet and rk4, exact).
double positionCurvature(Integrator integrator);

} // namespace ab::physical
