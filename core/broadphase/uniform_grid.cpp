// SPDX-License-Identifier: MIT
#include "uniform_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ab::broadphase {

namespace {

// The candidates a window [j, j + len) holds in its first 4 places, tested in float against
// a centre (ax, ay, az): bit l set when place l is inside the window and closer than
// sqrt(threshold); bit 4 set when the window is longer than 4.
struct FloatCentre {
#if defined(__SSE2__)
    __m128 x, y, z, threshold;
    FloatCentre(float ax, float ay, float az, float t)
        : x(_mm_set1_ps(ax)), y(_mm_set1_ps(ay)), z(_mm_set1_ps(az)), threshold(_mm_set1_ps(t))
    {
    }
#else
    float x, y, z, threshold;
    FloatCentre(float ax, float ay, float az, float t) : x(ax), y(ay), z(az), threshold(t) {}
#endif
};

inline unsigned windowHits(const float* fx, const float* fy, const float* fz, std::uint32_t j, std::uint32_t len,
                           const FloatCentre& c)
{
    const unsigned longer = len > 4 ? 16u : 0u;
#if defined(__SSE2__)
    const __m128 dx = _mm_sub_ps(_mm_loadu_ps(fx + j), c.x);
    const __m128 dy = _mm_sub_ps(_mm_loadu_ps(fy + j), c.y);
    const __m128 dz = _mm_sub_ps(_mm_loadu_ps(fz + j), c.z);
    const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    const __m128i places = _mm_setr_epi32(0, 1, 2, 3);
    const __m128 inside =
        _mm_castsi128_ps(_mm_cmplt_epi32(places, _mm_set1_epi32(static_cast<int>(std::min(len, 4u)))));
    return static_cast<unsigned>(_mm_movemask_ps(_mm_and_ps(_mm_cmplt_ps(d2, c.threshold), inside))) | longer;
#else
    unsigned hits = longer;
    for (std::uint32_t l = 0; l < std::min(len, 4u); ++l) {
        const float dx = fx[j + l] - c.x, dy = fy[j + l] - c.y, dz = fz[j + l] - c.z;
        if (dx * dx + dy * dy + dz * dz < c.threshold)
            hits |= 1u << l;
    }
    return hits;
#endif
}

// A float threshold that no pair closer than sqrt(reach2) can fail. Float copies of
// coordinates clamped to [0, side] are off by at most side 2^-24 each, and a difference of
// two by E = (2 side + reach + 1) 2^-24 (the +1 covers the rounding of the difference);
// so |d_float| < reach + sqrt(3) E, and the float sum of squares adds a relative 3 2^-24.
float floatThreshold(double reach2, double side)
{
    const double reach = std::sqrt(reach2);
    const double e = (2.0 * side + reach + 1.0) * 0x1.0p-24;
    const double t = (reach + 2.0 * e) * (reach + 2.0 * e) * (1.0 + 0x1.0p-20);
    return std::nextafter(static_cast<float>(t), HUGE_VALF);
}

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
    std::fill(p.count_, p.count_ + slabs, 0u);
    return p;
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
    std::fill(start + c0, start + c1, 0u);
    // Only the blocks that hold balls of this slab are read.
    const auto holds = [&](int b) { return blockSlabCount_[static_cast<std::size_t>(b) * slabs + s] != 0; };
    const auto blockEnd = [&](int b) { return static_cast<std::size_t>(blockBegin(b + 1)); };
    for (int b = 0; b < blockCount(); ++b)
        if (holds(b))
            for (std::size_t i = static_cast<std::size_t>(blockBegin(b)); i < blockEnd(b); ++i)
                if (slab_[i] == s)
                    ++start[cell_[i]];
    // Counts to end positions, then place from the last ball back: each cell keeps its
    // balls in index order and start[c] ends as the first position of cell c.
    std::uint32_t running = slabBegin_[static_cast<std::size_t>(s)];
    for (std::size_t c = c0; c < c1; ++c) {
        running += start[c];
        start[c] = running;
    }
    const double lo = geo_.lo(), side = geo_.side();
    // Clamped to the cube, which never brings two coordinates further apart.
    const auto copy = [&](double v) { return static_cast<float>(std::clamp(v - lo, 0.0, side)); };
    for (int b = blockCount() - 1; b >= 0; --b) {
        if (!holds(b))
            continue;
        for (std::size_t i = blockEnd(b); i-- > static_cast<std::size_t>(blockBegin(b));) {
            if (slab_[i] != s)
                continue;
            const std::uint32_t c = cell_[i];
            const std::uint32_t q = --start[c];
            order_[q] = static_cast<std::uint32_t>(i);
            sortedCell_[q] = c;
            fx_[q] = copy(x[i]);
            fy_[q] = copy(y[i]);
            fz_[q] = copy(z[i]);
        }
    }
}

