// SPDX-License-Identifier: MIT
// The window follows its run: the 3D view every new state, the panels (charts, slider,
// readings) four times a second while playing, spread over frames a part at a time.
#include "main_window.h"

#include "i18n/core_text.h"
#include "panels/status_readout.h"
#include "panels/transport_bar.h"
#include "sim/playback_rate.h"
#include "view/ball_view.h"

#include <algorithm>

namespace ab::ui {

namespace {

constexpr int maxTracePoints = 20000;

} // namespace

void MainWindow::refresh()
{
    if (!controller_.hasRun())
        return;
    const EngineStatus status = controller_.status();
    const std::optional<double> viewT = transport_->viewTime();
    // Where the report's limit moved the ball to the origin, its path ends at the halt.
    const std::optional<double> pathEnd = controller_.layout().pathEndsAtHalt ? status.haltedAt : std::nullopt;
    controller_.engine().read(
        [&](const Recording& rec, const Frame& current) { refreshView(rec, current, viewT, pathEnd); });
    if (const RunEngine* compare = controller_.comparisonEngine()) {
        compare->read([&](const Recording& rec, const Frame& current) {
            if (view_) { // the comparison at the moment shown: it never runs ahead of the main run
                const Frame* shown = viewT ? rec.frameAt(*viewT) : &current;
                view_->setGhosts((shown ? shown : &current)->p, view_->ghostLegend());
            }
        });
    }
    // The 3D view follows every new state. The panels redraw four times a second while
    // playing: with a GL view in the window every widget redraw recomposes the whole
    // window, which software OpenGL pays for in the frame it lands in, so their refresh
    // is spread over the next frames, a chart at a time. The moment play stops is spread
    // too (it is still part of playback: the run ending under a lecturer's eyes); any
    // other change of a stopped run (a scrub, a new selection) redraws them at once.
    const bool stopping = panelsPlaying_ && !status.playing;
    const bool spread = status.playing || stopping;
    panelsPlaying_ = status.playing;
    if (!spread) {
        cancelPanelRefresh();
        refreshPanels();
        return;
    }
    const bool due = stopping || !panelClock_.isValid() || panelClock_.elapsed() >= 250;
    if (!due || (panelPart_ >= 0 && !stopping))
        return;
    panelClock_.restart();
    panelPart_ = 0; // from the first chart again, with what is recorded now
    panelTimer_.start();
}

void MainWindow::cancelPanelRefresh()
{
    panelTimer_.stop();
    panelPart_ = -1;
}

void MainWindow::refreshPanels()
{
    const EngineStatus status = controller_.status();
    const std::optional<double> viewT = transport_->shownTime(); // the cursor at the state shown
    controller_.engine().read([&](const Recording& rec, const Frame&) { charts_->showTrack(rec.track()); });
    if (const RunEngine* compare = controller_.comparisonEngine())
        compare->read([&](const Recording& rec, const Frame&) { charts_->showComparisonTrack(rec.track()); });
    panelClock_.restart();
    charts_->setCursorTime(viewT ? viewT : std::optional<double>(status.t));
    refreshReadings(status);
}

void MainWindow::refreshPanelPart()
{
    if (!controller_.hasRun() || panelPart_ < 0) {
        cancelPanelRefresh();
        return;
    }
    const EngineStatus status = controller_.status();
    const std::optional<double> viewT = transport_->shownTime(); // the cursor at the state shown
    const std::optional<double> cursor = viewT ? viewT : std::optional<double>(status.t);
    // The next shown chart; hidden ones take no tick.
    while (static_cast<std::size_t>(panelPart_) < ChartPanel::kSlots) {
        const auto slot = static_cast<std::size_t>(panelPart_++);
        bool drawn = false;
        controller_.engine().read([&](const Recording& rec, const Frame&) {
            if (const RunEngine* compare = controller_.comparisonEngine())
                compare->read([&](const Recording& other, const Frame&) {
                    drawn = charts_->refreshSlot(slot, rec.track(), &other.track(), cursor);
                });
            else
                drawn = charts_->refreshSlot(slot, rec.track(), nullptr, cursor);
        });
        if (drawn)
            return;
    }
    refreshReadings(status); // the last part: slider and readings
    cancelPanelRefresh();
}

void MainWindow::refreshReadings(const EngineStatus& status)
{
    double start = status.t;
    controller_.engine().read([&](const Recording& rec, const Frame& current) {
        start = rec.frames().empty() ? current.t : rec.frames().front().t;
    });
    transport_->setRecorded(start, status.t, coreText(sceneInfo(scene_).timeUnit));
    // The readings are of the moment on screen: the one looked back at, or the live one.
    const std::optional<double> viewT = transport_->viewTime();
    controller_.engine().read([&](const Recording& rec, const Frame& current) {
        const Frame* shown = viewT ? rec.frameAt(*viewT) : &current;
        readout_->show(status, shown ? shown : &current, viewT && shown);
    });
    followKeptSpeed(status);
    if (view_ && !status.playing) {
        // Paused, the view draws only when moved: its rate says nothing of the run ("0.5 fps",
        // "2 fps" by turns). A dash until the run plays again.
        readout_->setFrameRate(0.0);
        fpsClock_.restart();
        framesSinceFps_ = 0;
    } else if (view_ && fpsClock_.elapsed() >= 1000) {
        readout_->setFrameRate(1000.0 * framesSinceFps_ / double(fpsClock_.restart()));
        framesSinceFps_ = 0;
    }
}

void MainWindow::refreshView(const Recording& rec, const Frame& current, std::optional<double> viewT,
                             std::optional<double> pathEnd)
{
    const Frame* shown = viewT ? rec.frameAt(*viewT) : &current;
    if (!shown)
        shown = &current;
    if (viewT)
        transport_->setShownTime(shown->t); // the bar's time is the state's the view shows
    if (!view_)
        return;
    view_->setBalls(shown->p, shown->q);
    if (controller_.layout().axes == 1) {
        view_->setTrace({}); // the vertical scene's trace would hide the ball's own line
        return;
    }
    // The selected ball's path so far (Figure 2.6), thinned to a drawable number of points.
    const MotionTrack& track = rec.track();
    const double until = viewT.value_or(current.t);
    auto end = std::upper_bound(track.t().begin(), track.t().end(), until) - track.t().begin();
    if (pathEnd) // the states from the halt on are the zeroed ones
        end = std::min(end, std::lower_bound(track.t().begin(), track.t().end(), *pathEnd) - track.t().begin());
    const std::size_t n = static_cast<std::size_t>(end);
    const std::size_t stride = std::max<std::size_t>(1, n / maxTracePoints);
    std::vector<QVector3D> trace;
    trace.reserve(n / stride + 2);
    for (std::size_t i = 0; i < n; i += stride)
        trace.emplace_back(float(track.p(0)[i]), float(track.p(1)[i]), float(track.p(2)[i]));
    if (n > 0 && (n - 1) % stride != 0)
        trace.emplace_back(float(track.p(0)[n - 1]), float(track.p(1)[n - 1]), float(track.p(2)[n - 1]));
    view_->setTrace(std::move(trace));
}

void MainWindow::followKeptSpeed(const EngineStatus& status)
{
    // Kept speed = (run time gained / wall time) / the run time of a real second at 1x
    // (playbackRate), over the last two seconds of play; unknown before one and a half.
    const double now = double(paceClock_.elapsed()) / 1000.0;
    if (!status.playing || status.finished || (!pace_.empty() && status.t < pace_.back().second)) {
        pace_.clear(); // paused, ended, or gone back: a new count
        transport_->setKeptSpeed(std::nullopt);
        if (!status.playing || status.finished)
            return;
    }
    pace_.emplace_back(now, status.t);
    while (pace_.size() > 2 && now - pace_[1].first >= 2.0)
        pace_.pop_front();
    const double wall = now - pace_.front().first;
    if (wall < 1.5)
        return;
    transport_->setKeptSpeed((status.t - pace_.front().second) / wall / playbackRate(sceneInfo(scene_)));
}

} // namespace ab::ui
