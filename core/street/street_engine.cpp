// SPDX-License-Identifier: MIT
// The street engine's phases (street_engine.h): the substeps, and the balls that leave.
#include "street_engine.h"

#include "../physical/worker_pool.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ab::street {

namespace {

constexpr double kMaxTravel = 1.0; // of r per substep (point 1)
constexpr int kMaxSubsteps = 4096;
constexpr int kFlightChunk = 1024; // balls a worker flies at a time
constexpr int kMaxPairPasses = 8;  // over the contacts of a substep
// A pile several balls deep (the advert's hopper) still overlaps by some hundredths of r after
// eight passes: passes go on while an overlap above 2e-3 r is left, up to 32, so that what
// the next substep's flight adds stays below the health check's 1e-2 r.
constexpr int kMaxPilePasses = 32;
constexpr double kPileOverlap = 2e-3; // of r
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// v[j] = v[order[j]] for every j (order a permutation of v's indices), through `scratch`.
template <typename T> void reorder(std::vector<T>& v, const std::vector<int>& order, std::vector<T>& scratch)
{
    scratch.resize(v.size());
    for (std::size_t j = 0; j < v.size(); ++j)
        scratch[j] = v[static_cast<std::size_t>(order[j])];
    v.swap(scratch);
}

} // namespace

Surface Settings::surface() const
{
    Surface s;
    s.e = e;
    // A rebound that rises h_rest leaves with v = sqrt(2 g h_rest) (energy: v^2 / 2 = g h).
    s.restSpeed = std::sqrt(2.0 * g * restHeight);
    s.g = g;
    s.friction = Friction{mu, beta, inertia, radius};
    s.rough = rough();
    return s;
}

