// SPDX-License-Identifier: MIT
#include "impacts.h"

#include <algorithm>
#include <cmath>

namespace ab::physical {

double resolveWallImpact(const World& w, const Wall& wall, Eigen::Vector3d& v, Eigen::Vector3d& omega, double minFlight)
{
    const double approach = -wall.normalSpeed(v);
    if (!(approach > 0.0))
        return 0.0;
    double rebound = wall.k * approach; // eq 2.3
    // Rest rule: a rebound too slow to matter, or too short for the run to resolve, ends
    // in resting contact instead of an endless (Zeno) series of ever smaller bounces.
    if (w.supports(wall) && (rebound <= w.restSpeed || 2.0 * rebound < minFlight * w.g))
        rebound = 0.0;
    if (w.rough(wall)) {
        // Slip before the impact, g_t = v_t - r w x n (S1). Per unit mass the sticking
        // impulse is (1 + beta) q/(1+q) |g_t| and the sliding bound mu (approach + rebound).
        const Eigen::Vector3d n = wall.normal();
        Eigen::Vector3d g = v - w.spinRadius * omega.cross(n);
        g[wall.axis] = 0.0;
        const double q = w.inertia, speed = g.norm();
        if (speed > 0.0) {
            const double c = waltonFactor(q, w.beta, speed, wall.mu * (approach + rebound));
            v -= c * q * g;                         // dv = P_t / m = -c q g_t      (S9-S10)
            omega += c / w.spinRadius * n.cross(g); // dw = -r n x P_t / I = c n x g_t / r (S13)
        }
    }
    v[wall.axis] = wall.side * rebound;
    return approach;
}

double resolvePairImpact(const World& w, int i, int j, const Eigen::Vector3d& pi, const Eigen::Vector3d& pj,
                         Eigen::Vector3d& vi, Eigen::Vector3d& vj, Spins spins, std::optional<double> e)
{
    const Eigen::Vector3d n = (pi - pj).normalized();
    const double closing = (vi - vj).dot(n);
    if (!(closing < 0.0))
        return 0.0;
    const double mi = w.mass[static_cast<std::size_t>(i)];
    const double mj = w.mass[static_cast<std::size_t>(j)];
    // One impulse J n, added to one ball and taken from the other: momentum is conserved
    // by construction, and the relative normal velocity becomes -e times what it was.
    const double restitution = e.value_or(w.e);
    // The slip at the contact point before the impact (pi - r n = pj + r n):
    // g = v_i - v_j - r (w_i + w_j) x n, and its part along the contact plane (S11).
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    if (w.roughPairs()) {
        g = vi - vj - w.spinRadius * (spins.i + spins.j).cross(n);
        g -= g.dot(n) * n;
    }
    const Eigen::Vector3d impulse = (-(1.0 + restitution) * closing / (1.0 / mi + 1.0 / mj)) * n;
    vi += impulse / mi;
    vj -= impulse / mj;
    const double speed = g.norm();
    if (speed > 0.0) {
        // Per unit reduced mass mr: sticking (1 + beta) q/(1+q) |g_t|, sliding mu (1 + e) |closing|;
        // P_t = -c q mr g_t on i, -P_t on j, and each ball turns by -r n x (+-P_t) / (q m r^2)
        // = c mr n x g_t / (m r), the same sign for both (S12).
        const double q = w.inertia, mr = 1.0 / (1.0 / mi + 1.0 / mj);
        const double c = waltonFactor(q, w.beta, speed, w.pairMu * (1.0 + restitution) * -closing);
        const Eigen::Vector3d tangential = c * q * mr * g; // -P_t
        vi -= tangential / mi;
        vj += tangential / mj;
        const Eigen::Vector3d turn = c * mr / w.spinRadius * n.cross(g);
        spins.i += turn / mi;
        spins.j += turn / mj;
    }
    return -closing;
}

namespace {

// Touching a wall that a push along `dir` would drive the centre into.
bool pinned(const World& w, const Eigen::Vector3d& p, const Eigen::Vector3d& dir)
{
    for (const Wall& wall : w.walls)
        if (wall.gap(p) <= 0.0 && wall.side * dir[wall.axis] < 0.0)
            return true;
    return false;
}

} // namespace

void separatePair(const World& w, int i, int j, Eigen::Vector3d& pi, Eigen::Vector3d& pj, bool walls)
{
    const Eigen::Vector3d d = pi - pj;
    const double dist = d.norm();
    if (dist == 0.0)
        return; // coincident centres have no line between them; nothing sensible to do
    const double mi = w.mass[static_cast<std::size_t>(i)];
    const double mj = w.mass[static_cast<std::size_t>(j)];
    const Eigen::Vector3d push = (2.0 * w.radius - dist) / dist * d;
    double shareI = mj / (mi + mj);
    if (walls) {
        const bool pinI = pinned(w, pi, push), pinJ = pinned(w, pj, -push);
        if (pinI != pinJ)
            shareI = pinI ? 0.0 : 1.0;
    }
    pi += shareI * push;
    pj -= (1.0 - shareI) * push;
}

} // namespace ab::physical
