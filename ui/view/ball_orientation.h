// SPDX-License-Identifier: MIT
// Which way each ball faces, for drawing only: the 3D view paints a pattern on the balls
// of a run whose balls turn, and the pattern turns as the ball does, so rolling, back-spin
// and slipping can be seen. The orientation is integrated from the angular velocities of
// the recorded states (State::w); the physics never reads it. Free of Qt: the recording,
// the animation export and the tests share it.
#pragma once

#include "core/state.h"

#include <Eigen/Geometry>

#include <vector>

namespace ab::ui {

// Floats a ball's orientation takes in a frame: the unit quaternion's x, y, z (the axis
// times sin(angle/2)) and then w (cos(angle/2)), as the shaders read a vec4.
inline constexpr int kOrientationFloats = 4;

// Orientation q turned on by a step of length dt at the mean angular velocity wMean
// (world frame, rad per time unit, right-hand rule): equation O1,
//     q' = exp(1/2 wMean dt) (x) q, renormalised.
Eigen::Quaterniond turnedBy(const Eigen::Quaterniond& q, const Eigen::Vector3d& wMean, double dt);

// The running orientation of every ball of a run, in double precision. Each ball starts
// facing the world's axes (the identity: its pole on world z); follow() then takes the
// run's states in order, one per step.
class BallOrientations {
public:
    // Whether it holds an orientation per ball (false before the first state, and for a
    // run whose balls do not turn).
    bool active() const { return !q_.empty(); }
    int balls() const { return static_cast<int>(q_.size()); }
    double time() const { return t_; }
    const Eigen::Quaterniond& operator[](int i) const { return q_[static_cast<std::size_t>(i)]; }

    // Forgets every orientation: the next state followed starts the balls anew.
    void clear();
    // Takes the next state of the run: the balls turn from the last state followed to
    // `s` (equation O1 with the mean of the two states' w). The first state, one with
    // another number of balls, or one whose balls do not turn, starts afresh (identity).
    void follow(const State& s);
    // Restarts from orientations stored as floats (kOrientationFloats per ball) and the
    // angular velocities (3 per ball) of time t, as a recorded frame keeps them.
    void restart(double t, const std::vector<float>& q, const std::vector<float>& w);

    // The orientations as floats, kOrientationFloats per ball (empty when not active).
    std::vector<float> floats() const;
    // What follow(s) would give, as floats, leaving this as it is: the orientations of a
    // state drawn before it is recorded.
    std::vector<float> floatsAt(const State& s) const;

private:
    std::vector<Eigen::Quaterniond> q_;
    Vec3Array w_; // the angular velocities of the last state followed, 3 x N
    double t_ = 0.0;
};

} // namespace ab::ui
