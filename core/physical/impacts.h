// SPDX-License-Identifier: MIT
// Impact rules of the physical model, shared by every integrator and scene: an
// instantaneous impulse along the contact normal with restitution, a tangential impulse
// at rough contacts (Walton's model, below), and the rest rule. They change velocities
// and spins only; where the impact happens is the integrator's business.
//
// Walton's tangential impulse (docs/spin.md, eqs S9-S13). At the contact point the
// tangential relative velocity g_t (the slip, rolling.h S1) changes by an impulse P_t;
// with the ball's rotation it answers with the effective mass m* = q/(1+q) m (for a pair
// with m the reduced mass m_i m_j / (m_i + m_j)), g_t' = g_t + P_t / m*. The impulse is
// the smaller of
//     sticking:  P_t = -(1 + beta) m* g_t      (g_t' = -beta g_t)        (S9)
//     sliding:   |P_t| = mu P_n, against g_t   (Coulomb)                  (S10)
// and it turns the ball(s) by dw = -r n x P_t / I about the centre (n: the normal towards
// the ball). With mu = 0 or beta = -1 the impulse is zero and nothing changes.
#pragma once

#include "world.h"

#include <Eigen/Geometry> // cross products

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ab::physical {

// Walton's rule (S9-S10) as one factor c: the tangential impulse is P_t = -c q m g_t, m the
// ball's mass at a wall or the pair's reduced mass, so that g_t' = g_t + P_t / m* with
// m* = q/(1+q) m. `slip` is |g_t|; `slide` is the sliding bound mu P_n / m (P_n the normal
// impulse). Sticking (S9) gives c = (1 + beta)/(1 + q); when it asks for more than
// Coulomb's bound (S10) it is scaled down to that bound. Every scene's contacts use it
// (impacts.cpp; the many-balls engine's walls and pairs).
inline double waltonFactor(double q, double beta, double slip, double slide)
{
    const double stick = (1.0 + beta) * q / (1.0 + q) * slip;  // |P_t| / m of S9
    const double share = stick <= slide ? 1.0 : slide / stick; // S10 when smaller
    return share * (1.0 + beta) / (1.0 + q);
}

// Ball with velocity v and spin omega hits `wall` (its centre on the wall). Along the
// normal v_n'' = -k v_n' (eq 2.3); along the wall Walton's impulse (S9-S10) on a rough
// wall, which keeps the angular momentum about the contact point, m r n x v + I w (S13).
// On a supporting wall the rebound is cut to zero (the ball stays in resting contact)
// when it is slower than w.restSpeed or when its flight 2 u / g would be shorter than
// `minFlight`. Returns the approach speed (0 when the ball was not approaching: nothing
// changes).
double resolveWallImpact(const World& w, const Wall& wall, Eigen::Vector3d& v, Eigen::Vector3d& omega,
                         double minFlight);

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
// e (eqs 2.4-2.7 with masses):
// J = -(1 + e) (v_i - v_j).n / (1/m_i + 1/m_j), v_i += J n / m_i, v_j -= J n / m_j.
// Smooth balls keep their tangential parts (eqs 2.8-2.11); rough ones (World::roughPairs)
// exchange Walton's impulse P_t at their contact point, +P_t on i and -P_t on j (S11-S12),
// so momentum is kept and both spins change by -r n x P_t / I, the same for equal balls.
// Returns the approach speed along n (0 when they were not approaching). `e` overrides
// the world's restitution when given.
struct Spins {
    Eigen::Vector3d& i;
    Eigen::Vector3d& j;
};
double resolvePairImpact(const World& w, int i, int j, const Eigen::Vector3d& pi, const Eigen::Vector3d& pj,
                         Eigen::Vector3d& vi, Eigen::Vector3d& vj, Spins spins, std::optional<double> e = std::nullopt);

// Moves two overlapping (or nearly touching) centres apart along their line to exactly
// 2 r, each by its share of the inverse mass, so the centre of mass stays where it was.
// With `walls`, a ball touching a wall that the push would drive it into stays put and
// the other moves the whole way (a ball on the floor is not pushed into it).
void separatePair(const World& w, int i, int j, Eigen::Vector3d& pi, Eigen::Vector3d& pj, bool walls = false);

} // namespace ab::physical
