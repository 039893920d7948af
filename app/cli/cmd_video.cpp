// SPDX-License-Identifier: MIT
// `video`: the run as an animation (MP4, WebM or GIF), headless, from the window's
// rendering and encoding code (ui/video/animation_export.h). It needs OpenGL: software
// OpenGL (Mesa llvmpipe) under an X server such as Xvfb, or Mesa's EGL without any
// display; where neither exists it says so in one line and exits with status 5.
#include "commands.h"

#include "interrupt.h"
#include "run_progress.h"
#include "run_setup.h"

#include "../../core/io/atomic_file.h"
#include "../../core/io/preset.h"
#include "../../ui/charts/headless_app.h"
#include "../../ui/video/animation_export.h"

#include <QGuiApplication>

#include <cmath>
#include <cstdlib>
#include <ostream>
#include <regex>

namespace ab::cli {

namespace {

constexpr int kNoOpenGl = 5; // exit status: no OpenGL to render with

video::VideoFormat readFormat(const std::string& path)
{
    const auto format = video::videoFormatOfPath(path);
    if (!format)
        throw InputError("--out: " + printableInput(path) + " must end in .mp4, .webm or .gif");
    return *format;
}

void readSize(Parsed& args, video::VideoSettings& s)
{
    const auto text = args.option("size");
    if (!text || *text == "720p") {
        s.width = 1280;
        s.height = 720;
        return;
    }
    if (*text == "1080p") {
        s.width = 1920;
        s.height = 1080;
        return;
    }
    static const std::regex wxh(R"((\d{1,6})[xX](\d{1,6}))");
    std::smatch m;
    if (!std::regex_match(*text, m, wxh))
        throw InputError("--size: '" + printableInput(*text) + "' is not WxH, 720p or 1080p");
    s.width = std::stoi(m[1].str());
    s.height = std::stoi(m[2].str());
}

// The view a preset saved (camera, charts, followed ball), where it saved one; else the
// scene is framed as the window frames it, with every chart that applies.
void applyPresetView(const RunSetup& setup, ui::AnimationRequest& request, bool ballGiven)
{
    if (!setup.presetKey)
        return;
    const PresetView v = loadPreset(*setup.presetKey).view;
    if (v.cameraYaw && v.cameraPitch && v.cameraDistance && v.cameraTarget) {
        const Eigen::Vector3d& t = *v.cameraTarget;
        request.camera = ui::CameraPose{QVector3D(float(t.x()), float(t.y()), float(t.z())), float(*v.cameraYaw),
                                        float(*v.cameraPitch), float(*v.cameraDistance)};
    }
    for (const std::string& key : v.charts)
        if (const auto kind = ui::parseChartKind(key))
            request.chartKinds.push_back(*kind);
    if (v.selectedBall && !ballGiven)
        request.ball = *v.selectedBall;
}

// Software OpenGL without a window: under X (DISPLAY set) the xcb platform's GLX, else
// the offscreen platform, which Qt 6.4 gives EGL contexts on Mesa's surfaceless EGL.
void chooseGlPlatform()
{
    if (QCoreApplication::instance() || std::getenv("QT_QPA_PLATFORM"))
        return;
    const char* display = std::getenv("DISPLAY");
    qputenv("QT_QPA_PLATFORM", display && *display ? "xcb" : "offscreen");
}

class Progress {
public:
    // On a terminal only, as run's: a script reading stderr got a line of "\r"s per percent.
    Progress(std::ostream& err, bool quiet, std::string name)
        : err_(err), quiet_(quiet || !RunProgress::isTerminal(err)), name_(std::move(name))
    {
    }
    bool operator()(long long done, long long total)
    {
        throwIfInterrupted();
        if (quiet_ || total <= 0)
            return true;
        const int percent = int(100 * done / total);
        if (percent != last_) {
            err_ << "\rvideo: " << name_ << " " << percent << "% (" << done << "/" << total << ")" << std::flush;
            last_ = percent;
        }
        return true;
    }
    void end()
    {
        if (!quiet_ && last_ >= 0)
            err_ << "\n";
        last_ = -1;
    }

private:
    std::ostream& err_;
    bool quiet_;
    std::string name_;
    int last_ = -1;
};

} // namespace

int videoCommand(Parsed& args, std::ostream&, std::ostream& err)
{
    const RunSetup setup = readRunSetup(args);
    const auto out = args.option("out");
    if (!out)
        throw InputError("video: missing --out FILE.mp4, FILE.webm or FILE.gif");
    ui::AnimationRequest request(setup.spec);
    request.steps = setup.steps;
    request.video.format = readFormat(*out);
    readSize(args, request.video);
    request.video.fps = int(args.integer("fps", video::kMinFps, video::kMaxFps).value_or(30));
    request.from = args.real("from");
    request.to = args.real("to");
    request.speed = args.real("speed").value_or(1.0);
    request.charts = args.flag("charts");
    const auto ball = args.integer("ball", 1, 4'000'000);
    request.ball = int(ball.value_or(1) - 1);
    const bool quiet = args.flag("quiet");
    applyPresetView(setup, request, ball.has_value());

    const ui::AnimationPlan plan = ui::planAnimation(request); // bad input: before any GL or file
    checkWritable(*out);
    chooseGlPlatform();
    ui::ensureGuiApplication();
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        throw std::logic_error("video: the process has a QCoreApplication; rendering needs a QGuiApplication");

    Progress progress(err, quiet, *out);
    ui::AnimationStats stats;
    try {
        stats = ui::exportAnimation(request, *out, std::ref(progress));
    } catch (const Interrupted&) {
        progress.end();
        throw;
    } catch (const InputError&) {
        progress.end();
        throw;
    } catch (const std::runtime_error& e) {
        // No OpenGL here (no X server, no EGL): one line, its own status, no file.
        progress.end();
        if (std::string(e.what()).find("OpenGL") == std::string::npos &&
            std::string(e.what()).find("framebuffer") == std::string::npos)
            throw;
        err << "amazeballs-cli: video: " << e.what()
            << "; run it under an X server (xvfb-run -a amazeballs-cli video ...); no file was written\n";
        return kNoOpenGl;
    }
    progress.end();
    if (!stats.warning.empty())
        err << "amazeballs-cli: warning: " << stats.warning << "\n";
    if (!quiet) {
        const double n = double(std::max(stats.frames, 1LL));
        err << "video: wrote " << *out << ": " << stats.frames << " frames, " << request.video.width << "x"
            << request.video.height << " at " << request.video.fps << " fps (" << formatNumber(plan.seconds)
            << " s); per frame: simulate " << formatNumber(std::round(stats.simulate / n * 1e4) / 10) << " ms, render "
            << formatNumber(std::round(stats.render / n * 1e4) / 10) << " ms, encode "
            << formatNumber(std::round(stats.encode / n * 1e4) / 10) << " ms; "
            << formatNumber(std::round(n / stats.total * 10) / 10) << " frames/s\n";
    }
    return stats.warning.empty() ? 0 : 3;
}

} // namespace ab::cli
