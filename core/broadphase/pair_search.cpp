// SPDX-License-Identifier: MIT
#include "pair_search.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(AB_AVX2_KERNEL)
#include <immintrin.h>
#endif

namespace ab::broadphase::detail {

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

// The exact test in double that confirms a float candidate.
inline void confirm(const Search& s, std::uint32_t a, std::uint32_t b, std::vector<Pair>& out)
{
    const double dx = s.x[b] - s.x[a];
    const double dy = s.y[b] - s.y[a];
    const double dz = s.z[b] - s.z[a];
    if (dx * dx + dy * dy + dz * dz < s.reach2)
        out.push_back({a, b});
}

// Confirms the candidates of the five windows of ball a, in window order, each window's
// first 4 places by their hit bits, then its places beyond 4 (bit 4) one by one. Both
// kernels list pairs through this, so they list them in the same order.
inline void confirmWindows(const Search& s, std::uint32_t a, const std::uint32_t begin[5],
                           const std::uint32_t length[5], const unsigned hits[5], std::vector<Pair>& out)
{
    for (int k = 0; k < 5; ++k) {
        for (unsigned h = hits[k] & 15u; h != 0; h &= h - 1)
            confirm(s, a, s.order[begin[k] + static_cast<std::uint32_t>(__builtin_ctz(h))], out);
        if (hits[k] & 16u)
            for (std::uint32_t j = begin[k] + 4; j < begin[k] + length[k]; ++j)
                confirm(s, a, s.order[j], out);
    }
}

} // namespace

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

void searchPortable(const Search& s, std::vector<Pair>& out)
{
    std::uint32_t cell = ~0u;
    std::uint32_t begin[5] = {}, length[5] = {};
    std::uint32_t ownEnd = 0; // the end of its own cell and the +x one
    for (std::uint32_t q = s.qBegin; q < s.qEnd; ++q) {
        if (s.sortedCell[q] != cell) {
            cell = s.sortedCell[q];
            for (int k = 0; k < 4; ++k) {
                begin[k] = s.start[cell + s.rows[k]];
                length[k] = s.start[cell + s.rows[k] + 3] - begin[k];
            }
            ownEnd = s.start[cell + 2];
        }
        // Later balls of its own cell and the +x cell.
        begin[4] = q + 1;
        length[4] = ownEnd - begin[4];
        const FloatCentre centre(s.fx[q], s.fy[q], s.fz[q], s.threshold);
        unsigned hits[5];
        unsigned any = 0;
        for (int k = 0; k < 5; ++k) {
            hits[k] = windowHits(s.fx, s.fy, s.fz, begin[k], length[k], centre);
            any |= hits[k];
        }
        if (any == 0) [[likely]]
            continue;
        confirmWindows(s, s.order[q], begin, length, hits, out);
    }
}

#if defined(AB_AVX2_KERNEL)
namespace {

// Two windows' first 4 places, window `lo` in the low lanes and `hi` in the high ones.
__attribute__((target("avx2"))) inline __m256 twoWindows(const float* f, std::uint32_t lo, std::uint32_t hi)
{
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(f + lo)), _mm_loadu_ps(f + hi), 1);
}

// Four all-ones lanes then eight zero lanes: the 4 lanes loaded from kLanes + 4 - l (as
// int32) are all ones in their first min(l, 4) places.
alignas(32) constexpr std::int32_t kLanes[12] = {-1, -1, -1, -1, 0, 0, 0, 0, 0, 0, 0, 0};

__attribute__((target("avx2"))) inline __m128 lengthMask(std::uint32_t length)
{
    return _mm_loadu_ps(reinterpret_cast<const float*>(kLanes + 4 - std::min(length, 4u)));
}

// Lanes 0-3 inside window lo (of length a), lanes 4-7 inside window hi (of length b).
__attribute__((target("avx2"))) inline __m256 twoLengths(std::uint32_t a, std::uint32_t b)
{
    return _mm256_insertf128_ps(_mm256_castps128_ps256(lengthMask(a)), lengthMask(b), 1);
}

