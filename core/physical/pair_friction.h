// SPDX-License-Identifier: MIT
// Walton's tangential impulse between two equal rough balls (docs/spin.md S11-S12), per
// unit mass: the many-balls engine and the street's pairs use this one rule.
#pragma once

#include "many_balls_walls.h"

#include <Eigen/Geometry>

namespace ab::physical {

// The two balls of a contact, a and b (the normal n from a to b), unit masses.
struct PairVelocities {
    Eigen::Vector3d va, vb, wa, wb;
};

// The reduced mass is 1/2: the slip at the contact point g = v_b - v_a - r (w_a + w_b) x n,
// its part along the contact plane, the factor c of S9-S10 (impacts.h) with pn the normal
// impulse per unit reduced mass (1 + e) |u|; P_t = -c q g / 2 on b and -P_t on a, so the
// momentum v_a + v_b is kept, and both spins change by c n x g / (2 r): equally, in the
// same sense.
inline void waltonBetween(PairVelocities& p, const Eigen::Vector3d& n, double pn, const manyballs::Friction& f)
{
    Eigen::Vector3d g = p.vb - p.va - f.r * (p.wa + p.wb).cross(n);
    g -= g.dot(n) * n;
    const double slip = g.norm();
    if (!(slip > 0.0))
        return;
    const double c = waltonFactor(f.q, f.beta, slip, f.mu * pn);
    const Eigen::Vector3d tangential = 0.5 * c * f.q * g; // -P_t on b    (S11)
    p.vb -= tangential;
    p.va += tangential;
    const Eigen::Vector3d turn = 0.5 * c / f.r * n.cross(g); // -r n x (+-P_t) / I   (S12)
    p.wa += turn;
    p.wb += turn;
}

} // namespace ab::physical
