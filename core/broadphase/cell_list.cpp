// SPDX-License-Identifier: MIT
#include "cell_list.h"

#include "../interrupt.h"

#include <algorithm>

namespace ab::broadphase {

void CellList::build(const GridGeometry& geometry, const Vec3Array& p)
{
    const auto n = static_cast<std::size_t>(p.cols());
    if (geometry == geo_ && head_.size() == geometry.cellCount() && cell_.size() == n) {
        // Only the cells that held balls need clearing: O(N), not O(cells).
        for (std::uint32_t c : cell_)
            head_[c] = -1;
    } else {
        head_.assign(geometry.cellCount(), -1);
    }
    geo_ = geometry;
    next_.resize(n);
    prev_.resize(n);
    cell_.resize(n);
    for (std::size_t i = n; i > 0; --i) { // pushed at the front: lists end in index order
        const int b = static_cast<int>(i - 1);
        const std::uint32_t c = geo_.cellOf(p(0, b), p(1, b), p(2, b));
        cell_[i - 1] = c;
        link(b, static_cast<int>(c));
    }
}

void CellList::link(int i, int c)
{
    const int first = head_[static_cast<std::size_t>(c)];
    next_[static_cast<std::size_t>(i)] = first;
    prev_[static_cast<std::size_t>(i)] = -1;
    if (first >= 0)
        prev_[static_cast<std::size_t>(first)] = i;
    head_[static_cast<std::size_t>(c)] = i;
}

void CellList::unlink(int i)
{
    const int before = prev_[static_cast<std::size_t>(i)];
    const int after = next_[static_cast<std::size_t>(i)];
    if (before >= 0)
        next_[static_cast<std::size_t>(before)] = after;
    else
        head_[cell_[static_cast<std::size_t>(i)]] = after;
    if (after >= 0)
        prev_[static_cast<std::size_t>(after)] = before;
}

void CellList::move(int i, double x, double y, double z)
{
    const std::uint32_t c = geo_.cellOf(x, y, z);
    if (c == cell_[static_cast<std::size_t>(i)])
        return;
    unlink(i);
    cell_[static_cast<std::size_t>(i)] = c;
    link(i, static_cast<int>(c));
}

int CellList::lowestWithin(int i, const Eigen::Vector3d& q, double reach, const Vec3Array& p) const
{
    const int m = geo_.perAxis();
    const int cx = geo_.coord(q.x()), cy = geo_.coord(q.y()), cz = geo_.coord(q.z());
    int best = -1;
    unsigned visited = 0; // a crowded cell (the report's start cube) holds up to all N balls
    for (int z = std::max(cz - 1, 0); z <= std::min(cz + 1, m - 1); ++z)
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, m - 1); ++y)
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, m - 1); ++x)
                for (int j = head_[geo_.cell(x, y, z)]; j >= 0; j = next_[static_cast<std::size_t>(j)]) {
                    if ((++visited & 0xFFFFu) == 0)
                        throwIfInterruptRequested(); // Ctrl+C within one query of millions
                    if (j != i && (best < 0 || j < best) && withinReach(q, p, j, reach))
                        best = j;
                }
    return best;
}

} // namespace ab::broadphase
