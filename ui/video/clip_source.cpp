// SPDX-License-Identifier: MIT
#include "clip_source.h"

#include "ui/charts/scene_layout.h"

#include "core/diagnostics/conservation.h"
#include "core/params.h"
#include "core/street/street_census.h"

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

constexpr std::size_t kMaxTrace = 20'000; // points; past it every other one is dropped

// A state's time within rounding of t counts as reached (t = from + k rate / fps is
// rarely the exact double of t0 + n dt).
bool reached(double stateT, double t)
{
    return stateT <= t + 1e-9 * std::max(1.0, std::abs(t));
}

bool finite(const State& s)
{
    return s.p.allFinite() && s.v.allFinite();
}

} // namespace

ClipSource::ClipSource(const RunSpec& spec, long long steps, int ball, bool trace)
    : sim_(makeSimulation(spec)), maxSteps_(steps), ball_(ball), traceOn_(trace),
      pathEndsAtHalt_(layoutFor(spec).pathEndsAtHalt)
{
    shown_ = sim_->start();
    orientations_.follow(shown_);
    if (traceOn_ && ball_ < shown_.size())
        trace_.emplace_back(float(shown_.p(0, ball_)), float(shown_.p(1, ball_)), float(shown_.p(2, ball_)));
}

bool ClipSource::stepOnce()
{
    if (ended_)
        return false;
    if (!haveNext_) {
        if (steps_ >= maxSteps_) {
            ended_ = true;
            return false;
        }
        // After this step `shown_` is final (the report's rules may correct it while stepping).
        sim_->step(shown_, next_);
        ++steps_;
        haveNext_ = true;
        if (!finite(next_)) {
            warning_ =
                "the state became non-finite after t = " + formatNumber(shown_.t) + "; the clip holds that moment";
            ended_ = true;
            return false;
        }
    }
    return true;
}

const std::vector<float>& ClipSource::advanceTo(double t)
{
    // First make the shown state final, then move on while the next one is due.
    while (stepOnce() && reached(next_.t, t)) {
        std::swap(shown_, next_);
        haveNext_ = false;
        orientations_.follow(shown_);
        if (traceOn_ && ball_ < shown_.size() && steps_ % traceStride_ == 0 && !(pathEndsAtHalt_ && shown_.halted)) {
            trace_.emplace_back(float(shown_.p(0, ball_)), float(shown_.p(1, ball_)), float(shown_.p(2, ball_)));
            if (trace_.size() > kMaxTrace) {
                std::vector<QVector3D> thinned;
                for (std::size_t i = 0; i < trace_.size(); i += 2)
                    thinned.push_back(trace_[i]);
                trace_ = std::move(thinned);
                traceStride_ *= 2;
            }
        }
    }
    const auto n = static_cast<std::size_t>(shown_.size());
    xyz_.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 3; ++k)
            xyz_[3 * i + k] = float(shown_.p(Eigen::Index(k), Eigen::Index(i)));
    q_ = orientations_.floats();
    return xyz_;
}

MotionTrack recordTrack(const RunSpec& spec, long long steps, int ball, double tEnd,
                        const std::function<bool()>& cancelled)
{
    const auto sim = makeSimulation(spec);
    const ConservationMeter meter(*sim);
    const SceneLayout layout = layoutFor(spec); // the street's, for its own charts
    MotionTrack track;
    long long index = 0;
    bool healthy = true, past = false;
    runRecorded(
        *sim, sim->start(), steps, 1,
        [&](const State& s) {
            healthy = healthy && finite(s);
            past = past || !reached(s.t, tEnd);
            if (healthy && !past)
                addState(track, index++, s, ball, meter.measure(s), layout.street ? &*layout.street : nullptr);
        },
        [&] { return !healthy || past || (cancelled && cancelled()); });
    return track;
}

} // namespace ab::ui
