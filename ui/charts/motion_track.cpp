// SPDX-License-Identifier: MIT
#include "motion_track.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace ab::ui {

MotionTrack::MotionTrack(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 4)) {}

void MotionTrack::clear()
{
    stride_ = 1;
    step_.clear();
    t_.clear();
    for (int a = 0; a < 3; ++a) {
        p_[a].clear();
        v_[a].clear();
    }
    energy_.clear();
}

void MotionTrack::add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v, double energy)
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
    }
    energy_.push_back(energy);
    while (t_.size() > capacity_)
        thin();
}

void MotionTrack::truncateFrom(long long step)
{
    const auto kept = static_cast<std::size_t>(std::lower_bound(step_.begin(), step_.end(), step) - step_.begin());
    step_.resize(kept);
    t_.resize(kept);
    for (int a = 0; a < 3; ++a) {
        p_[a].resize(kept);
        v_[a].resize(kept);
    }
    energy_.resize(kept);
}

void MotionTrack::thin()
{
    stride_ *= 2;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < step_.size(); ++i) {
        if (step_[i] % stride_ != 0)
            continue;
        step_[kept] = step_[i];
        t_[kept] = t_[i];
        for (int a = 0; a < 3; ++a) {
            p_[a][kept] = p_[a][i];
            v_[a][kept] = v_[a][i];
        }
        energy_[kept] = energy_[i];
        ++kept;
    }
    step_.resize(kept);
    t_.resize(kept);
    for (int a = 0; a < 3; ++a) {
        p_[a].resize(kept);
        v_[a].resize(kept);
    }
    energy_.resize(kept);
}

void writeMotionCsv(std::ostream& out, const MotionTrack& track, int axes, int ball)
{
    static const char* names[3] = {"x", "y", "z"};
    const std::vector<int> shown = axes == 1 ? std::vector<int>{1} : std::vector<int>{0, 1, 2};
    out << "t,ball";
    for (int a : shown)
        out << "," << names[a];
    for (int a : shown)
        out << ",v" << names[a];
    out << ",energy_per_mass\n";
    char number[32];
    auto put = [&](double x) {
        std::snprintf(number, sizeof number, "%.17g", x);
        out << "," << number;
    };
    for (std::size_t i = 0; i < track.size(); ++i) {
        std::snprintf(number, sizeof number, "%.17g", track.t()[i]);
        out << number << "," << ball;
        for (int a : shown)
            put(track.p(a)[i]);
        for (int a : shown)
            put(track.v(a)[i]);
        put(track.energy()[i]);
        out << "\n";
    }
}

} // namespace ab::ui
