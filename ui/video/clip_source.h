// SPDX-License-Identifier: MIT
// The run, stepped deterministically for a clip: the state shown at clip time t is the
// last final state at or before t (as the window's time slider shows it), so the same
// request gives the same frames whatever the machine or the wall clock. Also records the
// tracked ball's path for the 3D view's trace, and its motion for the charts.
#pragma once

#include "ui/charts/motion_track.h"
#include "ui/view/ball_orientation.h"

#include "core/simulation.h"

#include <QVector3D>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ab::ui {

class ClipSource {
public:
    // A fresh run of `spec`, at most `steps` steps, following ball `ball` for the trace
    // (`trace` false: none, as the vertical scene has none).
    ClipSource(const RunSpec& spec, long long steps, int ball, bool trace);

    // Steps on to time t (never earlier than a previous call) and returns the centres of
    // the state shown then, x y z per ball. A run that turns non-finite holds its last
    // good state (warning() says when).
    const std::vector<float>& advanceTo(double t);
    const std::vector<QVector3D>& trace() const { return trace_; }
    // The orientations of the state shown (kOrientationFloats per ball), integrated over
    // every step as the window's recording does; empty where the balls do not turn.
    const std::vector<float>& orientations() const { return q_; }
    double shownTime() const { return shown_.t; }
    const std::string& warning() const { return warning_; }
    const Simulation& simulation() const { return *sim_; }

private:
    bool stepOnce(); // false at the run's end or on a non-finite state

    std::unique_ptr<Simulation> sim_;
    long long maxSteps_;
    long long steps_ = 0;
    int ball_;
    bool traceOn_;
    bool pathEndsAtHalt_; // SceneLayout::pathEndsAtHalt: the zeroed states add nothing to the path
    State shown_, next_;
    bool haveNext_ = false, ended_ = false;
    std::vector<float> xyz_;
    BallOrientations orientations_;
    std::vector<float> q_;
    std::vector<QVector3D> trace_;
    long long traceStride_ = 1;
    std::string warning_;
};

// The tracked ball's motion and the scene's conserved quantities at every step up to
// time `tEnd`, for the charts; `cancelled` is polled between steps.
MotionTrack recordTrack(const RunSpec& spec, long long steps, int ball, double tEnd,
                        const std::function<bool()>& cancelled);

} // namespace ab::ui
