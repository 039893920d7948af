// SPDX-License-Identifier: MIT
// One ball's motion and what the whole scene conserves (energy in parts, momentum, moving
// balls, impacts: core/diagnostics/conservation.h), sample by sample, as the charts draw them.
// Memory stays bounded: past `capacity` samples every other sample is dropped and later
// steps are kept at twice the stride, so a long run is thinned evenly, never cut short.
#pragma once

#include "street_sample.h"

#include "core/diagnostics/conservation.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace ab::ui {

class MotionTrack {
public:
    explicit MotionTrack(std::size_t capacity = std::size_t(1) << 20);

    void clear();
    // Offers the sample of step `step` (0 for the start); kept when the step falls on the
    // current stride. Steps must come in increasing order.
    void add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
             const ConservationSample& scene);
    // The same, with the ball's angular velocity `w` (a ball that turns).
    void add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& w,
             const ConservationSample& scene);
    // The same, with what the street's charts draw (stage 5).
    void add(long long step, double t, const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& w,
             const ConservationSample& scene, const StreetSample& street);

    // Drops every sample of step `step` and later (a run forked back to that step).
    void truncateFrom(long long step);
    // The ball has left the run (the street's open foot) by step `step`, which comes next or
    // came before: its own lines end there. The first call counts.
    void markBallGone(long long step);
    // The samples before the ball left, all of them while it has not: its position,
    // velocity and spin are drawn from these; the scene's columns from all.
    std::size_t ballSamples() const;
    // The samples up to the last with a ball on the street: the speeds are drawn from these
    // (the street's; 0 elsewhere, where no sample has one).
    std::size_t streetSamples() const;

    std::size_t size() const { return t_.size(); }
    bool empty() const { return t_.empty(); }
    long long stride() const { return stride_; }
    std::size_t capacity() const { return capacity_; }

    const std::vector<long long>& steps() const { return step_; }
    const std::vector<double>& t() const { return t_; }
    const std::vector<double>& p(int axis) const { return p_[static_cast<std::size_t>(axis)]; }
    const std::vector<double>& v(int axis) const { return v_[static_cast<std::size_t>(axis)]; }
    const std::vector<double>& w(int axis) const { return w_[static_cast<std::size_t>(axis)]; }
    // Of all balls: kinetic (translation and rotation), potential, spring and total
    // energy, the kinetic energy's parts of translation and rotation, what the balls that
    // left the street took with them (EnergyParts::left, 0 elsewhere); momentum per axis.
    const std::vector<double>& kinetic() const { return kinetic_; }
    const std::vector<double>& translation() const { return translation_; }
    const std::vector<double>& rotation() const { return rotation_; }
    const std::vector<double>& potential() const { return potential_; }
    const std::vector<double>& spring() const { return spring_; }
    const std::vector<double>& energy() const { return energy_; }
    const std::vector<double>& left() const { return left_; }
    const std::vector<double>& momentum(int axis) const { return momentum_[static_cast<std::size_t>(axis)]; }
    const std::vector<double>& moving() const { return moving_; }
    const std::vector<long long>& impacts() const { return impacts_; } // since the start
    // The street's (zero elsewhere): balls past the foot of charted block `line`
    // (footBlocks), and the speed percentiles (StreetSample::speed).
    const std::vector<double>& pastFoot(int line) const { return feet_[static_cast<std::size_t>(line)]; }
    const std::vector<double>& speed(int line) const { return speeds_[static_cast<std::size_t>(line)]; }
    const std::vector<double>& onStreet() const { return onStreet_; }

private:
    void thin();
    template <typename F> void forEachColumn(F&& f);

    std::size_t capacity_;
    long long stride_ = 1;
    long long goneStep_ = kNotGone;
    static constexpr long long kNotGone = std::numeric_limits<long long>::max();
    std::vector<long long> step_;
    std::vector<double> t_;
    std::array<std::vector<double>, 3> p_, v_, w_, momentum_;
    std::vector<double> kinetic_, translation_, rotation_, potential_, spring_, energy_, left_, moving_;
    std::vector<long long> impacts_;
    std::array<std::vector<double>, kFootLines> feet_;
    std::array<std::vector<double>, kSpeedLines> speeds_;
    std::vector<double> onStreet_;
};

// Offers state `s` of step `step` to `track`: ball `ball`'s motion, `scene` (the state's
// ConservationSample) and, on `street` (null for the other scenes), its own sample (`measured`
// where the caller has it, else measured here); a ball that has left at the street's foot ends
// its own lines there (markBallGone).
void addState(MotionTrack& track, long long step, const State& s, int ball, const ConservationSample& scene,
              const street::Layout* street, const StreetSample* measured = nullptr);

// Impacts per unit of time at every kept sample: the impacts counted over the window
// (t - window, t], divided by the time that window spans (shorter at the start). A
// count, not a derivative, so it is exact for any stride: impacts(i) - impacts(j) over
// t(i) - t(j).
std::vector<double> impactRate(const MotionTrack& track, double window);

} // namespace ab::ui
