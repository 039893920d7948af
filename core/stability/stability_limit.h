// SPDX-License-Identifier: MIT
// Stability limits of the integrators in h = dt omega0, measured on the undamped
// oscillator y'' = -omega0^2 y (the spring floor without gravity or damping, acting on
// both sides) by bisection on a growth criterion, beside the textbook values.
#pragma once

#include "../scene.h"

namespace ab::stability {

// "Unstable" means: over `steps` steps from (y, v) = (1, 0) the amplitude
// sqrt(y^2 + (v / omega0)^2) exceeds `growth` times its start.
struct GrowthCriterion {
    long long steps = 1000;
    double growth = 10.0;
    double hMin = 1e-4; // the search range of h
    double hMax = 1e4;
    double zeta = 0.0; // damping ratio of the oscillator (0: undamped, the textbook case)
};

// The largest amplitude ratio over the run at h = dt omega0 (infinite once non-finite),
// on y'' = -omega0^2 y - 2 zeta omega0 y'.
double oscillatorGrowth(Integrator integrator, double h, long long steps, double zeta = 0.0);

struct StabilityLimit {
    double h = 0.0;                  // largest stable h found (hMin when unstable already there)
    bool unstableEverywhere = false; // unstable at hMin already
    bool stableEverywhere = false;   // stable up to hMax: no limit in range
};
StabilityLimit measureStabilityLimit(Integrator integrator, const GrowthCriterion& criterion = {});

// Textbook limits of h on the undamped oscillator (an eigenvalue i omega0 of the test
// equation): explicit Euler 0 (|1 + i h| > 1 for every h), symplectic Euler and velocity
// Verlet 2, RK4 2 sqrt(2), the implicit ones none (infinite).
double theoreticalLimit(Integrator integrator);
// What `criterion` should measure for a method of that theory: the textbook limit, except
// explicit Euler, whose amplitude grows as (1 + h^2)^(n/2) and so crosses `growth` within
// `steps` steps only above h = sqrt(growth^(2/steps) - 1), a limit that goes to 0 as the
// run gets longer.
double expectedMeasuredLimit(Integrator integrator, const GrowthCriterion& criterion);

} // namespace ab::stability
