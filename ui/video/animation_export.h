// SPDX-License-Identifier: MIT
// An animation of a run, from the window (File > Export animation...) and from
// `amazeballs-cli video`, by one code path: the run stepped deterministically over a time
// range (ui/video/clip_source.h), each frame drawn offscreen at the clip's size
// (ui/video/offscreen_view.h), alone or beside the charts with their time cursor
// (ui/video/chart_strip.h), and encoded (ui/video/video_encoder.h) into a temporary file
// renamed over the target at the end: the file is written whole or not at all.
//
// Clip time and run time: at speed 1 the clip plays as the window does at 1x
// (ui/sim/playback_rate.h: `rate` run units per real second), so frame k of a clip at
// `fps` shows the run at t_k = from + k * speed * rate / fps, and a clip of the range
// [from, to] has round((to - from) / (speed * rate) * fps) frames: 60 s of run at 1x and
// 30 fps is 1,800 frames.
#pragma once

#include "offscreen_view.h"
#include "video_encoder.h"

#include "ui/charts/motion_chart.h"

#include "core/simulation.h"

#include <QColor>

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ab::ui {

class ChartStrip;
class ClipSource;

struct AnimationRequest {
    explicit AnimationRequest(RunSpec s) : spec(std::move(s)) {}

    RunSpec spec;
    long long steps = 0;                 // the run's planned steps
    std::optional<double> from, to;      // run time; unset: the run's start, its end
    double speed = 1.0;                  // playback speed, 1 = the window's 1x
    video::VideoSettings video;          // format, size, fps
    bool charts = false;                 // the charts beside the 3D view
    std::vector<ChartKind> chartKinds;   // which; empty: every one that applies
    int ball = 0;                        // the tracked ball (trace, charts, ring)
    std::optional<CameraPose> camera;    // unset: the scene framed as the window frames it
    QColor background{0xec, 0xf0, 0xf5}; // the 3D view's clear colour
};

struct AnimationPlan {
    double from = 0.0, to = 0.0; // run time
    double runStart = 0.0, runEnd = 0.0;
    double rate = 1.0; // run time per clip second: speed times the scene's 1x rate
    long long frames = 0;
    int fps = 30;
    double seconds = 0.0; // the clip's length
    // Run time shown by frame k.
    double timeOf(long long k) const;
};

// Checks everything that can be checked before a frame is drawn: the run's spec, the
// time range within the run, the speed, the size and fps for the format, the encoder;
// throws InputError with one line naming what is wrong.
AnimationPlan planAnimation(const AnimationRequest& request);

// What a clip cost, for `--quiet`-less reports and the benchmark (wall seconds).
struct AnimationStats {
    long long frames = 0;
    double simulate = 0.0, render = 0.0, encode = 0.0, total = 0.0;
    std::string warning; // the run turned non-finite: the clip holds the last good state
};

class AnimationCancelled : public std::runtime_error {
public:
    AnimationCancelled() : std::runtime_error("cancelled") {}
};

// Reports progress (frames done of total, palette samples and the charts' run included
// as a first phase) and returns false to cancel; may also throw to stop.
using AnimationProgress = std::function<bool(long long done, long long total)>;

// Writes the clip to `path` (its format is request.video.format). Throws InputError for
// bad input or an unwritable path, AnimationCancelled when `progress` said stop, or
// whatever `progress` threw; in every such case no file is left. Needs a
// QGuiApplication whose platform has OpenGL (std::runtime_error when it has none).
AnimationStats exportAnimation(const AnimationRequest& request, const std::string& path,
                               const AnimationProgress& progress = {});

// The clip's frames one at a time, as exportAnimation draws them: for tests and previews.
class AnimationFrames {
public:
    AnimationFrames(const AnimationRequest& request, const AnimationPlan& plan,
                    const std::function<bool()>& cancelled = {});
    ~AnimationFrames();
    // Frame k (k never decreasing from one call to the next), QImage::Format_RGB888.
    QImage frame(long long k);
    const OffscreenView& view() const { return view_; }
    QRect viewRect() const { return viewRect_; }
    const std::string& warning() const;
    double simulateSeconds() const { return simulate_; }
    double renderSeconds() const { return render_; }

private:
    AnimationRequest request_;
    AnimationPlan plan_;
    QRect viewRect_;
    OffscreenView view_;
    std::unique_ptr<ClipSource> source_;
    std::unique_ptr<ChartStrip> charts_;
    QString timeUnit_;
    double simulate_ = 0.0, render_ = 0.0;
};

} // namespace ab::ui
