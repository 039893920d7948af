// SPDX-License-Identifier: MIT
// The physical model of stage 4 (`many-balls`): N equal balls of radius r in a closed
// cubic box of side L centred at the origin, gravity g along -y, restitution k at the walls
// and e between balls. With mu > 0 and beta > -1 the balls are rough spheres that turn
// (docs/spin.md): Walton's tangential impulse at every wall and ball-ball impact, Coulomb
// friction while a ball rests on the floor. Otherwise they are smooth and their spins, if
// the start gives them any, stay as they are. ManyBallsEngine steps the balls in place (what the
// benchmark and a large view drive); the Simulation built by makeManyBalls() wraps it for
// the State interface, copying the state in and out once per step.
#pragma once

#include "../broadphase/uniform_grid.h"
#include "../simulation.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace ab::physical {

class WorkerPool;

// Everything a step reads, from a RunSpec whose parameters are already valid.
struct ManyBallsSettings {
    int n = 0;
    double radius = 1.0;          // r
    double box = 100.0;           // L, walls at +-L/2
    double g = 0.0;               // gravity magnitude, along -y
    double wallRestitution = 1.0; // k (primary_loss)
    double ballRestitution = 1.0; // e (secondary_loss)
    double restHeight = 0.0;      // h_rest: rebounds lower than this end at rest
    double mu = 0.0;              // Coulomb friction at every contact (docs/spin.md, S2, S10)
    double beta = 0.0;            // tangential restitution (S9), -1 smooth .. 1 superball
    double inertia = 0.4;         // q of I = q m r^2
    double spin = 0.0;            // start spins: each component uniform in [-spin, spin]
    Integrator integrator = Integrator::SymplecticEuler;
    ImpactMode impacts = ImpactMode::Located;
    Broadphase broadphase = Broadphase::Grid;
    int threads = 1;
    double dt = 1.0;
    // The instruction set of the grid and of the flight (the same numbers with either).
    broadphase::UniformGrid::Kernel kernel = broadphase::UniformGrid::bestKernel();

    // Throws InputError for what many-balls does not offer (event, implicit integrators).
    static ManyBallsSettings fromSpec(const RunSpec& spec, double dt);
    // Friction acts at the contacts: the balls' spins change in the run.
    bool rough() const { return mu > 0.0 && beta > -1.0 && radius > 0.0; }
};

// n balls on a jittered cubic lattice inside the cube [-side/2, side/2]^3, centred at the
// origin: k = ceil(cbrt(n)) sites a side, spacing a = side / k, each centre moved from its
// site by up to (a - 2r)/2 on each axis, so centres stay >= 2r apart and >= r inside the
// cube. Sites fill from the bottom layer (lowest y) up. Velocities are uniform in
// [-speed, speed]^3. Draws per ball: 3 offsets, then 3 velocity components (SplitMix64).
// Throws InputError when the lattice does not fit (a < 2r).
State jitteredGridStart(int n, double radius, double side, double speed, std::uint64_t seed);

// Start spins for `s`: each component of every ball's w uniform in [-bound, bound], from
// their own SplitMix64 stream of `seed` (the positions and velocities do not change).
void randomSpins(State& s, double bound, std::uint64_t seed);

// Sites a side of the start lattice for n balls, ceil(cbrt(n)); and the refusal of a
// lattice that does not fit in a cube of `side` (InputError).
int latticeSide(int n);
void checkLatticeFits(int n, double radius, double side);

class ManyBallsEngine {
public:
    explicit ManyBallsEngine(const ManyBallsSettings& settings);
    ~ManyBallsEngine();
    ManyBallsEngine(const ManyBallsEngine&) = delete;
    ManyBallsEngine& operator=(const ManyBallsEngine&) = delete;

    // Takes positions, velocities, spins (when `s` has them) and per-ball rebound counts
    // (State::bounces) from `s`, which must hold settings.n balls.
    void load(const State& s);
    // Writes them back in the caller's ball order, the spins where the engine turns its
    // balls (rough, or a start that spins); `s.t`, `count` and `halted` are left alone.
    void store(State& s) const;
    // Advances every ball by settings.dt.
    void step();
    // Rebounds during the last step(): off a wall, or a pair of balls (counted once).
    long long impactsLastStep() const { return impacts_; }

    int size() const { return settings_.n; }
    // The engine carries spins: rough balls, or spins loaded with the state.
    bool spinning() const { return spinning_; }
    const ManyBallsSettings& settings() const { return settings_; }
    // Memory held by the engine, in bytes (arrays and lists, not the thread stacks).
    std::size_t bytes() const;

    // The passes over the contacts of a substep: impulses (with Walton's between rough
    // balls) and projection, or the resting contacts of a pile (many_balls_contacts.cpp).
    enum class Pass : unsigned char { Contact, Support };

private:
    void substep(double h);
    void fly(int block, int worker, double h);
    void findPairs(int list);
    void resolvePass(Pass pass, bool shared);
    void resolveList(const std::vector<broadphase::Pair>& pairs, Pass pass, int worker);
    void reorder(int block);
    int substepsFor(double dt) const;

    ManyBallsSettings settings_;
    double lo_, hi_;   // the range of every centre coordinate: -L/2 + r, L/2 - r
    double restSpeed_; // sqrt(2 g h_rest)
    std::unique_ptr<WorkerPool> pool_;
    Vec3Array p_, v_; // in the engine's order (by cell, now and then)
    Vec3Array w_;     // spins, 3 x N where spinning_ (else 3 x 0)
    bool spinning_ = false;
    Vec3Array pSpare_, vSpare_, wSpare_;      // the target of a re-ordering
    std::vector<std::uint32_t> id_, idSpare_; // engine order -> caller's ball index
    std::vector<int> rebounds_, reboundsSpare_;
    std::vector<std::uint8_t> supported_; // resting on the floor, or on a supported ball (set each substep)
    broadphase::UniformGrid grid_;
    std::vector<std::vector<broadphase::Pair>> pairs_; // per slab (grid) or per range of rows (all pairs)
    std::vector<double> workerMaxSpeed2_;              // largest squared speed each worker saw this substep
    std::vector<long long> workerImpacts_;             // rebounds each worker resolved this step
    long long impacts_ = 0;
    double maxSpeed_ = 0.0;
    long long substepsDone_ = 0;
};

std::unique_ptr<Simulation> makeManyBalls(const RunSpec& spec, double dt);

// The benchmark workload of `amazeballs-cli bench` and docs/performance.md: radius 1, a
// cubic box of side max(100, (N (4/3) pi / 0.10)^(1/3)) (about 10% of it filled), a
// jittered-grid start filling the box, velocities uniform in [-1, 1]^3 (length/s) from a
// fixed seed, g = 9.82, restitution 0.9 at walls and 0.95 between balls, dt = 1/240 s.
// The report model, which counts in frames of dt, gets the same start and constants
// converted to frames.
double benchmarkBoxSide(int n);
RunSpec benchmarkSpec(int n, ModelKind model, Broadphase broadphase, int threads);

} // namespace ab::physical
