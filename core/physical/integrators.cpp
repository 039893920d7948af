// SPDX-License-Identifier: MIT
#include "integrators.h"

#include "rolling.h"

#include <stdexcept>

namespace ab::physical {

Kinematics advance(Integrator integrator, const World& w, int i, const Wall* support, const Kinematics& s, double h)
{
    // The rates depend on the velocity and spin only (gravity, drag, contact, friction),
    // never on the position: a = a(v, w), dw/dt = alpha(v, w).
    auto f = [&](const Eigen::Vector3d& v, const Eigen::Vector3d& om) { return rates(w, i, v, om, support); };
    switch (integrator) {
    case Integrator::Euler: { // explicit Euler (eq 2.12): both updates from the old state
        const Rates k = f(s.v, s.w);
        return {s.p + h * s.v, s.v + h * k.a, s.w + h * k.alpha};
    }
    case Integrator::SymplecticEuler: { // semi-implicit: the position moves with the new velocity
        const Rates k = f(s.v, s.w);
        const Eigen::Vector3d v = s.v + h * k.a;
        return {s.p + h * v, v, s.w + h * k.alpha};
    }
    case Integrator::Verlet: {
        // Velocity Verlet: p' = p + v h + a h^2 / 2, v' = v + (a + a') h / 2. The drag makes
        // a' depend on v', so a' is taken at the Euler-predicted v + a h (Heun), which keeps
        // second order; without drag a is constant and the step is exact.
        const Rates k0 = f(s.v, s.w);
        const Rates k1 = f(s.v + h * k0.a, s.w + h * k0.alpha);
        return {s.p + h * s.v + 0.5 * h * h * k0.a, s.v + 0.5 * h * (k0.a + k1.a),
                s.w + 0.5 * h * (k0.alpha + k1.alpha)};
    }
    case Integrator::Rk4: {
        // Classical fourth-order Runge-Kutta on (p, v, w) with dp/dt = v, dv/dt = a(v, w),
        // dw/dt = alpha(v, w).
        const Rates k1 = f(s.v, s.w);
        const Eigen::Vector3d v2 = s.v + 0.5 * h * k1.a, w2 = s.w + 0.5 * h * k1.alpha;
        const Rates k2 = f(v2, w2);
        const Eigen::Vector3d v3 = s.v + 0.5 * h * k2.a, w3 = s.w + 0.5 * h * k2.alpha;
        const Rates k3 = f(v3, w3);
        const Eigen::Vector3d v4 = s.v + h * k3.a, w4 = s.w + h * k3.alpha;
        const Rates k4 = f(v4, w4);
        return {s.p + h / 6.0 * (s.v + 2.0 * v2 + 2.0 * v3 + v4),
                s.v + h / 6.0 * (k1.a + 2.0 * k2.a + 2.0 * k3.a + k4.a),
                s.w + h / 6.0 * (k1.alpha + 2.0 * k2.alpha + 2.0 * k3.alpha + k4.alpha)};
    }
    case Integrator::Event:
    case Integrator::ImplicitEuler:
    case Integrator::ImplicitMidpoint:
        break;
    }
    throw std::logic_error("integrator without a step rule for flight");
}

double positionCurvature(Integrator integrator)
{
    switch (integrator) {
    case Integrator::Euler:
        return 0.0;
    case Integrator::SymplecticEuler:
        return 1.0;
    case Integrator::Verlet:
    case Integrator::Rk4:
        return 0.5;
    case Integrator::Event:
    case Integrator::ImplicitEuler:
    case Integrator::ImplicitMidpoint:
        break;
    }
    throw std::logic_error("integrator without a step rule for flight");
}

} // namespace ab::physical
