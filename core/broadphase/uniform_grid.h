// SPDX-License-Identifier: MIT
// The uniform grid of the N-ball scene, rebuilt every step by a counting sort.
//
// 1. Cells are at least one contact distance wide (GridGeometry), so every pair in contact
//    lies in one cell or two adjacent ones, and each ball needs only the 13 cells of half
//    its neighbourhood (+x; the +y row; the 9 cells of the +z layer) to find each pair once.
// 2. After the sort, order[cellStart[c] .. cellStart[c + 1]) are the balls of cell c in
//    increasing index order (the sort is stable, so the result does not depend on how the
//    work was shared out). The 3 cells x-1..x+1 of a row are one contiguous range there, so
//    a ball's candidates are 5 ranges ("windows"), almost always 0 to 4 balls long.
// 3. The sort also copies the centres into float arrays in that order. The pair search
//    tests the first 4 places of every window at once, masked by the window's length (no
//    branch that depends on it), in float with a margin that covers float rounding, and
//    confirms each candidate with the exact test in double: the pairs are exactly those
//    findAllPairs finds.
// 4. The cube is cut into slabs of whole z layers. A pair is found from its ball with the
//    lower z layer, so the pairs of slab s touch only slabs s and s + 1: slabs of one
//    parity never share a ball, and threads can resolve them at the same time.
// 5. The build runs in stages that workers share item by item: place (every ball's cell,
//    block by block of 1024 balls, counted per block and slab), countSlabs (where each
//    slab starts, on one thread), then sortSlab (each slab counting-sorts its balls into
//    its cells, reading only the blocks that hold some of them: once the engine has
//    re-ordered its balls by cell, about its own share).
// 6. The sort and the pair search have two kernels with the same results, pairs in the
//    same order: the portable one (SSE2 where there is SSE2) and one for AVX2, chosen at
//    run time when the processor has it. The AVX2 search loads the four row windows of a
//    cell once, when it enters the cell, two windows to a 256-bit register, and tests each
//    ball of the cell against them in two operations instead of four; the AVX2 sort turns
//    cell counts into positions eight cells at a time.
#pragma once

#include "grid_geometry.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace ab::broadphase {

struct Pair {
    std::uint32_t a;
    std::uint32_t b;
};

class UniformGrid {
public:
    // Blocks of balls [b 1024, (b + 1) 1024): the unit of the first stage.
    static constexpr int kBlockShift = 10;
    static constexpr int kBlockSize = 1 << kBlockShift;

    // The instruction set of the sort and the pair search (point 6).
    enum class Kernel : unsigned char { Portable, Avx2 };
    // Whether this processor runs `kernel`; the best one that it runs.
    static bool runs(Kernel kernel);
    static Kernel bestKernel();
    // The kernel of the placing, sortSlab and findPairs: bestKernel() unless set (tests
    // compare them).
    void setKernel(Kernel kernel);
    Kernel kernel() const { return kernel_; }

    // Sizes the grid for `balls` balls with at most `maxSlabs` (<= 255) slabs, fewer when
    // there are fewer z layers.
    void reset(const GridGeometry& geometry, int balls, int maxSlabs);

    const GridGeometry& geometry() const { return geo_; }
    int balls() const { return n_; }
    int blockCount() const { return (n_ + kBlockSize - 1) >> kBlockShift; }
    int slabCount() const { return static_cast<int>(slabFirstLayer_.size()) - 1; }

    // Stage 1, one ball at a time, so that a caller can place each ball as soon as it has
    // moved it: placer(b) clears block b's counts, then the placer takes every ball i of
    // the block with its centre.
    class Placer {
    public:
        void operator()(int i, double x, double y, double z) const
        {
            const int iz = geo_->coord(z);
            const std::uint8_t s = slabOfLayer_[iz];
            cell_[i] = geo_->cell(geo_->coord(x), geo_->coord(y), iz);
            slab_[i] = s;
            ++count_[s];
        }
        // The same for every ball i in [begin, end) of the block, centres x[i], y[i], z[i],
        // four at a time with AVX2 where the grid's kernel is Kernel::Avx2.
        void placeRun(int begin, int end, const double* x, const double* y, const double* z) const;

