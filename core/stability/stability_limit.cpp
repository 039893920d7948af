// SPDX-License-Identifier: MIT
#include "stability_limit.h"

#include "../physical/spring_contact.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace ab::stability {

double oscillatorGrowth(Integrator integrator, double h, long long steps, double zeta)
{
    // omega0 = 1, so dt = h; the same step code as the spring floor, acting on both sides.
    physical::SpringFloor spring{physical::ContactLaw::LinearSpring, 1.0, 2.0 * zeta, 0.0, false};
    physical::PointState s{1.0, 0.0};
    double largest = 1.0;
    for (long long i = 0; i < steps; ++i) {
        s = physical::springStep(integrator, spring, s, h);
        const double amplitude = std::hypot(s.y, s.v);
        if (!std::isfinite(amplitude))
            return std::numeric_limits<double>::infinity();
        largest = std::max(largest, amplitude);
    }
    return largest;
}

StabilityLimit measureStabilityLimit(Integrator integrator, const GrowthCriterion& c)
{
    auto stable = [&](double h) { return oscillatorGrowth(integrator, h, c.steps, c.zeta) <= c.growth; };
    if (!stable(c.hMin))
        return {c.hMin, true, false};
    // Walk up by factors of 2 to the first unstable h, then bisect to 1e-7 relative.
    double lo = c.hMin;
    double hi = lo;
    while (stable(hi)) {
        lo = hi;
        if (hi >= c.hMax)
            return {c.hMax, false, true};
        hi = std::min(2.0 * hi, c.hMax);
    }
    while (hi - lo > 1e-7 * lo) {
        const double mid = 0.5 * (lo + hi);
        (stable(mid) ? lo : hi) = mid;
    }
    return {lo, false, false};
}

double theoreticalLimit(Integrator integrator)
{
    switch (integrator) {
    case Integrator::Euler:
        return 0.0;
    case Integrator::SymplecticEuler:
    case Integrator::Verlet:
        // Both have the one-step matrix of trace 2 - h^2 and determinant 1: eigenvalues on
        // the unit circle while |2 - h^2| <= 2, i.e. h <= 2.
        return 2.0;
    case Integrator::Rk4:
        // |R(i h)|^2 = 1 - h^6 / 72 + h^8 / 576 <= 1 while h^2 <= 8.
        return 2.0 * std::numbers::sqrt2;
    case Integrator::ImplicitEuler:    // |1 / (1 - i h)| = 1 / sqrt(1 + h^2) < 1
    case Integrator::ImplicitMidpoint: // |(1 + i h / 2) / (1 - i h / 2)| = 1
    case Integrator::Event:
        break;
    }
    return std::numeric_limits<double>::infinity();
}

double expectedMeasuredLimit(Integrator integrator, const GrowthCriterion& c)
{
    if (integrator == Integrator::Euler)
        return std::sqrt(std::pow(c.growth, 2.0 / static_cast<double>(c.steps)) - 1.0);
    return theoreticalLimit(integrator);
}

} // namespace ab::stability
