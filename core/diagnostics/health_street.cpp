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

void HealthCheck::Impl::hashedOverlaps(const State& b, const State& a)
{
    // Cells 2r wide hashed into 2^k >= 2N buckets, a counting sort, and each ball against the
    // buckets of its 27 cells (each bucket once), each pair once (j > i).
    const int n = a.size();
    std::size_t buckets = 64;
    while (buckets < 2 * static_cast<std::size_t>(n))
        buckets *= 2;
    const auto mask = static_cast<std::uint32_t>(buckets - 1);
    const double inv = 1.0 / (2.0 * r);
    const auto key = [&](int i, int dx, int dy, int dz) {
        const auto c = [&](int axis, int d) {
            return static_cast<std::uint32_t>(static_cast<std::int32_t>(std::floor(a.p(axis, i) * inv)) + d);
        };
        const std::uint32_t h = c(0, dx) * 73856093u ^ c(1, dy) * 19349663u ^ c(2, dz) * 83492791u;
        return (h ^ (h >> 16)) & mask;
    };
    cellOf.resize(static_cast<std::size_t>(n));
    order.resize(static_cast<std::size_t>(n));
    cellStart.assign(buckets + 1, 0);
    for (int i = 0; i < n; ++i) {
        cellOf[static_cast<std::size_t>(i)] = key(i, 0, 0, 0);
        ++cellStart[cellOf[static_cast<std::size_t>(i)] + 1];
    }
    for (std::size_t c = 1; c < cellStart.size(); ++c)
        cellStart[c] += cellStart[c - 1];
    cursor.assign(cellStart.begin(), cellStart.end() - 1);
    for (int i = 0; i < n; ++i)
        order[cursor[cellOf[static_cast<std::size_t>(i)]]++] = static_cast<std::uint32_t>(i);
    std::uint32_t seen[27];
    for (int i = 0; i < n; ++i) {
        if (street::hasLeft(*streetLayout, a.p(0, i)))
            continue;
        int count = 0;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::uint32_t c = key(i, dx, dy, dz);
                    if (std::find(seen, seen + count, c) != seen + count)
                        continue;
                    seen[count++] = c;
                    for (std::uint32_t k = cellStart[c]; k < cellStart[c + 1]; ++k)
                        if (const int j = static_cast<int>(order[k]);
                            j > i && !street::hasLeft(*streetLayout, a.p(0, j))) // left balls rest out of the run
                            checkPair(b, a, i, j);
                }
    }
}

} // namespace ab::diagnostics
