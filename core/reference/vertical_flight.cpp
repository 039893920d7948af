// SPDX-License-Identifier: MIT
// Vertical flight, dv/dt = -g - beta v (linear drag) or dv/dt = -g - kappa |v| v
// (quadratic drag), dy/dt = v. Each solution below is the textbook one, derived in the
// comment beside it and written in a form that keeps its precision (no cancellation for
// short times, no overflow for long ones).
#include "vertical_flight.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ab::reference {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// ln(cosh x + w sinh x) for x >= 0, w >= 0. Short times: cosh x - 1 = 2 sinh^2(x/2), so
// the argument of log1p is small and exact; long times: e^x ((1 + w) + (1 - w) e^-2x) / 2.
double logCoshSinh(double x, double w)
{
    if (x <= 20.0) {
        const double s = std::sinh(0.5 * x);
        return std::log1p(2.0 * s * s + w * std::sinh(x));
    }
    return x + std::log(0.5 * (1.0 + w) + 0.5 * (1.0 - w) * std::exp(-2.0 * x));
}

// The x >= 0 with ln(cosh x + w sinh x) = L (L >= 0). With z = e^x the equation is
// (1 + w) z^2 - 2 e^L z + (1 - w) = 0, whose larger root is
// z = (e^L + sqrt(e^2L - 1 + w^2)) / (1 + w); z - 1 is formed without cancellation.
double solveLogCoshSinh(double L, double w)
{
    if (L <= 0.0)
        return 0.0;
    if (L > 300.0) // cosh x + w sinh x = e^x (1 + w) / 2 to double precision
        return L - std::log(0.5 * (1.0 + w));
    const double e2 = std::expm1(2.0 * L);
    const double s = std::sqrt(e2 + w * w);
    return std::log1p((std::expm1(L) + e2 / (w + s)) / (1.0 + w));
}

} // namespace

VerticalFlight::VerticalFlight(double g, Drag drag, double y0, double v0) : g_(g), drag_(drag), y0_(y0), v0_(v0)
{
    if (drag_.beta > 0.0)
        vt_ = g_ / drag_.beta;
    if (drag_.kappa > 0.0 && g_ > 0.0) {
        vt_ = std::sqrt(g_ / drag_.kappa);
        // Rising (v > 0): dv/dt = -g (1 + v^2/vt^2) gives v = vt tan(atan(v0/vt) - g t / vt),
        // which reaches 0 at t = (vt / g) atan(v0 / vt).
        if (v0_ > 0.0)
            tApex_ = vt_ / g_ * std::atan(v0_ / vt_);
    }
}

double VerticalFlight::fallFrom(double y, double v, double tau, bool wantHeight) const
{
    // Falling (v <= 0): dv/dt = -g (1 - v^2/vt^2). With w = -v0/vt and x = g t / vt,
    // v = -vt tanh(psi0 + x) for w < 1 (tanh psi0 = w) and -vt coth(psi0 + x) for w > 1
    // (coth psi0 = w); both are v = -vt (w + tanh x) / (1 + w tanh x). Integrating,
    // y = y0 - (vt^2 / g) ln(cosh(psi0 + x) / cosh psi0) = y0 - (vt^2/g) ln(cosh x + w sinh x)
    // (sinh in place of cosh for w > 1 gives the same expression).
    const double w = -v / vt_;
    const double x = g_ * tau / vt_;
    if (wantHeight)
        return y - vt_ * vt_ / g_ * logCoshSinh(x, w);
    const double th = std::tanh(x);
    return -vt_ * (w + th) / (1.0 + w * th);
}

double VerticalFlight::height(double tau) const
{
    if (drag_.beta > 0.0) {
        // dv/dt = -beta (v + vt): v + vt decays as e^(-beta t), so v = (v0 + vt) e^(-beta t) - vt
        // and y = y0 - vt t + (v0 + vt)(1 - e^(-beta t)) / beta.
        return y0_ - vt_ * tau - (v0_ + vt_) * std::expm1(-drag_.beta * tau) / drag_.beta;
    }
    if (drag_.kappa > 0.0) {
        if (g_ ==
            0.0) // dv/dt = -kappa |v| v: v = v0 / (1 + kappa |v0| t), y = y0 + sign(v0) ln(1 + kappa |v0| t) / kappa
            return y0_ + std::copysign(std::log1p(drag_.kappa * std::abs(v0_) * tau), v0_) / drag_.kappa;
        if (v0_ > 0.0 && tau <= tApex_) {
            // y - y0 = (vt^2/g) ln(cos(phi0 - x) / cos phi0) with tan phi0 = v0/vt, x = g t / vt;
            // cos(phi0 - x) / cos phi0 = cos x + (v0/vt) sin x = 1 - 2 sin^2(x/2) + (v0/vt) sin x.
            const double x = g_ * tau / vt_;
            const double s = std::sin(0.5 * x);
            return y0_ + vt_ * vt_ / g_ * std::log1p(-2.0 * s * s + v0_ / vt_ * std::sin(x));
        }
        if (v0_ > 0.0)
            return fallFrom(apex(), 0.0, tau - tApex_, true);
        return fallFrom(y0_, v0_, tau, true);
    }
    return y0_ + v0_ * tau - 0.5 * g_ * tau * tau;
}

