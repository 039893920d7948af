// SPDX-License-Identifier: MIT
// Impact rules of the physical model, shared by every integrator and scene: an
// instantaneous impulse along the contact normal with restitution, Coulomb friction
// along the tangent the velocity itself gives, and the rest rule. They change velocities
// only; where the impact happens is the integrator's business.
#pragma once

#include "world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ab::physical {

// Ball with velocity v hits `wall` (its centre on the wall). Along the normal
// v_n'' = -k v_n' (eq 2.3); along the wall the tangential velocity v_t (whatever its
// direction) loses at most mu times the normal change, |dv_t| <= mu |dv_n| (Coulomb
// impulse friction; it stops at zero, it does not reverse). On a supporting wall the
// rebound is cut to zero (the ball stays in resting contact) when it is slower than
// w.restSpeed or when its flight 2 u / g would be shorter than `minFlight`.
// Returns the approach speed (0 when the ball was not approaching: v is unchanged).
double resolveWallImpact(const World& w, const Wall& wall, Eigen::Vector3d& v, double minFlight);

// The shortest bounce off `wall` that double precision can follow at time t. A flight
// must last about a thousand units in the last place of t, or its timing is so coarse
// that rounding, not restitution, sets the rebound (it stops shrinking); and it must
// rise a thousand units in the last place of the wall's coordinate, or the height cannot
// be told from the wall. The rest rule cuts shorter bounces: they are far below anything
// a run can show.
inline double shortestFlight(const World& w, const Wall& wall, double t)
{
    constexpr double ulps = 1024.0 * std::numeric_limits<double>::epsilon();
    const double height = ulps * std::abs(wall.position); // a bounce of height H lasts 2 sqrt(2 H / g)
    return std::max(ulps * std::abs(t), w.g > 0.0 ? 2.0 * std::sqrt(2.0 * height / w.g) : 0.0);
}

// Balls i and j (centres pi, pj) collide: with n the unit vector along the line of
// centres, the normal parts follow momentum conservation for any masses and restitution
// e (eqs 2.4-2.7 with masses), the tangential parts are kept (eqs 2.8-2.11):
// J = -(1 + e) (v_i - v_j).n / (1/m_i + 1/m_j), v_i += J n / m_i, v_j -= J n / m_j.
// Returns the approach speed along n (0 when they were not approaching). `e` overrides
// the world's restitution when given.
double resolvePairImpact(const World& w, int i, int j, const Eigen::Vector3d& pi, const Eigen::Vector3d& pj,
                         Eigen::Vector3d& vi, Eigen::Vector3d& vj, std::optional<double> e = std::nullopt);

// Moves two overlapping (or nearly touching) centres apart along their line to exactly
// 2 r, each by its share of the inverse mass, so the centre of mass stays where it was.
// With `walls`, a ball touching a wall that the push would drive it into stays put and
// the other moves the whole way (a ball on the floor is not pushed into it).
void separatePair(const World& w, int i, int j, Eigen::Vector3d& pi, Eigen::Vector3d& pj, bool walls = false);

} // namespace ab::physical
