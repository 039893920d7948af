// SPDX-License-Identifier: MIT
// `study`: error against run time of the physical model's integrators, measured against
// the scene's closed form (core/study). Writes a CSV, a Markdown report (stdout without
// --markdown) and the work-precision chart; progress goes to stderr. Every output is
// written only once the study is complete, so Ctrl+C leaves no file behind.
#include "commands.h"

#include "interrupt.h"
#include "run_setup.h"

#include "../../core/io/atomic_file.h"
#include "../../core/io/preset.h"
#include "../../core/study/study.h"
#include "ui/charts/chart_export.h"
#include "ui/charts/headless_app.h"
#include "ui/charts/work_precision_chart.h"

#include <QChart>
#include <QFileInfo>

#include <cmath>
#include <iomanip>
#include <ostream>

namespace ab::cli {

namespace {

RunSpec readScene(Parsed& args)
{
    const SceneInfo* info = readSceneOperand(args);
    RunSpec spec(info->id);
    if (const auto preset = args.option("preset"))
        applyPreset(loadPreset(*preset), spec);
    for (const std::string& assignment : args.options("set"))
        applyAssignment(spec, assignment);
    spec.model = ModelKind::Physical;
    return spec;
}

double positiveOption(Parsed& args, const std::string& name, double fallback)
{
    const auto value = args.real(name);
    if (value && !(*value > 0.0))
        throw InputError("--" + name + ": " + formatNumber(*value) + " must be positive");
    return value.value_or(fallback);
}

void readSweep(Parsed& args, study::Options& o)
{
    o.tEnd = positiveOption(args, "t-end", o.tEnd);
    const double dtMax = positiveOption(args, "dt-max", o.dts.front());
    const double dtMin = positiveOption(args, "dt-min", o.dts.back());
    if (dtMin > dtMax)
        throw InputError("--dt-min: " + formatNumber(dtMin) + " is larger than --dt-max " + formatNumber(dtMax));
    const int perDecade = static_cast<int>(args.integer("per-decade", 1, 20).value_or(3));
    o.dts = study::logSweep(dtMax, dtMin, perDecade);
    if (o.dts.size() > 200)
        throw InputError("--dt-min: " + formatNumber(dtMin) + " to " + formatNumber(dtMax) + " at " +
                         std::to_string(perDecade) + " per decade is more than 200 steps to try");
    if (o.tEnd / o.dts.back() > 1e9)
        throw InputError("--dt-min: " + formatNumber(dtMin) + " needs more than 1e9 steps to reach --t-end " +
                         formatNumber(o.tEnd));
    o.repeats = static_cast<int>(args.integer("repeats", 1, 100).value_or(o.repeats));
    o.impactIndex = static_cast<int>(args.integer("impact", 1, 100000).value_or(o.impactIndex));
}

void checkChartPath(const std::string& path)
{
    const std::string suffix = QFileInfo(QString::fromStdString(path)).suffix().toLower().toStdString();
    if (suffix != "png" && suffix != "svg")
        throw InputError("--chart: " + printableInput(path) +
                         (suffix.empty() ? std::string(": no image type")
                                         : ": unknown image type '" + printableInput(suffix) + "'") +
                         " (use .png or .svg)");
    checkWritable(path);
}

void reportRow(std::ostream& err, const std::string& scene, std::size_t done, std::size_t total, const study::Row& row)
{
    err << "study " << scene << ": " << done << "/" << total << "  " << std::left << std::setw(26) << row.method.label()
        << std::right << " dt " << std::setw(10) << formatNumber(row.dt) << "  error " << std::setw(9)
        << std::setprecision(2) << row.relativeError << " (relative)  " << std::setprecision(3) << row.cpuSeconds * 1e3
        << " ms\n";
    err.flush();
}

} // namespace

int studyCommand(Parsed& args, std::ostream& out, std::ostream& err)
{
    const RunSpec spec = readScene(args);
    study::Options options = study::defaultOptions(spec); // refuses scenes without a closed form
    readSweep(args, options);
    const auto csvPath = args.option("out");
    const auto chartPath = args.option("chart");
    const auto markdownPath = args.option("markdown");
    const bool quiet = args.flag("quiet");
    if (csvPath)
        checkWritable(*csvPath); // fail now, not after the study
    if (markdownPath)
        checkWritable(*markdownPath);
    if (chartPath)
        checkChartPath(*chartPath);

    const std::string scene = sceneInfo(spec.scene).key;
    const auto progress = [&](std::size_t done, std::size_t total, const study::Row& row) {
        if (!quiet)
            reportRow(err, scene, done, total, row);
    };
    const study::Result result = study::runStudy(options, progress, interrupted);
    throwIfInterrupted();
    if (!result.complete)
        throw Interrupted();

    if (csvPath)
        writeFileAtomically(*csvPath, [&](std::ostream& f) { study::writeCsv(f, result); });
    if (markdownPath)
        writeFileAtomically(*markdownPath, [&](std::ostream& f) { study::writeMarkdown(f, result); });
    else
        study::writeMarkdown(out, result);
    if (chartPath) {
        ui::ensureGuiApplication();
        const std::unique_ptr<QChart> chart = ui::makeWorkPrecisionChart(result);
        ui::exportChart(chart.get(), QString::fromStdString(*chartPath));
    }
    return 0;
}

} // namespace ab::cli
