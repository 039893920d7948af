// SPDX-License-Identifier: MIT
// A health check after every step, for every scene, model and integrator: it says what
// went wrong in physical terms, with its figure, and what to change. The front ends
// report it (the CLI on stderr, the app in its status line) and stop before a
// non-finite state is shown.
//
// Checks, on each pair of consecutive final states:
//  1. non-finite positions or velocities, or an energy that overflows (failed);
//  2. a centre beyond the floor or a wall: within one step's travel it is an impact found
//     late (warning), deeper it has left the box (failed); on the spring floor the
//     allowance is twice the compression the start energy allows (failed; at the spring's
//     backstop, 1.5 times it, failed too: the integrator is unstable; over 1% beyond it, a
//     warning);
//  3. energy (kinetic + g times the height above the floor, + the spring's; each ball
//     weighed by the physical model's mass, per unit mass where all are equal) above its
//     start: k and e are at most 1, so any gain is the method's (warning above 1e-6 of the
//     start, failed above 10%; a start with less energy than a ball raised by the scene's
//     size is measured against that instead);
//  4. ball overlap, balls passing through each other within a step (failed; a path that
//     only grazes the contact distance, by under a tenth of a radius, is a warning; two-balls
//     and small many-balls runs all pairs; larger runs look for overlaps on a grid, the
//     largest on every 10th step only), and the momentum change of a pair contact away from the walls (two-balls);
//  5. rough balls (docs/spin.md): the angular momentum about the contact point,
//     r n x v + q r^2 w per unit mass, kept across a floor impact and while a ball slides or
//     rolls on the floor, for each ball whose step stays clear of the other faces and balls
//     (a warning above 1e-9 of its size); energy (3.) counts rotation, so any gain with
//     e, k <= 1 and |beta| <= 1 is the method's;
//  6. the report model's own known failures, named as such: its stage-1 Euler energy
//     gain, the stage-3 swap repeating while the balls overlap, stage-4 balls stuck on the
//     floor and its unclamped push beyond the walls.
#pragma once

#include "finding.h"

#include "../simulation.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ab::diagnostics {

enum class Health { Ok, Warning, Failed };
std::string_view healthKey(Health h); // "ok", "warning", "failed"

struct HealthStatus {
    Health level = Health::Ok;
    std::string what;   // what happened, with its figure, the time and the ball
    std::string advice; // what to change
    double t = 0.0;
    Finding finding; // the same as data

    // "what; advice" on one line.
    std::string line() const;
};

// Running figures of a run, as the stability suite tabulates them.
struct HealthFigures {
    long long steps = 0;
    double maxEnergyGain = 0.0;  // largest (E - E0) / E0 (see 3. above), 0 when it never rose
    double maxPenetration = 0.0; // deepest centre beyond the floor or a wall (length unit)
    int escaped = 0;             // balls that left the box or fell through the floor
    bool nonfinite = false;
    std::optional<double> maxMomentumError;        // pair contacts: |dp| / (|v1| + |v2|), two-balls
    std::optional<double> maxOverlap;              // deepest 2r - distance between two balls
    std::optional<double> maxAngularMomentumError; // floor contacts of turning balls: |dL| / |L| (5.)
};

class HealthCheck {
public:
    // Runs with more than `sampledAbove` balls check their pairs (overlaps, balls passing
    // through each other) on every 10th step only; every other check runs on every step.
    // The window lowers it to keep a large run in real time beside the drawing.
    static constexpr int defaultSampledAbove = 100'000;
    HealthCheck(const Simulation& sim, const State& start, int sampledAbove = defaultSampledAbove);
    ~HealthCheck();
    HealthCheck(HealthCheck&&) noexcept;
    HealthCheck& operator=(HealthCheck&&) noexcept;

    // Takes over `earlier`'s findings up to time `upTo`, before any of its own: a run that
    // goes back to a state at `upTo` and checks its steps again from there keeps what its
    // first pass found before that state (each kind still once).
    void keepFindings(const HealthCheck& earlier, double upTo);

    // Checks the step from `before` to `after`, consecutive final states; returns the
    // worst level found in this step.
    Health check(const State& before, const State& after);

    const HealthFigures& figures() const;
    // Each kind of problem met, once, at its first occurrence, in time order.
    const std::vector<HealthStatus>& issues() const;
    // The non-finite state that stopped a run, else the first failure, else the first
    // warning, else an ok status.
    HealthStatus worst() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace ab::diagnostics
