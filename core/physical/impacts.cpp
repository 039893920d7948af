// SPDX-License-Identifier: MIT
#include "impacts.h"

#include <algorithm>
#include <cmath>

namespace ab::physical {

double resolveWallImpact(const World& w, const Wall& wall, Eigen::Vector3d& v, double minFlight)
{
    const double approach = -wall.normalSpeed(v);
    if (!(approach > 0.0))
        return 0.0;
    double rebound = wall.k * approach; // eq 2.3
    // Rest rule: a rebound too slow to matter, or too short for the run to resolve, ends
    // in resting contact instead of an endless (Zeno) series of ever smaller bounces.
    if (w.supports(wall) && (rebound <= w.restSpeed || 2.0 * rebound < minFlight * w.g))
        rebound = 0.0;
    if (wall.mu > 0.0) {
        Eigen::Vector3d slide = v;
        slide[wall.axis] = 0.0;
        const double speed = slide.norm();
        if (speed > 0.0) {
            const double loss = std::min(speed, wall.mu * (approach + rebound));
            v -= loss / speed * slide;
        }
    }
    v[wall.axis] = wall.side * rebound;
    return approach;
}

double resolvePairImpact(const World& w, int i, int j, const Eigen::Vector3d& pi, const Eigen::Vector3d& pj,
                         Eigen::Vector3d& vi, Eigen::Vector3d& vj, std::optional<double> e)
{
    const Eigen::Vector3d n = (pi - pj).normalized();
    const double closing = (vi - vj).dot(n);
    if (!(closing < 0.0))
        return 0.0;
    const double mi = w.mass[static_cast<std::size_t>(i)];
    const double mj = w.mass[static_cast<std::size_t>(j)];
    // One impulse J n, added to one ball and taken from the other: momentum is conserved
    // by construction, and the relative normal velocity becomes -e times what it was.
    const Eigen::Vector3d impulse = (-(1.0 + e.value_or(w.e)) * closing / (1.0 / mi + 1.0 / mj)) * n;
    vi += impulse / mi;
    vj -= impulse / mj;
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
