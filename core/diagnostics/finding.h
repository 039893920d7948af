// SPDX-License-Identifier: MIT
// A health finding as data (what happened, to which balls, with which figures, the
// report's rule behind it and what to change), so that each front end words it in its own
// language and words: the CLI in English with its options (remedyText below, the advice
// half of HealthStatus::line()), the window in its language with its controls.
#pragma once

#include "../scene.h"

#include <string>
#include <vector>

namespace ab::diagnostics {

enum class FindingKind {
    NonFinite,         // the state became non-finite
    Escaped,           // a ball left the box or fell through the floor (wallAxis, wallFace, amount)
    SpringEscaped,     // a ball went twice deeper into the floor spring than its energy allows (amount)
    Backstop,          // held by the floor spring's backstop (amount; bound: the depth its energy allows)
    SpringPenetration, // deeper into the floor spring than its energy allows (amount, bound)
    Penetration,       // a centre beyond a face within one step's travel: an impact found late
    Energy,            // energy above its start (amount: the gain in per cent)
    Overlap,           // two balls overlap (amount)
    Tunnel,            // two balls passed through each other within a step (amount: closest, bound: contact)
    Graze,             // two balls grazed without colliding (amount: closest, bound: depth inside)
    Momentum,          // momentum changed in a pair contact (amount: per cent of the pair's speeds)
    RepeatedSwap,      // the report's stage-3 swap repeats while the balls overlap
    Stuck,             // the report's stage-4 ball on the floor keeps its speed (amount) without moving
    AngularMomentum,   // angular momentum about the contact point changed at the floor (amount: per cent)
};

// The report's own rule behind a finding, with where the report has it.
enum class ReportRule {
    None,
    ExplicitEulerGain,  // eq 2.16: the position moves with the old velocity (stage 1)
    FloorRuleGain,      // Appendix B: v' = -k v - g dt adds a step of gravity to each rebound
    PushAndWallGravity, // Appendix D: the push of one radius and the extra gravity at a side wall
    UnclampedPush,      // Appendix D: the push is not clamped into the box
    OneFacePerStep,     // Appendix B: one face a step, the floor first
    SwapWithoutTest,    // Appendix C: the swap has no test that the balls approach
    SwapScaledByE,      // Appendix C: both swapped velocities are scaled by e
    OnlyAboveFloor,     // Appendix D: only balls above the floor are updated
};

// What to change.
enum class Remedy {
    None,
    ReportSmallerDt,   // the report's own rule; a smaller step shrinks it, the physical model avoids it
    ReportPhysical,    // the report's own rule; the physical model avoids it
    ReportMomentum,    // the report's own rule; the physical model conserves momentum
    ReportOnePerFrame, // the report's own rule, one update per frame; the physical model avoids it
    ReportStepEnd,     // the report finds impacts only at a step's end; a smaller step shrinks it
    SpringEuler,       // explicit Euler gains energy on a spring (dtOmega)
    SpringLimit,       // the integrator is stable only below limit: dt below dtLimit, or implicit Euler
    EulerAddsEnergy,   // explicit Euler adds energy every step: another integrator
    LocatedOrSmallerDt,
    SmallerDt,
    StreetContacts, // the street: substeps follow the fastest ball, not dt; piles leave the most
};

struct Finding {
    FindingKind kind = FindingKind::NonFinite;
    std::vector<int> balls; // numbered from 0 (the window shows them from 1)
    double amount = 0.0;    // the kind's figure (see FindingKind), in the scene's units
    double bound = 0.0;     // what it is measured against
    int wallAxis = 1;       // 1: the floor; 0 or 2: the wall at x or z = wallFace
    double wallFace = 0.0;
    ReportRule rule = ReportRule::None;
    Remedy remedy = Remedy::None;
    Integrator integrator = Integrator::SymplecticEuler; // of SpringEuler and SpringLimit
    double dtOmega = 0.0, limit = 0.0, dtLimit = 0.0;    // SpringEuler, SpringLimit
};

// The remedy in the command line's words ("use --impacts located or a smaller --dt").
std::string remedyText(const Finding& f);

} // namespace ab::diagnostics
