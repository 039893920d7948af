// SPDX-License-Identifier: MIT
// The health check's working parts (health.h), shared by its files: health.cpp (set-up,
// energy, the step's order of checks, the public class), health_place.cpp (centres beyond
// the floor and walls), health_pairs.cpp (overlaps, balls passing through each other, a
// pair's momentum), health_spin.cpp (angular momentum about the contact point).
#pragma once

#include "health.h"

#include "../physical/spring_contact.h"
#include "../street/street_census.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ab::diagnostics {

namespace health_parts {

constexpr double infinity = std::numeric_limits<double>::infinity();

enum class Kind {
    NonFinite,
    Escaped,
    Backstop,
    Penetration,
    Energy,
    Overlap,
    Tunnel,
    Graze,
    Momentum,
    RepeatedSwap,
    Stuck,
    AngularMomentum,
    Count
};

// Three significant figures for messages.
inline std::string num(double x)
{
    return formatSignificant(x, 3);
}

// Where a centre may be: the floor and the walls as limits on the centre, infinite where
// the scene has no wall (bounce1d has only a floor; no scene has a ceiling). Walls are
// checked at any height, as both models do.
struct Walls {
    Eigen::Vector3d lo;
    Eigen::Vector3d hi;
};
Walls wallsOf(const RunSpec& spec);

// The wall a centre is furthest beyond, and by how much (0 when inside).
struct Beyond {
    double depth = 0.0;
    int axis = 1;
    bool low = true;
};
Beyond beyond(const Walls& w, const Eigen::Vector3d& p);

// Closest distance between two balls moving in straight lines over the step (s in [0, 1]).
double closestApproach(const Eigen::Vector3d& d0, const Eigen::Vector3d& d1);

} // namespace health_parts

using namespace health_parts;

struct HealthCheck::Impl {
    const Simulation& sim;
    const RunSpec& spec;
    bool report;
    double dt, g, r;
    Walls walls;
    double tolerance; // round-off allowance on lengths
    std::optional<physical::SpringFloor> spring;
    double springAllowance = infinity;
    std::vector<double> mass; // the physical model's masses (its World); empty: equal masses
    double spinInertia = 0.0; // q r^2 of I = q m r^2 (docs/spin.md); 0: the balls do not turn
    double e0 = 0.0;
    double energyScale = 0.0;
    HealthFigures fig;
    std::vector<HealthStatus> issues;
    std::vector<Kind> issueKinds; // of each issue
    std::array<std::array<bool, 3>, static_cast<std::size_t>(Kind::Count)> seen{};
    std::vector<char> escapedBall;
    Health level = Health::Ok; // of the step being checked
    double t = 0.0;            // of the state being checked
    long long pairChecks = 0;
    int sampledAbove = HealthCheck::defaultSampledAbove;
    // gridOverlaps' arrays, kept between steps.
    std::vector<std::uint32_t> cellOf, order, cellStart, cursor;
    std::vector<std::array<std::int32_t, 3>> cellXyz; // hashedOverlaps' cells, 2r wide
    std::vector<std::uint32_t> visitedBy;             // and the last ball to look into each bucket
    // The angular momentum check (health_spin.cpp): the faces other than the floor, a
    // ceiling where the scene has one; balls near another ball in this step (checkPairs).
    Eigen::Vector3d sideLo, sideHi;
    bool angularChecked = false; // the scene's balls turn and no drag acts on them
    double lever = 0.0;          // r, the lever arm of friction
    std::vector<char> nearBall;
    std::optional<street::Layout> streetLayout; // stage 5's boxes (health_street.cpp)
    // Two balls overlapping by more than this times r is a finding. The street resolves its
    // contacts in at most four Gauss-Seidel passes (street_pairs.cpp): a pile keeps overlaps of
    // a few thousandths of r, a solver's slop (0.1 mm for its 3 cm balls); elsewhere round-off.
    double overlapAllowance = 1e-9;

    double potential(double y) const { return spring ? spring->potential(y) : g * (y - walls.lo.y()); }

