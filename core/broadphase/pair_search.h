// SPDX-License-Identifier: MIT
// The pair search over one slab of the uniform grid (uniform_grid.h points 3 and 6): the
// portable kernel (SSE2 where there is SSE2) and the AVX2 one, which list the same pairs in
// the same order. Internal to the broad phase.
#pragma once

#include "uniform_grid.h"

#include <cstdint>
#include <vector>

#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#define AB_AVX2_KERNEL 1
#endif

namespace ab::broadphase::detail {

// What a pair search over one slab reads: the sorted grid, the centres, the thresholds,
// the row offsets of the half neighbourhood and the slab's range of sorted places.
struct Search {
    const std::uint32_t* start;
    const std::uint32_t* order;
    const std::uint32_t* sortedCell;
    const float* fx;
    const float* fy;
    const float* fz;
    const double* x;
    const double* y;
    const double* z;
    double reach2;
    float threshold;
    std::uint32_t rows[4];
    std::uint32_t qBegin, qEnd;
};

// A float threshold that no pair closer than sqrt(reach2) can fail, for coordinates
// clamped to [0, side].
float floatThreshold(double reach2, double side);

// Appends to `out` the pairs closer than sqrt(reach2) that the balls at sorted places
// [qBegin, qEnd) find in the half neighbourhood of their cells (so each pair once), in
// sorted order. Both kernels give the same list.
void searchPortable(const Search& s, std::vector<Pair>& out);
#if defined(AB_AVX2_KERNEL)
void searchAvx2(const Search& s, std::vector<Pair>& out); // only where the processor has AVX2
#endif

} // namespace ab::broadphase::detail
