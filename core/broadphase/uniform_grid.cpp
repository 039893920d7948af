// SPDX-License-Identifier: MIT
#include "uniform_grid.h"

#include "pair_search.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#if defined(AB_AVX2_KERNEL)
#include <immintrin.h>
#endif

namespace ab::broadphase {

namespace {

// c[k] becomes running + c[0] + ... + c[k] (the inclusive running sum, from `running`).
void runningSums(std::uint32_t* c, std::size_t count, std::uint32_t running)
{
    for (std::size_t k = 0; k < count; ++k) {
        running += c[k];
        c[k] = running;
    }
}

#if defined(AB_AVX2_KERNEL)
// The same sums eight at a time: within each 128-bit half by two shifted adds (lane l
// gains lanes l-1, then l-2 and l-3), the low half's total carried into the high half,
// then the running total of everything before added to all eight. Integer sums, so the
// result is the scalar one exactly.
__attribute__((target("avx2"))) void runningSumsAvx2(std::uint32_t* c, std::size_t count, std::uint32_t running)
{
    std::size_t k = 0;
    __m256i total = _mm256_set1_epi32(static_cast<int>(running));
    const __m256i last = _mm256_set1_epi32(7);
    for (; k + 8 <= count; k += 8) {
        __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(c + k));
        v = _mm256_add_epi32(v, _mm256_slli_si256(v, 4));
        v = _mm256_add_epi32(v, _mm256_slli_si256(v, 8));
        const __m256i lowTotal = _mm256_shuffle_epi32(v, _MM_SHUFFLE(3, 3, 3, 3));
        v = _mm256_add_epi32(v, _mm256_permute2x128_si256(lowTotal, lowTotal, 0x08)); // low half: zero
        v = _mm256_add_epi32(v, total);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(c + k), v);
        total = _mm256_permutevar8x32_epi32(v, last);
    }
    runningSums(c + k, count - k, static_cast<std::uint32_t>(_mm256_cvtsi256_si32(total)));
}

// GridGeometry::coord of four values: (x - lo) scale clamped to [0, top], truncated.
// _mm256_max_pd(u, 0) returns its second operand when u is NaN, so NaN falls in cell 0
// as in coord; for every other u the two agree with std::max(0, u) and std::min(., top).
__attribute__((target("avx2"))) inline __m128i fourCoords(const double* x, __m256d lo, __m256d scale, __m256d top)
{
    const __m256d u = _mm256_mul_pd(_mm256_sub_pd(_mm256_loadu_pd(x), lo), scale);
    return _mm256_cvttpd_epi32(_mm256_min_pd(_mm256_max_pd(u, _mm256_setzero_pd()), top));
}

// Placer::operator() for balls [begin, end) four at a time, as far as whole fours go;
// returns where it stopped. Slabs change rarely along the engine's order (by cell), so
// four balls of one slab are counted with one addition.
__attribute__((target("avx2"))) int placeFoursAvx2(const GridGeometry& geo, const std::uint8_t* slabOfLayer,
                                                   std::uint32_t* cell, std::uint8_t* slab, std::uint32_t* count,
                                                   int begin, int end, const double* x, const double* y,
                                                   const double* z)
{
    const __m256d lo = _mm256_set1_pd(geo.lo()), scale = _mm256_set1_pd(geo.scale()), top = _mm256_set1_pd(geo.top());
    const __m128i one = _mm_set1_epi32(1);
    const __m128i stride = _mm_set1_epi32(static_cast<int>(geo.rowStride()));
    int i = begin;
    for (; i + 4 <= end; i += 4) {
        const __m128i ix = _mm_add_epi32(fourCoords(x + i, lo, scale, top), one);
        const __m128i iy = _mm_add_epi32(fourCoords(y + i, lo, scale, top), one);
        const __m128i layer = fourCoords(z + i, lo, scale, top);
        const __m128i iz = _mm_add_epi32(layer, one);
        // GridGeometry::cell: (ix + 1) + s ((iy + 1) + s (iz + 1)), in 32-bit wrapping arithmetic.
        const __m128i c = _mm_add_epi32(ix, _mm_mullo_epi32(stride, _mm_add_epi32(iy, _mm_mullo_epi32(stride, iz))));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(cell + i), c);
        const std::uint8_t s[4] = {slabOfLayer[_mm_cvtsi128_si32(layer)], slabOfLayer[_mm_extract_epi32(layer, 1)],
                                   slabOfLayer[_mm_extract_epi32(layer, 2)], slabOfLayer[_mm_extract_epi32(layer, 3)]};
        std::copy(s, s + 4, slab + i);
        if (s[0] == s[3] && s[1] == s[3] && s[2] == s[3]) {
            count[s[0]] += 4;
        } else {
            for (std::uint8_t k : s)
                ++count[k];
        }
    }
    return i;
}
#endif

} // namespace

