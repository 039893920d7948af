// SPDX-License-Identifier: MIT
// The street of stage 5 (docs/street.md): its static geometry, built once from the scene's
// parameters, in the frame every front end uses. x runs down the street, y up (gravity
// along -y), z across it; the road's foot (the lower end of the last block) is at x = xFoot,
// y = 0, and the street's centre line is z = 0.
//
// Along x: a flat top crossing [xTop, 0], then `blocks` road blocks descending at `slope`,
// each `block_length` long along the road, with a flat crossing of `crossing` between two
// blocks (terraced like San Francisco's hills: the flood jumps where each crossing ends).
// Across z: the roadway |z| <= width/2, then a sidewalk of `sidewalk` on each side, raised
// `kerb` above the road, then the house fronts. A back wall closes the top; the foot is
// open, and balls whose centres pass it leave the run.
//
// Every item is a box turned about z (a road block by -slope, so its top face is the road);
// balls meet boxes only, so one closest-point rule and one face rule serve them all.
#pragma once

#include <Eigen/Core>

#include <cmath>

#include <cstdint>
#include <span>
#include <vector>

namespace ab {
class ParamValues;
}

namespace ab::street {

enum class ItemKind : unsigned char { Road, Crossing, Sidewalk, House, Car, BackWall };

// A box with half extents `half` in its own frame, turned by `angle` about +z: its axes are
// ex = (cos a, sin a, 0), ey = (-sin a, cos a, 0), ez = (0, 0, 1).
struct Box {
    ItemKind kind;
    int segment = -1; // the road block (0..blocks-1) or crossing (-1 top, k after block k) it belongs to
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double angle = 0.0;
    Eigen::Vector3d half = Eigen::Vector3d::Ones();
    double cosA = 1.0, sinA = 0.0; // of `angle`

    Box(ItemKind k, int seg, const Eigen::Vector3d& c, double a, const Eigen::Vector3d& h)
        : kind(k), segment(seg), centre(c), angle(a), half(h), cosA(std::cos(a)), sinA(std::sin(a))
    {
    }

    Eigen::Vector3d axis(int a) const;
    // p in the box's frame, and back; a direction (velocity, acceleration) in the box's frame.
    Eigen::Vector3d toLocal(const Eigen::Vector3d& p) const { return rotateIn(p - centre); }
    Eigen::Vector3d toWorld(const Eigen::Vector3d& local) const { return centre + rotateOut(local); }
    Eigen::Vector3d rotateIn(const Eigen::Vector3d& d) const // R^T d, R the turn by `angle` about z
    {
        return {cosA * d.x() + sinA * d.y(), -sinA * d.x() + cosA * d.y(), d.z()};
    }
    Eigen::Vector3d rotateOut(const Eigen::Vector3d& d) const
    {
        return {cosA * d.x() - sinA * d.y(), sinA * d.x() + cosA * d.y(), d.z()};
    }
    // From the box's point nearest to `local` (a point in the box's frame) to that point: zero
    // when it is inside the box; its norm is the point's distance from the box.
    Eigen::Vector3d outside(const Eigen::Vector3d& local) const { return local - local.cwiseMax(-half).cwiseMin(half); }
};

// The region the balls start in: a rectangle of the road seen from above, [x0, x1] x [z0, z1],
// holding a lattice of `columns` x `rows` sites a layer (spacing `spacing`), `layers` layers
// deep; the lowest layer's centres are `lift` above the road under each site.
struct Hopper {
    double x0 = 0.0, x1 = 0.0, z0 = 0.0, z1 = 0.0, lift = 0.5, spacing = 1.0;
    int columns = 1, rows = 1, layers = 1;
    double top() const { return lift + layers * spacing; } // above the road
};

struct Layout {
    // From valid parameters of the street scene (slope in degrees there, radians here).
    static Layout fromParams(const ParamValues& v);
    Layout(double slopeRadians, int blocks, double blockLength, double crossing, double width, double kerb,
           double sidewalk, int cars, double radius, int balls);

    double slope, blockLength, crossing, width, kerb, sidewalk, radius;
    int blocks, cars;
    double xTop = 0.0;   // uphill end of the top crossing
    double xFoot = 0.0;  // the open lower end
    double height = 0.0; // road height at the top: blocks * block_length * sin(slope)
    double houseTop = 0.0;
    std::vector<Box> boxes;
    std::vector<double> blockStartX, blockFootX; // per block, where it starts and ends along x
    Hopper hopper{};

    // The road's surface height at x (the crossings flat, the blocks sloping; the top
    // crossing's height beyond xTop, 0 beyond the foot).
    double roadY(double x) const;
    // The items a ball whose centre has this x may touch within one substep: every box whose
    // x extent, grown by a few radii, holds x (binned once, at construction).
    std::span<const std::uint16_t> itemsNear(double x) const;
    // Every box that itemsNear(x) leaves out is farther than this from the centre (m).
    double binPad() const { return binPad_; }
    // Largest number of parked cars these blocks hold (two sides, one car a slot).
    static int carSlots(int blocks, double blockLength);

private:
    void build(int cars, int balls);
    void placeHopper(int balls);
    // A road block or a crossing: its road's top face from (x0, y0), `length` long at `angle`;
    // its sidewalks reach `before` and `after` beyond that along it.
    struct Segment {
        ItemKind kind;
        int index;
        double x0, y0, length, angle, before, after;
    };
    void addSegment(const Segment& seg);
    void bin(double pad);

    double binLo_ = 0.0, binWidth_ = 1.0, binPad_ = 0.0;
    std::vector<std::uint32_t> binStart_;
    std::vector<std::uint16_t> binItems_;
};

// Car size (m): length along the road, height, width across it.
inline constexpr double kCarLength = 4.4, kCarHeight = 1.5, kCarWidth = 1.8;

} // namespace ab::street
