// SPDX-License-Identifier: MIT
#include "ball_orientation.h"

#include <cmath>

namespace ab::ui {

// Equation O1. A ball's orientation is the unit quaternion q that carries a direction
// fixed in the ball (body frame) to the world: x_world = q x_body q*. A ball turning at
// angular velocity w (world frame) for a time dt turns by the angle |w| dt about the axis
// w/|w|, the rotation whose quaternion is
//     r = (cos(|w| dt / 2), sin(|w| dt / 2) w/|w|) = exp(1/2 w dt),
// and, the rotation being about a world axis, it acts after q: q' = r (x) q. That is the
// solution of dq/dt = 1/2 (0, w) (x) q over dt while w stays constant, so O1 is exact then
// (any number of steps turn the ball by |w| t about w/|w|). Over a step in which w changes
// (a bounce, friction), w is taken as the mean of its values at the step's two ends: the
// trapezoidal rule, second order in dt, for a turn that is drawn and never fed back. The
// product is renormalised, so rounding over millions of steps never scales the pattern.
Eigen::Quaterniond turnedBy(const Eigen::Quaterniond& q, const Eigen::Vector3d& wMean, double dt)
{
    const Eigen::Vector3d half = 0.5 * dt * wMean; // the rotation vector's half, |half| = angle / 2
    const double h = half.norm();
    // sin(h) / h, by its series near 0 (1 - h^2/6 + h^4/120; the next term, h^6/5040, is
    // below rounding for h < 1e-3), so a ball at rest or nearly so stays exact.
    const double sinc = h < 1e-3 ? 1.0 - h * h / 6.0 + h * h * h * h / 120.0 : std::sin(h) / h;
    const Eigen::Quaterniond r(std::cos(h), sinc * half.x(), sinc * half.y(), sinc * half.z());
    return (r * q).normalized();
}

void BallOrientations::clear()
{
    q_.clear();
    w_.resize(3, 0);
    t_ = 0.0;
}

void BallOrientations::follow(const State& s)
{
    if (!s.spins()) {
        clear();
        return;
    }
    if (q_.size() != static_cast<std::size_t>(s.size())) {
        q_.assign(static_cast<std::size_t>(s.size()), Eigen::Quaterniond::Identity());
    } else {
        const double dt = s.t - t_;
        for (int i = 0; i < s.size(); ++i) {
            const Eigen::Vector3d wMean = 0.5 * (w_.col(i) + s.w.col(i));
            q_[static_cast<std::size_t>(i)] = turnedBy(q_[static_cast<std::size_t>(i)], wMean, dt);
        }
    }
    w_ = s.w;
    t_ = s.t;
}

void BallOrientations::restart(double t, const std::vector<float>& q, const std::vector<float>& w)
{
    const std::size_t n = q.size() / kOrientationFloats;
    if (n == 0 || w.size() != 3 * n) {
        clear();
        return;
    }
    q_.resize(n);
    w_.resize(3, static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const float* f = &q[kOrientationFloats * i];
        q_[i] = Eigen::Quaterniond(f[3], f[0], f[1], f[2]).normalized();
        for (int a = 0; a < 3; ++a)
            w_(a, static_cast<Eigen::Index>(i)) = w[3 * i + static_cast<std::size_t>(a)];
    }
    t_ = t;
}

namespace {

void putFloats(const Eigen::Quaterniond& q, float* out)
{
    out[0] = static_cast<float>(q.x());
    out[1] = static_cast<float>(q.y());
    out[2] = static_cast<float>(q.z());
    out[3] = static_cast<float>(q.w());
}

} // namespace

std::vector<float> BallOrientations::floats() const
{
    std::vector<float> out(kOrientationFloats * q_.size());
    for (std::size_t i = 0; i < q_.size(); ++i)
        putFloats(q_[i], &out[kOrientationFloats * i]);
    return out;
}

std::vector<float> BallOrientations::floatsAt(const State& s) const
{
    if (!s.spins())
        return {};
    const auto n = static_cast<std::size_t>(s.size());
    std::vector<float> out(kOrientationFloats * n);
    const bool same = q_.size() == n;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<Eigen::Index>(i);
        const Eigen::Quaterniond q =
            same ? turnedBy(q_[i], 0.5 * (w_.col(c) + s.w.col(c)), s.t - t_) : Eigen::Quaterniond::Identity();
        putFloats(q, &out[kOrientationFloats * i]);
    }
    return out;
}

} // namespace ab::ui
