// SPDX-License-Identifier: MIT
#include "street_layout.h"

#include "../params.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ab::street {

namespace {

constexpr double kGround = 2.0;     // thickness of road and crossing boxes under their top face (m)
constexpr double kCarGap = 2.0;     // between parked cars, and before the first (m)
constexpr double kHouseDepth = 3.0; // of the house-front boxes across z (m)
constexpr double kBinWidth = 2.0;   // of the bins along x that list the items near a ball (m)

} // namespace

Eigen::Vector3d Box::axis(int a) const
{
    const double c = std::cos(angle), s = std::sin(angle);
    if (a == 0)
        return {c, s, 0.0};
    if (a == 1)
        return {-s, c, 0.0};
    return Eigen::Vector3d::UnitZ();
}

Eigen::Vector3d Box::toLocal(const Eigen::Vector3d& p) const
{
    const Eigen::Vector3d d = p - centre;
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()}; // R^T d, R the turn by `angle` about z
}

Eigen::Vector3d Box::toWorld(const Eigen::Vector3d& local) const
{
    const double c = std::cos(angle), s = std::sin(angle);
    return centre + Eigen::Vector3d(c * local.x() - s * local.y(), s * local.x() + c * local.y(), local.z());
}

Layout Layout::fromParams(const ParamValues& v)
{
    return Layout(v.real("slope") * std::numbers::pi / 180.0, static_cast<int>(v.integer("blocks")),
                  v.real("block_length"), v.real("crossing"), v.real("width"), v.real("kerb"), v.real("sidewalk"),
                  static_cast<int>(v.integer("cars")), v.real("r"));
}

Layout::Layout(double slopeRadians, int blocks_, double blockLength_, double crossing_, double width_, double kerb_,
               double sidewalk_, int cars_, double radius_)
    : slope(slopeRadians), blockLength(blockLength_), crossing(crossing_), width(width_), kerb(kerb_),
      sidewalk(sidewalk_), radius(radius_), blocks(blocks_), cars(cars_)
{
    build(cars_);
    // A ball moves at most r/4 in a substep (street_engine.cpp), so items within 2 m + 2 r of
    // its x are every item it can reach.
    bin(kBinWidth + 2.0 * radius);
}

int Layout::carSlots(int blocks, double blockLength)
{
    const auto perSide = static_cast<int>(std::floor((blockLength - kCarGap) / (kCarLength + kCarGap)));
    return 2 * blocks * std::max(perSide, 0);
}

void Layout::addSegment(ItemKind kind, int segment, double x0, double y0, double length, double angle)
{
    // The road: a box whose top face runs from (x0, y0) for `length` at `angle`, under the
    // sidewalks too; the sidewalks: boxes on it whose tops are `kerb` higher.
    const Eigen::Vector3d along(std::cos(angle), std::sin(angle), 0.0), up(-std::sin(angle), std::cos(angle), 0.0);
    const Eigen::Vector3d topMiddle = Eigen::Vector3d(x0, y0, 0.0) + 0.5 * length * along;
    const double across = 0.5 * width + sidewalk;
    boxes.push_back({kind, segment, topMiddle - 0.5 * kGround * up, angle,
                     Eigen::Vector3d(0.5 * length, 0.5 * kGround, across)});
    if (sidewalk > 0.0)
        for (double side : {-1.0, 1.0}) {
            const double half = 0.5 * (kGround + kerb);
            const Eigen::Vector3d centre = topMiddle + (kerb - half) * up +
                                           Eigen::Vector3d(0.0, 0.0, side * (0.5 * width + 0.5 * sidewalk));
            boxes.push_back({ItemKind::Sidewalk, segment, centre, angle,
                             Eigen::Vector3d(0.5 * length, half, 0.5 * sidewalk)});
        }
}

