// SPDX-License-Identifier: MIT
// A rough ball resting on a supporting wall (the floor): Coulomb friction acts at its
// contact point, continuously, and turns sliding into rolling (docs/spin.md, eqs S1-S6).
// With n the wall's inward normal, the contact point sits at -r n from the centre and
// moves with the slip velocity
//     u = v_t - r w x n                                             (S1)
// (v_t: the centre's velocity along the wall). While u != 0 the ball slides: friction
// F = -mu N u/|u| decelerates the centre and spins the ball up,
//     dv/dt = -mu (N/m) u/|u|,   dw/dt = mu (N/m) (n x u/|u|) / (q r)   (S2)
// so that du/dt = -(1 + 1/q) mu (N/m) u/|u|: the slip keeps its direction and shrinks
// linearly to zero at
//     t* = q |u| / ((1 + q) mu N/m)                                   (S3)
// (t* = q v0 / ((1 + q) mu g) for a ball set down sliding without spin). From there it
// rolls, u = 0, as long as the friction that takes costs at most mu N.
#pragma once

#include "world.h"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

namespace ab::physical {

// The time derivatives of a ball's velocity and spin.
struct Rates {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    Eigen::Vector3d alpha = Eigen::Vector3d::Zero();
};

// Ball i at velocity v and spin omega, resting on `support` (or flying, null): gravity,
// drag, the normal force and, on a rough support, friction (S2 sliding, S6 rolling).
// Without friction alpha is zero and a is acceleration() exactly.
Rates rates(const World& w, int i, const Eigen::Vector3d& v, const Eigen::Vector3d& omega, const Wall* support);

// The slip velocity u of S1 at `wall`.
Eigen::Vector3d slip(const World& w, const Wall& wall, const Eigen::Vector3d& v, const Eigen::Vector3d& omega);

// Rolling: the slip is zero up to round-off of the velocities it is made of.
bool rolls(const World& w, const Wall& wall, const Eigen::Vector3d& v, const Eigen::Vector3d& omega);

// When the sliding ball i rolls (S3 with its friction as it is now; exact without drag,
// first order with it); `never` when it rolls already, flies or nothing rubs. 0 for
// q = 0: a ball without rotational inertia spins up at once.
double rollTime(const World& w, int i, const Eigen::Vector3d& v, const Eigen::Vector3d& omega, const Wall* support);

// The rolling state that friction leads a sliding ball to: the angular momentum about
// the contact point, m r n x v + I w, is kept (friction acts there), so
//     v' = (v_t + q r w x n) / (1 + q) + v_n n,   w' = n x v'_t / r + (w.n) n   (S4)
// (spin about the normal is kept: the contact point has no lever on it).
void roll(const World& w, const Wall& wall, Eigen::Vector3d& v, Eigen::Vector3d& omega);

// The centre's velocity along the wall once it rolls (S4): vt the velocity along the wall,
// n the wall's inward normal, q and r of I = q m r^2. Shared with the many-balls engine.
inline Eigen::Vector3d rollingVelocity(const Eigen::Vector3d& vt, const Eigen::Vector3d& omega,
                                       const Eigen::Vector3d& n, double q, double r)
{
    return (vt + q * r * omega.cross(n)) / (1.0 + q);
}

} // namespace ab::physical
