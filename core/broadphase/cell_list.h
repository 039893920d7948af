// SPDX-License-Identifier: MIT
// Linked cells for rules that move one ball at a time and must see every earlier move at
// once: the report's stage 4 moves ball i, then looks for the lowest-index ball within
// reach of its new centre, while later balls have not moved yet. Each cell holds a doubly
// linked list of its balls, so moving a ball to another cell costs O(1); the lists are
// rebuilt from the positions at the start of each frame in O(N).
#pragma once

#include "grid_geometry.h"

#include "../state.h"

#include <vector>

namespace ab::broadphase {

// The contact test of the report's ball check, shared by its all-pairs scan and the cell
// list so that both decide every pair by the same floating-point operations.
inline bool withinReach(const Eigen::Vector3d& q, const Vec3Array& p, int j, double reach)
{
    return (q - p.col(j)).norm() < reach;
}

class CellList {
public:
    // Puts every ball of `p` into its cell. `geometry` cells must be at least `reach` wide
    // for the queries below.
    void build(const GridGeometry& geometry, const Vec3Array& p);
    // Ball i now has centre (x, y, z).
    void move(int i, double x, double y, double z);
    // The lowest index j != i with withinReach(q, p, j, reach), or -1: the ball a scan of
    // every other ball in index order would find first. The lists must be current for
    // every ball but i.
    int lowestWithin(int i, const Eigen::Vector3d& q, double reach, const Vec3Array& p) const;

private:
    void link(int i, int c);
    void unlink(int i);

    GridGeometry geo_;
    std::vector<int> head_; // per cell, -1 when empty
    std::vector<int> next_; // per ball
    std::vector<int> prev_; // per ball
    std::vector<std::uint32_t> cell_;
};

} // namespace ab::broadphase
