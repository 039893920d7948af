// SPDX-License-Identifier: MIT
#include "animation_export.h"

#include "chart_strip.h"
#include "clip_source.h"

#include "ui/charts/scene_layout.h"
#include "ui/sim/playback_rate.h"
#include "ui/view/view_frame.h"

#include "core/io/atomic_file.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QPainter>

#include <cmath>
#include <sstream>
#include <string>

namespace ab::ui {

namespace {

constexpr long long kMaxFrames = 1'000'000; // 9 hours at 30 fps
constexpr int kPaletteSamples = 24;         // frames a GIF's palette is computed from

std::string num(double x)
{
    return formatNumber(x);
}

// The 3D view's part of the frame: all of it, or the left 60% beside the charts.
QRect viewRectOf(const AnimationRequest& r)
{
    const QSize size(r.video.width, r.video.height);
    if (!r.charts)
        return QRect(QPoint(0, 0), size);
    return QRect(0, 0, std::max(1, int(std::lround(0.6 * size.width()))), size.height());
}

std::vector<ChartKind> chartKindsOf(const AnimationRequest& r)
{
    if (r.chartKinds.empty())
        return chartsFor(r.spec);
    std::vector<ChartKind> kinds;
    for (ChartKind k : r.chartKinds)
        if (chartApplies(k, r.spec))
            kinds.push_back(k);
    return kinds;
}

double seconds(const QElapsedTimer& timer)
{
    return double(timer.nsecsElapsed()) * 1e-9;
}

} // namespace

double AnimationPlan::timeOf(long long k) const
{
    return from + double(k) * rate / double(fps);
}

AnimationPlan planAnimation(const AnimationRequest& r)
{
    const std::string format(video::videoFormatKey(r.video.format));
    video::checkFrameSize(r.video.format, r.video.width, r.video.height);
    video::checkFps(r.video.fps);
    if (r.charts && r.video.width < 400)
        throw InputError("--size: " + std::to_string(r.video.width) + " pixels wide leaves no room for the charts (" +
                         "--charts needs 400 or more)");
    if (!(r.speed > 0.0) || !std::isfinite(r.speed) || r.speed > 1e6)
        throw InputError("--speed: " + num(r.speed) + " must be a positive number up to 1e6");
    const auto sim = makeSimulation(r.spec); // validates the spec
    const State start = sim->start();
    if (r.ball < 0 || r.ball >= start.size())
        throw InputError("ball " + std::to_string(r.ball + 1) + " is outside [1, " + std::to_string(start.size()) +
                         "]");
    AnimationPlan plan;
    plan.runStart = start.t;
    plan.runEnd = start.t + double(r.steps) * sim->dt();
    plan.from = r.from.value_or(plan.runStart);
    plan.to = r.to.value_or(plan.runEnd);
    std::string run = "["; // appended, not "[" + ...: GCC 12 warns falsely (-Wrestrict) on that
    run.append(num(plan.runStart)).append(", ").append(num(plan.runEnd)).append("]");
    const double slack = 1e-9 * std::max(1.0, std::abs(plan.runEnd));
    if (!std::isfinite(plan.from) || plan.from < plan.runStart - slack || plan.from >= plan.runEnd)
        throw InputError("--from: " + num(plan.from) + " is outside the run " + run);
    if (!std::isfinite(plan.to) || plan.to > plan.runEnd + slack || plan.to < plan.runStart)
        throw InputError("--to: " + num(plan.to) + " is outside the run " + run);
    if (plan.to <= plan.from)
        throw InputError("--to: " + num(plan.to) + " is not after --from " + num(plan.from));
    plan.rate = r.speed * playbackRate(sim->scene());
    plan.seconds = (plan.to - plan.from) / plan.rate;
    const double frames = std::round(plan.seconds * r.video.fps);
    if (frames < 1.0)
        throw InputError("--to: the range " + num(plan.from) + " to " + num(plan.to) + " at speed " + num(r.speed) +
                         " is shorter than one frame at " + std::to_string(r.video.fps) + " fps");
    if (frames > double(kMaxFrames))
        throw InputError("the clip would have " + num(frames) + " frames; at most " + std::to_string(kMaxFrames) +
                         " (raise --speed or narrow --from/--to)");
    plan.frames = static_cast<long long>(frames);
    plan.fps = r.video.fps;
    plan.seconds = double(plan.frames) / r.video.fps;
    video::checkEncoderAvailable(r.video.format);
    return plan;
}

AnimationFrames::AnimationFrames(const AnimationRequest& request, const AnimationPlan& plan,
                                 const std::function<bool()>& cancelled)
    : request_(request), plan_(plan), viewRect_(viewRectOf(request)), view_(viewRect_.size())
{
    view_.initialize();
    const SceneLayout layout = layoutFor(request.spec);
    source_ = std::make_unique<ClipSource>(request.spec, request.steps, request.ball, layout.axes != 1);
    const SceneInfo& scene = source_->simulation().scene();
    timeUnit_ = QString::fromStdString(scene.timeUnit);
    view_.setScene(layout, QString::fromStdString(scene.lengthUnit), ballColours(request.spec, layout.balls),
                   request.ball, request.background, request.camera);
    if (request.charts) {
        QElapsedTimer timer;
        timer.start();
        const MotionTrack track = recordTrack(request.spec, request.steps, request.ball, plan.to, cancelled);
        if (cancelled && cancelled())
            throw AnimationCancelled();
        simulate_ += seconds(timer);
        const QSize strip(request.video.width - viewRect_.width(), request.video.height);
        charts_ = std::make_unique<ChartStrip>(source_->simulation(), request.ball, chartKindsOf(request), track,
                                               plan.to, strip);
    }
}

AnimationFrames::~AnimationFrames() = default;

const std::string& AnimationFrames::warning() const
{
    return source_->warning();
}

QImage AnimationFrames::frame(long long k)
{
    const double t = plan_.timeOf(k);
    QElapsedTimer timer;
    timer.start();
    const std::vector<float>& xyz = source_->advanceTo(t);
    simulate_ += seconds(timer);
    timer.restart();
    const QImage view = view_.render(xyz, source_->trace(), source_->orientations());
    // Composed in QPainter's native format (drawing into packed RGB converts every pixel
    // on a slow path: 4x the cost at 720p), handed over as packed RGB.
    QImage out(request_.video.width, request_.video.height, QImage::Format_RGB32);
    out.fill(Qt::white);
    {
        QPainter p(&out);
        p.drawImage(viewRect_.topLeft(), view);
        if (charts_)
            charts_->paint(p, QPoint(viewRect_.right() + 1, 0), t);
        // The moment shown, in the scene's own unit, at the top left of the 3D view.
        QFont font;
        font.setPixelSize(std::max(12, request_.video.height / 36));
        p.setFont(font);
        // Whole steps of 1 (stage 1's steps, stage 4's frames) need no decimals.
        const double shown = source_->shownTime();
        const int decimals = source_->simulation().dt() >= 1.0 ? 0 : shown < 100.0 ? 2 : 1;
        const QString text = QCoreApplication::translate("ab::ui::AnimationFrames", "t = %1 %2")
                                 .arg(QString::number(shown, 'f', decimals), timeUnit_);
        const int margin = font.pixelSize() / 2;
        drawHaloText(p, QPointF(margin, margin + font.pixelSize() / 2.0), text, QColor(0x20, 0x20, 0x20), Qt::AlignLeft,
                     request_.background);
    }
    out.convertTo(QImage::Format_RGB888);
    render_ += seconds(timer);
    return out;
}

namespace {

// Counts the work done and asks `progress` whether to go on.
struct Work {
    const AnimationProgress& progress;
    long long total = 0, done = 0;

