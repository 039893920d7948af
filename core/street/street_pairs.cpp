// SPDX-License-Identifier: MIT
// The contacts between the street's balls (street_engine.h point 2b).
// 1. The balls roll and bounce in a thin layer over a long, narrow street, so the grid is one
//    of columns: cells over (x, z) at least 4 r wide (contact 2 r and a skin of 2 r), the
//    street's whole length and width, every height in one column. A centre beyond the grid
//    falls in its outermost column (clamping never separates two coordinates). Each substep
//    the active balls are sorted by their columns' keys, x * 2^zBits + z (two stable counting
//    sorts, by z then by x: O(N + columns along x + columns across)), and their slots and
//    centres copied out in that order, so a column is a run of that array and two columns
//    side by side across the street are one run.
// 2. Two centres closer than 4 r lie in the same or adjacent columns. Each ball looks at the
//    later balls of its own column and the column at z + 1 (one run from the ball on), and
//    at the columns z - 1, z, z + 1 of the next x (one run, found by a pointer that only moves
//    forward as the balls go by), so every pair is found once, in an order that does not
//    depend on the threads; the exact distance then keeps only the near ones.
// 3. The pairs are resolved in passes until none overlaps by more than 1e-4 r and none
//    approaches (Gauss-Seidel; 8 passes at most, up to 32 while a deep pile overlaps by more
//    than 2e-3 r). The sorted balls are cut into chunks of about 2,048 that end where a column
//    along x ends, and each chunk's pairs into two colours by the parity of the column along x
//    of their first ball. A pair joins balls of that column and the next one along x, so the
//    pairs of one colour in two different columns share no ball: a pass resolves the even
//    colour, every chunk on whichever thread takes it, then the odd one, each chunk's pairs
//    in the search's order. What a pair sees then depends on the chunks and the colours only,
//    never on the threads. Each pair: eqs 2.4-2.7 along the line of centres with
//    restitution e, Walton's impulse between rough balls (pair_friction.h), the overlap
//    parted half each, over-relaxed (point 4); a ball moved then meets the street again
//    (settle). Every pass also takes the pairs that will meet within the next substep
//    (speculative contacts). Approaches slower than 1e-10 of the scene's speeds and overlaps
//    below 1e-9 r are round-off and left alone, so a pair a pass resolved does nothing in the
//    next unless a ball of it changed since: each pass after the first visits only the pairs
//    with a ball changed by the pass before or by this one (a ball keeps the number of the
//    last pass that changed it), and the rest of a pile costs nothing more.
// 4. A pair is parted by 1.8 times its overlap, not exactly to touching (successive
//    over-relaxation of the passes). In a pile several balls deep, a pass that parts a pair to
//    touching has the next pair, or the street, push one of its balls back, so the passes put
//    a pile right layer by layer; parting past touching, by a gap of 0.8 times the overlap it
//    had, hands each pair's correction on faster. Over-relaxed Gauss-Seidel converges for
//    factors between 0 and 2 (projected SOR, Cryer 1971). The pair's centre of mass, and so
//    its momentum and potential energy, are kept as before; the gap closes under the next
//    substep's gravity. On a street 3 m wide holding 40,000 balls (a pile as deep as the
//    advert's) the first 6 s visit 0.42 times the pairs that parting to touching visits, with
//    the health check as clean (docs/performance.md).
#include "street_engine.h"

#include "../physical/pair_friction.h"
#include "../physical/worker_pool.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace ab::street {

using broadphase::Pair;

namespace {

constexpr int kPairChunk = 2048; // active balls a worker searches at a time
// Pairs are listed within 2 r + a skin of 2 r: a pass that pushes a ball into a neighbour it
// did not touch after the flight still finds that pair in the list, and so does a pair that
// will touch within the next substep (two balls close by at most 2 r in one).
constexpr double kSkin = 2.0;
constexpr double kOverRelax = 1.8; // point 4
// A phase of the passes goes to the threads with this much work at least (pairs listed, balls
// to settle); less is done on this thread, in the chunks' order, rather than wake the others
// for a few microseconds of work. The chunks of a phase share no ball, so the balls come out
// the same either way.
constexpr std::size_t kSharedPairs = 8192;
constexpr std::size_t kSharedSettles = 512;

} // namespace