void UniformGrid::reset(const GridGeometry& geometry, int balls, int maxSlabs)
{
    if (balls < 0 || maxSlabs < 1 || maxSlabs > 255)
        throw std::invalid_argument("grid: bad ball or slab count");
    geo_ = geometry;
    n_ = balls;
    floatLo_ = 0.0f;
    floatHi_ = static_cast<float>(geo_.side());
    const int m = geo_.perAxis();
    const int slabs = std::min(m, maxSlabs);
    slabFirstLayer_.resize(static_cast<std::size_t>(slabs) + 1);
    slabOfLayer_.resize(static_cast<std::size_t>(m));
    for (int s = 0; s <= slabs; ++s)
        slabFirstLayer_[static_cast<std::size_t>(s)] = static_cast<int>(static_cast<long long>(m) * s / slabs);
    for (int s = 0; s < slabs; ++s)
        for (int l = slabFirstLayer_[static_cast<std::size_t>(s)]; l < slabFirstLayer_[static_cast<std::size_t>(s) + 1];
             ++l)
            slabOfLayer_[static_cast<std::size_t>(l)] = static_cast<std::uint8_t>(s);
    const auto n = static_cast<std::size_t>(balls);
    cell_.assign(n, 0);
    slab_.assign(n, 0);
    order_.assign(n, 0);
    sortedCell_.assign(n, 0);
    fx_.assign(n + 4, 0.0f);
    fy_.assign(n + 4, 0.0f);
    fz_.assign(n + 4, 0.0f);
    blockSlabCount_.assign(static_cast<std::size_t>(blockCount()) * slabs, 0);
    slabBegin_.assign(static_cast<std::size_t>(slabs) + 1, 0);
    cellStart_.assign(geo_.cellCount() + 1, 0);
    cellStart_.back() = static_cast<std::uint32_t>(balls);
}

UniformGrid::Placer UniformGrid::placer(int block)
{
    const auto slabs = static_cast<std::size_t>(slabCount());
    Placer p;
    p.geo_ = &geo_;
    p.slabOfLayer_ = slabOfLayer_.data();
    p.cell_ = cell_.data();
    p.slab_ = slab_.data();
    p.count_ = blockSlabCount_.data() + static_cast<std::size_t>(block) * slabs;
    p.avx2_ = kernel_ == Kernel::Avx2;
    std::fill(p.count_, p.count_ + slabs, 0u);
    return p;
}

void UniformGrid::Placer::placeRun(int begin, int end, const double* x, const double* y, const double* z) const
{
#if defined(AB_AVX2_KERNEL)
    if (avx2_)
        begin = placeFoursAvx2(*geo_, slabOfLayer_, cell_, slab_, count_, begin, end, x, y, z);
#endif
    for (int i = begin; i < end; ++i)
        (*this)(i, x[i], y[i], z[i]);
}

void UniformGrid::countSlabs()
{
    const int slabs = slabCount();
    std::fill(slabBegin_.begin(), slabBegin_.end(), 0u);
    for (int b = 0; b < blockCount(); ++b)
        for (int s = 0; s < slabs; ++s)
            slabBegin_[static_cast<std::size_t>(s) + 1] += blockSlabCount_[static_cast<std::size_t>(b) * slabs + s];
    for (int s = 0; s < slabs; ++s)
        slabBegin_[static_cast<std::size_t>(s) + 1] += slabBegin_[static_cast<std::size_t>(s)];
}

void UniformGrid::sortSlab(int s, const double* x, const double* y, const double* z)
{
    const int slabs = slabCount();
    const std::size_t c0 = slabFirstCell(s), c1 = slabFirstCell(s + 1);
    std::uint32_t* start = cellStart_.data();
    const std::uint32_t* cellOf = cell_.data();
    const std::uint8_t* slabOf = slab_.data();
    const std::uint32_t* blockCounts = blockSlabCount_.data();
    std::uint32_t* order = order_.data();
    std::uint32_t* sortedCell = sortedCell_.data();
    float* fx = fx_.data();
    float* fy = fy_.data();
    float* fz = fz_.data();
    const auto slab = static_cast<std::uint8_t>(s);
    std::fill(start + c0, start + c1, 0u);
    // Only the blocks that hold balls of this slab are read.
    const auto holds = [&](int b) { return blockCounts[static_cast<std::size_t>(b) * slabs + s] != 0; };
    const auto blockEnd = [&](int b) { return static_cast<std::size_t>(blockBegin(b + 1)); };
    for (int b = 0; b < blockCount(); ++b) {
        if (holds(b))
            for (std::size_t i = static_cast<std::size_t>(blockBegin(b)); i < blockEnd(b); ++i)
                if (slabOf[i] == slab)
                    ++start[cellOf[i]];
    }
    // Counts to end positions, then place from the last ball back: each cell keeps its
    // balls in index order and start[c] ends as the first position of cell c.
#if defined(AB_AVX2_KERNEL)
    if (kernel_ == Kernel::Avx2)
        runningSumsAvx2(start + c0, c1 - c0, slabBegin_[static_cast<std::size_t>(s)]);
    else
#endif
        runningSums(start + c0, c1 - c0, slabBegin_[static_cast<std::size_t>(s)]);
    const double lo = geo_.lo(), side = geo_.side();
    // Clamped to the cube, which never brings two coordinates further apart. As min(max())
    // rather than std::clamp, which compiles to branches; the same value, NaN included.
    const auto copy = [&](double v) { return static_cast<float>(std::min(std::max(v - lo, 0.0), side)); };
    for (int b = blockCount() - 1; b >= 0; --b) {
        if (!holds(b))
            continue;
        for (std::size_t i = blockEnd(b); i-- > static_cast<std::size_t>(blockBegin(b));) {
            if (slabOf[i] != slab)
                continue;
            const std::uint32_t c = cellOf[i];
            const std::uint32_t q = --start[c];
            order[q] = static_cast<std::uint32_t>(i);
            sortedCell[q] = c;
            fx[q] = copy(x[i]);
            fy[q] = copy(y[i]);
            fz[q] = copy(z[i]);
        }
    }
}

