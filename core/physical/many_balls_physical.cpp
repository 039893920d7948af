// SPDX-License-Identifier: MIT
// Stage 4, physical model.
// 1. A step is cut into substeps short enough that no ball travels more than r/4 in one
//    (from the largest speed plus what gravity adds), so two balls cannot pass through
//    each other between two contact checks.
// 2. A substep: (a) every ball flies with its integrator; walls are met inside the
//    substep (`located`: the time of impact solved, the flight split there) or at its end
//    (`step-end`); (b) the grid sorts the balls by cell and lists the pairs in contact
//    (centres closer than 2r); (c) passes over those contacts: the first applies the
//    impulses, every pass moves the two centres apart along the normal, half the overlap
//    each, never through a wall. A velocity that an impulse turns into a wall meets the
//    wall in the next substep's flight.
// 3. Threads take the work item by item (WorkerPool::forEach): blocks of 4096 balls for
//    the flight, the grid's slabs for the sort, the pair search and, even slabs then odd
//    slabs, the contacts (uniform_grid.h). Each ball's numbers come from the same
//    operations in the same order whoever does an item, so runs are bit-identical for 1,
//    2 or more threads. The slabs (a fixed number for a given N, about 4096 balls each or
//    more, at most 128) decide the order the contacts are resolved in.
// 4. Every 32 substeps the arrays are permuted into the grid's cell order, so that
//    neighbours are near in memory; id_ maps the engine's order back to the caller's.
// 5. Where the processor has AVX2 (the grid's kernel, uniform_grid.h point 6), the flight
//    takes four balls at a time in vector lanes when all four stay clear of the walls, by
//    the scalar operations in the scalar order: the same numbers on any x86-64.
#include "many_balls_physical.h"

#include "physical_models.h"
#include "worker_pool.h"

#include "../random.h"

#include <algorithm>
#include <cmath>
#include <limits>

#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define AB_AVX2_FLIGHT 1
#endif

