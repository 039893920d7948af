// SPDX-License-Identifier: MIT
#include "grid_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ab::broadphase {

GridGeometry::GridGeometry(double lo, double side, double reach, std::size_t maxCells) : lo_(lo), side_(side)
{
    if (!(side > 0.0) || !(reach > 0.0) || !std::isfinite(side) || !std::isfinite(reach))
        throw std::invalid_argument("grid: side and reach must be positive and finite");
    // A hair wider than `reach`: two coordinates closer than `reach` then differ by less
    // than one cell even after the rounding of (x - lo) m / side, so their cells are
    // adjacent or equal.
    const double wanted = std::floor(side / (reach * (1.0 + 1e-9)));
    const double cap = std::floor(std::cbrt(static_cast<double>(std::max<std::size_t>(maxCells, 1))) + 1e-9);
    m_ = static_cast<int>(std::clamp(std::min(wanted, cap), 1.0, 1024.0));
    scale_ = m_ / side_;
    top_ = m_ - 1;
}

} // namespace ab::broadphase