    std::string at() const { return " at t = " + num(t) + " " + sim.scene().timeUnit; }
    std::string length(double x) const { return num(x) + " " + sim.scene().lengthUnit; }

    Impl(const Simulation& s, const State& start);

    // sum m (|v|^2 / 2 + q r^2 |w|^2 / 2 + potential): with the physical model's masses where
    // it has them (two balls of different masses share the energy, not the energy per unit
    // mass), else per unit mass (the report's and many-balls' equal masses, the spring
    // floor's one ball). A turning ball's rotational energy I |w|^2 / 2 = m q r^2 |w|^2 / 2
    // (docs/spin.md) counts: friction trades it with the translation's.
    double energy(const State& s) const;

    // Records a problem the first time its kind is met at this level; the text is built
    // only then.
    template <typename Describe> void raise(Kind kind, Health h, Describe describe)
    {
        level = std::max(level, h);
        bool& first = seen[static_cast<std::size_t>(kind)][static_cast<std::size_t>(h)];
        if (first)
            return;
        first = true;
        HealthStatus status{h, {}, {}, t, {}};
        describe(status.what, status.advice, status.finding);
        issues.push_back(std::move(status));
        issueKinds.push_back(kind);
    }

    // What to change when the method itself misbehaves (energy, divergence): sets the
    // finding's remedy and returns it in the command line's words.
    std::string methodAdvice(Finding& f) const;

    std::string impactAdvice(Finding& f) const;

    // The remedy kept in the finding, returned in the command line's words.
    static std::string advise(Finding& f, Remedy r);

    // A state is non-finite when a number in it is, or when its energy overflows (a speed
    // beyond 1e154): nothing after it can be shown.
    bool checkFinite(const State& a, double e);

    void checkEnergy(const State& a, double e);

    std::string energyCause(Finding& f) const;

    std::string wallName(const Beyond& b, Finding& f) const;

    void checkPlace(const State& b, const State& a, int i);

    std::string pushCause(Finding& f) const;

    std::string escapeCause(const State& b, int i, const Beyond& where, Finding& f) const;

    template <typename Describe> void escape(int i, Describe describe)
    {
        if (!escapedBall[static_cast<std::size_t>(i)]) {
            escapedBall[static_cast<std::size_t>(i)] = 1;
            ++fig.escaped;
        }
        raise(Kind::Escaped, Health::Failed, [&](std::string& what, std::string& advice, Finding& f) {
            f.balls = {i};
            what = describe(f);
            advice = spring ? methodAdvice(f) : impactAdvice(f);
        });
    }

    void checkStuck(const State& b, const State& a, int i);

    void checkPair(const State& b, const State& a, int i, int j);

    // Only gravity acted on the ball in the step: its velocity and its centre moved as a
    // projectile's (no wall, no other ball, no contact pass moving its centre).
    bool freeFlight(const State& b, const State& a, int i) const;

    // Momentum of a two-ball contact: away from the walls only gravity changes it.
    void checkMomentum(const State& b, const State& a);

    void checkPairs(const State& b, const State& a);

    void gridOverlaps(const State& b, const State& a);

    // Stage 5 (health_street.cpp): a ball inside one of the street's boxes, and the overlaps
    // of many balls in a hashed grid.
    void checkStreet(const State& a, int i);
    void hashedOverlaps(const State& b, const State& a);
    std::uint32_t hashStreetBalls(const State& a); // hashedOverlaps' grid; returns its mask

    // Angular momentum about the contact point at the floor, r n x v + q r^2 w per unit mass
    // (docs/spin.md S13, S4), for each ball that the step brought near the floor and kept
    // clear of the other faces and balls (health_spin.cpp).
    void setUpAngularMomentum();
    void markNearBalls(const State& b, const State& a);
    void checkAngularMomentum(const State& b, const State& a, int i);
    bool clearOfSides(const State& b, const State& a, int i) const;

    Health check(const State& b, const State& a);
};

} // namespace ab::diagnostics