namespace ab::physical {

using broadphase::Pair;

// The passes over the contacts of a substep (resolveList): impulses and projection, then
// the resting contacts carried from below, then impulses and projection twice more for
// what the earlier passes left (Gauss-Seidel: each pass sees the previous one's results).
enum class ManyBallsEngine::Pass : unsigned char { Contact, Support };

namespace {

constexpr ManyBallsEngine::Pass kPasses[] = {ManyBallsEngine::Pass::Contact, ManyBallsEngine::Pass::Support,
                                             ManyBallsEngine::Pass::Contact, ManyBallsEngine::Pass::Contact};
constexpr double kTouching = 1.0 + 1e-6;      // centres this close, relative to 2r, touch
constexpr int kMaxSlabs = 128;                // slabs of the grid: threads share these out
constexpr int kSlabBalls = 4096;              // about this many balls a slab at least
constexpr std::size_t kSharedContacts = 8192; // fewer contacts are resolved on one thread
constexpr int kAllPairsChunks = 64;           // the all-pairs search is shared out in this many row ranges
constexpr int kBlock = broadphase::UniformGrid::kBlockSize; // balls a worker flies (and re-orders) at a time
constexpr int kReorderEvery = 32;                           // substeps between re-orderings by cell
constexpr double kMaxTravel = 0.25;                         // of r per substep
constexpr int kMaxSubsteps = 1024;
constexpr int kMaxWallEvents = 8; // located wall impacts of one ball in one substep
constexpr double kNever = std::numeric_limits<double>::infinity();

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

// A wall contact on one axis: the centre goes onto the wall, an outward velocity is
// reflected with restitution k (eq 2.3, v1 = -k v0), or stopped when the rebound would be
// slower than the rest speed (a restitution threshold: the ball stays on the wall).
// Returns true for a rebound.
inline bool wallContact(double& p, double& v, double lo, double hi, double k, double restSpeed)
{
    double outward = 0.0;
    if (p <= lo) {
        p = lo;
        outward = -v;
    } else if (p >= hi) {
        p = hi;
        outward = v;
    }
    if (!(outward > 0.0))
        return false;
    const double rebound = k * outward;
    const bool bounces = rebound > 0.0 && rebound >= restSpeed;
    v = bounces ? -k * v : 0.0;
    return bounces;
}

// The earliest time in [0, T] at which the distance to a wall, d + b t + q t^2 (b and q the
// velocity and acceleration towards the inside), reaches zero; kNever if it does not.
double timeToWall(double d, double b, double q, double T)
{
    if (d <= 0.0) // on the wall: an impact now if heading out
        return (b < 0.0 || (b == 0.0 && q < 0.0)) ? 0.0 : kNever;
    double t = kNever;
    if (q == 0.0) {
        if (b < 0.0)
            t = d / -b;
    } else {
        const double disc = b * b - 4.0 * q * d;
        if (disc >= 0.0) {
            // Roots of q t^2 + b t + d = 0 without cancellation: s = -(b + sign(b) sqrt(disc)) / 2,
            // t1 = s / q, t2 = d / s.
            const double s = -0.5 * (b + std::copysign(std::sqrt(disc), b));
            const double roots[2] = {s / q, s != 0.0 ? d / s : kNever};
            for (double r : roots)
                if (r >= 0.0 && r < t)
                    t = r;
        }
    }
    return t <= T ? t : kNever;
}

struct Walls {
    double lo, hi, k, restSpeed, g;
};

// Flight of one ball for time h with every wall impact located: fly to the earliest
// impact, reflect there, go on with what is left of h. A ball left at rest on a wall that
// gravity presses it against stays there for the rest of h. Returns the rebounds.
template <Integrator I> int flyLocated(double p[3], double v[3], double h, const Walls& w)
{
    const double acc[3] = {0.0, -w.g, 0.0};
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
            const double tLo = timeToWall(p[a] - w.lo, v[a], q, left);
            const double tHi = timeToWall(w.hi - p[a], -v[a], -q, left);
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
        p[axis] = lower ? w.lo : w.hi; // exactly on the wall, whatever the rounding of the flight
        rebounds += wallContact(p[axis], v[axis], w.lo, w.hi, w.k, w.restSpeed) ? 1 : 0;
        const bool pressed = lower ? acc[axis] < 0.0 : acc[axis] > 0.0;
        pinned[axis] = v[axis] == 0.0 && pressed;
    }
    for (int a = 0; a < 3; ++a) {
        if (left > 0.0 && !pinned[a])
            flight<I>(p[a], v[a], acc[a], left); // more impacts than located: the rest unlocated
        rebounds += wallContact(p[a], v[a], w.lo, w.hi, w.k, w.restSpeed) ? 1 : 0;
    }
    return rebounds;
}

// What the flight of a block of balls reads and writes: the engine's arrays and the walls.
struct Flight {
    double *x, *y, *z, *vx, *vy, *vz;
    int* rebounds;
    std::uint8_t* supported;
    double h;
    Walls walls;
    bool located;
};

// Flies ball i and hands its new centre to `place`; adds its wall rebounds to `wallRebounds`
// and its squared speed to the running maximum. A ball left at rest on the floor is marked
// as supported.
template <Integrator I, typename Place>
inline void flyOne(const Flight& f, int i, const Place& place, double& maxSpeed2, long long& wallRebounds)
{
    const Walls& w = f.walls;
    const double h = f.h;
    const int before = f.rebounds[i];
    double p[3] = {f.x[i] + f.vx[i] * h, f.y[i], f.z[i] + f.vz[i] * h};
    double v[3] = {f.vx[i], f.vy[i], f.vz[i]};
    flight<I>(p[1], v[1], -w.g, h);
    const bool inside = p[0] > w.lo && p[0] < w.hi && p[1] > w.lo && p[1] < w.hi && p[2] > w.lo && p[2] < w.hi;
    if (!inside) {
        if (f.located) {
            p[0] = f.x[i], p[1] = f.y[i], p[2] = f.z[i];
            v[1] = f.vy[i];
            f.rebounds[i] += flyLocated<I>(p, v, h, w);
        } else {
            for (int a = 0; a < 3; ++a)
                f.rebounds[i] += wallContact(p[a], v[a], w.lo, w.hi, w.k, w.restSpeed) ? 1 : 0;
        }
    }
    // At rest on the floor (the rest rule stopped its bounce): it supports what lies on
    // it, and a slide slower than the rest speed stops too.
    const bool resting = p[1] == w.lo && v[1] == 0.0 && w.g > 0.0;
    if (resting && v[0] * v[0] + v[2] * v[2] < w.restSpeed * w.restSpeed)
        v[0] = v[2] = 0.0;
    f.supported[i] = resting;
    wallRebounds += f.rebounds[i] - before; // the wall rebounds of this flight
    place(i, p[0], p[1], p[2]);
    f.x[i] = p[0], f.y[i] = p[1], f.z[i] = p[2];
    f.vx[i] = v[0], f.vy[i] = v[1], f.vz[i] = v[2];
    maxSpeed2 = std::max(maxSpeed2, v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// Flies balls [begin, end) and hands each new centre to `place`; returns the largest
// squared speed after the flight.
template <Integrator I, typename Place>
double flyRange(const Flight& f, int begin, int end, const Place& place, long long& impacts)
{
    double maxSpeed2 = 0.0;
    long long wallRebounds = 0; // counted here, added to `impacts` once: one worker's tally
    for (int i = begin; i < end; ++i)
        flyOne<I>(f, i, place, maxSpeed2, wallRebounds);
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
// not resting on the floor (not supported). Any other four go through flyOne one by one.
// The block is placed in the grid afterwards, in one run (Placer::placeRun).
template <Integrator I>
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
                flyOne<I>(f, k, unplaced, maxSpeed2, wallRebounds);
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
        flyOne<I>(f, i, unplaced, maxSpeed2, wallRebounds);
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, fastMax);
    for (double lane : lanes)
        maxSpeed2 = std::max(maxSpeed2, lane);
    place.placeRun(begin, end, f.x, f.y, f.z);
    impacts += wallRebounds;
    return maxSpeed2;
}
#endif

int latticeSide(int n)
{
    int k = static_cast<int>(std::cbrt(static_cast<double>(n)));
    while (static_cast<long long>(k) * k * k < n)
        ++k;
    return std::max(k, 1);
}

void checkLatticeFits(int n, double radius, double side)
{
    const int k = latticeSide(n);
    if (side / k < 2.0 * radius)
        throw InputError("n: " + std::to_string(n) + " balls of radius " + formatNumber(radius) +
                         " need a start lattice of side " + formatNumber(2.0 * radius * k) + " (" + std::to_string(k) +
                         " sites of 2 r a side); the room is " + formatNumber(side));
}

} // namespace

ManyBallsSettings ManyBallsSettings::fromSpec(const RunSpec& spec, double dt)
{
    switch (spec.integrator) {
    case Integrator::Euler:
    case Integrator::SymplecticEuler:
    case Integrator::Verlet:
    case Integrator::Rk4:
        break;
    case Integrator::Event:
        throw InputError("--integrator event: not available for many-balls (its N-ball contacts are resolved at "
                         "the end of each substep); choose euler, symplectic-euler, verlet or rk4");
    case Integrator::ImplicitEuler:
    case Integrator::ImplicitMidpoint:
        throw InputError("--integrator " + std::string(integratorKey(spec.integrator)) +
                         ": not available for many-balls (it has no spring contacts); choose euler, "
                         "symplectic-euler, verlet or rk4");
    }
    ManyBallsSettings s;
    s.n = static_cast<int>(spec.params.integer("n"));
    s.radius = spec.params.real("r");
    s.box = spec.params.real("box");
    s.g = spec.params.real("g");
    s.wallRestitution = spec.params.real("primary_loss");
    s.ballRestitution = spec.params.real("secondary_loss");
    s.restHeight = spec.params.real("rest_height");
    s.integrator = spec.integrator;
    s.impacts = spec.impacts;
    s.broadphase = spec.broadphase;
    s.threads = spec.threads;
    s.dt = dt;
    return s;
}

State jitteredGridStart(int n, double radius, double side, double speed, std::uint64_t seed)
{
    checkLatticeFits(n, radius, side);
    const int k = latticeSide(n);
    const double a = side / k;
    // Two neighbouring centres are at least a - 2 j = 2r apart; the hair keeps rounding
    // from bringing them closer.
    const double jitter = 0.5 * (a - 2.0 * radius) * (1.0 - 1e-9);
    State s;
    s.resize(n);
    SplitMix64 rng(seed);
    for (int i = 0; i < n; ++i) {
        const int site[3] = {i % k, i / (k * k), (i / k) % k}; // x fastest, then z, then y (layers up)
        for (int ax = 0; ax < 3; ++ax)
            s.p(ax, i) = -side / 2.0 + a * (site[ax] + 0.5) + jitter * (2.0 * rng.uniform() - 1.0);
        for (int ax = 0; ax < 3; ++ax)
            s.v(ax, i) = speed * (2.0 * rng.uniform() - 1.0);
    }
    return s;
}

ManyBallsEngine::ManyBallsEngine(const ManyBallsSettings& settings)
    : settings_(settings), lo_(-settings.box / 2.0 + settings.radius), hi_(settings.box / 2.0 - settings.radius),
      // A rebound that rises h_rest leaves with v = sqrt(2 g h_rest) (energy: v^2 / 2 = g h).
      restSpeed_(std::sqrt(2.0 * settings.g * settings.restHeight)),
      pool_(std::make_unique<WorkerPool>(settings.threads))
{
    const int n = settings.n;
    p_.setZero(3, n);
    v_.setZero(3, n);
    id_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        id_[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(i);
    rebounds_.assign(static_cast<std::size_t>(n), 0);
    supported_.assign(static_cast<std::size_t>(n), 0);
    const int workers = pool_->size();
    workerMaxSpeed2_.assign(static_cast<std::size_t>(workers), 0.0);
    workerImpacts_.assign(static_cast<std::size_t>(workers), 0);
    if (settings.broadphase == Broadphase::Grid) {
        pSpare_.setZero(3, n);
        vSpare_.setZero(3, n);
        idSpare_.resize(static_cast<std::size_t>(n));
        reboundsSpare_.resize(static_cast<std::size_t>(n));
        // Cells one ball diameter wide over the centres' range; at most 8 cells a ball.
        const double side = std::max(hi_ - lo_, 2.0 * settings.radius);
        grid_.reset(broadphase::GridGeometry(lo_, side, 2.0 * settings.radius,
                                             std::max<std::size_t>(8 * static_cast<std::size_t>(n), 64)),
                    n, std::clamp(n / kSlabBalls, 1, kMaxSlabs));
        grid_.setKernel(settings.kernel);
        pairs_.resize(static_cast<std::size_t>(grid_.slabCount()));
    } else {
        pairs_.resize(static_cast<std::size_t>(std::clamp(n, 1, kAllPairsChunks)));
    }
    // Room for about one contact a ball; lists that need more grow (doubling), once.
    for (auto& list : pairs_)
        list.reserve(static_cast<std::size_t>(n) / pairs_.size() + 64);
}

ManyBallsEngine::~ManyBallsEngine() = default;

void ManyBallsEngine::load(const State& s)
{
    if (s.size() != settings_.n)
        throw std::invalid_argument("many-balls: the state's ball count differs from the engine's");
    const bool counted = static_cast<int>(s.bounces.size()) == settings_.n;
    double maxSpeed2 = 0.0;
    for (int k = 0; k < settings_.n; ++k) {
        const int i = static_cast<int>(id_[static_cast<std::size_t>(k)]);
        p_.col(k) = s.p.col(i);
        v_.col(k) = s.v.col(i);
        rebounds_[static_cast<std::size_t>(k)] = counted ? s.bounces[static_cast<std::size_t>(i)] : 0;
        maxSpeed2 = std::max(maxSpeed2, v_.col(k).squaredNorm());
    }
    maxSpeed_ = std::sqrt(maxSpeed2);
}

void ManyBallsEngine::store(State& s) const
{
    const int n = settings_.n;
    s.p.resize(3, n);
    s.v.resize(3, n);
    s.bounces.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        const int i = static_cast<int>(id_[static_cast<std::size_t>(k)]);
        s.p.col(i) = p_.col(k);
        s.v.col(i) = v_.col(k);
        s.bounces[static_cast<std::size_t>(i)] = rebounds_[static_cast<std::size_t>(k)];
    }
}

int ManyBallsEngine::substepsFor(double dt) const
{
    // The fastest ball, gaining at most g dt, should travel at most r/4 in a substep.
    const double travel = (maxSpeed_ + settings_.g * dt) * dt;
    const double count = std::ceil(travel / (kMaxTravel * settings_.radius));
    if (!(count > 1.0))
        return 1;
    return count < kMaxSubsteps ? static_cast<int>(count) : kMaxSubsteps;
}

void ManyBallsEngine::step()
{
    const int substeps = substepsFor(settings_.dt);
    const double h = settings_.dt / substeps;
    std::fill(workerImpacts_.begin(), workerImpacts_.end(), 0);
    for (int k = 0; k < substeps; ++k)
        substep(h);
    impacts_ = 0;
    for (long long count : workerImpacts_)
        impacts_ += count;
}

void ManyBallsEngine::substep(double h)
{
    const bool grid = settings_.broadphase == Broadphase::Grid;
    const auto n = static_cast<std::size_t>(settings_.n);
    const double* x = p_.data();
    std::fill(workerMaxSpeed2_.begin(), workerMaxSpeed2_.end(), 0.0);
    pool_->forEach((settings_.n + kBlock - 1) / kBlock, [&](int block, int w) { fly(block, w, h); });
    if (grid) {
        grid_.countSlabs();
        pool_->forEach(grid_.slabCount(), [&](int slab, int) { grid_.sortSlab(slab, x, x + n, x + 2 * n); });
    }
    pool_->forEach(static_cast<int>(pairs_.size()), [&](int list, int) { findPairs(list); });
    std::size_t contacts = 0;
    for (const auto& list : pairs_)
        contacts += list.size();
    // Few contacts cost less than waking the workers for each pass: then one thread
    // resolves the slabs in the same order, with the same result.
    const bool shared = contacts >= kSharedContacts;
    if (contacts > 0)
        for (Pass pass : kPasses)
            resolvePass(pass, shared);
    maxSpeed_ = std::sqrt(*std::max_element(workerMaxSpeed2_.begin(), workerMaxSpeed2_.end()));
    if (grid && substepsDone_ % kReorderEvery == 0) {
        pool_->forEach((settings_.n + kBlock - 1) / kBlock, [&](int block, int) { reorder(block); });
        p_.swap(pSpare_);
        v_.swap(vSpare_);
        id_.swap(idSpare_);
        rebounds_.swap(reboundsSpare_);
    }
    ++substepsDone_;
}

void ManyBallsEngine::fly(int block, int worker, double h)
{
    const auto n = static_cast<std::size_t>(settings_.n);
    double* x = p_.data();
    double* vx = v_.data();
    const Flight f{x,
                   x + n,
                   x + 2 * n,
                   vx,
                   vx + n,
                   vx + 2 * n,
                   rebounds_.data(),
                   supported_.data(),
                   h,
                   Walls{lo_, hi_, settings_.wallRestitution, restSpeed_, settings_.g},
                   settings_.impacts == ImpactMode::Located};
    const int begin = block * kBlock, end = std::min(settings_.n, begin + kBlock);
    double maxSpeed2 = 0.0;
    long long& impacts = workerImpacts_[static_cast<std::size_t>(worker)];
    auto run = [&](auto integrator) {
        constexpr Integrator I = decltype(integrator)::value;
        if (settings_.broadphase != Broadphase::Grid) {
            maxSpeed2 = flyRange<I>(
                f, begin, end, [](int, double, double, double) {}, impacts);
            return;
        }
#if defined(AB_AVX2_FLIGHT)
        if (grid_.kernel() == broadphase::UniformGrid::Kernel::Avx2) {
            maxSpeed2 = flyRangeAvx2<I>(f, begin, end, grid_.placer(block), impacts);
            return;
        }
#endif
        maxSpeed2 = flyRange<I>(f, begin, end, grid_.placer(block), impacts);
    };
    switch (settings_.integrator) {
    case Integrator::Euler:
        run(std::integral_constant<Integrator, Integrator::Euler>{});
        break;
    case Integrator::SymplecticEuler:
        run(std::integral_constant<Integrator, Integrator::SymplecticEuler>{});
        break;
    case Integrator::Verlet:
        run(std::integral_constant<Integrator, Integrator::Verlet>{});
        break;
    case Integrator::Rk4:
        run(std::integral_constant<Integrator, Integrator::Rk4>{});
        break;
    default:
        throw std::logic_error("many-balls: integrator refused at build time");
    }
    double& slot = workerMaxSpeed2_[static_cast<std::size_t>(worker)];
    slot = std::max(slot, maxSpeed2);
}

void ManyBallsEngine::findPairs(int list)
{
    const auto n = static_cast<std::size_t>(settings_.n);
    const double* x = p_.data();
    const double contact2 = 4.0 * settings_.radius * settings_.radius; // (2 r)^2
    auto& out = pairs_[static_cast<std::size_t>(list)];
    out.clear();
    if (settings_.broadphase == Broadphase::Grid) {
        grid_.findPairs(list, x, x + n, x + 2 * n, contact2, out); // one list per slab
        return;
    }
    const int chunks = static_cast<int>(pairs_.size());
    broadphase::findAllPairs(x, x + n, x + 2 * n, settings_.n, broadphase::allPairsRowBegin(settings_.n, list, chunks),
                             broadphase::allPairsRowBegin(settings_.n, list + 1, chunks), contact2, out);
}

void ManyBallsEngine::resolvePass(Pass pass, bool shared)
{
    if (settings_.broadphase != Broadphase::Grid) {
        // The all-pairs lists, joined in row order, are one sequence whatever the thread
        // count; they are resolved in that order on one thread.
        for (const auto& list : pairs_)
            resolveList(list, pass, 0);
        return;
    }
    const int slabs = grid_.slabCount();
    for (int parity = 0; parity < 2; ++parity) {
        const int count = (slabs - parity + 1) / 2; // slabs parity, parity + 2, ...
        const auto resolve = [&](int j, int w) {
            resolveList(pairs_[static_cast<std::size_t>(parity + 2 * j)], pass, w);
        };
        if (shared) {
            pool_->forEach(count, resolve);
        } else {
            for (int j = 0; j < count; ++j)
                resolve(j, 0);
        }
    }
}

void ManyBallsEngine::resolveList(const std::vector<Pair>& pairs, Pass pass, int worker)
{
    const auto n = static_cast<std::size_t>(settings_.n);
    double* x = p_.data();
    double* y = x + n;
    double* z = y + n;
    double* vx = v_.data();
    double* vy = vx + n;
    double* vz = vy + n;
    const double contact = 2.0 * settings_.radius;
    const double reach2 = pass == Pass::Support ? contact * contact * kTouching * kTouching : contact * contact;
    const double e = settings_.ballRestitution;
    double& maxSpeed2 = workerMaxSpeed2_[static_cast<std::size_t>(worker)];
    long long pairRebounds = 0; // added to the worker's tally once, at the end: the tallies
                                // of two workers share a cache line
    const auto speed2 = [&](std::uint32_t i) { return vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]; };
    const auto inside = [&](double& c) { c = std::clamp(c, lo_, hi_); };
    for (const Pair& pair : pairs) {
        std::uint32_t a = pair.a, b = pair.b;
        if (pass == Pass::Support && y[b] < y[a])
            std::swap(a, b); // a below b
        double nx = x[b] - x[a], ny = y[b] - y[a], nz = z[b] - z[a];
        const double d2 = nx * nx + ny * ny + nz * nz;
        if (!(d2 < reach2))
            continue; // parted by an earlier contact
        const double d = std::sqrt(d2);
        if (d > 0.0) {
            nx /= d, ny /= d, nz /= d;
        } else {
            nx = 0.0, ny = 1.0, nz = 0.0; // coincident centres: part them vertically
        }
        // The normal relative velocity, negative while the two approach.
        const double u = (vx[b] - vx[a]) * nx + (vy[b] - vy[a]) * ny + (vz[b] - vz[a]) * nz;
        if (pass == Pass::Support) {
            // Shock propagation (Guendelman, Bridson, Fedkiw 2003) for resting contacts only
            // (slower than the rest speed): a ball resting on a supported ball below it is
            // stopped along the normal as if that ball were held by what is under it, which
            // lets a pile come to rest in one pass instead of many. Only the upper ball
            // changes, and only when the lower one does not move towards it (va.n <= 0), so
            // its kinetic energy falls by u^2 + 2 u (va.n) >= u^2. It needs gravity (the rest
            // speed is 0 without it), so free collisions keep their momentum.
            if (!supported_[a] || !(ny > 0.0) || !(std::abs(u) < restSpeed_))
                continue;
            const double lowerTowards = vx[a] * nx + vy[a] * ny + vz[a] * nz;
            if (u < 0.0 && lowerTowards <= 0.0)
                vx[b] -= u * nx, vy[b] -= u * ny, vz[b] -= u * nz;
            supported_[b] = 1;
            if (speed2(b) < restSpeed_ * restSpeed_)
                vx[b] = vy[b] = vz[b] = 0.0;
            continue;
        }
        if (u < 0.0) {
            // Eqs 2.4-2.7 along the normal n (a to b), equal masses: u becomes -e u; an
            // impulse j n on a and -j n on b with j = (1 + e) u / 2 keeps the momentum va + vb
            // and changes the kinetic energy by (e^2 - 1) u^2 / 4 <= 0. Tangential parts are
            // untouched (eqs 2.8-2.9). A rebound slower than the rest speed is stopped.
            const double rebound = -e * u;
            const bool bounces = rebound > 0.0 && rebound >= restSpeed_;
            const double j = 0.5 * (1.0 + (bounces ? e : 0.0)) * u;
            vx[a] += j * nx, vy[a] += j * ny, vz[a] += j * nz;
            vx[b] -= j * nx, vy[b] -= j * ny, vz[b] -= j * nz;
            if (bounces) {
                ++rebounds_[a];
                ++rebounds_[b];
                ++pairRebounds; // the pair's impact, once
            }
            maxSpeed2 = std::max({maxSpeed2, speed2(a), speed2(b)});
        }
        // Projection: each centre moves half the overlap along n, which leaves their mean
        // where it was and the velocities as they are; the walls stay hard.
        const double half = 0.5 * (contact - d);
        x[a] -= half * nx, y[a] -= half * ny, z[a] -= half * nz;
        x[b] += half * nx, y[b] += half * ny, z[b] += half * nz;
        inside(x[a]), inside(y[a]), inside(z[a]);
        inside(x[b]), inside(y[b]), inside(z[b]);
    }
    workerImpacts_[static_cast<std::size_t>(worker)] += pairRebounds;
}

