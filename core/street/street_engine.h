// SPDX-License-Identifier: MIT
// The physical model of stage 5 (`street`): N equal rough balls released above the top of
// the street (street_layout.h), under gravity, meeting the street's boxes and each other
// (docs/street.md).
// 1. A step is cut into substeps short enough that no ball travels more than r in one, so
//    two balls close by at most 2 r in one: no more than the skin within which their pair is
//    listed, so none passes through another between two contact checks.
// 2. A substep: (a) every ball on the street flies with its exact constant-acceleration
//    motion, free or resting on a face (rolling or sliding, street_contact.h point 4);
//    impacts with faces, leaving a face's edge and the start of rolling are located in
//    time and the motion is split there (street_flight.cpp); edges and corners are met by
//    closest point at the end of the flight. (b) Pairs of balls closer than 4 r (contact and a
//    skin of 2 r) are found in a grid of columns over the street's plan and resolved in a fixed
//    order, in passes until none overlaps by more than 1e-4 r (8 at most; up to 32 while a pile
//    overlaps by more than 2e-3 r): impulse with restitution e and Walton's tangential impulse
//    while they approach, then the overlap parted, half each and over-relaxed, and the street
//    met again; pairs apart that will touch within the next substep collide at once
//    (speculative contacts; street_pairs.cpp).
//    (c) Balls beyond the open foot leave the run: they stay there at rest and cost nothing
//    more.
// 3. Threads share the flight, the pair search and the contact passes. The pairs are cut into
//    chunks of whole columns along the street and resolved in two colours by the parity of
//    their first ball's column: the pairs of one colour in different columns never share a
//    ball, so each chunk resolves its own on any thread, and a run is the same bit for bit
//    for any thread count (street_pairs.cpp point 3).
#pragma once

#include "street_census.h"
#include "street_contact.h"
#include "street_layout.h"

#include "../broadphase/uniform_grid.h"
#include "../simulation.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace ab::physical {
class WorkerPool;
}

namespace ab::street {

struct NearestBoxes; // street_flight.cpp

struct Settings {
    int n = 0;
    double radius = 0.03;
    double g = 9.82;
    double e = 0.8;
    double restHeight = 0.001;
    double mu = 0.0, beta = 0.0, inertia = 0.4;
    double speed = 0.5;
    std::uint64_t seed = 2014;
    int threads = 1;
    double dt = 1.0 / 60.0;

    // Throws InputError for what the street does not offer (its flight is `event`'s).
    static Settings fromSpec(const RunSpec& spec, double dt);
    bool rough() const { return mu > 0.0 && beta > -1.0; }
    Surface surface() const;
};

// The hopper's start: n balls on its lattice (street_layout.h), filling the lowest layer
// first, downhill columns first; each centre moved from its site by up to 0.1 r on every
// axis and given a velocity uniform in [-speed, speed]^3 (SplitMix64 from `seed`: 3 offsets,
// then 3 velocity components per ball); no spin.
State hopperStart(const Layout& layout, const Settings& s);

class Engine {
public:
    Engine(Layout layout, const Settings& settings);
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // Takes positions, velocities and spins from `s` (settings.n balls); finds again which
    // balls rest on a face.
    void load(const State& s);
    void store(State& s) const;
    void step();

    // `s` holds exactly the balls the engine holds (the state it stored last, say): stepping
    // on needs no load, which would find the resting contacts again.
    bool holds(const State& s) const;