double VerticalFlight::velocity(double tau) const
{
    if (drag_.beta > 0.0)
        return (v0_ + vt_) * std::exp(-drag_.beta * tau) - vt_;
    if (drag_.kappa > 0.0) {
        if (g_ == 0.0)
            return v0_ / (1.0 + drag_.kappa * std::abs(v0_) * tau);
        if (v0_ > 0.0 && tau <= tApex_) {
            // v = vt tan(phi0 - x) = (v0 - vt tan x) / (1 + (v0/vt) tan x)
            const double tx = std::tan(g_ * tau / vt_);
            return (v0_ - vt_ * tx) / (1.0 + v0_ / vt_ * tx);
        }
        if (v0_ > 0.0)
            return fallFrom(apex(), 0.0, tau - tApex_, false);
        return fallFrom(y0_, v0_, tau, false);
    }
    return v0_ - g_ * tau;
}

double VerticalFlight::apex() const
{
    if (v0_ <= 0.0)
        return y0_;
    if (drag_.beta > 0.0) // v = 0 at e^(-beta t) = vt / (v0 + vt)
        return g_ > 0.0 ? height(std::log1p(v0_ / vt_) / drag_.beta) : y0_ + v0_ / drag_.beta;
    if (g_ == 0.0)
        return inf;
    if (drag_.kappa > 0.0) // at x = atan(v0/vt): ln(cos x + (v0/vt) sin x) = ln(1 + v0^2/vt^2) / 2
        return y0_ + vt_ * vt_ / (2.0 * g_) * std::log1p(v0_ * v0_ / (vt_ * vt_));
    return y0_ + v0_ * v0_ / (2.0 * g_);
}

double VerticalFlight::landing(double floor) const
{
    const double drop = y0_ - floor;
    if (drag_.beta > 0.0) {
        if (g_ == 0.0) // y -> y0 + v0 / beta: y = y0 - (v0/beta) expm1(-beta t) reaches the floor at
            return v0_ < 0.0 && drop * drag_.beta < -v0_ ? -std::log1p(drop * drag_.beta / v0_) / drag_.beta : inf;
        // No closed form for the time (it needs Lambert's W): bisection on the closed-form
        // height, which decreases from the apex on.
        double lo = v0_ > 0.0 ? std::log1p(v0_ / vt_) / drag_.beta : 0.0;
        double hi = (drop + std::max(0.0, (v0_ + vt_) / drag_.beta)) / vt_ + lo + 1.0;
        while (height(hi) > floor)
            hi *= 2.0;
        for (int i = 0; i < 2100; ++i) {
            const double mid = lo + 0.5 * (hi - lo);
            if (mid <= lo || mid >= hi)
                break;
            (height(mid) > floor ? lo : hi) = mid;
        }
        return hi;
    }
    if (drag_.kappa > 0.0) {
        if (g_ == 0.0) // ln(1 + kappa |v0| t) = kappa drop
            return v0_ < 0.0 ? std::expm1(drag_.kappa * drop) / (drag_.kappa * -v0_) : inf;
        // Falling from the apex (or the start), ln(cosh x + w sinh x) = g drop / vt^2.
        const double start = v0_ > 0.0 ? apex() : y0_;
        const double w = v0_ > 0.0 ? 0.0 : -v0_ / vt_;
        const double x = solveLogCoshSinh(g_ * (start - floor) / (vt_ * vt_), w);
        return (v0_ > 0.0 ? tApex_ : 0.0) + x * vt_ / g_;
    }
    if (g_ == 0.0)
        return v0_ < 0.0 ? drop / -v0_ : inf;
    // y0 + v0 t - g t^2 / 2 = floor; the larger root, in the form without cancellation.
    const double root = std::sqrt(v0_ * v0_ + 2.0 * g_ * drop);
    if (v0_ > 0.0)
        return (v0_ + root) / g_;
    return root - v0_ > 0.0 ? 2.0 * drop / (root - v0_) : 0.0;
}

} // namespace ab::reference
