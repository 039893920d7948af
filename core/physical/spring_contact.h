// SPDX-License-Identifier: MIT
// The floor as a spring: the contact model the report considered before it chose a
// coefficient of restitution (its section 1.2). Below the floor (y < 0) a spring and a
// dashpot push the ball back; above it the ball flies. The ODE is y'' = -g + F(y, v)/m,
// smooth inside and outside the contact, so every integrator applies and none needs
// impact events; a stiff spring makes it a stiff ODE.
//
// Design:
//  1. The ball's mass is 1 (the report never states one and all its balls are equal), so
//     stiffness and damping are per unit mass: k_s = omega0^2 for the linear spring.
//  2. Stiffness and damping come from the restitution e (the scene's k) and either a
//     contact duration t_c or a stiffness given directly (closed forms in the .cpp).
//  3. The integrators step (y, v) of one ball; the implicit ones solve their stage
//     equation exactly for the linear spring and by safeguarded Newton for Hertz.
//  4. A backstop under the spring: no solution of the ODE compresses the spring deeper
//     than maxCompression of the start's energy (with e <= 1 the energy never rises),
//     so a ball stepped below 1.5 times that depth is the integrator's failure, beyond
//     its stability limit. The simulation stops such a ball at the backstop (position
//     clamped, its velocity into the floor removed: energy only taken away) rather than
//     let it fall through the floor; the method's failure still shows, as the energy
//     it gained and the depth reached, which the health check reports with their figures.
//     The stability limits are measured on springStep itself, without a backstop.
#pragma once

#include "../simulation.h"

#include <memory>

namespace ab::physical {

// The `contact` parameter of bounce1d: 0 = impulse, 1 = linear spring-dashpot, 2 = Hertz.
enum class ContactLaw { Impulse = 0, LinearSpring = 1, Hertz = 2 };

// The floor's force law per unit mass, and gravity.
struct SpringFloor {
    ContactLaw law = ContactLaw::LinearSpring;
    // Linear: k_s = omega0^2 (1/time^2). Hertz: k_h in F/m = k_h d^(3/2) (1/(length^1/2 time^2)).
    double stiffness = 0.0;
    // Linear: c_s = 2 zeta omega0 (1/time). Hertz: c_h in F/m = -c_h d^(1/4) v (1/(length^1/4 time)).
    double damping = 0.0;
    double g = 0.0; // magnitude, down is -y
    // false: the spring acts on both sides of y = 0 (the plain oscillator y'' = -k_s y
    // on which stability limits are measured); linear law only.
    bool oneSided = true;

    bool inContact(double y) const { return !oneSided || y < 0.0; }
    // In contact, counting a ball on y = 0 that moves in.
    bool touching(double y, double v) const { return inContact(y) || (y == 0.0 && v < 0.0); }
    // y'' = restoring(y) - dampingRate(y, v) v: gravity and spring, and the dashpot, which
    // is linear in v for both laws. At y = 0 a ball moving in feels the dashpot (the linear
    // law's force jumps to -c_s v there), one moving out does not.
    double restoring(double y) const;
    double dampingRate(double y, double v) const;
    double acceleration(double y, double v) const { return restoring(y) - dampingRate(y, v) * v; }
    // Energy per unit mass stored at height y: gravity above y = 0 plus the spring.
    double potential(double y) const;
};

// Closed forms of the linear spring-dashpot (derivations in the .cpp).
double dampingRatioForRestitution(double e);
double restitutionForDampingRatio(double zeta);
SpringFloor linearFloorFromContactTime(double e, double contactTime, double g);
SpringFloor linearFloorFromStiffness(double e, double stiffness, double g);

// Hertz with damping c_h = alpha sqrt(k_h): its restitution depends on alpha only (not on
// the impact speed); alpha for a restitution is found numerically, with tau, the contact
// duration in the dimensionless time of the .cpp.
struct HertzDamping {
    double alpha = 0.0;
    double tau = 0.0;
};
HertzDamping hertzDampingForRestitution(double e);
SpringFloor hertzFloorFromContactTime(double e, double contactTime, double impactSpeed, double g);
SpringFloor hertzFloorFromStiffness(double e, double stiffness, double g);

// The backstop's depth in units of maxCompression of the start's energy (design note 4).
inline constexpr double kBackstopFactor = 1.5;

// Deepest compression a ball reaching the floor with energy `energy` per unit mass (above
// y = 0) can have, without damping: the allowance beyond which it has "fallen through".
double maxCompression(const SpringFloor& floor, double energy);
// The contact frequency that limits the step: omega0 for the linear spring; for Hertz the
// linearised frequency at the deepest compression, sqrt(3/2 k_h d^(1/2)).
double contactFrequency(const SpringFloor& floor, double energy);

// One ball's vertical position and velocity.
struct PointState {
    double y = 0.0;
    double v = 0.0;
};

// The integrators the spring contact takes: all but `event` (there are no impacts).
bool springIntegratorAvailable(Integrator integrator);
// One step of y'' = floor.acceleration(y, v), blind to where the force law switches
// (`--impacts step-end`); logic_error for `event`.
PointState springStep(Integrator integrator, const SpringFloor& floor, PointState s, double dt);
// The same with the contact's onset located (`--impacts located`): a step that would
// reach the floor in flight is split there, the flight part taken exactly (a parabola)
// and the rest with the integrator from y = 0. Without this a step lands at an arbitrary
// depth in the spring and the spring hands back energy the ball never had: at dt omega0
// of order 1, even for the implicit integrators.
PointState springStepLocated(Integrator integrator, const SpringFloor& floor, PointState s, double dt);
// Time until free flight from (y0 >= 0, v0) reaches y = 0 (infinite if never).
double timeToFloor(double y0, double v0, double g);

// The contact law of a bounce1d spec (params contact, contact_time, stiffness, k, g,
// h0, v0); the law is Impulse when contact is 0.
ContactLaw contactLawOf(const RunSpec& spec);
SpringFloor springFloorFor(const RunSpec& spec);
// Energy per unit mass of the spec's start above the floor (1/2 v0^2 + g h0).
double startEnergy(const RunSpec& spec);

// The bounce1d physical model with a spring floor; InputError for the event integrator.
std::unique_ptr<Simulation> makeSpringBounce1d(const RunSpec& spec, double dt);

} // namespace ab::physical
