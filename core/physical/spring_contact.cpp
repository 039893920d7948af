// SPDX-License-Identifier: MIT
#include "spring_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>

namespace ab::physical {

using std::numbers::pi;

double SpringFloor::restoring(double y) const
{
    if (!inContact(y))
        return -g;
    if (law == ContactLaw::LinearSpring)
        return -g - stiffness * y; // m y'' = -m g - k_s y - c_s v
    const double d = -y;           // Hertz: F/m = k_h d^(3/2) - c_h d^(1/4) v, d = -y > 0
    return -g + stiffness * d * std::sqrt(d);
}

double SpringFloor::dampingRate(double y, double v) const
{
    if (!touching(y, v))
        return 0.0;
    if (law == ContactLaw::LinearSpring)
        return damping;
    return damping * std::sqrt(std::sqrt(std::max(-y, 0.0))); // Tsuji: c_h d^(1/4), so e does not depend on the speed
}

double SpringFloor::potential(double y) const
{
    if (!inContact(y))
        return g * y;
    if (law == ContactLaw::LinearSpring)
        return g * y + 0.5 * stiffness * y * y;
    const double d = -y; // integral of k_h d^(3/2) dd = 2/5 k_h d^(5/2)
    return g * y + 0.4 * stiffness * d * d * std::sqrt(d);
}

// Linear spring-dashpot, derived. In contact (gravity aside) y'' + 2 zeta omega0 y' +
// omega0^2 y = 0 with omega0 = sqrt(k_s), zeta = c_s / (2 omega0). Entering at y = 0 with
// speed u, y(t) = -(u / omega_d) exp(-zeta omega0 t) sin(omega_d t), omega_d = omega0
// sqrt(1 - zeta^2), so y is back at 0 after t_c = pi / omega_d with speed u exp(-zeta
// omega0 t_c). Hence e = exp(-zeta pi / sqrt(1 - zeta^2)); solving, ln e = -zeta pi /
// sqrt(1 - zeta^2) gives zeta = -ln e / sqrt(pi^2 + ln^2 e), and then sqrt(1 - zeta^2) =
// pi / sqrt(pi^2 + ln^2 e), so omega0 = omega_d / sqrt(1 - zeta^2) = sqrt(pi^2 + ln^2 e) / t_c.
// (The dashpot pulls slightly in the last part of the contact; that is the model whose
// restitution is exactly e. Gravity shifts the exit speed by O(g / (omega0 u)).)
double dampingRatioForRestitution(double e)
{
    if (e >= 1.0)
        return 0.0;
    if (e <= 0.0)
        return 1.0; // critical: the ball never leaves (the limit of the formula)
    const double l = std::log(e);
    return -l / std::sqrt(pi * pi + l * l);
}

double restitutionForDampingRatio(double zeta)
{
    if (zeta >= 1.0)
        return 0.0;
    return std::exp(-zeta * pi / std::sqrt(1.0 - zeta * zeta));
}

SpringFloor linearFloorFromStiffness(double e, double stiffness, double g)
{
    const double omega0 = std::sqrt(stiffness);
    return {ContactLaw::LinearSpring, stiffness, 2.0 * dampingRatioForRestitution(e) * omega0, g, true};
}

SpringFloor linearFloorFromContactTime(double e, double contactTime, double g)
{
    // omega0 = sqrt(pi^2 + ln^2 e) / t_c (above). For e = 0 the critically damped contact
    // never ends, and t_c is taken as the undamped half period: omega0 = pi / t_c.
    const double l = e > 0.0 ? std::log(e) : 0.0;
    const double omega0 = std::sqrt(pi * pi + l * l) / contactTime;
    return linearFloorFromStiffness(e, omega0 * omega0, g);
}

namespace {

// Hertz, made dimensionless. With d = L x, t = T s, d'' = -k_h d^(3/2) - c_h d^(1/4) d'
// becomes x'' = -x^(3/2) - alpha x^(1/4) x' when k_h L^(1/2) T^2 = 1 and alpha = c_h /
// sqrt(k_h); entering with speed u and choosing L / T = u makes x'(0) = 1, so the
// restitution depends on alpha alone (Tsuji et al. 1992) and the contact lasts tau T with
// T = k_h^(-2/5) u^(-1/5). Integrated here with RK4 (step 1e-3, restitution to ~1e-5).
struct HertzBounce {
    double restitution;
    double tau; // infinite when the ball is captured
};

HertzBounce dimensionlessHertzBounce(double alpha)
{
    auto acc = [alpha](double x, double v) {
        return x > 0.0 ? -x * std::sqrt(x) - alpha * std::sqrt(std::sqrt(x)) * v : 0.0;
    };
    const double h = 1e-3;
    double x = 0.0, v = 1.0, s = 0.0;
    while (s < 200.0) { // tau is 3.2 at e = 1 and 12 at e = 0.002; beyond 200 counts as captured
        const double k1x = v, k1v = acc(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
        const double xn = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        const double vn = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if (xn <= 0.0) {
            const double f = x / (x - xn); // linear interpolation to the exit
            return {-(v + f * (vn - v)), s + f * h};
        }
        if (v < 0.0 && vn >= 0.0)
            break; // turned back inside the spring: captured
        x = xn;
        v = vn;
        s += h;
    }
    return {0.0, std::numeric_limits<double>::infinity()};
}

} // namespace

HertzDamping hertzDampingForRestitution(double e)
{
    static std::mutex mutex;
    static std::map<double, HertzDamping> cache;
    const std::lock_guard lock(mutex);
    if (const auto it = cache.find(e); it != cache.end())
        return it->second;
    // e(alpha) falls from 1 at alpha = 0 to 0 at alpha ~ 2.02 (capture): bisect.
    double lo = 0.0, hi = 4.0;
    while (hi - lo > 1e-10) {
        const double mid = 0.5 * (lo + hi);
        (dimensionlessHertzBounce(mid).restitution > e ? lo : hi) = mid;
    }
    HertzDamping d{e >= 1.0 ? 0.0 : hi, 0.0};
    const HertzBounce b = dimensionlessHertzBounce(d.alpha);
    // e = 0: the contact never ends; t_c is then the undamped contact duration.
    d.tau = std::isfinite(b.tau) ? b.tau : dimensionlessHertzBounce(0.0).tau;
    cache.emplace(e, d);
    return d;
}

SpringFloor hertzFloorFromStiffness(double e, double stiffness, double g)
{
    const HertzDamping d = hertzDampingForRestitution(e);
    return {ContactLaw::Hertz, stiffness, d.alpha * std::sqrt(stiffness), g, true};
}

SpringFloor hertzFloorFromContactTime(double e, double contactTime, double impactSpeed, double g)
{
    // t_c = tau T = tau k_h^(-2/5) u^(-1/5)  =>  k_h = (tau / t_c)^(5/2) u^(-1/2).
    const double tau = hertzDampingForRestitution(e).tau;
    const double stiffness = std::pow(tau / contactTime, 2.5) / std::sqrt(impactSpeed);
    return hertzFloorFromStiffness(e, stiffness, g);
}

double maxCompression(const SpringFloor& floor, double energy)
{
    energy = std::max(energy, 0.0);
    if (floor.law == ContactLaw::LinearSpring) // 1/2 k_s d^2 - g d = E
        return (floor.g + std::sqrt(floor.g * floor.g + 2.0 * floor.stiffness * energy)) / floor.stiffness;
    // 2/5 k_h d^(5/2) - g d = E: convex in d and negative at 0, so bisect on a bracket.
    auto excess = [&](double d) { return 0.4 * floor.stiffness * d * d * std::sqrt(d) - floor.g * d - energy; };
    double hi =
        std::max(std::pow(2.5 * energy / floor.stiffness, 0.4), std::pow(2.5 * floor.g / floor.stiffness, 2.0 / 3.0));
    if (!(hi > 0.0))
        return 0.0;
    while (excess(hi) < 0.0)
        hi *= 2.0;
    double lo = 0.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (excess(mid) < 0.0 ? lo : hi) = mid;
    }
    return hi;
}

double contactFrequency(const SpringFloor& floor, double energy)
{
    if (floor.law == ContactLaw::LinearSpring)
        return std::sqrt(floor.stiffness);
    // d/dd of k_h d^(3/2) is 3/2 k_h d^(1/2): the local omega^2, largest at the deepest point
    // (at least the resting compression, where k_h d^(3/2) = g).
    const double d = std::max(maxCompression(floor, energy), std::pow(floor.g / floor.stiffness, 2.0 / 3.0));
    return std::sqrt(1.5 * floor.stiffness * std::sqrt(d));
}

namespace {

// Implicit stage of the theta-method: implicit Euler is theta = 1, implicit midpoint 1/2.
// The stage (Y, V) = (y0 + theta dy, v0 + theta dv) with dy = dt V and dv = dt a(Y, V);
// with h = theta dt, Y = y0 + h V leaves one equation in the stage velocity:
//   R(V) = V - v0 - h a(y0 + h V, V) = 0.
// (Solving for V rather than Y keeps tiny steps exact: Y - y0 would lose h^2 g to round-off.)
double solveStage(const SpringFloor& f, double y0, double v0, double h)
{
    // Free flight (a = -g): V = v0 - h g.
    const double vFree = v0 - h * f.g;
    if (!f.inContact(y0 + h * vFree))
        return vFree;
    if (f.law == ContactLaw::LinearSpring) {
        // The 2x2 linear system Y = y0 + h V, V = v0 + h (-g - k Y - c V), reduced:
        // V (1 + h c + h^2 k) = v0 - h g - h k y0.
        const double v = (v0 - h * f.g - h * f.stiffness * y0) / (1.0 + h * f.damping + h * h * f.stiffness);
        // A one-sided spring whose solution lands above the floor has no root in contact
        // either (the dashpot force jumps at y = 0): the stage ends on the floor, Y = 0.
        return f.inContact(y0 + h * v) ? v : -y0 / h;
    }
    // Hertz: the contact is V < vEdge = -y0 / h; R is continuous, R(vEdge) = vEdge - vFree
    // > 0 and R -> -inf as V -> -inf. Bracket, then Newton safeguarded by bisection (R
    // need not be monotone).
    auto residual = [&](double v, double& slope) {
        const double d = std::max(-(y0 + h * v), 0.0);
        const double d4 = std::sqrt(std::sqrt(d));
        // a_y = -(3/2) k d^(1/2) + (1/4) c d^(-3/4) v and a_v = -c d^(1/4), at (Y, V);
        // dR/dV = 1 - h^2 a_y - h a_v.
        const double ay = -1.5 * f.stiffness * std::sqrt(d) + 0.25 * f.damping * v / (d4 * d4 * d4);
        const double av = -f.damping * d4;
        slope = 1.0 - h * h * ay - h * av;
        return v - v0 - h * f.acceleration(y0 + h * v, v);
    };
    double slope = 0.0;
    double hi = -y0 / h;
    double lo = vFree;
    for (double span = std::max({std::abs(vFree), std::abs(hi), 1e-300}); residual(lo, slope) >= 0.0; span *= 2.0)
        lo = vFree - span;
    double v = lo;
    for (int i = 0; i < 200; ++i) {
        const double r = residual(v, slope);
        (r < 0.0 ? lo : hi) = v;
        double next = v - r / slope;
        if (!(next > lo && next < hi) || !std::isfinite(next))
            next = 0.5 * (lo + hi);
        const double scale = std::max({std::abs(v), std::abs(v0), h * f.g});
        if (std::abs(next - v) <= 1e-15 * scale || hi - lo <= 1e-15 * scale)
            return next;
        v = next;
    }
    return v;
}

PointState thetaStep(const SpringFloor& f, PointState s, double dt, double theta)
{
    const double v = solveStage(f, s.y, s.v, theta * dt);
    // y1 = y0 + dt V; v1 = v0 + dt a(Y, V) = v0 + (V - v0) / theta.
    return {s.y + dt * v, s.v + (v - s.v) / theta};
}

PointState rk4Step(const SpringFloor& f, PointState s, double dt)
{
    const double k1y = s.v, k1v = f.acceleration(s.y, s.v);
    const double k2y = s.v + 0.5 * dt * k1v, k2v = f.acceleration(s.y + 0.5 * dt * k1y, k2y);
    const double k3y = s.v + 0.5 * dt * k2v, k3v = f.acceleration(s.y + 0.5 * dt * k2y, k3y);
    const double k4y = s.v + dt * k3v, k4v = f.acceleration(s.y + dt * k3y, k4y);
    return {s.y + dt / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y), s.v + dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v)};
}

} // namespace

