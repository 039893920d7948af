// SPDX-License-Identifier: MIT
// The health check's pairs (health.h, check 4): overlaps, balls passing through each other
// or grazing within a step, on all pairs or a grid, and the momentum of a two-ball contact.
#include "health_parts.h"

#include "../broadphase/grid_geometry.h"

#include <cmath>

namespace ab::diagnostics {

namespace health_parts {

double closestApproach(const Eigen::Vector3d& d0, const Eigen::Vector3d& d1)
{
    const Eigen::Vector3d m = d1 - d0;
    const double mm = m.squaredNorm();
    const double s = mm > 0.0 ? std::clamp(-d0.dot(m) / mm, 0.0, 1.0) : 0.0;
    return (d0 + s * m).norm();
}

} // namespace health_parts

void HealthCheck::Impl::checkPair(const State& b, const State& a, int i, int j)
{
    const double contact = 2.0 * r;
    const Eigen::Vector3d d0 = b.p.col(i) - b.p.col(j);
    const Eigen::Vector3d d1 = a.p.col(i) - a.p.col(j);
    const double overlap = contact - d1.norm();
    if (overlap > overlapAllowance * r) {
        fig.maxOverlap = std::max(fig.maxOverlap.value_or(0.0), overlap);
        raise(Kind::Overlap, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
            f.kind = FindingKind::Overlap;
            f.balls = {i, j};
            f.amount = overlap;
            what = "balls " + std::to_string(i) + " and " + std::to_string(j) + " overlap by " + length(overlap) + at();
            advice = impactAdvice(f);
        });
        if (report && spec.scene == SceneId::TwoBalls && d0.norm() < contact)
            raise(Kind::RepeatedSwap, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
                f.kind = FindingKind::RepeatedSwap;
                f.balls = {i, j};
                f.rule = ReportRule::SwapWithoutTest;
                what = "the balls still overlap after a swap" + at() +
                       ": Appendix C swaps velocities with no test that the balls approach, so the swap repeats";
                advice = advise(f, Remedy::ReportPhysical);
            });
    } else if (d0.norm() >= contact) {
        // Both flew freely (equal gravity keeps their relative motion straight), so
        // their distance in the step is that of the straight path from d0 to d1. Where
        // it dips below the contact distance neither saw the other: by more than a
        // tenth of a radius they passed through each other (failed); a shallower dip
        // is a grazing contact the step missed (warning), as a model that finds
        // contacts at the step's end and separates overlaps by moving the centres
        // may leave at speed. (The straight path is measured first: most pairs a grid
        // offers never come near, and then neither flight needs checking.)
        const double closest = closestApproach(d0, d1);
        const double depth = contact - closest;
        const bool missed = depth > 1e-3 * r && freeFlight(b, a, i) && freeFlight(b, a, j);
        if (missed && depth > 0.1 * r)
            raise(Kind::Tunnel, Health::Failed, [&](std::string& what, std::string& advice, Finding& f) {
                f.kind = FindingKind::Tunnel;
                f.balls = {i, j};
                f.amount = closest;
                f.bound = contact;
                what = "balls " + std::to_string(i) + " and " + std::to_string(j) +
                       " passed through each other within one step" + at() + " (closest approach " + length(closest) +
                       ", contact at " + length(contact) + ")";
                advice = impactAdvice(f);
            });
        else if (missed)
            raise(Kind::Graze, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
                f.kind = FindingKind::Graze;
                f.balls = {i, j};
                f.amount = closest;
                f.bound = depth;
                what = "balls " + std::to_string(i) + " and " + std::to_string(j) +
                       " grazed within one step without colliding" + at() + " (closest approach " + length(closest) +
                       ", " + length(depth) + " inside the contact distance)";
                advice = impactAdvice(f);
            });
    }
    fig.maxOverlap = std::max(fig.maxOverlap.value_or(0.0), 0.0);
}

// Only gravity acted on the ball in the step: no wall, no other ball. Its velocity changed
// by gravity's -g dt alone, and its centre moved as a projectile's. Under a constant
// acceleration the move is exactly the mean of the two velocities times dt (x1 - x0 =
// v0 dt + a dt^2 / 2 = (v0 + v1) dt / 2). The street flies exactly (street_flight.cpp), so
// there it must hold to round-off; an integrator of the other scenes may move by v0 dt
// (explicit Euler) to v1 dt (symplectic Euler), each g dt^2 / 2 from the mean. A contact pass
// that parts balls found inside each other moves their centres and leaves their velocities
// alone (street_pairs.cpp point 4): such a ball touched another, and its path in the step
// is not the straight one checkPair assumes.
bool HealthCheck::Impl::freeFlight(const State& b, const State& a, int i) const
{
    const Eigen::Vector3d change = a.v.col(i) - b.v.col(i) + Eigen::Vector3d(0.0, g * dt, 0.0);
    if (change.norm() > 1e-9 * (b.v.col(i).norm() + g * dt))
        return false;
    const Eigen::Vector3d offPath = a.p.col(i) - b.p.col(i) - 0.5 * dt * (a.v.col(i) + b.v.col(i));
    const double slack = streetLayout ? 0.0 : 0.5 * g * dt * dt * (1.0 + 1e-9);
    return offPath.norm() <= slack + tolerance;
}