    bool goOn() const { return !progress || progress(done, total); }
    void step()
    {
        ++done;
        if (!goOn())
            throw AnimationCancelled();
    }
};

// A GIF's palette from `samples` frames spread evenly over the clip, first to last.
void samplePalette(const AnimationRequest& request, const AnimationPlan& plan, long long samples,
                   video::VideoEncoder& encoder, Work& work, AnimationStats& stats)
{
    AnimationFrames sampler(request, plan, [&] { return !work.goOn(); });
    QElapsedTimer timer;
    for (long long i = 0; i < samples; ++i) {
        const long long k = samples > 1 ? i * (plan.frames - 1) / (samples - 1) : 0;
        const QImage f = sampler.frame(k);
        timer.start();
        encoder.addPaletteSample(f.constBits(), int(f.bytesPerLine()));
        stats.encode += seconds(timer);
        work.step();
    }
    stats.simulate += sampler.simulateSeconds();
    stats.render += sampler.renderSeconds();
}

} // namespace

AnimationStats exportAnimation(const AnimationRequest& request, const std::string& path,
                               const AnimationProgress& progress)
{
    const AnimationPlan plan = planAnimation(request);
    checkWritable(path);
    QElapsedTimer total;
    total.start();
    AnimationStats stats;
    const bool gif = request.video.format == video::VideoFormat::Gif;
    const long long samples = gif ? std::min<long long>(kPaletteSamples, plan.frames) : 0;
    Work work{progress, samples + plan.frames, 0};
    // Encoded in memory (the MP4 muxer seeks back to write its index), then written through
    // core/io/atomic_file.h: whole or not at all, devices and links respected.
    std::stringstream out(std::ios::in | std::ios::out | std::ios::binary);
    {
        video::VideoEncoder encoder(request.video, out);
        if (samples > 0)
            samplePalette(request, plan, samples, encoder, work, stats);
        AnimationFrames frames(request, plan, [&] { return !work.goOn(); });
        if (!work.goOn())
            throw AnimationCancelled();
        QElapsedTimer timer;
        for (long long k = 0; k < plan.frames; ++k) {
            const QImage f = frames.frame(k);
            timer.start();
            encoder.addFrame(f.constBits(), int(f.bytesPerLine()));
            stats.encode += seconds(timer);
            work.step();
        }
        timer.start();
        encoder.finish();
        stats.encode += seconds(timer);
        stats.frames = encoder.framesWritten();
        stats.simulate += frames.simulateSeconds();
        stats.render += frames.renderSeconds();
        stats.warning = frames.warning();
    }
    const std::string bytes = std::move(out).str();
    writeFileAtomically(path, std::string_view(bytes));
    stats.total = seconds(total);
    return stats;
}

} // namespace ab::ui