void ManyBallsEngine::reorder(int block)
{
    const auto n = static_cast<std::size_t>(settings_.n);
    const std::uint32_t* order = grid_.order().data();
    const int begin = block * kBlock, end = std::min(settings_.n, begin + kBlock);
    for (int q = begin; q < end; ++q) {
        const std::size_t i = order[q];
        for (std::size_t a = 0; a < 3; ++a) {
            pSpare_.data()[a * n + static_cast<std::size_t>(q)] = p_.data()[a * n + i];
            vSpare_.data()[a * n + static_cast<std::size_t>(q)] = v_.data()[a * n + i];
        }
        idSpare_[static_cast<std::size_t>(q)] = id_[i];
        reboundsSpare_[static_cast<std::size_t>(q)] = rebounds_[i];
    }
}

std::size_t ManyBallsEngine::bytes() const
{
    std::size_t pairs = 0;
    for (const auto& list : pairs_)
        pairs += list.capacity() * sizeof(Pair);
    const std::size_t arrays =
        static_cast<std::size_t>(p_.size() + v_.size() + pSpare_.size() + vSpare_.size()) * sizeof(double);
    const std::size_t perBall = (id_.capacity() + idSpare_.capacity()) * sizeof(std::uint32_t) +
                                (rebounds_.capacity() + reboundsSpare_.capacity()) * sizeof(int);
    return arrays + perBall + grid_.bytes() + pairs;
}