void Engine::sizeColumns()
{
    // Over the street's plan from the back wall to beyond the foot, in cells of at least the
    // pair distance and at most about max(8 N, 2^20) cells in all (cells grow beyond that
    // distance to respect it), so that the counting sorts' histograms stay small beside N and
    // a key, x * 2^zBits + z < 2 nx nz, fits in 32 bits.
    const double reach = (2.0 + kSkin) * settings_.radius;
    columns_.x0 = layout_.xTop - 4.0;
    columns_.z0 = -(0.5 * layout_.width + layout_.sidewalk);
    const double lengthX = layout_.xFoot + 1.0 - columns_.x0, lengthZ = -2.0 * columns_.z0;
    const double cells = std::max(8.0 * settings_.n, 1048576.0);
    columns_.side = std::max(reach * (1.0 + 1e-9), std::sqrt(lengthX * lengthZ / cells));
    columns_.nx = std::max(1, static_cast<int>(std::ceil(lengthX / columns_.side)));
    columns_.nz = std::max(1, static_cast<int>(std::ceil(lengthZ / columns_.side)));
    columns_.zBits = 0;
    while ((1 << columns_.zBits) < columns_.nz)
        ++columns_.zBits;
}

Engine::Cell Engine::cellOf(const Eigen::Vector3d& p) const
{
    const double inv = 1.0 / columns_.side;
    // max/min clamps NaN to the first column too
    return Cell{static_cast<std::uint32_t>(std::min(std::max(0.0, (p.x() - columns_.x0) * inv), columns_.nx - 1.0)),
                static_cast<std::uint32_t>(std::min(std::max(0.0, (p.z() - columns_.z0) * inv), columns_.nz - 1.0))};
}

std::uint32_t Engine::keyOf(const Eigen::Vector3d& p) const
{
    const Cell c = cellOf(p);
    return (c.x << columns_.zBits) | c.z;
}

namespace {

// A stable counting sort of (key, slot) by digit(key) < buckets, from `key`/`slot` into
// `keyOut`/`slotOut`.
template <typename Digit>
void sortByDigit(const std::vector<std::uint32_t>& key, const std::vector<std::uint32_t>& slot,
                 std::vector<std::uint32_t>& keyOut, std::vector<std::uint32_t>& slotOut,
                 std::vector<std::uint32_t>& histogram, std::size_t buckets, Digit digit)
{
    histogram.assign(buckets + 1, 0);
    for (std::uint32_t k : key)
        ++histogram[digit(k) + 1];
    for (std::size_t b = 1; b <= buckets; ++b)
        histogram[b] += histogram[b - 1]; // where each digit's run starts
    for (std::size_t i = 0; i < key.size(); ++i) {
        const std::uint32_t at = histogram[digit(key[i])]++;
        keyOut[at] = key[i];
        slotOut[at] = slot[i];
    }
}

} // namespace

void Engine::sortActiveByColumn()
{
    // Point 1: keys in active order, sorted by z then (stably) by x.
    const std::size_t count = active_.size();
    for (auto* v : {&cellKey_, &cellSlot_, &keyScratch_, &slotScratch_})
        v->resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const auto slot = static_cast<std::uint32_t>(active_[k]);
        cellKey_[k] = keyOf(balls_[slot].p);
        cellSlot_[k] = slot;
    }
    const std::uint32_t zMask = (1u << columns_.zBits) - 1u;
    const int zBits = columns_.zBits;
    sortByDigit(cellKey_, cellSlot_, keyScratch_, slotScratch_, histogram_, static_cast<std::size_t>(columns_.nz),
                [zMask](std::uint32_t key) { return key & zMask; });
    sortByDigit(keyScratch_, slotScratch_, cellKey_, cellSlot_, histogram_, static_cast<std::size_t>(columns_.nx),
                [zBits](std::uint32_t key) { return key >> zBits; });
}

void Engine::buildCells()
{
    // Point 1: the balls sorted by column, then their centres in that order.
    sortActiveByColumn();
    const std::size_t count = active_.size();
    cellPos_.resize(count);
    for (std::size_t s = 0; s < count; ++s)
        cellPos_[s] = balls_[cellSlot_[s]].p;
    cutChunks();
}

void Engine::cutChunks()
{
    // Point 3: about kPairChunk balls a chunk, grown to the end of its last column along x.
    const std::size_t count = cellKey_.size();
    const int zBits = columns_.zBits;
    std::size_t chunks = 0;
    for (std::size_t begin = 0; begin < count; ++chunks) {
        std::size_t end = std::min(count, begin + kPairChunk);
        while (end < count && (cellKey_[end] >> zBits) == (cellKey_[end - 1] >> zBits))
            ++end;
        if (pairs_.size() <= chunks)
            pairs_.emplace_back();
        pairs_[chunks].begin = begin;
        pairs_[chunks].end = end;
        begin = end;
    }
    pairs_.resize(chunks);
}