void UniformGrid::build(const double* x, const double* y, const double* z)
{
    for (int b = 0; b < blockCount(); ++b)
        placer(b).placeRun(blockBegin(b), blockBegin(b + 1), x, y, z);
    countSlabs();
    for (int s = 0; s < slabCount(); ++s)
        sortSlab(s, x, y, z);
}

void UniformGrid::findPairs(int s, const double* x, const double* y, const double* z, double reach2,
                            std::vector<Pair>& out) const
{
    const std::uint32_t row = geo_.rowStride(), layer = geo_.layerStride();
    const detail::Search search{cellStart_.data(),
                                order_.data(),
                                sortedCell_.data(),
                                fx_.data(),
                                fy_.data(),
                                fz_.data(),
                                x,
                                y,
                                z,
                                reach2,
                                detail::floatThreshold(reach2, geo_.side()),
                                // The first cells of the other rows of the half neighbourhood, less
                                // one (x - 1): +y in this layer, then y-1, y, y+1 in the next layer.
                                {row - 1, layer - row - 1, layer - 1, layer + row - 1},
                                cellStart_[slabFirstCell(s)],
                                cellStart_[slabFirstCell(s + 1)]};
#if defined(AB_AVX2_KERNEL)
    if (kernel_ == Kernel::Avx2) {
        detail::searchAvx2(search, out);
        return;
    }
#endif
    detail::searchPortable(search, out);
}

bool UniformGrid::runs(Kernel kernel)
{
    if (kernel == Kernel::Portable)
        return true;
#if defined(AB_AVX2_KERNEL)
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

UniformGrid::Kernel UniformGrid::bestKernel()
{
    static const Kernel best = runs(Kernel::Avx2) ? Kernel::Avx2 : Kernel::Portable;
    return best;
}

void UniformGrid::setKernel(Kernel kernel)
{
    if (!runs(kernel))
        throw std::invalid_argument("grid: this processor does not run the chosen kernel");
    kernel_ = kernel;
}

std::size_t UniformGrid::bytes() const
{
    return (cell_.capacity() + order_.capacity() + sortedCell_.capacity() + cellStart_.capacity() +
            blockSlabCount_.capacity()) *
               sizeof(std::uint32_t) +
           slab_.capacity() + slabBegin_.capacity() * sizeof(std::uint32_t) +
           (fx_.capacity() + fy_.capacity() + fz_.capacity()) * sizeof(float);
}

void findAllPairs(const double* x, const double* y, const double* z, int n, double reach2, std::vector<Pair>& out)
{
    findAllPairs(x, y, z, n, 0, n, reach2, out);
}

void findAllPairs(const double* x, const double* y, const double* z, int n, int rowBegin, int rowEnd, double reach2,
                  std::vector<Pair>& out)
{
    for (int i = rowBegin; i < rowEnd; ++i)
        for (int j = i + 1; j < n; ++j) {
            const double dx = x[j] - x[i];
            const double dy = y[j] - y[i];
            const double dz = z[j] - z[i];
            if (dx * dx + dy * dy + dz * dz < reach2)
                out.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        }
}

int allPairsRowBegin(int n, int part, int parts)
{
    if (part <= 0)
        return 0;
    if (part >= parts)
        return n;
    // Rows [0, a) hold n^2/2 - (n - a)^2/2 pairs; a share p/P of n^2/2 gives
    // a = n (1 - sqrt(1 - p/P)).
    const double a = n * (1.0 - std::sqrt(1.0 - static_cast<double>(part) / parts));
    return std::clamp(static_cast<int>(a), 0, n);
}

} // namespace ab::broadphase