namespace {

class ManyBallsPhysical final : public Simulation {
public:
    ManyBallsPhysical(const RunSpec& spec, double dt)
        : Simulation(spec, dt), engine_(ManyBallsSettings::fromSpec(spec, dt))
    {
    }

    // The report's start cube (centres in [-9, 9]^3, so balls within 9 + r of the centre),
    // grown when the lattice needs more room, within the box; velocities in [-1, 1]^3 per
    // unit of time, as the report draws them.
    static double startSide(const ManyBallsSettings& s)
    {
        const double wanted = std::max(18.0 + 2.0 * s.radius, 2.2 * s.radius * latticeSide(s.n));
        return std::min(s.box, wanted);
    }

    State initialState() const override
    {
        const ManyBallsSettings& s = engine_.settings();
        return jitteredGridStart(s.n, s.radius, startSide(s), 1.0,
                                 static_cast<std::uint64_t>(spec_.params.integer("seed")));
    }

    void step(State& s, State& next) override
    {
        engine_.load(s);
        engine_.step();
        engine_.store(next);
        next.t = s.t + dt_;
        next.count = s.count;
        next.impacts = s.impacts + engine_.impactsLastStep();
        next.halted = false;
    }

private:
    ManyBallsEngine engine_;
};

} // namespace

std::unique_ptr<Simulation> makeManyBalls(const RunSpec& spec, double dt)
{
    const ManyBallsSettings settings = ManyBallsSettings::fromSpec(spec, dt);
    if (spec.init && spec.init->size() != settings.n)
        throw InputError("--init: the state has " + std::to_string(spec.init->size()) + " balls; n is " +
                         std::to_string(settings.n));
    if (!spec.init) // refuse a start that does not fit now, not at the first state
        checkLatticeFits(settings.n, settings.radius, ManyBallsPhysical::startSide(settings));
    return std::make_unique<ManyBallsPhysical>(spec, dt);
}

