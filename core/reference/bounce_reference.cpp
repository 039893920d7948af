// SPDX-License-Identifier: MIT
#include "bounce_reference.h"

#include <algorithm>
#include <cmath>

namespace ab::reference {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double inf = std::numeric_limits<double>::infinity();

// Drag changes a flight launched at u by a fraction of about kappa u^2 / g (quadratic) or
// beta u / g (linear) of gravity's effect: below double precision the flight is drag-free.
bool dragNegligible(double g, Drag drag, double u)
{
    return drag.kappa * u * u <= eps * g && drag.beta * u <= eps * g;
}

} // namespace

BounceReference::BounceReference(double g, double k, double y0, double v0, double floor, Drag drag, double horizon)
    : g_(g), k_(k), floor_(floor)
{
    const bool dragFree = drag.beta == 0.0 && drag.kappa == 0.0;
    double t = 0.0;
    double y = y0, v = v0;
    for (;;) {
        flights_.push_back({t, VerticalFlight(g, drag, y, v)});
        const double land = flights_.back().flight.landing(floor);
        if (!std::isfinite(land))
            return; // flies off (g = 0): no more impacts, never rests
        // Speed at the impact: energy conservation without drag, the flight's own velocity with it.
        const double s = dragFree ? std::sqrt(v * v + 2.0 * g * (y - floor)) : -flights_.back().flight.velocity(land);
        t += land;
        const double u = k * s; // eq 2.3
        if (!(u > 0.0)) {
            tRest_ = t;
            tTail_ = t;
            return;
        }
        if (g > 0.0 && dragNegligible(g, drag, u)) {
            // Without drag each bounce lasts 2 u_n / g with u_n = u k^n: the launch times
            // T_n = t + (2u/g)(1 - k^n)/(1 - k) accumulate at T_inf = t + 2u / (g (1 - k)).
            tTail_ = t;
            uTail_ = u;
            tRest_ = k < 1.0 ? tailLaunch(inf) : inf;
            return;
        }
        if (t > horizon)
            return;
        y = floor;
        v = u;
    }
}

double BounceReference::tailLaunch(double n) const
{
    if (k_ == 1.0)
        return tTail_ + n * 2.0 * uTail_ / g_;
    const double kn = std::isfinite(n) ? std::pow(k_, n) : 0.0;
    return tTail_ + 2.0 * uTail_ / g_ * ((1.0 - kn) / (1.0 - k_));
}

// The bounce n of the tail with T_n <= t < T_(n+1): doubling, then bisection on n.
long long BounceReference::tailBounce(double t) const
{
    if (k_ == 1.0)
        return static_cast<long long>(std::floor((t - tTail_) * g_ / (2.0 * uTail_)));
    const long long h = hint_;
    if (tailLaunch(static_cast<double>(h)) <= t && t < tailLaunch(static_cast<double>(h + 1)))
        return h;
    if (tailLaunch(static_cast<double>(h + 1)) <= t && t < tailLaunch(static_cast<double>(h + 2)))
        return hint_ = h + 1;
    long long lo = 0, hi = 1;
    while (tailLaunch(static_cast<double>(hi)) <= t) {
        lo = hi;
        hi *= 2;
    }
    while (hi - lo > 1) {
        const long long mid = lo + (hi - lo) / 2;
        (tailLaunch(static_cast<double>(mid)) <= t ? lo : hi) = mid;
    }
    return hint_ = lo;
}

double BounceReference::height(double t) const
{
    if (t >= tRest_)
        return floor_;
    if (t >= tTail_) {
        const long long n = tailBounce(t);
        const double tau = t - tailLaunch(static_cast<double>(n));
        const double u = uTail_ * std::pow(k_, static_cast<double>(n));
        return floor_ + u * tau - 0.5 * g_ * tau * tau;
    }
    const auto it =
        std::upper_bound(flights_.begin(), flights_.end(), t, [](double x, const Flight& f) { return x < f.t0; });
    const Flight& f = *std::prev(it);
    return f.flight.height(t - f.t0);
}

double BounceReference::velocity(double t) const
{
    if (t >= tRest_)
        return 0.0;
    if (t >= tTail_) {
        const long long n = tailBounce(t);
        const double tau = t - tailLaunch(static_cast<double>(n));
        return uTail_ * std::pow(k_, static_cast<double>(n)) - g_ * tau;
    }
    const auto it =
        std::upper_bound(flights_.begin(), flights_.end(), t, [](double x, const Flight& f) { return x < f.t0; });
    const Flight& f = *std::prev(it);
    return f.flight.velocity(t - f.t0);
}

std::vector<double> BounceReference::impactTimes(double tEnd) const
{
    std::vector<double> times;
    for (std::size_t i = 1; i < flights_.size(); ++i)
        if (flights_[i].t0 <= tEnd)
            times.push_back(flights_[i].t0);
    if (std::isfinite(tTail_) && tTail_ <= tEnd && (times.empty() || times.back() != tTail_))
        times.push_back(tTail_);
    if (uTail_ > 0.0) {
        for (double n = 1.0;; n += 1.0) {
            const double tn = tailLaunch(n);
            if (tn > tEnd || tn >= tRest_ || tn - times.back() <= 8.0 * eps * tn)
                break;
            times.push_back(tn);
        }
    }
    return times;
}

double BounceReference::maxHeight() const
{
    return flights_.front().flight.apex();
}

WallAxisReference::WallAxisReference(double x0, double v0, double lo, double hi, double kLo, double kHi, double horizon)
{
    double t = 0.0, x = x0, v = v0;
    for (;;) {
        const bool up = v > 0.0;
        legs_.push_back({t, x, v, up});
        if (v == 0.0)
            return;
        // Free flight to the wall ahead, then v -> -k v there (eq 2.3).
        const double target = up ? hi : lo;
        t += (target - x) / v;
        if (t > horizon)
            return;
        x = target;
        v = -(up ? kHi : kLo) * v;
    }
}

const WallAxisReference::Leg& WallAxisReference::legAt(double t) const
{
    const auto it =
        std::upper_bound(legs_.begin(), legs_.end(), t, [](double x, const Leg& leg) { return x < leg.t0; });
    return it == legs_.begin() ? legs_.front() : *std::prev(it);
}

double WallAxisReference::position(double t) const
{
    const Leg& leg = legAt(t);
    return leg.x0 + leg.v * (t - leg.t0);
}

double WallAxisReference::velocity(double t) const
{
    return legAt(t).v;
}

std::vector<double> WallAxisReference::impactTimes(double tEnd, bool hiOnly, bool loOnly) const
{
    std::vector<double> times;
    for (std::size_t i = 1; i < legs_.size(); ++i) {
        const bool atHi = legs_[i - 1].endsAtHi;
        if (legs_[i].t0 <= tEnd && !(hiOnly && !atHi) && !(loOnly && atHi))
            times.push_back(legs_[i].t0);
    }
    return times;
}

} // namespace ab::reference
