// SPDX-License-Identifier: MIT
// What the window keeps of a run, to draw the charts and to scrub back through it: the
// tracked ball's motion and what the scene conserves at every step (MotionTrack, thinned past its
// capacity), and frames of every ball at a stride that doubles whenever the frames
// would pass a byte budget. Memory stays bounded for any run length and ball count;
// with few balls every step is a frame.
#pragma once

#include "ui/charts/motion_track.h"
#include "ui/charts/scene_layout.h"

#include "ui/view/ball_orientation.h"

#include "core/state.h"

#include <cstddef>
#include <vector>

namespace ab::ui {

// Every ball at one recorded step, as floats (x, y, z interleaved per ball, ready to draw).
struct Frame {
    long long step = 0;
    double t = 0.0;
    std::vector<float> p;
    std::vector<float> v;
    // Angular velocities, x, y, z per ball, where the balls turn (State::spins()); empty
    // where they do not.
    std::vector<float> w;
    // Orientations, kOrientationFloats per ball (quaternion x, y, z, w; see
    // ui/view/ball_orientation.h), where the balls turn: the 3D view turns each ball's
    // pattern by it. Filled by the recording (integrated over every step, not only the
    // kept frames); empty where the balls do not turn.
    std::vector<float> q;
    ConservationSample scene; // of all balls: energy, momentum, moving balls, impacts
    StreetSample street;      // the street's counts and speeds (stage 5); zero elsewhere

    int balls() const { return static_cast<int>(p.size() / 3); }
    bool spins() const { return !w.empty(); }
    // What the frame's numbers take (the recording's budget counts it).
    std::size_t bytes() const { return sizeof(float) * (p.size() + v.size() + w.size() + q.size()); }
    // Ball i's angular velocity; zero where the frame has none.
    Eigen::Vector3d spin(int i) const
    {
        if (w.empty())
            return Eigen::Vector3d::Zero();
        const auto k = static_cast<std::size_t>(3 * i);
        return {w[k], w[k + 1], w[k + 2]};
    }
};

// The frame of `s` and, in the same pass over the balls, what `meter` measures of it.
Frame makeFrame(long long step, const State& s, const ConservationMeter& meter);
// The frame of `s` with `scene` measured already. Neither fills the orientations (q): they
// come from the recording, which follows every step.
Frame makeFrame(long long step, const State& s, const ConservationSample& scene);

class Recording {
public:
    static constexpr std::size_t defaultFrameBudget = std::size_t(192) << 20;

    Recording(const SceneLayout& layout, const ConservationMeter& meter, int trackedBall,
              std::size_t frameBudgetBytes = defaultFrameBudget, std::size_t trackCapacity = std::size_t(1) << 20);

    // Adds final state `s` of step `step`; steps come in increasing order.
    void add(long long step, const State& s);

    // The state on screen, `s` of step `step` (with `scene`, its ConservationSample), before
    // the next step makes it final: a step may still correct the state it starts from
    // (RunEngine::advance), so it is added only then. Until then its sample ends the track, so
    // that the charts, their data and figures reach the moment shown (a paused run's CSV
    // ended one step before it); add() of the same step puts the final sample in its place.
    void showCurrent(long long step, const State& s, const ConservationSample& scene);

    // Forgets every state of step `step` and later: the run forks back to that step and
    // records its new course from there, the balls turning on from the orientations of the
    // last frame kept before it.
    void truncateFrom(long long step);

    // The orientations (Frame::q) of state `s`, the step after the last one added: those
    // of the frame drawn while the run plays, before that state is recorded.
    std::vector<float> orientationsAt(const State& s) const { return orientations_.floatsAt(s); }

    // Follows another ball: its track is rebuilt from the frames (coarser where the
    // frames are), and continues at every step from here on.
    void setTrackedBall(int ball);
    int trackedBall() const { return trackedBall_; }

    const MotionTrack& track() const { return track_; }
    const std::vector<Frame>& frames() const { return frames_; }
    long long frameStride() const { return frameStride_; }
    std::size_t maxFrames() const { return maxFrames_; }
    // The last frame at or before time t; nullptr before the first frame.
    const Frame* frameAt(double t) const;
    bool empty() const { return frames_.empty() && track_.empty(); }
    double lastTime() const { return track_.empty() ? 0.0 : track_.t().back(); }

private:
    void thinFrames();
    void dropShown(); // takes the shown state's sample (showCurrent) off the track's end

    SceneLayout layout_;
    ConservationMeter meter_;
    int trackedBall_;
    std::size_t frameBudget_;
    std::size_t maxFrames_;
    long long frameStride_ = 1;
    std::vector<Frame> frames_;
    MotionTrack track_;
    BallOrientations orientations_; // of the last state added, in double precision
    long long current_ = -1;        // the step whose sample ends the track until it is added (showCurrent)
};

} // namespace ab::ui
