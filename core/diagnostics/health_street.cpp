// SPDX-License-Identifier: MIT
// The health check on the street (health.h, checks 2 and 4 for stage 5): no ball inside the
// road, a kerb, a car or a house front (street_layout.h), and overlaps between the balls in
// a hashed grid (the street is long and thin: no cube of cells fits it).
#include "health_parts.h"

#include <cmath>

namespace ab::diagnostics {

namespace {

std::string itemName(const street::Box& b)
{
    switch (b.kind) {
    case street::ItemKind::Road:
        return "the road of block " + std::to_string(b.segment + 1);
    case street::ItemKind::Crossing:
        return b.segment < 0 ? std::string("the top crossing")
                             : "the crossing below block " + std::to_string(b.segment + 1);
    case street::ItemKind::Sidewalk:
        return "a kerb";
    case street::ItemKind::House:
        return "a house front";
    case street::ItemKind::Car:
        return "a parked car";
    case street::ItemKind::BackWall:
        return "the wall at the top";
    }
    return "the street";
}

// How far the ball of radius r at p reaches into box b: r less the distance of its centre
// from the box (negative when clear), or r plus the centre's depth when the centre is inside.
double depthInto(const street::Box& b, const Eigen::Vector3d& p, double r)
{
    const Eigen::Vector3d local = b.toLocal(p);
    const Eigen::Vector3d outside = b.outside(local);
    if (outside.squaredNorm() > 0.0)
        return r - outside.norm();
    return r + (b.half - local.cwiseAbs()).minCoeff();
}

} // namespace

void HealthCheck::Impl::checkStreet(const State& a, int i)
{
    const street::Layout& layout = *streetLayout;
    const Eigen::Vector3d p = a.p.col(i);
    if (street::hasLeft(layout, p.x()))
        return;
    double depth = 0.0;
    const street::Box* into = nullptr;
    for (std::uint16_t item : layout.itemsNear(p.x())) {
        const double d = depthInto(layout.boxes[item], p, r);
        if (d > depth)
            depth = d, into = &layout.boxes[item];
    }
    fig.maxPenetration = std::max(fig.maxPenetration, depth);
    if (depth <= 1e-9 * r + tolerance || !into)
        return;
    if (depth > r) {
        escape(i, [&](Finding& f) {
            f.kind = FindingKind::Escaped;
            f.amount = depth - r;
            return "ball " + std::to_string(i) + "'s centre is " + length(depth - r) + " inside " + itemName(*into) +
                   at() + " (it went through)";
        });
        return;
    }
    raise(Kind::Penetration, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
        f.kind = FindingKind::Penetration;
        f.balls = {i};
        f.amount = depth;
        what = "ball " + std::to_string(i) + " reaches " + length(depth) + " into " + itemName(*into) + at();
        advice = impactAdvice(f);
    });
}

namespace {

constexpr std::uint32_t kLeft = ~0u; // no bucket: the ball left the street

// The bucket of the cell c + (dx, dy, dz) of cells 2r wide, among mask + 1 (a power of two).
std::uint32_t bucketOf(const std::array<std::int32_t, 3>& c, int dx, int dy, int dz, std::uint32_t mask)
{
    const std::uint32_t h = static_cast<std::uint32_t>(c[0] + dx) * 73856093u ^
                            static_cast<std::uint32_t>(c[1] + dy) * 19349663u ^
                            static_cast<std::uint32_t>(c[2] + dz) * 83492791u;
    return (h ^ (h >> 16)) & mask;
}

} // namespace

std::uint32_t HealthCheck::Impl::hashStreetBalls(const State& a)
{
    // Cells 2r wide hashed into 2^k >= 2N buckets and a counting sort of the balls on the street
    // (those that left rest out of the run). A ball's cell is found once, its neighbours' by
    // adding to it. Returns the buckets' mask.
    const int n = a.size();
    std::size_t buckets = 64;
    while (buckets < 2 * static_cast<std::size_t>(n))
        buckets *= 2;
    const auto mask = static_cast<std::uint32_t>(buckets - 1);
    const double inv = 1.0 / (2.0 * r);
    cellXyz.resize(static_cast<std::size_t>(n));
    cellOf.resize(static_cast<std::size_t>(n));
    order.resize(static_cast<std::size_t>(n));
    cellStart.assign(buckets + 1, 0);
    for (int i = 0; i < n; ++i) {
        const auto u = static_cast<std::size_t>(i);
        if (street::hasLeft(*streetLayout, a.p(0, i))) {
            cellOf[u] = kLeft;
            continue;
        }
        for (int axis = 0; axis < 3; ++axis)
            cellXyz[u][static_cast<std::size_t>(axis)] = static_cast<std::int32_t>(std::floor(a.p(axis, i) * inv));
        cellOf[u] = bucketOf(cellXyz[u], 0, 0, 0, mask);
        ++cellStart[cellOf[u] + 1];
    }
    for (std::size_t c = 1; c < cellStart.size(); ++c)
        cellStart[c] += cellStart[c - 1];
    cursor.assign(cellStart.begin(), cellStart.end() - 1);
    for (int i = 0; i < n; ++i)
        if (const std::uint32_t c = cellOf[static_cast<std::size_t>(i)]; c != kLeft)
            order[cursor[c]++] = static_cast<std::uint32_t>(i);
    return mask;
}

void HealthCheck::Impl::hashedOverlaps(const State& b, const State& a)
{
    // Each ball looks into its own bucket and those of the 13 cells after its own (dz, dy, dx
    // in lexicographic order), so that of two balls in neighbouring cells one looks at the
    // other; two balls of one cell meet once (j > i). A bucket holds the balls of every cell
    // hashed to it: in its own, a ball also meets those of other cells (met again from their
    // side, harmless: a finding is raised once), and a bucket it looked into once is skipped.
    const std::uint32_t mask = hashStreetBalls(a);
    visitedBy.assign(std::size_t{mask} + 1, kLeft); // the last ball that looked into each bucket
    for (int i = 0; i < a.size(); ++i) {
        const auto u = static_cast<std::size_t>(i);
        const std::uint32_t own = cellOf[u];
        if (own == kLeft)
            continue;
        visitedBy[own] = static_cast<std::uint32_t>(i);
        for (std::uint32_t k = cellStart[own]; k < cellStart[own + 1]; ++k)
            if (const int j = static_cast<int>(order[k]);
                j > i || (j < i && cellXyz[static_cast<std::size_t>(j)] != cellXyz[u]))
                checkPair(b, a, std::min(i, j), std::max(i, j));
        for (int dz = 0; dz <= 1; ++dz)
            for (int dy = dz > 0 ? -1 : 0; dy <= 1; ++dy)
                for (int dx = dz > 0 || dy > 0 ? -1 : 1; dx <= 1; ++dx) {
                    const std::uint32_t c = bucketOf(cellXyz[u], dx, dy, dz, mask);
                    if (visitedBy[c] == static_cast<std::uint32_t>(i))
                        continue; // two of its cells share a bucket
                    visitedBy[c] = static_cast<std::uint32_t>(i);
                    for (std::uint32_t k = cellStart[c]; k < cellStart[c + 1]; ++k) {
                        const int j = static_cast<int>(order[k]); // of another cell than i's
                        checkPair(b, a, std::min(i, j), std::max(i, j));
                    }
                }
    }
}

} // namespace ab::diagnostics
