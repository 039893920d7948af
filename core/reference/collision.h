// SPDX-License-Identifier: MIT
// Textbook outcomes of one collision of two smooth balls, written independently of the
// simulation's impulse code (core/physical/impacts.cpp) so each checks the other.
#pragma once

#include <Eigen/Core>

#include <utility>

namespace ab::reference {

// Head-on (one dimension): velocities u1, u2 before, restitution e, masses m1, m2.
// Momentum m1 v1 + m2 v2 = m1 u1 + m2 u2 and restitution v2 - v1 = e (u1 - u2) give
//   v1 = (m1 u1 + m2 u2 - m2 e (u1 - u2)) / (m1 + m2),
//   v2 = (m1 u1 + m2 u2 + m1 e (u1 - u2)) / (m1 + m2);
// for m1 = m2 these are eqs 2.6-2.7.
std::pair<double, double> headOnOutcome(double m1, double m2, double u1, double u2, double e);

// Oblique: centres p1, p2 in contact. Each velocity splits into a part along the line of
// centres and a part across it (eqs 2.8-2.11); the parts along the line collide head-on,
// the parts across it are kept.
std::pair<Eigen::Vector3d, Eigen::Vector3d> obliqueOutcome(double m1, double m2, const Eigen::Vector3d& p1,
                                                           const Eigen::Vector3d& p2, const Eigen::Vector3d& u1,
                                                           const Eigen::Vector3d& u2, double e);

} // namespace ab::reference