Engine::Engine(Layout layout, const Settings& settings)
    : layout_(std::move(layout)), settings_(settings), surface_(settings.surface()),
      pool_(std::make_unique<physical::WorkerPool>(settings.threads))
{
    const auto n = static_cast<std::size_t>(settings.n);
    balls_.assign(n, Ball{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
    support_.assign(n, FaceRef{});
    room_.assign(n, Room{});
    id_.resize(n);
    changed_.assign(n, 0);
    moved_.assign(n, 0);
    workerImpacts_.assign(static_cast<std::size_t>(pool_->size()), 0);
    sizeColumns();
}

Engine::~Engine() = default;

void Engine::load(const State& s)
{
    if (s.size() != settings_.n)
        throw std::invalid_argument("street: the state's ball count differs from the engine's");
    active_.clear();
    double maxSpeed2 = 0.0;
    for (int i = 0; i < settings_.n; ++i) {
        Ball& b = balls_[static_cast<std::size_t>(i)];
        id_[static_cast<std::size_t>(i)] = i;
        b.p = s.p.col(i);
        b.v = s.v.col(i);
        b.w = s.spin(i);
        support_[static_cast<std::size_t>(i)] = FaceRef{};
        room_[static_cast<std::size_t>(i)] = Room{}; // not measured yet
        if (hasLeft(layout_, b.p.x()))
            continue;
        active_.push_back(i);
        findSupport(i);
        maxSpeed2 = std::max(maxSpeed2, b.v.squaredNorm());
    }
    maxSpeed_ = std::sqrt(maxSpeed2);
    energyLeft_ = s.energyLeft;
    covered_ = 0.0; // no contact has looked ahead from this state yet
    loaded_ = true;
}

bool Engine::holds(const State& s) const
{
    if (!loaded_ || s.size() != settings_.n || !s.spins() || s.energyLeft != energyLeft_)
        return false;
    for (int k = 0; k < settings_.n; ++k) {
        const Ball& b = balls_[static_cast<std::size_t>(k)];
        const int i = id_[static_cast<std::size_t>(k)];
        if (s.p.col(i) != b.p || s.v.col(i) != b.v || s.w.col(i) != b.w)
            return false;
    }
    return true;
}

void Engine::store(State& s) const
{
    const int n = settings_.n;
    s.p.resize(3, n);
    s.v.resize(3, n);
    s.w.resize(3, n);
    s.bounces.assign(static_cast<std::size_t>(n), 0);
    for (int k = 0; k < n; ++k) {
        const Ball& b = balls_[static_cast<std::size_t>(k)];
        const int i = id_[static_cast<std::size_t>(k)];
        s.p.col(i) = b.p;
        s.v.col(i) = b.v;
        s.w.col(i) = b.w;
    }
    s.energyLeft = energyLeft_;
}

int Engine::substepsFor(double dt) const
{
    // The fastest ball, gaining at most g dt, should travel at most r in a substep.
    const double travel = (maxSpeed_ + settings_.g * dt) * dt;
    const double count = std::ceil(travel / (kMaxTravel * settings_.radius));
    if (!(count > 1.0))
        return 1;
    return count < kMaxSubsteps ? static_cast<int>(count) : kMaxSubsteps;
}

void Engine::step()
{
    const int substeps = substepsFor(settings_.dt);
    const double h = settings_.dt / substeps;
    std::fill(workerImpacts_.begin(), workerImpacts_.end(), 0);
    sortByColumn();
    for (int k = 0; k < substeps && !active_.empty(); ++k)
        substep(h);
    impacts_ = 0;
    for (long long count : workerImpacts_)
        impacts_ += count;
}

void Engine::contacts(double h)
{
    if (active_.size() < 2)
        return;
    buildCells();
    pool_->forEach(static_cast<int>(pairs_.size()), [&](int chunk, int) { findPairs(chunk); });
    // Gauss-Seidel passes over the same pairs, each seeing the last one's results: what one
    // contact pushes into another, or into the street (settle), the next pass parts, until no
    // listed pair overlaps by more than 1e-4 r and a pass turns none (a pair that an impulse
    // turned towards another is seen again), eight passes at most, or up to 32 while more than
    // 2e-3 r is left. A pile keeps what the passes leave for the next substep.
    // Velocities below 1e-10 of the scene's speeds (the fastest ball, or sqrt(g r) for a pile
    // at rest) are round-off: an approach slower than that turns nothing.
    turnSpeed_ = 1e-10 * (maxSpeed_ + std::sqrt(settings_.g * settings_.radius));
    if (pass_ > std::numeric_limits<std::uint32_t>::max() - 2u * kMaxPilePasses) {
        pass_ = 0; // the numbers start again, every ball as changed long ago
        std::fill(changed_.begin(), changed_.end(), 0u);
    }
    PassResult pass{kInfinity, 1};
    const double r = settings_.radius;
    const auto another = [&](int k) {
        if (k < kMaxPairPasses && (pass.overlap > 1e-4 * r || pass.turned > 0))
            return true;
        return k < kMaxPilePasses && pass.overlap > kPileOverlap * r;
    };
    for (int k = 0; another(k); ++k) {
        pass = resolvePairs(h, k == 0);
        settleMoved();
    }
    covered_ = h;
}

void Engine::substep(double h)
{
    // The contacts of the last substep looked ahead by its length: a longer substep (a state
    // just loaded, or slower balls) looks ahead again first, so no pair meets unseen.
    if (h > covered_)
        contacts(h);
    const int count = static_cast<int>(active_.size());
    pool_->forEach((count + kFlightChunk - 1) / kFlightChunk, [&](int chunk, int worker) {
        const int end = std::min(count, (chunk + 1) * kFlightChunk);
        long long& impacts = workerImpacts_[static_cast<std::size_t>(worker)];
        for (int k = chunk * kFlightChunk; k < end; ++k)
            fly(active_[static_cast<std::size_t>(k)], h, impacts);
    });
    contacts(h);
    double maxSpeed2 = 0.0;
    for (int i : active_)
        maxSpeed2 = std::max(maxSpeed2, balls_[static_cast<std::size_t>(i)].v.squaredNorm());
    maxSpeed_ = std::sqrt(maxSpeed2);
    retire();
}

void Engine::sortByColumn()
{
    // The active balls by (column along x, column across z, slot): a stable order that
    // depends on the positions and the last order only, whatever the threads.
    sortActiveByColumn(); // the substeps' sort (street_pairs.cpp point 1)
    // New slot j takes old slot newOrder_[j]: the active balls sorted, then the rest in order
    // (active_ lists its slots in increasing order, so the rest are the gaps between them).
    const int n = settings_.n;
    newOrder_.clear();
    for (std::uint32_t slot : cellSlot_)
        newOrder_.push_back(static_cast<int>(slot));
    for (int k = 0, next = 0; k < n; ++k) {
        if (next < static_cast<int>(active_.size()) && active_[static_cast<std::size_t>(next)] == k)
            ++next;
        else
            newOrder_.push_back(k);
    }
    reorder(balls_, newOrder_, ballScratch_);
    reorder(support_, newOrder_, supportScratch_);
    reorder(room_, newOrder_, roomScratch_);
    reorder(id_, newOrder_, idScratch_);
    std::iota(active_.begin(), active_.end(), 0);
    std::fill(changed_.begin(), changed_.end(), 0u); // stamps belong to slots: the next pass visits every pair
}

void Engine::retire()
{
    // Balls whose centres passed the open foot leave the run, at rest where they are, and
    // take their energy per unit mass with them (State::energyLeft): |v|^2 / 2 + q r^2 |w|^2 / 2
    // (I = q m r^2, docs/spin.md) + g y, the foot at y = 0 (street_layout.h). Summed in slot
    // order, which is the same for any thread count.
    const double spinInertia = settings_.inertia * settings_.radius * settings_.radius;
    std::erase_if(active_, [&](int i) {
        Ball& b = balls_[static_cast<std::size_t>(i)];
        if (!hasLeft(layout_, b.p.x()))
            return false;
        energyLeft_ += 0.5 * b.v.squaredNorm() + 0.5 * spinInertia * b.w.squaredNorm() + settings_.g * b.p.y();
        b.v.setZero();
        b.w.setZero();
        support_[static_cast<std::size_t>(i)] = FaceRef{};
        return true;
    });
}

std::size_t Engine::bytes() const
{
    std::size_t pairs = 0;
    for (const auto& chunk : pairs_)
        pairs += (chunk.list[0].capacity() + chunk.list[1].capacity()) * sizeof(broadphase::Pair) +
                 chunk.moved.capacity() * sizeof(int);
    return (balls_.capacity() + ballScratch_.capacity()) * sizeof(Ball) +
           (support_.capacity() + supportScratch_.capacity()) * sizeof(FaceRef) +
           (room_.capacity() + roomScratch_.capacity()) * sizeof(Room) +
           (active_.capacity() + id_.capacity() + idScratch_.capacity() + newOrder_.capacity()) * sizeof(int) +
           (cellKey_.capacity() + cellSlot_.capacity() + keyScratch_.capacity() + slotScratch_.capacity() +
            histogram_.capacity()) *
               sizeof(std::uint32_t) +
           cellPos_.capacity() * sizeof(Eigen::Vector3d) + changed_.capacity() * sizeof(std::uint32_t) +
           moved_.capacity() + pairs;
}

} // namespace ab::street
