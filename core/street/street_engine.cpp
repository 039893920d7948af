// SPDX-License-Identifier: MIT
// The street engine's phases (street_engine.h): the substeps, and the balls that leave.
#include "street_engine.h"

#include "../physical/worker_pool.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ab::street {

namespace {

constexpr double kMaxTravel = 1.0; // of r per substep (point 1)
constexpr int kMaxSubsteps = 4096;
constexpr int kFlightChunk = 1024; // balls a worker flies at a time
constexpr int kMaxPairPasses = 8;  // over the contacts of a substep
constexpr double kInfinity = std::numeric_limits<double>::infinity();

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
    touched_.assign(n, 0);
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
        b.p = s.p.col(i);
        b.v = s.v.col(i);
        b.w = s.spin(i);
        support_[static_cast<std::size_t>(i)] = FaceRef{};
        if (hasLeft(layout_, b.p.x()))
            continue;
        active_.push_back(i);
        findSupport(i);
        maxSpeed2 = std::max(maxSpeed2, b.v.squaredNorm());
    }
    maxSpeed_ = std::sqrt(maxSpeed2);
    covered_ = 0.0; // no contact has looked ahead from this state yet
    loaded_ = true;
}

bool Engine::holds(const State& s) const
{
    if (!loaded_ || s.size() != settings_.n || !s.spins())
        return false;
    for (int i = 0; i < settings_.n; ++i) {
        const Ball& b = balls_[static_cast<std::size_t>(i)];
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
    for (int i = 0; i < n; ++i) {
        const Ball& b = balls_[static_cast<std::size_t>(i)];
        s.p.col(i) = b.p;
        s.v.col(i) = b.v;
        s.w.col(i) = b.w;
    }
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
    // turned towards another is seen again). A pile keeps what the passes leave (at most a few
    // thousandths of r) for the next substep.
    PassResult pass{kInfinity, 1};
    for (int k = 0; k < kMaxPairPasses && (pass.overlap > 1e-4 * settings_.radius || pass.turned > 0); ++k) {
        pass = resolvePairs(workerImpacts_[0], h);
        for (int i : active_)
            if (touched_[static_cast<std::size_t>(i)] != 0) {
                touched_[static_cast<std::size_t>(i)] = 0;
                settle(i, workerImpacts_[0]);
            }
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

void Engine::retire()
{
    // Balls whose centres passed the open foot leave the run, at rest where they are.
    std::erase_if(active_, [&](int i) {
        Ball& b = balls_[static_cast<std::size_t>(i)];
        if (!hasLeft(layout_, b.p.x()))
            return false;
        b.v.setZero();
        b.w.setZero();
        support_[static_cast<std::size_t>(i)] = FaceRef{};
        return true;
    });
}

std::size_t Engine::bytes() const
{
    std::size_t pairs = 0;
    for (const auto& list : pairs_)
        pairs += list.capacity() * sizeof(broadphase::Pair);
    return balls_.capacity() * sizeof(Ball) + support_.capacity() * sizeof(FaceRef) + active_.capacity() * sizeof(int) +
           (bucket_.capacity() + next_.capacity() + columnHead_.capacity()) * sizeof(std::uint32_t) +
           touched_.capacity() + pairs;
}

} // namespace ab::street