void Engine::findPairs(int chunk)
{
    Chunk& own = pairs_[static_cast<std::size_t>(chunk)];
    const double reach = (2.0 + kSkin) * settings_.radius, reach2 = reach * reach;
    const std::size_t count = cellKey_.size();
    const std::size_t begin = own.begin, end = own.end;
    own.count = {0, 0};
    const std::uint32_t* key = cellKey_.data();
    const int zBits = columns_.zBits;
    const auto nz = static_cast<std::uint32_t>(columns_.nz), nx = static_cast<std::uint32_t>(columns_.nx);
    // Each ball's candidates [from, to) are written whether near or not and only the near ones
    // kept (no branch on the distance, which goes either way), in the list of the colour of
    // the ball's column along x (point 3).
    const auto near = [&](std::size_t s, std::size_t from, std::size_t to) {
        const std::uint32_t colour = (key[s] >> zBits) & 1u;
        std::vector<Pair>& out = own.list[colour];
        std::size_t listed = own.count[colour];
        if (listed + (to - from) > out.size())
            out.resize(2 * (listed + (to - from)));
        const Eigen::Vector3d p = cellPos_[s];
        for (std::size_t t = from; t < to; ++t) {
            out[listed] = Pair{cellSlot_[s], cellSlot_[t]};
            listed += (cellPos_[t] - p).squaredNorm() < reach2 ? 1 : 0;
        }
        own.count[colour] = listed;
    };
    // The window of the next x for a key: its columns z - 1 .. z + 1 (within the grid).
    const auto window = [&](std::uint32_t k, std::uint32_t& low, std::uint32_t& high) {
        const std::uint32_t cz = k & ((1u << zBits) - 1u), row = ((k >> zBits) + 1u) << zBits;
        low = row | (cz > 0 ? cz - 1 : 0);
        high = row | std::min(cz + 1, nz - 1);
    };
    std::uint32_t low = 0, high = 0;
    window(key[begin], low, high);
    std::size_t ahead = static_cast<std::size_t>(std::lower_bound(key + begin, key + count, low) - key);
    for (std::size_t s = begin; s < end; ++s) {
        const std::uint32_t k = key[s];
        const std::uint32_t cz = k & ((1u << zBits) - 1u);
        const std::uint32_t last = cz + 1 < nz ? k + 1 : k; // its own column and the one at z + 1
        std::size_t to = s + 1;
        while (to < count && key[to] <= last)
            ++to;
        near(s, s + 1, to);
        if ((k >> zBits) + 1 >= nx)
            continue; // no columns beyond the last x
        window(k, low, high);
        while (ahead < count && key[ahead] < low)
            ++ahead; // low never decreases as the keys grow
        to = ahead;
        while (to < count && key[to] <= high)
            ++to;
        near(s, ahead, to);
    }
}

// Eqs 2.4-2.7 for equal masses along n (a to b), u = (v_b - v_a).n < 0: u becomes -e u through
// the impulse j n on a, -j n on b, j = (1 + e) u / 2; momentum kept, energy changes by
// (e^2 - 1) u^2 / 4. A rebound slower than the rest speed is stopped (e taken as 0). Rough
// balls exchange Walton's impulse too (S11-S12). Returns true for a rebound.
bool Engine::collide(Ball& a, Ball& b, const Eigen::Vector3d& n, double u) const
{
    const double e = settings_.e;
    const bool bounces = -e * u >= surface_.restSpeed;
    const double j = 0.5 * (1.0 + (bounces ? e : 0.0)) * u;
    if (surface_.rough) {
        physical::PairVelocities pv{a.v, b.v, a.w, b.w};
        physical::waltonBetween(pv, n, (1.0 + (bounces ? e : 0.0)) * -u, surface_.friction);
        a.v = pv.va, b.v = pv.vb, a.w = pv.wa, b.w = pv.wb;
    }
    a.v += j * n;
    b.v -= j * n;
    return bounces;
}

Engine::PassResult Engine::resolvePairs(double h, bool first)
{
    // Point 3: the even colour, then the odd one, each chunk on any thread; their results are
    // summed in the chunks' order.
    const std::uint32_t before = pass_++; // balls this pass or the last one changed: >= before
    const int chunks = static_cast<int>(pairs_.size());
    std::array<std::size_t, 2> listed{};
    for (Chunk& chunk : pairs_) {
        chunk.pass = PassResult{};
        chunk.impacts = 0;
        listed[0] += chunk.count[0];
        listed[1] += chunk.count[1];
    }
    for (int colour = 0; colour < 2; ++colour)
        pool_->forEach(
            chunks,
            [&](int chunk, int) { resolveChunk(pairs_[static_cast<std::size_t>(chunk)], colour, h, first, before); },
            listed[static_cast<std::size_t>(colour)] >= kSharedPairs);
    PassResult result;
    for (const Chunk& chunk : pairs_) {
        result.overlap = std::max(result.overlap, chunk.pass.overlap);
        result.turned += chunk.pass.turned;
        workerImpacts_[0] += chunk.impacts;
    }
    return result;
}

