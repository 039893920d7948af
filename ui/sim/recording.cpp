// SPDX-License-Identifier: MIT
#include "recording.h"

#include "core/street/street_census.h"

#include <algorithm>

namespace ab::ui {

Frame makeFrame(long long step, const State& s, const ConservationSample& scene)
{
    Frame f;
    f.step = step;
    f.t = s.t;
    f.scene = scene;
    const auto n = static_cast<std::size_t>(s.size());
    f.p.resize(3 * n);
    f.v.resize(3 * n);
    if (s.spins())
        f.w.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            f.p[3 * i + a] = static_cast<float>(s.p(a, static_cast<Eigen::Index>(i)));
            f.v[3 * i + a] = static_cast<float>(s.v(a, static_cast<Eigen::Index>(i)));
        }
    }
    if (s.spins())
        for (std::size_t i = 0; i < n; ++i)
            for (int a = 0; a < 3; ++a)
                f.w[3 * i + a] = static_cast<float>(s.w(a, static_cast<Eigen::Index>(i)));
    return f;
}

Frame makeFrame(long long step, const State& s, const ConservationMeter& meter)
{
    // The meter reads the state's rows (structure of arrays) in one streaming pass; the
    // float conversion below reads it ball by ball. Kept apart so that the meter stays in
    // the core, where the CLI and the tests use it without frames.
    return makeFrame(step, s, meter.measure(s));
}

Recording::Recording(const SceneLayout& layout, const ConservationMeter& meter, int trackedBall,
                     std::size_t frameBudgetBytes, std::size_t trackCapacity)
    : layout_(layout), meter_(meter), trackedBall_(trackedBall), frameBudget_(frameBudgetBytes), track_(trackCapacity)
{
    // A frame holds 6 floats per ball until the first frame tells (more where the balls turn).
    const std::size_t frameBytes = 6 * sizeof(float) * static_cast<std::size_t>(std::max(layout.balls, 1));
    maxFrames_ = std::max<std::size_t>(frameBudgetBytes / frameBytes, 2); // two at least; the start is always kept
}

void Recording::dropShown()
{
    if (current_ >= 0)
        track_.truncateFrom(current_);
    current_ = -1;
}

void Recording::showCurrent(long long step, const State& s, const ConservationSample& scene)
{
    dropShown();
    if (!track_.empty() && step <= track_.steps().back())
        return; // recorded already (the last state of a finished run)
    addState(track_, step, s, trackedBall_, scene, layout_.street ? &*layout_.street : nullptr);
    current_ = step;
}

void Recording::add(long long step, const State& s)
{
    dropShown();                                        // the sample shown, final now (showCurrent)
    const ConservationSample scene = meter_.measure(s); // one O(N) pass a step
    const StreetSample street = layout_.street ? measureStreet(*layout_.street, s) : StreetSample{}; // two more
    addState(track_, step, s, trackedBall_, scene, layout_.street ? &*layout_.street : nullptr, &street);
    orientations_.follow(s); // every step: the balls turn between the kept frames too
    if (step % frameStride_ != 0)
        return;
    frames_.push_back(makeFrame(step, s, scene));
    frames_.back().q = orientations_.floats();
    frames_.back().street = street;
    if (frames_.size() == 1)
        maxFrames_ = std::max<std::size_t>(frameBudget_ / std::max<std::size_t>(frames_.front().bytes(), 1), 2);
    while (frames_.size() > maxFrames_)
        thinFrames();
}

void Recording::truncateFrom(long long step)
{
    current_ = -1;
    track_.truncateFrom(step);
    const auto from =
        std::lower_bound(frames_.begin(), frames_.end(), step, [](const Frame& f, long long s) { return f.step < s; });
    frames_.erase(from, frames_.end());
    // The balls turn on from the last frame kept: between the frames the steps are not
    // kept, so the first step added after the fork spans them (O1 at the mean of the two
    // ends' spins, exact where the spin holds).
    if (frames_.empty())
        orientations_.clear();
    else
        orientations_.restart(frames_.back().t, frames_.back().q, frames_.back().w);
}

void Recording::thinFrames()
{
    frameStride_ *= 2;
    const auto off = [this](const Frame& f) { return f.step % frameStride_ != 0; };
    frames_.erase(std::remove_if(frames_.begin(), frames_.end(), off), frames_.end());
}

void Recording::setTrackedBall(int ball)
{
    if (ball == trackedBall_)
        return;
    trackedBall_ = ball;
    track_.clear();
    current_ = -1; // the caller shows its current state again
    for (const Frame& f : frames_) {
        const auto i = static_cast<std::size_t>(3 * ball);
        const Eigen::Vector3d p(f.p[i], f.p[i + 1], f.p[i + 2]);
        const Eigen::Vector3d v(f.v[i], f.v[i + 1], f.v[i + 2]);
        if (layout_.street && street::hasLeft(*layout_.street, p.x())) // as the census counts a frame
            track_.markBallGone(f.step);
        track_.add(f.step, f.t, p, v, f.spin(ball), f.scene, f.street);
    }
}

const Frame* Recording::frameAt(double t) const
{
    const auto it =
        std::upper_bound(frames_.begin(), frames_.end(), t, [](double x, const Frame& f) { return x < f.t; });
    return it == frames_.begin() ? nullptr : &*std::prev(it);
}

} // namespace ab::ui