double benchmarkBoxSide(int n)
{
    // Volume fraction 0.10: L^3 = N (4/3) pi r^3 / 0.10 with r = 1.
    return std::max(100.0, std::cbrt(n * (4.0 / 3.0) * 3.14159265358979323846 / 0.10));
}

RunSpec benchmarkSpec(int n, ModelKind model, Broadphase broadphase, int threads)
{
    constexpr double dt = 1.0 / 240.0; // s
    constexpr double g = 9.82;         // length/s^2
    RunSpec spec(SceneId::ManyBalls);
    spec.model = model;
    spec.broadphase = broadphase;
    spec.threads = threads;
    const double side = benchmarkBoxSide(n);
    auto set = [&](const char* key, double value) { spec.params.set(key, Eigen::Vector3d(value, 0.0, 0.0)); };
    set("n", n);
    set("r", 1.0);
    set("box", side);
    set("primary_loss", 0.9);
    set("secondary_loss", 0.95);
    State start = jitteredGridStart(n, 1.0, side, 1.0, static_cast<std::uint64_t>(spec.params.integer("seed")));
    if (model == ModelKind::Physical) {
        set("g", g);
        spec.dt = dt;
    } else {
        // The report counts in frames: one frame is dt, so g becomes g dt^2 per frame^2
        // and a velocity v becomes v dt per frame.
        set("g", g * dt * dt);
        start.v *= dt;
    }
    spec.init = std::move(start);
    return spec;
}

} // namespace ab::physical
