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
    if (a == 0)
        return {cosA, sinA, 0.0};
    if (a == 1)
        return {-sinA, cosA, 0.0};
    return Eigen::Vector3d::UnitZ();
}

Layout Layout::fromParams(const ParamValues& v)
{
    return Layout(v.real("slope") * std::numbers::pi / 180.0, static_cast<int>(v.integer("blocks")),
                  v.real("block_length"), v.real("crossing"), v.real("width"), v.real("kerb"), v.real("sidewalk"),
                  static_cast<int>(v.integer("cars")), v.real("r"), static_cast<int>(v.integer("n")));
}

Layout::Layout(double slopeRadians, int blocks_, double blockLength_, double crossing_, double width_, double kerb_,
               double sidewalk_, int cars_, double radius_, int balls)
    : slope(slopeRadians), blockLength(blockLength_), crossing(crossing_), width(width_), kerb(kerb_),
      sidewalk(sidewalk_), radius(radius_), blocks(blocks_), cars(cars_)
{
    build(cars_, balls);
    // A ball reaches r beyond its centre and moves about r in a substep (street_engine.cpp;
    // an impulse between two balls can raise a speed by up to sqrt 2), so items within 4 r of
    // its x are every item it can touch; half a metre (if more) leaves a ball away from every
    // listed box that much room before a box left out of its list can matter (street_flight.cpp
    // point 2).
    bin(std::max(4.0 * radius, 0.5));
}

namespace {

// Parked cars stand in slots along each side of a block, kCarGap apart; block 1 keeps its first
// 40 % (and a metre more) free for the hopper above it.
double firstSlotFrom(int block, double blockLength)
{
    return block == 0 ? 0.4 * blockLength + 1.0 : 0.0;
}

int slotsPerSide(int block, double blockLength)
{
    const double room = blockLength - firstSlotFrom(block, blockLength) - kCarGap;
    return std::max(0, static_cast<int>(std::floor(room / (kCarLength + kCarGap))));
}

} // namespace

int Layout::carSlots(int blocks, double blockLength)
{
    int slots = 0;
    for (int k = 0; k < blocks; ++k)
        slots += 2 * slotsPerSide(k, blockLength);
    return slots;
}

void Layout::addSegment(const Segment& seg)
{
    // The road: a box whose top face runs from (x0, y0) for `length` at `angle`, under the
    // sidewalks too; the sidewalks: boxes on it whose tops are `kerb` higher, reaching
    // `before` and `after` past the road's ends along it (the mitre, see build).
    const Eigen::Vector3d along(std::cos(seg.angle), std::sin(seg.angle), 0.0),
        up(-std::sin(seg.angle), std::cos(seg.angle), 0.0);
    const Eigen::Vector3d topMiddle = Eigen::Vector3d(seg.x0, seg.y0, 0.0) + 0.5 * seg.length * along;
    const double across = 0.5 * width + sidewalk;
    boxes.push_back({seg.kind, seg.index, topMiddle - 0.5 * kGround * up, seg.angle,
                     Eigen::Vector3d(0.5 * seg.length, 0.5 * kGround, across)});
    if (sidewalk > 0.0)
        for (double side : {-1.0, 1.0}) {
            const double half = 0.5 * (kGround + kerb);
            const Eigen::Vector3d centre = topMiddle + 0.5 * (seg.after - seg.before) * along + (kerb - half) * up +
                                           Eigen::Vector3d(0.0, 0.0, side * (0.5 * width + 0.5 * sidewalk));
            boxes.push_back({ItemKind::Sidewalk, seg.index, centre, seg.angle,
                             Eigen::Vector3d(0.5 * (seg.length + seg.before + seg.after), half, 0.5 * sidewalk)});
        }
}

void Layout::placeHopper(int balls)
{
    // Over the first part of block 1, min(0.2 m, r) in from the kerbs; sites 2.2 r apart, so that
    // a jitter of up to 0.1 r each way keeps the centres more than 2 r apart.
    const double run = blockLength * std::cos(slope);
    hopper.x0 = std::min(1.0, 0.1 * run);
    hopper.x1 = std::max(hopper.x0 + 2.2 * radius, std::min(0.4 * run, 30.0));
    hopper.z0 = -0.5 * width + radius + std::min(0.2, radius);
    hopper.z1 = -hopper.z0;
    hopper.spacing = 2.2 * radius;
    hopper.lift = 0.5;
    hopper.columns = std::max(1, static_cast<int>(std::floor((hopper.x1 - hopper.x0) / hopper.spacing)));
    hopper.rows = std::max(1, static_cast<int>(std::floor((hopper.z1 - hopper.z0) / hopper.spacing)));
    const long long perLayer = static_cast<long long>(hopper.columns) * hopper.rows;
    hopper.layers = static_cast<int>(std::max<long long>(1, (balls + perLayer - 1) / perLayer));
}