bool springIntegratorAvailable(Integrator integrator)
{
    return integrator != Integrator::Event;
}

PointState springStep(Integrator integrator, const SpringFloor& f, PointState s, double dt)
{
    switch (integrator) {
    case Integrator::Euler: // both from the start of the step
        return {s.y + dt * s.v, s.v + dt * f.acceleration(s.y, s.v)};
    case Integrator::SymplecticEuler: { // velocity first, the position moves with the new one
        const double v = s.v + dt * f.acceleration(s.y, s.v);
        return {s.y + dt * v, v};
    }
    case Integrator::Verlet: { // kick, drift, kick
        const double vHalf = s.v + 0.5 * dt * f.acceleration(s.y, s.v);
        const double y = s.y + dt * vHalf;
        // The last kick takes the dashpot at the new velocity, v1 = vHalf + dt/2 (r(y1) -
        // b(y1) v1), solved for v1: this keeps second order with a velocity-dependent
        // force (the half-step velocity would make it first order). Undamped, it is the
        // textbook velocity Verlet.
        return {y, (vHalf + 0.5 * dt * f.restoring(y)) / (1.0 + 0.5 * dt * f.dampingRate(y, vHalf))};
    }
    case Integrator::Rk4:
        return rk4Step(f, s, dt);
    case Integrator::ImplicitEuler:
        return thetaStep(f, s, dt, 1.0);
    case Integrator::ImplicitMidpoint:
        return thetaStep(f, s, dt, 0.5);
    case Integrator::Event:
        break;
    }
    throw std::logic_error("the spring contact has no event integrator");
}

