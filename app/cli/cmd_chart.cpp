// SPDX-License-Identifier: MIT
// `chart`: the window's position or velocity chart of one ball, or its energy, momentum
// or activity chart of the scene, rendered headless from the same chart code (no
// OpenGL), as PNG or SVG.
#include "commands.h"

#include "interrupt.h"
#include "run_setup.h"

#include "../../core/diagnostics/conservation.h"
#include "../../core/io/atomic_file.h"
#include "../../ui/charts/chart_export.h"
#include "../../ui/charts/headless_app.h"
#include "../../ui/charts/motion_chart.h"

#include <QFileInfo>
#include <QGuiApplication>

#include <cmath>
#include <ostream>

namespace ab::cli {

namespace {

std::string chartKeys()
{
    std::string keys;
    for (ui::ChartKind k : ui::allChartKinds())
        keys += (keys.empty() ? "" : ", ") + std::string(ui::chartKey(k));
    return keys;
}

ui::ChartKind readChartKind(Args& args)
{
    const auto key = args.option("chart");
    if (!key)
        throw InputError("chart: missing --chart (one of " + chartKeys() + ")");
    const auto kind = ui::parseChartKind(*key);
    if (!kind)
        throw InputError("--chart: unknown chart '" + printableInput(*key) + "' (choose " + chartKeys() + ")");
    return *kind;
}

std::string readImagePath(Args& args)
{
    const auto path = args.option("out");
    if (!path)
        throw InputError("chart: missing --out FILE.png or FILE.svg");
    const QString suffix = QFileInfo(QString::fromStdString(*path)).suffix().toLower();
    if (suffix != "png" && suffix != "svg")
        throw InputError("--out: " + printableInput(*path) + " must end in .png or .svg");
    checkWritable(*path); // fail before a long run, not after
    return *path;
}

QSize readSize(Args& args)
{
    const long long width = args.integer("width", 200, 8000).value_or(1200);
    const long long height = args.integer("height", 150, 8000).value_or(800);
    return QSize(static_cast<int>(width), static_cast<int>(height));
}

// Every state of the run into the chart's track, up to the first non-finite one.
ui::MotionTrack simulate(Simulation& sim, const RunSetup& setup, int ball, std::ostream& err)
{
    const ConservationMeter meter(sim);
    ui::MotionTrack track;
    long long index = 0;
    bool healthy = true;
    runRecorded(
        sim, sim.start(), setup.steps, 1,
        [&](const State& s) {
            healthy = healthy && s.p.allFinite() && s.v.allFinite();
            if (!healthy)
                return;
            track.add(index++, s.t, s.p.col(ball), s.v.col(ball), meter.measure(s));
        },
        [&] { return !healthy || interrupted(); });
    throwIfInterrupted();
    if (!healthy) {
        const double last = track.empty() ? sim.start().t : track.t().back();
        err << "amazeballs-cli: chart: warning: the state became non-finite "
            << (track.empty()         ? "at the start"
                : std::isfinite(last) ? "after t = " + formatNumber(last)
                                      : std::string("once the time itself overflowed"))
            << "; the chart ends there\n";
    }
    return track;
}

} // namespace

int chartCommand(Args& args, std::ostream&, std::ostream& err)
{
    const RunSetup setup = readRunSetup(args);
    const ui::ChartKind kind = readChartKind(args);
    const std::string path = readImagePath(args);
    const long long ballNumber = args.integer("ball", 1, 4'000'000).value_or(1);
    const QSize size = readSize(args);
    args.finish();

    if (!ui::chartApplies(kind, setup.spec.scene)) {
        const std::string scene = sceneInfo(setup.spec.scene).key;
        throw InputError("--chart: the " + std::string(ui::chartKey(kind)) + " chart is for " +
                         (kind == ui::ChartKind::Momentum ? "two-balls and many-balls" : "many-balls") + " only, not " +
                         scene);
    }
    const auto sim = makeSimulation(setup.spec);
    const State start = sim->start();
    if (ballNumber > start.size())
        throw InputError("--ball: " + std::to_string(ballNumber) + " is outside [1, " + std::to_string(start.size()) +
                         "] (" + sim->scene().key + " has " + std::to_string(start.size()) + " ball(s))");
    const int ball = static_cast<int>(ballNumber - 1);

    ui::ensureGuiApplication();
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        throw std::logic_error("chart: the process has a QCoreApplication; charts need a QApplication");
    const ui::MotionTrack track = simulate(*sim, setup, ball, err);
    ui::MotionChart chart(kind);
    const ConservationMeter meter(*sim);
    chart.configure(sim->scene(), ball, ui::ChartUnits{meter.perUnitMass(), meter.hasSpring()});
    chart.setTimeSpan(std::max(sim->dt() * static_cast<double>(setup.steps), sim->dt()));
    chart.showTrack(track, size.width());
    ui::exportChart(&chart, QString::fromStdString(path), size);
    return 0;
}

} // namespace ab::cli
