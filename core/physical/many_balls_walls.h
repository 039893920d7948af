// SPDX-License-Identifier: MIT
// The walls and floor of the many-balls engine (many_balls_physical.h): a ball meeting a
// wall on one axis, the time it takes to get there, and, for rough balls (docs/spin.md),
// Walton's tangential impulse at a wall impact and Coulomb friction while a ball rests on
// the floor. The box is a cube: every centre coordinate stays in [lo, hi]; the floor is
// y = lo, its inward normal n = +y. Quantities are per unit mass (the balls are equal).
#pragma once

#include "impacts.h"
#include "rolling.h"

#include <cmath>
#include <limits>

namespace ab::physical::manyballs {

constexpr double kNever = std::numeric_limits<double>::infinity();

// Friction at every contact: Coulomb's mu, tangential restitution beta, I = q m r^2.
struct Friction {
    double mu = 0.0, beta = -1.0, q = 0.4, r = 1.0;
};

struct Walls {
    double lo, hi, k, restSpeed, g;
    Friction friction;
};

// A wall contact on one axis: the centre goes onto the wall, an outward velocity is
// reflected with restitution k (eq 2.3, v1 = -k v0), or stopped when the rebound would be
// slower than the rest speed (a restitution threshold: the ball stays on the wall).
// Returns true for a rebound.
inline bool wallContact(double& p, double& v, double lo, double hi, double k, double restSpeed)
{
    double outward = 0.0;
    if (p <= lo) {
        p = lo;
        outward = -v;
    } else if (p >= hi) {
        p = hi;
        outward = v;
    }
    if (!(outward > 0.0))
        return false;
    const double rebound = k * outward;
    const bool bounces = rebound > 0.0 && rebound >= restSpeed;
    v = bounces ? -k * v : 0.0;
    return bounces;
}

// The earliest time in [0, T] at which the distance to a wall, d + b t + q t^2 (b and q the
// velocity and acceleration towards the inside), reaches zero; kNever if it does not.
inline double timeToWall(double d, double b, double q, double T)
{
    if (d <= 0.0) // on the wall: an impact now if heading out
        return (b < 0.0 || (b == 0.0 && q < 0.0)) ? 0.0 : kNever;
    double t = kNever;
    if (q == 0.0) {
        if (b < 0.0)
            t = d / -b;
    } else {
        const double disc = b * b - 4.0 * q * d;
        if (disc >= 0.0) {
            // Roots of q t^2 + b t + d = 0 without cancellation: s = -(b + sign(b) sqrt(disc)) / 2,
            // t1 = s / q, t2 = d / s.
            const double s = -0.5 * (b + std::copysign(std::sqrt(disc), b));
            const double roots[2] = {s / q, s != 0.0 ? d / s : kNever};
            for (double r : roots)
                if (r >= 0.0 && r < t)
                    t = r;
        }
    }
    return t <= T ? t : kNever;
}

// Walton's impulse at a plane with unit normal n towards the ball, per unit mass: the slip
// g_t = v_t - r w x n (S1), the factor c of S9-S10 (impacts.h) with the normal impulse pn =
// approach + rebound speed, then dv = -c q g_t and dw = c n x g_t / r (S13: the angular
// momentum about the contact point, r n x v + q r^2 w, is kept). The street's faces use it
// with any n (street_contact.h).
inline void waltonAtPlane(Eigen::Vector3d& v, Eigen::Vector3d& w, const Eigen::Vector3d& n, double pn,
                          const Friction& f)
{
    Eigen::Vector3d g = v - f.r * w.cross(n); // S1
    g -= g.dot(n) * n;
    const double slip = g.norm();
    if (!(slip > 0.0))
        return;
    const double c = waltonFactor(f.q, f.beta, slip, f.mu * pn);
    v -= c * f.q * g;          // dv = P_t / m = -c q g_t            (S9-S10)
    w += c / f.r * n.cross(g); // dw = -r n x P_t / I = c n x g_t / r (S13)
}

// waltonAtPlane at the wall of axis a with inward normal n = side e_a.
inline void waltonAtWall(double v[3], double w[3], int a, double side, double pn, const Friction& f)
{
    Eigen::Vector3d vel(v[0], v[1], v[2]), omega(w[0], w[1], w[2]);
    waltonAtPlane(vel, omega, side * Eigen::Vector3d::Unit(a), pn, f);
    for (int k = 0; k < 3; ++k)
        v[k] = vel[k], w[k] = omega[k];
}

// wallContact on axis a, and on a rough wall Walton's impulse when the ball met it. A ball
// `resting` on the floor does not strike it: its friction is floorFriction's.
template <bool Rough>
inline bool wallImpact(double p[3], double v[3], double w[3], int a, const Walls& walls, bool resting)
{
    if constexpr (!Rough) {
        return wallContact(p[a], v[a], walls.lo, walls.hi, walls.k, walls.restSpeed);
    } else {
        const double side = p[a] <= walls.lo ? 1.0 : p[a] >= walls.hi ? -1.0 : 0.0;
        const double approach = -side * v[a]; // towards the wall, > 0 for an impact
        const bool bounces = wallContact(p[a], v[a], walls.lo, walls.hi, walls.k, walls.restSpeed);
        if (approach > 0.0 && !(resting && a == 1 && side > 0.0))
            waltonAtWall(v, w, a, side, approach + std::abs(v[a]), walls.friction);
        return bounces;
    }
}

// A ball resting on the floor for time h: Coulomb friction mu g against the slip
// u = v_t - r w x n = (vx + r wz, 0, vz - r wx) (S1 with n = +y) slows the centre and spins
// the ball up (S2), u shrinking at (1 + 1/q) mu g. When it would vanish within h (t* of
// S3 at most h) the ball takes the rolling state that keeps the angular momentum about
// the contact point (S4); a rolling ball feels no friction (no drag, S5 with D = 0).
// The change is applied at once, at the start of h (first order in the position).
inline void floorFriction(double v[3], double w[3], double h, const Walls& walls)
{
    const Friction& f = walls.friction;
    const double ux = v[0] + f.r * w[2], uz = v[2] - f.r * w[0]; // S1
    const double slip = std::sqrt(ux * ux + uz * uz);
    if (!(slip > 0.0))
        return;
    const double push = f.mu * walls.g; // mu N / m
    if (f.q == 0.0 || slip <= (1.0 + 1.0 / f.q) * push * h) {
        const Eigen::Vector3d n = Eigen::Vector3d::UnitY();
        const Eigen::Vector3d rolled =
            rollingVelocity(Eigen::Vector3d(v[0], 0.0, v[2]), Eigen::Vector3d(w[0], w[1], w[2]), n, f.q, f.r);
        const Eigen::Vector3d spin = n.cross(rolled) / f.r; // w' = n x v' / r + (w.n) n   (S4)
        v[0] = rolled.x(), v[2] = rolled.z();
        w[0] = spin.x(), w[2] = spin.z();
        return;
    }
    const double dv = push * h / slip, dw = dv / (f.q * f.r);
    v[0] -= dv * ux, v[2] -= dv * uz; // dv/dt = -mu g u/|u|                  (S2)
    w[0] += dw * uz, w[2] -= dw * ux; // dw/dt = mu g (n x u/|u|) / (q r)     (S2)
}

} // namespace ab::physical::manyballs