// The squared float distance from (cx, cy, cz) to 8 places, compared with the threshold,
// masked by `inside`: one bit a lane.
__attribute__((target("avx2"))) inline unsigned eightHits(__m256 wx, __m256 wy, __m256 wz, __m256 inside, __m256 cx,
                                                          __m256 cy, __m256 cz, __m256 threshold)
{
    const __m256 dx = _mm256_sub_ps(wx, cx);
    const __m256 dy = _mm256_sub_ps(wy, cy);
    const __m256 dz = _mm256_sub_ps(wz, cz);
    const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
    return static_cast<unsigned>(_mm256_movemask_ps(_mm256_and_ps(_mm256_cmp_ps(d2, threshold, _CMP_LT_OQ), inside)));
}

} // namespace

__attribute__((target("avx2"))) void searchAvx2(const Search& s, std::vector<Pair>& out)
{
    // Local copies: the calls that confirm pairs would otherwise make the compiler load
    // them again from `s` on every ball.
    const std::uint32_t* start = s.start;
    const std::uint32_t* sortedCell = s.sortedCell;
    const float* fx = s.fx;
    const float* fy = s.fy;
    const float* fz = s.fz;
    const std::uint32_t rows[4] = {s.rows[0], s.rows[1], s.rows[2], s.rows[3]};
    const std::uint32_t qEnd = s.qEnd;
    const __m256 threshold = _mm256_set1_ps(s.threshold);
    std::uint32_t cell = ~0u;
    std::uint32_t begin[5] = {}, length[5] = {};
    std::uint32_t ownEnd = 0;
    unsigned rowLonger = 0; // bit k: row window k is longer than 4
    __m256 x01 = _mm256_setzero_ps(), y01 = x01, z01 = x01, in01 = x01;
    __m256 x23 = x01, y23 = x01, z23 = x01, in23 = x01;
    for (std::uint32_t q = s.qBegin; q < qEnd; ++q) {
        if (sortedCell[q] != cell) {
            // Entering a cell: its four row windows, loaded once for all its balls.
            cell = sortedCell[q];
            rowLonger = 0;
            for (int k = 0; k < 4; ++k) {
                begin[k] = start[cell + rows[k]];
                length[k] = start[cell + rows[k] + 3] - begin[k];
                rowLonger |= length[k] > 4 ? 1u << k : 0u;
            }
            ownEnd = start[cell + 2];
            x01 = twoWindows(fx, begin[0], begin[1]);
            y01 = twoWindows(fy, begin[0], begin[1]);
            z01 = twoWindows(fz, begin[0], begin[1]);
            x23 = twoWindows(fx, begin[2], begin[3]);
            y23 = twoWindows(fy, begin[2], begin[3]);
            z23 = twoWindows(fz, begin[2], begin[3]);
            in01 = twoLengths(length[0], length[1]);
            in23 = twoLengths(length[2], length[3]);
        }
        begin[4] = q + 1;
        length[4] = ownEnd - begin[4];
        const __m256 cx = _mm256_set1_ps(fx[q]), cy = _mm256_set1_ps(fy[q]), cz = _mm256_set1_ps(fz[q]);
        const unsigned h01 = eightHits(x01, y01, z01, in01, cx, cy, cz, threshold);
        const unsigned h23 = eightHits(x23, y23, z23, in23, cx, cy, cz, threshold);
        // Its own window, in the low lanes.
        const __m128 ox = _mm_sub_ps(_mm_loadu_ps(fx + begin[4]), _mm256_castps256_ps128(cx));
        const __m128 oy = _mm_sub_ps(_mm_loadu_ps(fy + begin[4]), _mm256_castps256_ps128(cy));
        const __m128 oz = _mm_sub_ps(_mm_loadu_ps(fz + begin[4]), _mm256_castps256_ps128(cz));
        const __m128 od2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(ox, ox), _mm_mul_ps(oy, oy)), _mm_mul_ps(oz, oz));
        const unsigned own = static_cast<unsigned>(_mm_movemask_ps(_mm_and_ps(
                                 _mm_cmplt_ps(od2, _mm256_castps256_ps128(threshold)), lengthMask(length[4])))) |
                             (length[4] > 4 ? 16u : 0u);
        if ((h01 | h23 | own | rowLonger) == 0) [[likely]]
            continue;
        const unsigned hits[5] = {(h01 & 15u) | (rowLonger & 1u ? 16u : 0u), (h01 >> 4) | (rowLonger & 2u ? 16u : 0u),
                                  (h23 & 15u) | (rowLonger & 4u ? 16u : 0u), (h23 >> 4) | (rowLonger & 8u ? 16u : 0u),
                                  own};
        confirmWindows(s, s.order[q], begin, length, hits, out);
    }
}
#endif

} // namespace ab::broadphase::detail
