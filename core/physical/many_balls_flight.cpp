// SPDX-License-Identifier: MIT
// The flight phase of the many-balls engine (many_balls_flight.h).
// 1. A ball clear of the walls flies with its integrator; one that would reach a wall in
//    the substep meets it at its located time (`located`: the flight split there) or at
//    the substep's end (`step-end`).
// 2. Rough balls (mu > 0, beta > -1; docs/spin.md): a wall impact adds Walton's tangential
//    impulse (S9-S10, S13); a ball resting on the floor at the start of the substep feels
//    Coulomb friction instead (S2-S4), until it rolls. Spin is constant in flight.
// 3. Where the processor has AVX2 (the grid's kernel, uniform_grid.h point 6), four balls
//    that all stay clear of the walls fly in vector lanes, by the scalar operations in the
//    scalar order: the same numbers on any x86-64. Their spins do not change.
#include "many_balls_flight.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define AB_AVX2_FLIGHT 1
#endif

namespace ab::physical::manyballs {

namespace {

constexpr int kMaxWallEvents = 8; // located wall impacts of one ball in one substep

// One integrator step of flight under constant acceleration a for time h.
template <Integrator I> inline void flight(double& p, double& v, double a, double h)
{
    if constexpr (I == Integrator::Euler) {
        p += v * h; // explicit Euler: the position moves with the old velocity
        v += a * h;
    } else if constexpr (I == Integrator::SymplecticEuler) {
        v += a * h; // symplectic Euler: velocity first, the position with the new one
        p += v * h;
    } else {
        // Velocity Verlet: p + v h + a h^2 / 2, exact for constant acceleration. RK4's four
        // stages reduce to the same parabola when the acceleration is constant.
        p += v * h + 0.5 * a * h * h;
        v += a * h;
    }
}

// The position after time t of that step is p + v t + c a t^2 with this c.
constexpr double curvature(Integrator i)
{
    return i == Integrator::Euler ? 0.0 : i == Integrator::SymplecticEuler ? 1.0 : 0.5;
}

// Flight of one ball for time h with every wall impact located: fly to the earliest
// impact, reflect there, go on with what is left of h. A ball left at rest on a wall that
// gravity presses it against stays there for the rest of h (until an impulse along that
// wall gives it a velocity off it). A ball `resting` on the floor at the start does not
// strike it (its friction is floorFriction's). Returns the rebounds.
template <Integrator I, bool Rough>
int flyLocated(double p[3], double v[3], double w[3], double h, const Walls& walls, bool resting)
{
    const double acc[3] = {0.0, -walls.g, 0.0};
    bool pinned[3] = {false, false, false};
    int rebounds = 0;
    double left = h;
    for (int event = 0; event < kMaxWallEvents && left > 0.0; ++event) {
        double when = kNever;
        int axis = -1;
        bool lower = false;
        for (int a = 0; a < 3; ++a) {
            if (pinned[a])
                continue;
            const double q = curvature(I) * acc[a];
            const double tLo = timeToWall(p[a] - walls.lo, v[a], q, left);
            const double tHi = timeToWall(walls.hi - p[a], -v[a], -q, left);
            if (std::min(tLo, tHi) < when) {
                when = std::min(tLo, tHi);
                axis = a;
                lower = tLo <= tHi;
            }
        }
        const double t = axis < 0 ? left : when;
        for (int a = 0; a < 3; ++a)
            if (!pinned[a])
                flight<I>(p[a], v[a], acc[a], t);
        left -= t;
        if (axis < 0)
            break;
        p[axis] = lower ? walls.lo : walls.hi; // exactly on the wall, whatever the rounding of the flight
        rebounds += wallImpact<Rough>(p, v, w, axis, walls, resting) ? 1 : 0;
        const bool pressed = lower ? acc[axis] < 0.0 : acc[axis] > 0.0;
        pinned[axis] = v[axis] == 0.0 && pressed;
        if constexpr (Rough)
            for (int a = 0; a < 3; ++a)
                pinned[a] = pinned[a] && v[a] == 0.0; // friction at a side wall may lift it off
    }
    for (int a = 0; a < 3; ++a) {
        if (left > 0.0 && !pinned[a])
            flight<I>(p[a], v[a], acc[a], left); // more impacts than located: the rest unlocated
        rebounds += wallImpact<Rough>(p, v, w, a, walls, resting) ? 1 : 0;
    }
    return rebounds;
}

// Flies ball i and hands its new centre to `place`; adds its wall rebounds to `wallRebounds`
// and its squared speed to the running maximum. A ball left at rest on the floor is marked
// as supported. A rough ball resting on the floor at the start feels its friction first.
template <Integrator I, bool Rough, typename Place>
inline void flyOne(const Flight& f, int i, const Place& place, double& maxSpeed2, long long& wallRebounds)
{
    const Walls& w = f.walls;
    const double h = f.h;
    const int before = f.rebounds[i];
    double spin[3] = {0.0, 0.0, 0.0};
    bool onFloor = false;
    if constexpr (Rough) {
        spin[0] = f.wx[i], spin[1] = f.wy[i], spin[2] = f.wz[i];
        onFloor = f.y[i] == w.lo && f.vy[i] == 0.0 && w.g > 0.0;
        if (onFloor) {
            double v0[3] = {f.vx[i], 0.0, f.vz[i]};
            floorFriction(v0, spin, h, w);
            f.vx[i] = v0[0], f.vz[i] = v0[2];
        }
    }
    double p[3] = {f.x[i] + f.vx[i] * h, f.y[i], f.z[i] + f.vz[i] * h};
    double v[3] = {f.vx[i], f.vy[i], f.vz[i]};
    flight<I>(p[1], v[1], -w.g, h);
    const bool inside = p[0] > w.lo && p[0] < w.hi && p[1] > w.lo && p[1] < w.hi && p[2] > w.lo && p[2] < w.hi;
    if (!inside) {
        if (f.located) {
            p[0] = f.x[i], p[1] = f.y[i], p[2] = f.z[i];
            v[1] = f.vy[i];
            f.rebounds[i] += flyLocated<I, Rough>(p, v, spin, h, w, onFloor);
        } else {
            for (int a = 0; a < 3; ++a)
                f.rebounds[i] += wallImpact<Rough>(p, v, spin, a, w, onFloor) ? 1 : 0;
        }
    }
    // At rest on the floor (the rest rule stopped its bounce): it supports what lies on
    // it, and a slide slower than the rest speed stops too (a rough ball's rolling with it).
    const bool resting = p[1] == w.lo && v[1] == 0.0 && w.g > 0.0;
    const double rest2 = w.restSpeed * w.restSpeed;
    if constexpr (Rough) {
        const double rolling2 = w.friction.r * w.friction.r * (spin[0] * spin[0] + spin[2] * spin[2]);
        if (resting && v[0] * v[0] + v[2] * v[2] < rest2 && rolling2 < rest2)
            v[0] = v[2] = spin[0] = spin[2] = 0.0;
        f.wx[i] = spin[0], f.wy[i] = spin[1], f.wz[i] = spin[2];
    } else if (resting && v[0] * v[0] + v[2] * v[2] < rest2) {
        v[0] = v[2] = 0.0;
    }
    f.supported[i] = resting;
    wallRebounds += f.rebounds[i] - before; // the wall rebounds of this flight
    place(i, p[0], p[1], p[2]);
    f.x[i] = p[0], f.y[i] = p[1], f.z[i] = p[2];
    f.vx[i] = v[0], f.vy[i] = v[1], f.vz[i] = v[2];
    maxSpeed2 = std::max(maxSpeed2, v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// Flies balls [begin, end) and hands each new centre to `place`; returns the largest
// squared speed after the flight.
template <Integrator I, bool Rough, typename Place>
double flyRange(const Flight& f, int begin, int end, const Place& place, long long& impacts)
{
    double maxSpeed2 = 0.0;
    long long wallRebounds = 0; // counted here, added to `impacts` once: one worker's tally
    for (int i = begin; i < end; ++i)
        flyOne<I, Rough>(f, i, place, maxSpeed2, wallRebounds);
    impacts += wallRebounds;
    return maxSpeed2;
}

#if defined(AB_AVX2_FLIGHT)
// Lanes strictly between lo and hi (false for NaN).
__attribute__((target("avx2"))) inline __m256d between(__m256d p, __m256d lo, __m256d hi)
{
    return _mm256_and_pd(_mm256_cmp_pd(p, lo, _CMP_GT_OQ), _mm256_cmp_pd(p, hi, _CMP_LT_OQ));
}

// flyRange for the grid with AVX2, four balls at a time. Four balls that all end strictly
// inside the box take the flight of flyOne in vector lanes, with the same operations in
// the same order (no fused multiply-add), so with the same numbers: no wall, no rebound,
// not resting on the floor (not supported), spins unchanged. Any other four go through flyOne one by one.
// The block is placed in the grid afterwards, in one run (Placer::placeRun).
template <Integrator I, bool Rough>
__attribute__((target("avx2"))) double flyRangeAvx2(const Flight& f, int begin, int end,
                                                    const broadphase::UniformGrid::Placer& place, long long& impacts)
{
    const Walls& w = f.walls;
    const __m256d h = _mm256_set1_pd(f.h), lo = _mm256_set1_pd(w.lo), hi = _mm256_set1_pd(w.hi);
    const double a = -w.g;
    const __m256d ah = _mm256_set1_pd(a * f.h);                   // flight<I>: v += a h
    const __m256d parabola = _mm256_set1_pd(0.5 * a * f.h * f.h); // flight<Verlet>: a h^2 / 2
    const auto unplaced = [](int, double, double, double) {};
    __m256d fastMax = _mm256_setzero_pd();
    double maxSpeed2 = 0.0;
    long long wallRebounds = 0;
    int i = begin;
    for (; i + 4 <= end; i += 4) {
        const __m256d vx = _mm256_loadu_pd(f.vx + i), vz = _mm256_loadu_pd(f.vz + i);
        const __m256d px = _mm256_add_pd(_mm256_loadu_pd(f.x + i), _mm256_mul_pd(vx, h));
        const __m256d pz = _mm256_add_pd(_mm256_loadu_pd(f.z + i), _mm256_mul_pd(vz, h));
        __m256d py = _mm256_loadu_pd(f.y + i), vy = _mm256_loadu_pd(f.vy + i);
        if constexpr (I == Integrator::Euler) {
            py = _mm256_add_pd(py, _mm256_mul_pd(vy, h));
            vy = _mm256_add_pd(vy, ah);
        } else if constexpr (I == Integrator::SymplecticEuler) {
            vy = _mm256_add_pd(vy, ah);
            py = _mm256_add_pd(py, _mm256_mul_pd(vy, h));
        } else {
            py = _mm256_add_pd(py, _mm256_add_pd(_mm256_mul_pd(vy, h), parabola));
            vy = _mm256_add_pd(vy, ah);
        }
        const __m256d inside =
            _mm256_and_pd(_mm256_and_pd(between(px, lo, hi), between(py, lo, hi)), between(pz, lo, hi));
        if (_mm256_movemask_pd(inside) != 15) {
            for (int k = i; k < i + 4; ++k)
                flyOne<I, Rough>(f, k, unplaced, maxSpeed2, wallRebounds);
            continue;
        }
        _mm256_storeu_pd(f.x + i, px);
        _mm256_storeu_pd(f.y + i, py);
        _mm256_storeu_pd(f.z + i, pz);
        _mm256_storeu_pd(f.vy + i, vy);
        std::fill(f.supported + i, f.supported + i + 4, std::uint8_t{0});
        const __m256d speed2 =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(vx, vx), _mm256_mul_pd(vy, vy)), _mm256_mul_pd(vz, vz));
        fastMax = _mm256_max_pd(fastMax, speed2);
    }
    for (; i < end; ++i)
        flyOne<I, Rough>(f, i, unplaced, maxSpeed2, wallRebounds);
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, fastMax);
    for (double lane : lanes)
        maxSpeed2 = std::max(maxSpeed2, lane);
    place.placeRun(begin, end, f.x, f.y, f.z);
    impacts += wallRebounds;
    return maxSpeed2;
}
#endif

// The integrator and the friction as template arguments, then the kernel.
template <Integrator I, bool Rough>
double flyWith(const Flight& f, bool avx2, const broadphase::UniformGrid::Placer* place, int begin, int end,
               long long& impacts)
{
    if (!place)
        return flyRange<I, Rough>(
            f, begin, end, [](int, double, double, double) {}, impacts);
#if defined(AB_AVX2_FLIGHT)
    if (avx2)
        return flyRangeAvx2<I, Rough>(f, begin, end, *place, impacts);
#else
    (void)avx2;
#endif
    return flyRange<I, Rough>(f, begin, end, *place, impacts);
}

template <Integrator I>
double flyWith(const Flight& f, bool avx2, const broadphase::UniformGrid::Placer* place, int begin, int end,
               long long& impacts)
{
    return f.rough ? flyWith<I, true>(f, avx2, place, begin, end, impacts)
                   : flyWith<I, false>(f, avx2, place, begin, end, impacts);
}

} // namespace

double flyBlock(const Flight& f, Integrator integrator, bool avx2, const broadphase::UniformGrid::Placer* place,
                int begin, int end, long long& impacts)
{
    switch (integrator) {
    case Integrator::Euler:
        return flyWith<Integrator::Euler>(f, avx2, place, begin, end, impacts);
    case Integrator::SymplecticEuler:
        return flyWith<Integrator::SymplecticEuler>(f, avx2, place, begin, end, impacts);
    case Integrator::Verlet:
        return flyWith<Integrator::Verlet>(f, avx2, place, begin, end, impacts);
    case Integrator::Rk4:
        return flyWith<Integrator::Rk4>(f, avx2, place, begin, end, impacts);
    default:
        throw std::logic_error("many-balls: integrator refused at build time");
    }
}

} // namespace ab::physical::manyballs
