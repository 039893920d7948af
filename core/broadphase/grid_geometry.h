// SPDX-License-Identifier: MIT
// A cube cut into m x m x m equal cells, each at least as wide as the contact distance, so
// two centres in contact lie in the same or in adjacent cells (the 27-cell neighbourhood).
// The cells are numbered with an empty border cell on every side (m + 2 a side), so the
// neighbours of any cell that holds a ball have numbers, with no bounds to check.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace ab::broadphase {

class GridGeometry {
public:
    GridGeometry() = default;
    // Cells of side >= `reach` over [lo, lo + side] on every axis, at most about
    // `maxCells` in all (cells grow beyond `reach` to respect it). Coordinates outside the
    // cube fall in the outermost cells, which keeps the neighbourhood property (clamping
    // never separates two coordinates more than they were).
    GridGeometry(double lo, double side, double reach, std::size_t maxCells);

    int perAxis() const { return m_; }
    double lo() const { return lo_; }
    double side() const { return side_; }
    double cellSide() const { return side_ / m_; }
    // Numbered cells, the border included: (m + 2)^3.
    std::size_t cellCount() const
    {
        const auto s = static_cast<std::size_t>(m_) + 2;
        return s * s * s;
    }
    // Step between the numbers of cells adjacent in y, and in z.
    std::uint32_t rowStride() const { return static_cast<std::uint32_t>(m_) + 2; }
    std::uint32_t layerStride() const { return rowStride() * rowStride(); }

    // Cell coordinate of one axis value, in [0, m); NaN falls in cell 0. Written as
    // max/min so that it compiles without branches.
    int coord(double x) const
    {
        const double u = (x - lo_) * scale_;
        const double inside = std::min(std::max(0.0, u), top_); // max(0, NaN) is 0
        return static_cast<int>(inside);
    }
    // Number of cell (ix, iy, iz), each in [-1, m] (-1 and m are the border): x varies
    // fastest and z slowest, so a range of z layers is a contiguous range of numbers.
    std::uint32_t cell(int ix, int iy, int iz) const
    {
        const std::uint32_t s = rowStride();
        return static_cast<std::uint32_t>(ix + 1) +
               s * (static_cast<std::uint32_t>(iy + 1) + s * static_cast<std::uint32_t>(iz + 1));
    }
    std::uint32_t cellOf(double x, double y, double z) const { return cell(coord(x), coord(y), coord(z)); }
    // The terms of coord(): (x - lo) scale, clamped to [0, top].
    double scale() const { return scale_; }
    double top() const { return top_; }

    friend bool operator==(const GridGeometry&, const GridGeometry&) = default;

private:
    double lo_ = 0.0;
    double side_ = 1.0;
    double scale_ = 1.0; // m / side
    double top_ = 0.0;   // m - 1
    int m_ = 1;
};

} // namespace ab::broadphase