    private:
        friend class UniformGrid;
        const GridGeometry* geo_ = nullptr;
        const std::uint8_t* slabOfLayer_ = nullptr;
        std::uint32_t* cell_ = nullptr;
        std::uint8_t* slab_ = nullptr;
        std::uint32_t* count_ = nullptr; // the block's row
        bool avx2_ = false;
    };
    Placer placer(int block);
    // Stage 2, on one thread once every block is placed: where each slab's balls start.
    void countSlabs();
    // Stage 3: slab s sorts its balls into its cells and copies their centres.
    void sortSlab(int s, const double* x, const double* y, const double* z);
    // All stages on the calling thread.
    void build(const double* x, const double* y, const double* z);

    // Appends every pair (a, b) found from a ball of slab `s` whose centres are closer than
    // sqrt(reach2) (strictly), by the same test as findAllPairs; a is the ball with the
    // lower z layer (then lower y, lower x, then the earlier one in index order). x, y, z
    // are the centres the grid was built from.
    void findPairs(int s, const double* x, const double* y, const double* z, double reach2,
                   std::vector<Pair>& out) const;

    // The balls [blockBegin(b), blockBegin(b + 1)) of block b.
    int blockBegin(int block) const { return std::min(n_, block << kBlockShift); }
    const std::vector<std::uint32_t>& order() const { return order_; }
    const std::vector<std::uint32_t>& cellStart() const { return cellStart_; }
    std::size_t bytes() const;

private:
    // Slab 0 starts with the border layer below the cube and the last one ends with the
    // border layer above it, so every numbered cell is in one slab.
    std::size_t slabFirstCell(int s) const
    {
        if (s == 0)
            return 0;
        if (s == slabCount())
            return geo_.cellCount();
        return static_cast<std::size_t>(slabFirstLayer_[static_cast<std::size_t>(s)] + 1) * geo_.layerStride();
    }

    GridGeometry geo_;
    Kernel kernel_ = bestKernel();
    int n_ = 0;
    float floatLo_ = 0.0f, floatHi_ = 0.0f;     // the float copies are clamped to this range
    std::vector<int> slabFirstLayer_;           // slabCount() + 1 entries
    std::vector<std::uint8_t> slabOfLayer_;     // per z layer
    std::vector<std::uint32_t> cell_;           // per ball
    std::vector<std::uint8_t> slab_;            // per ball
    std::vector<std::uint32_t> blockSlabCount_; // blocks x slabs: balls of each block in each slab
    std::vector<std::uint32_t> slabBegin_;      // slabCount() + 1: where each slab's balls start
    std::vector<std::uint32_t> order_;          // balls sorted by cell
    std::vector<std::uint32_t> sortedCell_;     // their cells
    std::vector<float> fx_, fy_, fz_;           // their centres less lo, in float, 4 spare at the end
    std::vector<std::uint32_t> cellStart_;      // cellCount() + 1
};

// Every pair closer than sqrt(reach2), by testing all of them: the reference the grid
// must agree with, and the report's own O(N^2) search. Pairs come with a < b, in (a, b)
// order; the second form covers the rows a in [rowBegin, rowEnd) only, so workers can
// share the search and their lists, joined in row order, equal the whole list.
void findAllPairs(const double* x, const double* y, const double* z, int n, double reach2, std::vector<Pair>& out);
void findAllPairs(const double* x, const double* y, const double* z, int n, int rowBegin, int rowEnd, double reach2,
                  std::vector<Pair>& out);
// Where worker `part` of `parts` starts its rows so that each tests about as many pairs
// (row a tests n - 1 - a of them).
int allPairsRowBegin(int n, int part, int parts);

} // namespace ab::broadphase
