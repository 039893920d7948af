// SPDX-License-Identifier: MIT
// The flight phase of the many-balls engine (many_balls_physical.h): every ball of a block
// flies for one substep with its integrator, meets the walls on the way (located or at
// the substep's end, many_balls_walls.h), and rough balls resting on the floor feel its
// friction. Each ball's numbers depend on that ball alone, so any thread may fly any
// block with the same result.
#pragma once

#include "many_balls_walls.h"

#include "../broadphase/uniform_grid.h"
#include "../simulation.h"

#include <cstdint>

namespace ab::physical::manyballs {

// What the flight of a block of balls reads and writes: the engine's arrays and the walls.
// wx, wy, wz (the spins) are read only when `rough`: free flight keeps w constant.
struct Flight {
    double *x, *y, *z, *vx, *vy, *vz;
    double *wx, *wy, *wz;
    int* rebounds;
    std::uint8_t* supported;
    double h;
    Walls walls;
    bool located;
    bool rough;
};

// Flies balls [begin, end) with `integrator` (one of the explicit four) and hands each new
// centre to `place` when there is one (the grid; null for all-pairs), with the AVX2 lanes
// when `avx2` (the same numbers). Adds the wall rebounds to `impacts`; returns the largest
// squared speed after the flight.
double flyBlock(const Flight& f, Integrator integrator, bool avx2, const broadphase::UniformGrid::Placer* place,
                int begin, int end, long long& impacts);

} // namespace ab::physical::manyballs