void Engine::resolveChunk(Chunk& chunk, int colour, double h, bool first, std::uint32_t before)
{
    const double contact = 2.0 * settings_.radius;
    // Overlaps below 1e-9 r are the round-off of parting (centres some hundred metres out):
    // left as they are, so that a pair once parted stays still.
    const double partSlack = 1e-9 * settings_.radius;
    PassResult& result = chunk.pass;
    // An approach turned along n: the impulse, counted, and both balls changed.
    const auto turn = [&](const Pair& pair, const Eigen::Vector3d& n, double u) {
        if (collide(balls_[pair.a], balls_[pair.b], n, u))
            ++chunk.impacts;
        ++result.turned;
        markChanged(pair.a);
        markChanged(pair.b);
    };
    const auto c = static_cast<std::size_t>(colour);
    for (const Pair& pair : std::span(chunk.list[c].data(), chunk.count[c])) {
        // A pair whose balls are as they were when it was last visited (it did nothing then)
        // would do nothing now.
        if (!first && changed_[pair.a] < before && changed_[pair.b] < before)
            continue;
        Ball& a = balls_[pair.a];
        Ball& b = balls_[pair.b];
        Eigen::Vector3d n = b.p - a.p;
        const double d = n.norm();
        if (!(d < contact)) {
            // Apart: in every pass (an earlier contact may have turned them), a pair that
            // would touch within the next substep
            // (|D + dV t| = 2 r for the relative position D and velocity dV, the earlier root
            // in [0, h]) collides now, along the normal it would meet at (a speculative
            // contact): no two balls graze or pass within a substep unseen.
            const Eigen::Vector3d dv = b.v - a.v;
            const double approach = n.dot(dv), vv = dv.squaredNorm();
            if (!(approach < 0.0))
                continue;
            const double disc = approach * approach - vv * (d * d - contact * contact);
            if (disc < 0.0)
                continue; // they pass each other
            const double t = (-approach - std::sqrt(disc)) / vv;
            if (!(t <= h))
                continue;
            const Eigen::Vector3d meet = (n + t * dv) / contact;
            const double u = dv.dot(meet);
            if (u < -turnSpeed_) // else they graze
                turn(pair, meet, u);
            continue;
        }
        n = d > 0.0 ? Eigen::Vector3d(n / d) : Eigen::Vector3d::UnitY();
        const double u = (b.v - a.v).dot(n); // negative while they approach
        if (u < -turnSpeed_)
            turn(pair, n, u);
        const double overlap = contact - d;
        if (!(overlap > partSlack))
            continue;
        result.overlap = std::max(result.overlap, overlap);
        part(chunk, pair.a, pair.b, n, overlap);
    }
}

void Engine::part(Chunk& chunk, std::uint32_t a, std::uint32_t b, const Eigen::Vector3d& n, double overlap)
{
    // Half each along n, over-relaxed (point 4): the pair ends (kOverRelax - 1) overlap apart,
    // its centre of mass (and its potential energy) kept.
    const double share = 0.5 * kOverRelax * overlap;
    for (const auto& [i, by] : {std::pair{a, -share}, std::pair{b, share}}) {
        balls_[i].p += by * n;
        room_[i].room -= std::abs(by); // n is a unit vector
        markChanged(i);
        if (moved_[i] == 0) {
            moved_[i] = 1;
            chunk.moved.push_back(static_cast<int>(i));
        }
    }
}

void Engine::settleMoved()
{
    // Each ball a pair moved is in one chunk's list, and settle reads and writes its own ball
    // only (and the street's boxes, which stay put).
    std::size_t moved = 0;
    for (const Chunk& chunk : pairs_)
        moved += chunk.moved.size();
    const auto settleChunk = [&](int c, int worker) {
        Chunk& chunk = pairs_[static_cast<std::size_t>(c)];
        long long met = 0;
        for (int i : chunk.moved) {
            moved_[static_cast<std::size_t>(i)] = 0;
            if (settle(i, met))
                markChanged(static_cast<std::uint32_t>(i));
        }
        chunk.moved.clear();
        workerImpacts_[static_cast<std::size_t>(worker)] += met;
    };
    pool_->forEach(static_cast<int>(pairs_.size()), settleChunk, moved >= kSharedSettles);
}

} // namespace ab::street