void Layout::build(int carCount)
{
    const double drop = blockLength * std::sin(slope), run = blockLength * std::cos(slope);
    height = blocks * drop;
    xTop = -crossing;
    hopper = Hopper{1.0, std::max(1.0 + 4.0 * radius, std::min(0.4 * run, 30.0)), -0.5 * width + radius + 0.2,
                    0.5 * width - radius - 0.2, 0.5};
    houseTop = height + 12.0;
    addSegment(ItemKind::Crossing, -1, xTop, height, crossing, 0.0);
    double x = 0.0, y = height;
    for (int k = 0; k < blocks; ++k) {
        blockStartX.push_back(x);
        addSegment(ItemKind::Road, k, x, y, blockLength, -slope);
        x += run;
        y -= drop;
        blockFootX.push_back(x);
        if (k + 1 < blocks) {
            addSegment(ItemKind::Crossing, k, x, y, crossing, 0.0);
            x += crossing;
        }
    }
    xFoot = x;
    // House fronts along both sides and a back wall at the top, axis-aligned and tall
    // enough that no ball released in the hopper can rise over them.
    const double bottom = -3.0, across = 0.5 * width + sidewalk;
    const double houseX0 = xTop - kHouseDepth, houseX1 = xFoot;
    for (double side : {-1.0, 1.0})
        boxes.push_back({ItemKind::House, -1,
                         Eigen::Vector3d(0.5 * (houseX0 + houseX1), 0.5 * (bottom + houseTop),
                                         side * (across + 0.5 * kHouseDepth)),
                         0.0,
                         Eigen::Vector3d(0.5 * (houseX1 - houseX0), 0.5 * (houseTop - bottom), 0.5 * kHouseDepth)});
    boxes.push_back({ItemKind::BackWall, -1,
                     Eigen::Vector3d(xTop - 0.5 * kHouseDepth, 0.5 * (height - kGround + houseTop), 0.0), 0.0,
                     Eigen::Vector3d(0.5 * kHouseDepth, 0.5 * (houseTop - height + kGround), across + kHouseDepth)});
    // Parked cars: block i % blocks, then alternating sides, then slots down the block.
    const int perSide = carSlots(1, blockLength) / 2;
    for (int i = 0; i < carCount && perSide > 0; ++i) {
        const int block = i % blocks, j = i / blocks;
        const double side = j % 2 == 0 ? -1.0 : 1.0;
        const int slot = j / 2;
        const double s = kCarGap + (slot + 0.5) * (kCarLength + kCarGap); // along the road from the block's top
        const Eigen::Vector3d along(std::cos(slope), -std::sin(slope), 0.0), up(std::sin(slope), std::cos(slope), 0.0);
        const Eigen::Vector3d top(blockStartX[static_cast<std::size_t>(block)], height - block * drop, 0.0);
        const Eigen::Vector3d centre = top + s * along + 0.5 * kCarHeight * up +
                                       Eigen::Vector3d(0.0, 0.0, side * (0.5 * width - 0.5 * kCarWidth - 0.3));
        boxes.push_back({ItemKind::Car, block, centre, -slope,
                         Eigen::Vector3d(0.5 * kCarLength, 0.5 * kCarHeight, 0.5 * kCarWidth)});
    }
}

void Layout::bin(double pad)
{
    binLo_ = xTop - kHouseDepth - pad;
    binWidth_ = kBinWidth;
    const auto bins = static_cast<std::size_t>(std::ceil((xFoot + pad - binLo_) / binWidth_)) + 1;
    std::vector<std::vector<std::uint16_t>> lists(bins);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Box& b = boxes[i];
        // The box's x extent: its centre +- the projections of its half extents on x.
        const double reach = std::abs(std::cos(b.angle)) * b.half.x() + std::abs(std::sin(b.angle)) * b.half.y();
        const double x0 = b.centre.x() - reach - pad, x1 = b.centre.x() + reach + pad;
        const auto first = static_cast<std::size_t>(std::clamp(std::floor((x0 - binLo_) / binWidth_), 0.0,
                                                               static_cast<double>(bins - 1)));
        const auto last = static_cast<std::size_t>(std::clamp(std::floor((x1 - binLo_) / binWidth_), 0.0,
                                                              static_cast<double>(bins - 1)));
        for (std::size_t k = first; k <= last; ++k)
            lists[k].push_back(static_cast<std::uint16_t>(i));
    }
    binStart_.assign(bins + 1, 0);
    binItems_.clear();
    for (std::size_t k = 0; k < bins; ++k) {
        binStart_[k] = static_cast<std::uint32_t>(binItems_.size());
        binItems_.insert(binItems_.end(), lists[k].begin(), lists[k].end());
    }
    binStart_[bins] = static_cast<std::uint32_t>(binItems_.size());
}

std::span<const std::uint16_t> Layout::itemsNear(double x) const
{
    const std::size_t bins = binStart_.size() - 1;
    const double u = std::floor((x - binLo_) / binWidth_);
    const auto k = static_cast<std::size_t>(std::clamp(std::isfinite(u) ? u : 0.0, 0.0, static_cast<double>(bins - 1)));
    return {binItems_.data() + binStart_[k], binItems_.data() + binStart_[k + 1]};
}

double Layout::roadY(double x) const
{
    if (x <= 0.0)
        return height;
    const double drop = blockLength * std::sin(slope);
    for (int k = 0; k < blocks; ++k) {
        const double top = height - k * drop;
        if (x <= blockFootX[static_cast<std::size_t>(k)])
            return top - (x - blockStartX[static_cast<std::size_t>(k)]) * std::tan(slope); // the block's line
        if (k + 1 < blocks && x <= blockStartX[static_cast<std::size_t>(k + 1)])
            return top - drop; // the crossing after it
    }
    return 0.0;
}

Eigen::Vector3d Layout::roadNormal(double x) const
{
    for (int k = 0; k < blocks; ++k)
        if (x > blockStartX[static_cast<std::size_t>(k)] && x < blockFootX[static_cast<std::size_t>(k)])
            return {std::sin(slope), std::cos(slope), 0.0};
    return Eigen::Vector3d::UnitY();
}

} // namespace ab::street
