// SPDX-License-Identifier: MIT
#include "rolling.h"

#include "roots.h"

#include <cmath>
#include <limits>

namespace ab::physical {

namespace {

Eigen::Vector3d along(const Wall& wall, Eigen::Vector3d v)
{
    v[wall.axis] = 0.0;
    return v;
}

// Rolling with a tangential force D (per unit mass, drag) on the centre: the constraint
// du/dt = 0 takes the friction F/m = -q D / (1 + q) (S5), so
//     a_t = D / (1 + q),   dw/dt = n x a_t / r                           (S6)
// while |F| <= mu N; past that the ball slides with |F| = mu N along the same direction
// (dw/dt = -(n x F/m) / (q r), from I dw/dt = -r n x F).
void rollingRates(const World& w, const Wall& wall, double press, Rates& out)
{
    const Eigen::Vector3d n = wall.normal();
    const double q = w.inertia, r = w.spinRadius;
    const Eigen::Vector3d d = along(wall, out.a);
    Eigen::Vector3d f = -q / (1.0 + q) * d;
    const double need = f.norm(), most = wall.mu * press;
    if (need <= most) {
        out.a += f;
        out.alpha = n.cross(along(wall, out.a)) / r;
        return;
    }
    f *= most / need;
    out.a += f;
    out.alpha = -n.cross(f) / (q * r);
}

} // namespace

Eigen::Vector3d slip(const World& w, const Wall& wall, const Eigen::Vector3d& v, const Eigen::Vector3d& omega)
{
    return along(wall, v) - w.spinRadius * omega.cross(wall.normal()); // S1
}

bool rolls(const World& w, const Wall& wall, const Eigen::Vector3d& v, const Eigen::Vector3d& omega)
{
    // u is a difference of two terms of size |v_t| and r |w x n|: a slip of a few hundred
    // units in their last place is round-off, and sliding it off would take ~1e-13 t*.
    constexpr double roundOff = 256.0 * std::numeric_limits<double>::epsilon();
    const double scale = along(wall, v).norm() + w.spinRadius * omega.cross(wall.normal()).norm();
    return slip(w, wall, v, omega).norm() <= roundOff * scale;
}

Rates rates(const World& w, int i, const Eigen::Vector3d& v, const Eigen::Vector3d& omega, const Wall* support)
{
    Rates out{acceleration(w, i, v, support), Eigen::Vector3d::Zero()};
    if (!support || !w.rough(*support))
        return out;
    const double press = pressing(w, i, v, *support);
    if (!(press > 0.0))
        return out; // lifting off: no normal force, no friction
    if (rolls(w, *support, v, omega) || w.inertia == 0.0) {
        rollingRates(w, *support, press, out);
        return out;
    }
    const Eigen::Vector3d u = slip(w, *support, v, omega);
    const Eigen::Vector3d dir = u / u.norm();
    const double f = support->mu * press;                                      // mu N / m
    out.a -= f * dir;                                                          // S2
    out.alpha = f / (w.inertia * w.spinRadius) * support->normal().cross(dir); // S2
    return out;
}

double rollTime(const World& w, int i, const Eigen::Vector3d& v, const Eigen::Vector3d& omega, const Wall* support)
{
    if (!support || !w.rough(*support) || rolls(w, *support, v, omega))
        return never;
    const double press = pressing(w, i, v, *support);
    if (!(press > 0.0))
        return never;
    if (w.inertia == 0.0)
        return 0.0;
    const Eigen::Vector3d u = slip(w, *support, v, omega);
    const double speed = u.norm();
    // The slip's rate of change along itself, du/dt = a_t - r alpha x n (from S1): with no
    // drag -(1 + 1/q) mu N/m exactly (S3).
    const Rates k = rates(w, i, v, omega, support);
    const double decel = -(along(*support, k.a) - w.spinRadius * k.alpha.cross(support->normal())).dot(u / speed);
    return decel > 0.0 ? speed / decel : never;
}

void roll(const World& w, const Wall& wall, Eigen::Vector3d& v, Eigen::Vector3d& omega)
{
    const Eigen::Vector3d n = wall.normal();
    const double q = w.inertia, r = w.spinRadius;
    const Eigen::Vector3d vt = rollingVelocity(along(wall, v), omega, n, q, r); // S4
    const double spinAbout = omega.dot(n);
    const double normalPart = v[wall.axis];
    v = vt;
    v[wall.axis] = normalPart;
    omega = n.cross(vt) / r + spinAbout * n;
}

} // namespace ab::physical