double timeToFloor(double y0, double v0, double g)
{
    // y0 + v0 t - g t^2 / 2 = 0: the root at or after t = 0 on the way down; each branch
    // is written without cancellation.
    const double disc = std::sqrt(v0 * v0 + 2.0 * g * y0);
    if (v0 < 0.0)
        return 2.0 * y0 / (disc - v0);
    if (g > 0.0)
        return (v0 + disc) / g;
    return y0 == 0.0 && v0 == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

namespace {

PointState exactFlight(PointState s, double t, double g)
{
    return {s.y + s.v * t - 0.5 * g * t * t, s.v - g * t};
}

// A step of `dt` from inside the spring (or from y = 0 on the way in). When it would end
// above the floor, the exit is located: the fraction f of the step at which the
// integrator's own step reaches y = 0 (regula falsi, Illinois variant), approached from
// inside so that the step's last force is still the contact's; `left` gets the time after
// the exit.
PointState contactSegment(Integrator integrator, const SpringFloor& f, PointState s, double dt, double& left)
{
    left = 0.0;
    const PointState end = springStep(integrator, f, s, dt);
    if (f.touching(end.y, end.v) || !std::isfinite(end.y) || !std::isfinite(end.v))
        return end;
    double lo = 0.0, yLo = s.y;   // inside: yLo <= 0
    double hi = 1.0, yHi = end.y; // outside: yHi >= 0
    PointState inside = s;
    const double tolerance = 1e-14 * (std::abs(s.y) + dt * std::abs(s.v));
    for (int i = 0; i < 100 && hi - lo > 1e-15 && (lo == 0.0 || -inside.y > tolerance); ++i) {
        double frac = yHi > yLo ? (lo * yHi - hi * yLo) / (yHi - yLo) : 0.5 * (lo + hi);
        if (!(frac > lo && frac < hi)) // an end on y = 0 itself (the way in): bisect
            frac = 0.5 * (lo + hi);
        const PointState at = springStep(integrator, f, s, frac * dt);
        if (f.touching(at.y, at.v)) {
            lo = frac, yLo = at.y, inside = at;
            yHi *= 0.5; // Illinois: keep the stale end from stalling the bracket
        } else {
            hi = frac, yHi = at.y;
            yLo *= 0.5;
        }
    }
    left = (1.0 - lo) * dt;
    return {0.0, inside.v}; // on the floor, leaving it
}

} // namespace

PointState springStepLocated(Integrator integrator, const SpringFloor& f, PointState s, double dt)
{
    if (!f.oneSided || (!f.touching(s.y, s.v) && !f.inContact(s.y + dt * s.v - 0.5 * f.g * dt * dt)))
        return springStep(integrator, f, s, dt); // flight all step: the integrator's own
    double left = dt;
    // A step holds at most a few switches; the cap keeps a chattering ball from looping.
    for (int segment = 0; segment < 16 && left > 0.0; ++segment) {
        if (!f.touching(s.y, s.v)) {
            const double tau = timeToFloor(s.y, s.v, f.g);
            if (tau >= left) // after an exit, flight to the end of the step
                return exactFlight(s, left, f.g);
            s = {0.0, s.v - f.g * tau}; // exactly on the floor, on the way in
            left -= tau;
        }
        double after = 0.0;
        s = contactSegment(integrator, f, s, left, after);
        left = after;
    }
    return s;
}

ContactLaw contactLawOf(const RunSpec& spec)
{
    return static_cast<ContactLaw>(spec.params.integer("contact"));
}

double startEnergy(const RunSpec& spec)
{
    const double v0 = spec.params.real("v0");
    return 0.5 * v0 * v0 + spec.params.real("g") * spec.params.real("h0");
}

SpringFloor springFloorFor(const RunSpec& spec)
{
    const ParamValues& p = spec.params;
    const double e = p.real("k");
    const double g = p.real("g");
    const double stiffness = p.real("stiffness");
    if (contactLawOf(spec) == ContactLaw::LinearSpring)
        return stiffness > 0.0 ? linearFloorFromStiffness(e, stiffness, g)
                               : linearFloorFromContactTime(e, p.real("contact_time"), g);
    if (stiffness > 0.0)
        return hertzFloorFromStiffness(e, stiffness, g);
    // Hertz's contact time depends on the impact speed: that of the first impact, at
    // least g t_c (a slower ball rests on the spring more than it bounces off it).
    const double tc = p.real("contact_time");
    double speed = std::max(std::sqrt(2.0 * startEnergy(spec)), g * tc);
    if (speed <= 0.0)
        speed = 1.0; // the ball never reaches the floor: any stiffness would do
    return hertzFloorFromContactTime(e, tc, speed, g);
}

namespace {

class SpringBounce1d final : public Simulation {
public:
    SpringBounce1d(const RunSpec& spec, double dt, const SpringFloor& floor) : Simulation(spec, dt), floor_(floor)
    {
        // The backstop (design note 4 in the header): 1.5 times the deepest compression
        // the start's energy per unit mass, 1/2 v^2 + potential(y), allows.
        const State s = start();
        const double e0 = 0.5 * s.v(1, 0) * s.v(1, 0) + floor_.potential(s.p(1, 0));
        backstop_ = kBackstopFactor * maxCompression(floor_, e0);
    }

    State initialState() const override
    {
        State s;
        s.resize(1);
        s.p(1, 0) = spec_.params.real("h0");
        s.v(1, 0) = spec_.params.real("v0");
        return s;
    }

    void step(State& s, State& next) override
    {
        next = s;
        next.t = s.t + dt_;
        const PointState before{s.p(1, 0), s.v(1, 0)};
        PointState after = spec_.impacts == ImpactMode::Located
                               ? springStepLocated(spec_.integrator, floor_, before, dt_)
                               : springStep(spec_.integrator, floor_, before, dt_);
        if (backstop_ > 0.0 && after.y < -backstop_) {
            after.y = -backstop_;             // stopped at the backstop: no further into the floor
            after.v = std::max(after.v, 0.0); // its speed into the floor taken away (energy only removed)
        }
        if (!floor_.inContact(s.p(1, 0)) && floor_.inContact(after.y))
            ++next.count; // a new contact with the floor
        next.p(1, 0) = after.y;
        next.v(1, 0) = after.v;
    }

private:
    SpringFloor floor_;
    double backstop_ = 0.0; // depth below y = 0 (length)
};

} // namespace

std::unique_ptr<Simulation> makeSpringBounce1d(const RunSpec& spec, double dt)
{
    if (!springIntegratorAvailable(spec.integrator))
        throw InputError("--integrator " + std::string(integratorKey(spec.integrator)) +
                         ": the spring contact has no impacts to find; choose euler, symplectic-euler, verlet, rk4, "
                         "implicit-euler or implicit-midpoint");
    const SpringFloor floor = springFloorFor(spec);
    if (!std::isfinite(floor.stiffness) || !std::isfinite(floor.damping))
        throw InputError("contact_time: " + formatNumber(spec.params.real("contact_time")) +
                         " gives a spring too stiff to represent; choose a longer contact or set stiffness");
    return std::make_unique<SpringBounce1d>(spec, dt, floor);
}

} // namespace ab::physical
