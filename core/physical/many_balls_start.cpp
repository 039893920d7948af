// SPDX-License-Identifier: MIT
// The many-balls engine's settings and starts (many_balls_physical.h): what a RunSpec asks
// for, the jittered start lattice and its spins, and the benchmark workload.
#include "many_balls_physical.h"

#include "physical_models.h"

#include "../random.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace ab::physical {

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
    s.mu = spec.params.real("mu");
    s.beta = spec.params.real("beta");
    s.inertia = spec.params.real("inertia");
    s.spin = spec.params.real("spin");
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

void randomSpins(State& s, double bound, std::uint64_t seed)
{
    // A stream of its own (the seed's bits mixed with a constant), so that a run with spin
    // starts from the same positions and velocities as one without.
    SplitMix64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
    s.w.setZero(3, s.size());
    for (int i = 0; i < s.size(); ++i)
        for (int ax = 0; ax < 3; ++ax)
            s.w(ax, i) = bound * (2.0 * rng.uniform() - 1.0);
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