// Momentum of a two-ball contact: away from the walls only gravity changes it.
void HealthCheck::Impl::checkMomentum(const State& b, const State& a)
{
    const double contact = 2.0 * r;
    const bool touching = (b.p.col(0) - b.p.col(1)).norm() < contact || (a.p.col(0) - a.p.col(1)).norm() < contact;
    if (!touching)
        return;
    for (int i = 0; i < 2; ++i) {
        const double travel = dt * std::max(b.v.col(i).norm(), a.v.col(i).norm()) + g * dt * dt;
        for (const State* s : {&b, &a})
            for (int axis = 0; axis < 3; ++axis)
                if (s->p(axis, i) - walls.lo[axis] <= travel || walls.hi[axis] - s->p(axis, i) <= travel)
                    return; // a wall may have acted in this step: not measurable
    }
    const double scale = b.v.col(0).norm() + b.v.col(1).norm();
    if (!(scale > 0.0))
        return;
    const Eigen::Vector3d gravity(0.0, -2.0 * g * dt, 0.0);
    const double error = ((a.v.col(0) + a.v.col(1)) - (b.v.col(0) + b.v.col(1)) - gravity).norm() / scale;
    fig.maxMomentumError = std::max(fig.maxMomentumError.value_or(0.0), error);
    if (error <= 1e-9)
        return;
    raise(Kind::Momentum, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
        f.kind = FindingKind::Momentum;
        f.balls = {0, 1};
        f.amount = 100.0 * error;
        if (report)
            f.rule = ReportRule::SwapScaledByE;
        what = "momentum changed by " + num(f.amount) + "% of the pair's speeds in a contact" + at() +
               (report ? " (Appendix C scales both swapped velocities by e)" : "");
        advice = advise(f, report ? Remedy::ReportMomentum : Remedy::SmallerDt);
    });
}

void HealthCheck::Impl::checkPairs(const State& b, const State& a)
{
    const int n = a.size();
    if (n < 2 || !(r > 0.0))
        return;
    if (streetLayout) { // the balls on the street, in a grid of any shape
        if (n <= sampledAbove || pairChecks++ % 10 == 0)
            hashedOverlaps(b, a);
        return;
    }
    if (n <= 256) {
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j)
                checkPair(b, a, i, j);
        if (spec.scene == SceneId::TwoBalls)
            checkMomentum(b, a);
        return;
    }
    // Many balls: overlaps on a grid of cells 2r wide; every 10th step beyond 1e5.
    if (n > sampledAbove && pairChecks++ % 10 != 0)
        return;
    gridOverlaps(b, a);
}

void HealthCheck::Impl::gridOverlaps(const State& b, const State& a)
{
    // Counting sort into cells at least 2r wide over the balls' bounding cube
    // (broadphase::GridGeometry: two centres closer than 2r lie in the same or adjacent
    // cells), then each ball against the 27 cells around it, each pair once (j > i):
    // O(N + cells) a step, no allocation once the arrays have grown.
    const int n = a.size();
    const double lo = a.p.minCoeff(), hi = a.p.maxCoeff(); // a cube holding every centre
    const broadphase::GridGeometry geo(lo, std::max(hi - lo, 2.0 * r), 2.0 * r, 4 * static_cast<std::size_t>(n) + 64);
    cellOf.resize(static_cast<std::size_t>(n));
    order.resize(static_cast<std::size_t>(n));
    cellStart.assign(geo.cellCount() + 1, 0);
    for (int i = 0; i < n; ++i) {
        const std::uint32_t c = geo.cellOf(a.p(0, i), a.p(1, i), a.p(2, i));
        cellOf[static_cast<std::size_t>(i)] = c;
        ++cellStart[c + 1];
    }
    for (std::size_t c = 1; c < cellStart.size(); ++c)
        cellStart[c] += cellStart[c - 1];
    cursor.assign(cellStart.begin(), cellStart.end() - 1);
    for (int i = 0; i < n; ++i)
        order[cursor[cellOf[static_cast<std::size_t>(i)]]++] = static_cast<std::uint32_t>(i);
    for (int i = 0; i < n; ++i) {
        const int cx = geo.coord(a.p(0, i)), cy = geo.coord(a.p(1, i)), cz = geo.coord(a.p(2, i));
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::uint32_t c = geo.cell(cx + dx, cy + dy, cz + dz);
                    for (std::uint32_t k = cellStart[c]; k < cellStart[c + 1]; ++k)
                        if (const int j = static_cast<int>(order[k]); j > i)
                            checkPair(b, a, i, j);
                }
    }
}

} // namespace ab::diagnostics
