// SPDX-License-Identifier: MIT
#include "integrators.h"

#include <stdexcept>

namespace ab::physical {

Kinematics advance(Integrator integrator, const World& w, int i, const Wall* support, const Kinematics& s, double h)
{
    // The acceleration depends on the velocity only (gravity, drag, contact), never on
    // the position: a = a(v).
    auto a = [&](const Eigen::Vector3d& v) { return acceleration(w, i, v, support); };
    switch (integrator) {
    case Integrator::Euler: // explicit Euler (eq 2.12): both updates from the old state
        return {s.p + h * s.v, s.v + h * a(s.v)};
    case Integrator::SymplecticEuler: { // semi-implicit: the position moves with the new velocity
        const Eigen::Vector3d v = s.v + h * a(s.v);
        return {s.p + h * v, v};
    }
    case Integrator::Verlet: {
        // Velocity Verlet: p' = p + v h + a h^2 / 2, v' = v + (a + a') h / 2. The drag makes
        // a' depend on v', so a' is taken at the Euler-predicted v + a h (Heun), which keeps
        // second order; without drag a is constant and the step is exact.
        const Eigen::Vector3d a0 = a(s.v);
        return {s.p + h * s.v + 0.5 * h * h * a0, s.v + 0.5 * h * (a0 + a(s.v + h * a0))};
    }
    case Integrator::Rk4: {
        // Classical fourth-order Runge-Kutta on (p, v) with dp/dt = v, dv/dt = a(v).
        const Eigen::Vector3d k1v = a(s.v);
        const Eigen::Vector3d v2 = s.v + 0.5 * h * k1v;
        const Eigen::Vector3d k2v = a(v2);
        const Eigen::Vector3d v3 = s.v + 0.5 * h * k2v;
        const Eigen::Vector3d k3v = a(v3);
        const Eigen::Vector3d v4 = s.v + h * k3v;
        const Eigen::Vector3d k4v = a(v4);
        return {s.p + h / 6.0 * (s.v + 2.0 * v2 + 2.0 * v3 + v4), s.v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v)};
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
