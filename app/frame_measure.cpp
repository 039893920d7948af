// SPDX-License-Identifier: MIT
// --measure-frames: the window plays for a while and prints its frame times.
#include "frame_measure.h"

#include "ui/main_window.h"
#include "ui/view/ball_view.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTimer>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

namespace ab::app {

namespace {

// CPU seconds used so far by this process's threads other than the stepping thread
// ("ab-stepper") and its helpers ("ab-worker", --threads): the window's own thread and the
// software renderer's. Linux only.
double drawingCpuSeconds()
{
    double ticks = 0.0;
    QDir tasks("/proc/self/task");
    for (const QString& tid : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile stat(tasks.filePath(tid + "/stat"));
        if (!stat.open(QIODevice::ReadOnly))
            continue;
        const QString line = QString::fromLatin1(stat.readAll());
        const int open = line.indexOf('('), close = line.lastIndexOf(')');
        const QString name = line.mid(open + 1, close - open - 1);
        if (name == QLatin1String("ab-stepper") || name == QLatin1String("ab-worker"))
            continue;
        const QStringList fields = line.mid(close + 2).split(' ');
        if (fields.size() > 12)
            ticks += fields[11].toDouble() + fields[12].toDouble(); // utime, stime
    }
    return ticks / double(sysconf(_SC_CLK_TCK));
}

struct Sample {
    double at, paint, interval; // seconds since play, milliseconds, milliseconds
};

// Fixed decimals whatever the locale (printf's follow LC_NUMERIC, which Qt sets).
std::string fixed(double x, int decimals = 1)
{
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, x, std::chars_format::fixed, decimals).ptr;
    return std::string(text, end);
}

// The summary line of a measurement: the frames after the start-up's (`startUp` seconds from
// the first), their paint times and intervals (median, p95, max), the drawing CPU a frame,
// the simulation's steps and the three longest intervals with their moments.
std::string frameSummary(const std::vector<Sample>& samples, double startUp, double cpu, long long steps,
                         double stepSeconds, int threads)
{
    const double firstAt = samples.empty() ? 0.0 : samples.front().at;
    std::vector<Sample> playing, first;
    for (const Sample& s : samples)
        (s.at - firstAt < startUp ? first : playing).push_back(s);
    std::vector<double> paint, interval;
    for (const Sample& s : playing) {
        paint.push_back(s.paint);
        interval.push_back(s.interval);
    }
    std::sort(paint.begin(), paint.end());
    std::sort(interval.begin(), interval.end());
    auto pct = [](const std::vector<double>& v, double q) {
        return fixed(v.empty() ? 0.0 : v[std::size_t(q * double(v.size() - 1))]);
    };
    double firstLongest = 0.0;
    for (const Sample& s : first)
        firstLongest = std::max(firstLongest, s.interval);
    std::sort(playing.begin(), playing.end(), [](const Sample& a, const Sample& b) { return a.interval > b.interval; });
    std::string longest;
    for (std::size_t k = 0; k < std::min<std::size_t>(3, playing.size()); ++k)
        longest += (k ? ", " : "") + fixed(playing[k].interval) + " ms at " + fixed(playing[k].at - firstAt, 2) + " s";
    const std::size_t frames = samples.size();
    return "frames " + std::to_string(interval.size()) + "; paint ms: median " + pct(paint, 0.5) + " p95 " +
           pct(paint, 0.95) + " max " + pct(paint, 1.0) + "; interval ms: median " + pct(interval, 0.5) + " p95 " +
           pct(interval, 0.95) + " max " + pct(interval, 1.0) + "; drawing CPU per frame " +
           fixed(frames ? 1e3 * cpu / double(frames) : 0.0) + " ms; simulation: " + std::to_string(steps) +
           " steps on " + std::to_string(threads) + (threads == 1 ? " thread" : " threads") + ", step " +
           fixed(stepSeconds * 1e3) + " ms; longest: " + longest + "; start-up (the first " + fixed(startUp) +
           " s of frames): " + std::to_string(first.size()) + " frames, longest " + fixed(firstLongest) + " ms\n";
}

} // namespace

// --measure-frames: plays with the turntable on (so every frame is drawn anew) and on
// through the health check's pauses, then prints the frame times and quits. The frames of
// the first half second (shaders compiled, buffers made, the window mapped) are reported
// apart as the start-up; the figures are those of the playing that follows, with the
// moments of its longest intervals. The run's own options come from --scene and --set.
void measureFrames(ab::ui::MainWindow& window, double seconds)
{
    auto* samples = new std::vector<Sample>;
    auto* clock = new QElapsedTimer;
    ab::ui::BallView* view = window.view();
    if (!view) {
        std::fprintf(
            stderr, "amazeballs: %s\n",
            qPrintable(QApplication::translate("main", "--measure-frames needs the 3D view (an OpenGL platform)")));
        QTimer::singleShot(0, qApp, [] { QCoreApplication::exit(2); });
        return;
    }
    QObject::connect(view, &ab::ui::BallView::framePainted, view, [samples, clock](double paint, double interval) {
        samples->push_back({double(clock->nsecsElapsed()) / 1e9, paint, interval});
    });
    window.setTurntable(true);
    clock->start();
    window.controller().play();
    // A measurement plays on through the health check's pauses (it still reports them).
    QObject::connect(&window.controller(), &ab::ui::RunController::playingChanged, &window, [&window](bool playing) {
        if (!playing && window.controller().status().pausedOnHealth)
            window.controller().play();
    });
    const double cpuStart = drawingCpuSeconds();
    QTimer::singleShot(int(seconds * 1000), qApp, [samples, clock, &window, cpuStart] {
        constexpr double startUp = 0.5; // seconds from the first frame
        const double cpu = drawingCpuSeconds() - cpuStart;
        const auto st = window.controller().status();
        const std::string line =
            frameSummary(*samples, startUp, cpu, st.steps, st.stepSeconds, window.controller().spec().threads);
        std::fputs(line.c_str(), stdout);
        delete samples;
        delete clock;
        QCoreApplication::quit();
    });
}

} // namespace ab::app