void Layout::build(int carCount, int balls)
{
    const double drop = blockLength * std::sin(slope), run = blockLength * std::cos(slope);
    height = blocks * drop;
    xTop = -crossing;
    placeHopper(balls);
    // Above the hopper's top by more than any rebound can rise (energy: no ball rises above
    // its start height).
    houseTop = height + hopper.top() + 10.0;
    // Where a flat crossing tips into a block, the sidewalks' tops (kerb above the road, each
    // along its own normal) would end kerb sin(slope) apart across x, leaving a notch between
    // two box edges that a ball can wedge in. Each reaches on to where the two top lines cross
    // (the mitre): with the crossing's top y = y_c + k and the block's through
    // (x_c + k sin a, y_c + k cos a) falling at tan a, they meet at x = x_c + k (1 - cos a) / sin a
    // = x_c + k tan(a/2), k tan(a/2) past the crossing's end and (k sin a - k tan(a/2)) / cos a
    // = k tan(a/2) before the block's start along the block. Where a block meets the crossing
    // below it, the lower sidewalk already covers the upper one's end.
    const double mitre = kerb * std::tan(0.5 * slope);
    addSegment({ItemKind::Crossing, -1, xTop, height, crossing, 0.0, 0.0, mitre});
    double x = 0.0, y = height;
    for (int k = 0; k < blocks; ++k) {
        blockStartX.push_back(x);
        addSegment({ItemKind::Road, k, x, y, blockLength, -slope, mitre, 0.0});
        x += run;
        y -= drop;
        blockFootX.push_back(x);
        if (k + 1 < blocks) {
            addSegment({ItemKind::Crossing, k, x, y, crossing, 0.0, 0.0, mitre});
            x += crossing;
        }
    }
    xFoot = x;
    // House fronts along both sides and a back wall at the top, axis-aligned and tall
    // enough that no ball released in the hopper can rise over them.
    const double bottom = -3.0, across = 0.5 * width + sidewalk;
    const double houseX0 = xTop - kHouseDepth, houseX1 = xFoot;
    for (double side : {-1.0, 1.0})
        boxes.push_back(
            {ItemKind::House, -1,
             Eigen::Vector3d(0.5 * (houseX0 + houseX1), 0.5 * (bottom + houseTop), side * (across + 0.5 * kHouseDepth)),
             0.0, Eigen::Vector3d(0.5 * (houseX1 - houseX0), 0.5 * (houseTop - bottom), 0.5 * kHouseDepth)});
    boxes.push_back({ItemKind::BackWall, -1,
                     Eigen::Vector3d(xTop - 0.5 * kHouseDepth, 0.5 * (height - kGround + houseTop), 0.0), 0.0,
                     Eigen::Vector3d(0.5 * kHouseDepth, 0.5 * (houseTop - height + kGround), across + kHouseDepth)});
    // Parked cars: round the blocks that still have a free slot, alternating sides, then slots
    // down each block (the hopper's part of block 1 kept free).
    std::vector<int> parked(static_cast<std::size_t>(blocks), 0);
    carCount = std::min(carCount, carSlots(blocks, blockLength));
    for (int i = 0, block = 0; i < carCount; block = (block + 1) % blocks) {
        if (parked[static_cast<std::size_t>(block)] >= 2 * slotsPerSide(block, blockLength))
            continue; // full (carSlots bounds carCount, so another block has room)
        const int j = parked[static_cast<std::size_t>(block)]++;
        ++i;
        const double side = j % 2 == 0 ? -1.0 : 1.0;
        const int slot = j / 2;
        // along the road from the block's top
        const double s = firstSlotFrom(block, blockLength) + kCarGap + (slot + 0.5) * (kCarLength + kCarGap);
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
    binPad_ = pad;
    binLo_ = xTop - kHouseDepth - pad;
    binWidth_ = kBinWidth;
    const auto bins = static_cast<std::size_t>(std::ceil((xFoot + pad - binLo_) / binWidth_)) + 1;
    std::vector<std::vector<std::uint16_t>> lists(bins);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Box& b = boxes[i];
        // The box's x extent: its centre +- the projections of its half extents on x.
        const double reach = std::abs(b.cosA) * b.half.x() + std::abs(b.sinA) * b.half.y();
        const double x0 = b.centre.x() - reach - pad, x1 = b.centre.x() + reach + pad;
        const auto first = static_cast<std::size_t>(
            std::clamp(std::floor((x0 - binLo_) / binWidth_), 0.0, static_cast<double>(bins - 1)));
        const auto last = static_cast<std::size_t>(
            std::clamp(std::floor((x1 - binLo_) / binWidth_), 0.0, static_cast<double>(bins - 1)));
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

} // namespace ab::street
