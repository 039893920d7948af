// SPDX-License-Identifier: MIT
// Root finding for impact times. A contact is a gap function f(h) that is positive while
// the ball is free and negative once it is inside a wall or another ball; the impact is
// the first h where f crosses from >= 0 to < 0. Two cases:
//  1. f is a polynomial (degree <= 4): drag-free flight under constant acceleration, for
//     every integrator's own step map and for the exact parabola of the event integrator.
//  2. f is any continuous function with a known sign change (flight with drag): a
//     bracketing solver (Illinois) on f, which the caller evaluates by re-integrating.
#pragma once

#include <array>
#include <functional>
#include <limits>

namespace ab::physical {

// c[0] + c[1] h + c[2] h^2 + c[3] h^3 + c[4] h^4
using Poly = std::array<double, 5>;

inline constexpr double never = std::numeric_limits<double>::infinity();

double evaluate(const Poly& c, double h);

// The first h in [0, hMax] at which f goes from >= 0 to < 0, or `never`. f(0) <= 0 with
// f moving inward (its first non-zero derivative negative) gives 0: the ball is already
// touching and approaching. hMax may be infinite. A tangent touch (a double root) is not
// a crossing.
double firstInwardCrossing(Poly c, double hMax);

// A root of f in [a, b] with f(a) >= 0 > f(b), to the last few bits of the interval.
// Returns a point where f is still >= 0 (the contact, not past it).
double bracketedRoot(const std::function<double(double)>& f, double a, double fa, double b, double fb);

} // namespace ab::physical
