// SPDX-License-Identifier: MIT
// One ball's motion and the scene's energy, sample by sample, as the charts draw them.
// Memory stays bounded: past `capacity` samples every other sample is dropped and later
// steps are kept at twice the stride, so a long run is thinned evenly, never cut short.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <ostream>
#include <vector>

namespace ab::ui {

class MotionTrack {
public:
    explicit MotionTrack(std::size_t capacity = std::size_t(1) << 20);

    void clear();
    // Offers the sample of step `step` (0 for the start); kept when the step falls on the
    // current stride. Steps must come in increasing order.
    void add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v, double energy);

    // Drops every sample of step `step` and later (a run forked back to that step).
    void truncateFrom(long long step);

    std::size_t size() const { return t_.size(); }
    bool empty() const { return t_.empty(); }
    long long stride() const { return stride_; }
    std::size_t capacity() const { return capacity_; }

    const std::vector<long long>& steps() const { return step_; }
    const std::vector<double>& t() const { return t_; }
    const std::vector<double>& p(int axis) const { return p_[static_cast<std::size_t>(axis)]; }
    const std::vector<double>& v(int axis) const { return v_[static_cast<std::size_t>(axis)]; }
    const std::vector<double>& energy() const { return energy_; }

private:
    void thin();

    std::size_t capacity_;
    long long stride_ = 1;
    std::vector<long long> step_;
    std::vector<double> t_;
    std::array<std::vector<double>, 3> p_, v_;
    std::vector<double> energy_;
};

// The track as CSV, every kept sample at full precision: `t,ball,` then the position and
// velocity of the axes shown (`axes` 1: y alone; 3: x, y, z), then `energy_per_mass`.
// `ball` is the index the trajectory CSV uses (0 for the first ball).
void writeMotionCsv(std::ostream& out, const MotionTrack& track, int axes, int ball);

} // namespace ab::ui
