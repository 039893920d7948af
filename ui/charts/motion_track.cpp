// SPDX-License-Identifier: MIT
#include "motion_track.h"

#include "core/street/street_census.h"

#include <algorithm>
#include <stdexcept>

namespace ab::ui {

MotionTrack::MotionTrack(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 4)) {}

template <typename F> void MotionTrack::forEachColumn(F&& f)
{
    f(step_);
    f(t_);
    for (int a = 0; a < 3; ++a) {
        f(p_[a]);
        f(v_[a]);
        f(w_[a]);
        f(momentum_[a]);
    }
    f(kinetic_);
    f(translation_);
    f(rotation_);
    f(potential_);
    f(spring_);
    f(energy_);
    f(left_);
    f(moving_);
    f(impacts_);
    for (auto& column : feet_)
        f(column);
    for (auto& column : speeds_)
        f(column);
    f(onStreet_);
}

void MotionTrack::clear()
{
    stride_ = 1;
    goneStep_ = kNotGone;
    forEachColumn([](auto& column) { column.clear(); });
}

void MotionTrack::add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                      const ConservationSample& scene)
{
    add(step, t, p, v, Eigen::Vector3d::Zero(), scene);
}

void MotionTrack::add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                      const Eigen::Vector3d& w, const ConservationSample& scene)
{
    add(step, t, p, v, w, scene, StreetSample{});
}

void MotionTrack::add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                      const Eigen::Vector3d& w, const ConservationSample& scene, const StreetSample& street)
{
    if (!step_.empty() && step <= step_.back())
        throw std::logic_error("motion samples out of order");
    if (step % stride_ != 0)
        return;
    step_.push_back(step);
    t_.push_back(t);
    for (int a = 0; a < 3; ++a) {
        p_[a].push_back(p[a]);
        v_[a].push_back(v[a]);
        w_[a].push_back(w[a]);
        momentum_[a].push_back(scene.momentum[a]);
    }
    kinetic_.push_back(scene.energy.kinetic);
    translation_.push_back(scene.energy.translation());
    rotation_.push_back(scene.energy.rotation);
    potential_.push_back(scene.energy.potential);
    spring_.push_back(scene.energy.spring);
    energy_.push_back(scene.energy.total());
    left_.push_back(scene.energy.left);
    moving_.push_back(static_cast<double>(scene.moving));
    impacts_.push_back(scene.impacts);
    for (std::size_t k = 0; k < feet_.size(); ++k)
        feet_[k].push_back(street.pastFoot[k]);
    for (std::size_t k = 0; k < speeds_.size(); ++k)
        speeds_[k].push_back(street.speed[k]);
    onStreet_.push_back(street.onStreet);
    while (t_.size() > capacity_)
        thin();
}

void MotionTrack::truncateFrom(long long step)
{
    const auto kept = static_cast<std::size_t>(std::lower_bound(step_.begin(), step_.end(), step) - step_.begin());
    forEachColumn([kept](auto& column) { column.resize(kept); });
    if (goneStep_ >= step)
        goneStep_ = kNotGone; // the run goes on from before the ball left
}

void MotionTrack::markBallGone(long long step)
{
    goneStep_ = std::min(goneStep_, step);
}

std::size_t MotionTrack::ballSamples() const
{
    return static_cast<std::size_t>(std::lower_bound(step_.begin(), step_.end(), goneStep_) - step_.begin());
}

std::size_t MotionTrack::streetSamples() const
{
    std::size_t n = onStreet_.size();
    while (n > 0 && !(onStreet_[n - 1] > 0.0))
        --n;
    return n;
}

void addState(MotionTrack& track, long long step, const State& s, int ball, const ConservationSample& scene,
              const street::Layout* street, const StreetSample* measured)
{
    const Eigen::Index b = ball;
    if (!street) {
        track.add(step, s.t, s.p.col(b), s.v.col(b), s.spin(ball), scene);
        return;
    }
    if (street::hasLeft(*street, s.p(0, b)))
        track.markBallGone(step);
    track.add(step, s.t, s.p.col(b), s.v.col(b), s.spin(ball), scene, measured ? *measured : measureStreet(*street, s));
}

void MotionTrack::thin()
{
    stride_ *= 2;
    std::vector<char> keep(step_.size());
    for (std::size_t i = 0; i < step_.size(); ++i)
        keep[i] = step_[i] % stride_ == 0;
    forEachColumn([&](auto& column) {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < column.size(); ++i)
            if (keep[i])
                column[kept++] = column[i];
        column.resize(kept);
    });
}

std::vector<double> impactRate(const MotionTrack& track, double window)
{
    // rate_i = (N_i - N_j) / (t_i - t_j), N the impacts since the start and j the latest
    // sample at or before t_i - window (the first sample while the run is younger).
    const std::vector<double>& t = track.t();
    const std::vector<long long>& n = track.impacts();
    std::vector<double> rate(t.size(), 0.0);
    std::size_t from = 0;
    for (std::size_t i = 1; i < t.size(); ++i) {
        while (from + 1 < i && t[from + 1] <= t[i] - window)
            ++from;
        const double span = t[i] - t[from];
        rate[i] = span > 0.0 ? static_cast<double>(n[i] - n[from]) / span : 0.0;
    }
    if (rate.size() > 1)
        rate[0] = rate[1]; // no interval ends at the start: show the first one's rate
    return rate;
}

} // namespace ab::ui
