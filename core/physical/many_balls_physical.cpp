// SPDX-License-Identifier: MIT
// Stage 4, physical model: the engine's phases. The flight is many_balls_flight.cpp, the
// walls and floor many_balls_walls.h, the contacts between balls many_balls_contacts.cpp,
// the settings and starts many_balls_start.cpp.
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
// 6. Rough balls (docs/spin.md) carry a spin w each: Walton's impulse at wall impacts (the
//    flight) and ball-ball impacts (the first contact pass), Coulomb friction on the floor
//    (the flight). Smooth balls (mu = 0 or beta = -1) take exactly the operations they did
//    before spin existed, so their runs are the same bit for bit, at the same cost.
#include "many_balls_physical.h"

#include "engine_step.h"
#include "many_balls_flight.h"
#include "physical_models.h"
#include "worker_pool.h"

#include <algorithm>
#include <cmath>

namespace ab::physical {

namespace {

// The passes over the contacts of a substep (resolveList): impulses and projection, then
// the resting contacts carried from below, then impulses and projection twice more for
// what the earlier passes left (Gauss-Seidel: each pass sees the previous one's results).
constexpr ManyBallsEngine::Pass kPasses[] = {ManyBallsEngine::Pass::Contact, ManyBallsEngine::Pass::Support,
                                             ManyBallsEngine::Pass::Contact, ManyBallsEngine::Pass::Contact};
constexpr int kMaxSlabs = 128;                // slabs of the grid: threads share these out
constexpr int kSlabBalls = 4096;              // about this many balls a slab at least
constexpr std::size_t kSharedContacts = 8192; // fewer contacts are resolved on one thread
constexpr int kAllPairsChunks = 64;           // the all-pairs search is shared out in this many row ranges
constexpr int kBlock = broadphase::UniformGrid::kBlockSize; // balls a worker flies (and re-orders) at a time
constexpr int kReorderEvery = 32;                           // substeps between re-orderings by cell
constexpr double kMaxTravel = 0.25;                         // of r per substep
constexpr int kMaxSubsteps = 1024;

} // namespace

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
    spinning_ = settings.rough();
    w_.setZero(3, spinning_ ? n : 0);
    supported_.assign(static_cast<std::size_t>(n), 0);
    const int workers = pool_->size();
    workerMaxSpeed2_.assign(static_cast<std::size_t>(workers), 0.0);
    workerImpacts_.assign(static_cast<std::size_t>(workers), 0);
    if (settings.broadphase == Broadphase::Grid) {
        pSpare_.setZero(3, n);
        vSpare_.setZero(3, n);
        wSpare_.setZero(3, spinning_ ? n : 0);
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
    // Spins are carried when the balls are rough or the state brings them.
    spinning_ = settings_.rough() || s.spins();
    const int turning = spinning_ ? settings_.n : 0;
    if (w_.cols() != turning) {
        w_.setZero(3, turning);
        if (settings_.broadphase == Broadphase::Grid)
            wSpare_.setZero(3, turning);
    }
    double maxSpeed2 = 0.0;
    for (int k = 0; k < settings_.n; ++k) {
        const int i = static_cast<int>(id_[static_cast<std::size_t>(k)]);
        p_.col(k) = s.p.col(i);
        v_.col(k) = s.v.col(i);
        if (spinning_)
            w_.col(k) = s.spin(i);
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
    s.w.resize(3, spinning_ ? n : 0);
    s.bounces.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        const int i = static_cast<int>(id_[static_cast<std::size_t>(k)]);
        s.p.col(i) = p_.col(k);
        s.v.col(i) = v_.col(k);
        if (spinning_)
            s.w.col(i) = w_.col(k);
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
        w_.swap(wSpare_);
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
    double* wx = w_.data(); // read only by rough balls, which always have spins
    const bool rough = settings_.rough();
    const manyballs::Friction friction{settings_.mu, settings_.beta, settings_.inertia, settings_.radius};
    const manyballs::Flight f{x,
                              x + n,
                              x + 2 * n,
                              vx,
                              vx + n,
                              vx + 2 * n,
                              rough ? wx : nullptr,
                              rough ? wx + n : nullptr,
                              rough ? wx + 2 * n : nullptr,
                              rebounds_.data(),
                              supported_.data(),
                              h,
                              manyballs::Walls{lo_, hi_, settings_.wallRestitution, restSpeed_, settings_.g, friction},
                              settings_.impacts == ImpactMode::Located,
                              rough};
    const int begin = block * kBlock, end = std::min(settings_.n, begin + kBlock);
    long long& impacts = workerImpacts_[static_cast<std::size_t>(worker)];
    const bool grid = settings_.broadphase == Broadphase::Grid;
    const broadphase::UniformGrid::Placer placer = grid ? grid_.placer(block) : broadphase::UniformGrid::Placer{};
    const double maxSpeed2 =
        manyballs::flyBlock(f, settings_.integrator, grid && grid_.kernel() == broadphase::UniformGrid::Kernel::Avx2,
                            grid ? &placer : nullptr, begin, end, impacts);
    double& slot = workerMaxSpeed2_[static_cast<std::size_t>(worker)];
    slot = std::max(slot, maxSpeed2);
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
            if (spinning_)
                wSpare_.data()[a * n + static_cast<std::size_t>(q)] = w_.data()[a * n + i];
        }
        idSpare_[static_cast<std::size_t>(q)] = id_[i];
        reboundsSpare_[static_cast<std::size_t>(q)] = rebounds_[i];
    }
}

std::size_t ManyBallsEngine::bytes() const
{
    std::size_t pairs = 0;
    for (const auto& list : pairs_)
        pairs += list.capacity() * sizeof(broadphase::Pair);
    const std::size_t arrays =
        static_cast<std::size_t>(p_.size() + v_.size() + w_.size() + pSpare_.size() + vSpare_.size() + wSpare_.size()) *
        sizeof(double);
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
        const auto seed = static_cast<std::uint64_t>(spec_.params.integer("seed"));
        State start = jitteredGridStart(s.n, s.radius, startSide(s), 1.0, seed);
        if (s.spin > 0.0)
            randomSpins(start, s.spin, seed);
        else if (s.rough())
            start.w.setZero(3, s.n); // at rest, turning from the first contact on
        return start;
    }

    void step(State& s, State& next) override
    {
        engine_.load(s);
        stepEngine(engine_, s, next, dt_);
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

} // namespace ab::physical