    long long impactsLastStep() const { return impacts_; }
    const Layout& layout() const { return layout_; }
    const Settings& settings() const { return settings_; }
    std::size_t bytes() const;

private:
    struct Ball {
        Eigen::Vector3d p, v, w;
    };
    void substep(double h);
    // The contact phase (street_pairs.cpp): pairs found, then the passes, looking ahead by h.
    void contacts(double h);
    void fly(int i, double h, long long& impacts);
    // Returns true when it moved the ball or changed its velocity.
    bool settle(int i, long long& impacts);
    // One sweep of settle over the boxes near ball i: each one the centre is within r of
    // (`close`) is pushed out of unless the ball rests on it (`pushed`); `near` gathers the
    // distances.
    struct SweepCount {
        int pushed = 0, close = 0;
    };
    SweepCount settleSweep(int i, NearestBoxes& near, long long& impacts);
    // Ball i's centre is on its support's face, within the resting gap.
    bool restsOnSupport(int i) const;
    // Moves a centre `dist` from box `item` (box coordinates `local`, `away` from its closest
    // point) out to r along the normal there, and meets the box (street_contact.h point 2).
    void pushOut(Ball& b, FaceRef& sup, int item, const Eigen::Vector3d& local, Eigen::Vector3d away, double dist,
                 long long& impacts) const;
    void findSupport(int i);
    void sizeColumns();
    // The column of a centre (x along the street, z across), clamped into the grid, and its
    // key: x * 2^zBits + z, so that keys sort along x first.
    struct Cell {
        std::uint32_t x, z;
    };
    Cell cellOf(const Eigen::Vector3d& p) const;
    std::uint32_t keyOf(const Eigen::Vector3d& p) const;
    // cellKey_ and cellSlot_: the active balls' keys and slots by key, slots in increasing
    // order within a key (stable counting sorts of active_, which is in slot order).
    void sortActiveByColumn();
    void buildCells();
    // Cuts the sorted balls into chunks of whole columns along x (street_pairs.cpp point 3).
    void cutChunks();
    void findPairs(int chunk);
    // One pass over the listed pairs, the speculative contacts of pairs apart that meet
    // within h included: the largest overlap it parted, and how many pairs it turned. The
    // first pass of a substep visits every pair; a later one only the pairs with a ball that
    // changed since the pass before (street_pairs.cpp point 3).
    struct PassResult {
        double overlap = 0.0;
        int turned = 0;
    };
    struct Chunk;
    PassResult resolvePairs(double h, bool first);
    // The pairs of one colour of a chunk, in the search's order; `before`: the pass's number.
    void resolveChunk(Chunk& chunk, int colour, double h, bool first, std::uint32_t before);
    // The street met again by the balls the pairs moved in the pass.
    void settleMoved();
    bool collide(Ball& a, Ball& b, const Eigen::Vector3d& n, double u) const;
    void markChanged(std::uint32_t i) { changed_[i] = pass_; }
    // Parts two balls that overlap by `overlap` along n (a to b), half each, over-relaxed
    // (street_pairs.cpp point 4); the balls it moves first in a pass join the chunk's list.
    void part(Chunk& chunk, std::uint32_t a, std::uint32_t b, const Eigen::Vector3d& n, double overlap);
    void retire();
    int substepsFor(double dt) const;
    // Re-orders the balls' slots: the active ones by column (x first), then the others, so
    // that the balls a pair search and a contact pass read together lie together in memory.
    void sortByColumn();

    Layout layout_;
    Settings settings_;
    Surface surface_;
    std::unique_ptr<physical::WorkerPool> pool_;
    // Per slot: the ball, the face it rests on, its index in a State (id_). Slots are
    // re-ordered every step (sortByColumn); load and store translate.
    std::vector<Ball> balls_;
    std::vector<FaceRef> support_;
    // How far a ball's centre may still move before a box of the street other than `nearest`
    // (the nearest box when measured; -1: none) can come within r of it: a lower bound, less
    // every move since it was measured (street_flight.cpp point 2).
    struct Room {
        double room = -1.0;
        int nearest = -1;
    };
    std::vector<Room> room_;
    std::vector<int> id_;
    std::vector<int> active_; // the slots of the balls on the street, in slot order
    std::vector<int> newOrder_;
    std::vector<Ball> ballScratch_;
    std::vector<FaceRef> supportScratch_;
    std::vector<Room> roomScratch_;
    std::vector<int> idScratch_;
    // The grid of columns over the street's plan (street_pairs.cpp): the active balls sorted
    // by their columns' keys each substep, with their slots and centres in that order.
    struct Columns {
        double x0 = 0.0, z0 = 0.0, side = 1.0;
        int nx = 1, nz = 1;
        int zBits = 0; // 2^zBits >= nz
    } columns_;
    std::vector<std::uint32_t> cellKey_, cellSlot_, keyScratch_, slotScratch_, histogram_;
    std::vector<Eigen::Vector3d> cellPos_;
    // Per chunk of the sorted balls, places [begin, end), whole columns along x: its pairs by
    // the parity of their first ball's column, the first count[c] of list[c] (the lists keep
    // their sizes from substep to substep, so that filling one writes each entry once); what
    // its pairs did in the pass under way, and the balls they moved first in it.
    struct Chunk {
        std::size_t begin = 0, end = 0;
        std::array<std::vector<broadphase::Pair>, 2> list;
        std::array<std::size_t, 2> count{};
        PassResult pass;
        long long impacts = 0;
        std::vector<int> moved;
    };
    std::vector<Chunk> pairs_;
    // Passes over the pairs are numbered through the run (pass_, the current one); each ball
    // keeps the number of the last pass that changed it.
    std::vector<std::uint32_t> changed_;
    std::vector<std::uint8_t> moved_; // moved by a pair in this pass
    std::uint32_t pass_ = 0;
    double turnSpeed_ = 0.0; // an approach slower than this is round-off, not a turn
    std::vector<long long> workerImpacts_;
    long long impacts_ = 0;
    double maxSpeed_ = 0.0;
    double energyLeft_ = 0.0; // State::energyLeft: what the balls that left took with them
    double covered_ = 0.0;    // how far ahead the last contact phase looked for pairs that meet
    bool loaded_ = false;     // a state was loaded: the balls are a run's
};

std::unique_ptr<Simulation> makeStreet(const RunSpec& spec, double dt);

} // namespace ab::street