void UniformGrid::build(const double* x, const double* y, const double* z)
{
    for (int b = 0; b < blockCount(); ++b) {
        const Placer place = placer(b);
        for (int i = blockBegin(b); i < blockBegin(b + 1); ++i)
            place(i, x[i], y[i], z[i]);
    }
    countSlabs();
    for (int s = 0; s < slabCount(); ++s)
        sortSlab(s, x, y, z);
}

void UniformGrid::findPairs(int s, const double* x, const double* y, const double* z, double reach2,
                            std::vector<Pair>& out) const
{
    const std::uint32_t* start = cellStart_.data();
    const std::uint32_t* order = order_.data();
    const float* fx = fx_.data();
    const float* fy = fy_.data();
    const float* fz = fz_.data();
    const float threshold = floatThreshold(reach2, geo_.side());
    const std::uint32_t row = geo_.rowStride(), layer = geo_.layerStride();
    // The first cells of the other rows of the half neighbourhood, less one (x - 1):
    // +y in this layer, then y-1, y, y+1 in the next layer.
    const std::uint32_t rows[4] = {row - 1, layer - row - 1, layer - 1, layer + row - 1};
    const auto exact = [&](std::uint32_t a, std::uint32_t b) {
        const double dx = x[b] - x[a];
        const double dy = y[b] - y[a];
        const double dz = z[b] - z[a];
        if (dx * dx + dy * dy + dz * dz < reach2)
            out.push_back({a, b});
    };
    const std::uint32_t qEnd = start[slabFirstCell(s + 1)];
    std::uint32_t cell = ~0u;
    std::uint32_t begin[5] = {}, length[5] = {};
    for (std::uint32_t q = start[slabFirstCell(s)]; q < qEnd; ++q) {
        if (sortedCell_[q] != cell) {
            cell = sortedCell_[q];
            for (int k = 0; k < 4; ++k) {
                begin[k] = start[cell + rows[k]];
                length[k] = start[cell + rows[k] + 3] - begin[k];
            }
            length[4] = start[cell + 2]; // its own cell and the +x one: made relative below
        }
        // Later balls of its own cell and the +x cell.
        begin[4] = q + 1;
        const std::uint32_t ownLength = length[4] - begin[4];
        const FloatCentre centre(fx[q], fy[q], fz[q], threshold);
        unsigned hits[5];
        unsigned any = 0;
        for (int k = 0; k < 5; ++k) {
            hits[k] = windowHits(fx, fy, fz, begin[k], k == 4 ? ownLength : length[k], centre);
            any |= hits[k];
        }
        if (any == 0) [[likely]]
            continue;
        const std::uint32_t a = order[q];
        for (int k = 0; k < 5; ++k) {
            for (unsigned h = hits[k] & 15u; h != 0; h &= h - 1)
                exact(a, order[begin[k] + static_cast<std::uint32_t>(__builtin_ctz(h))]);
            if (hits[k] & 16u) {
                const std::uint32_t end = begin[k] + (k == 4 ? ownLength : length[k]);
                for (std::uint32_t j = begin[k] + 4; j < end; ++j)
                    exact(a, order[j]);
            }
        }
    }
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
