// SPDX-License-Identifier: MIT
// `chart`: the window's chart of one ball (position, velocity, the difference between
// two runs) or of the scene (energy, momentum, activity), built from the same recipe the
// window exports (ui/charts/chart_recipe.h): closed form and comparison included, at a
// size for where the figure goes, as PNG, SVG or PDF, optionally with a caption; and the
// chart-data CSV the window writes (--data).
#include "commands.h"
#include "suggest.h"

#include "interrupt.h"
#include "run_setup.h"

#include "../../core/diagnostics/conservation.h"
#include "../../core/io/atomic_file.h"
#include "../../core/reference/reference.h"
#include "../../core/street/street_layout.h"
#include "../../ui/charts/chart_data_csv.h"
#include "../../ui/charts/chart_recipe.h"
#include "../../ui/charts/headless_app.h"
#include "../../ui/charts/run_description.h"
#include "../../ui/charts/street_sample.h"

#include <QFileInfo>
#include <QGuiApplication>

#include <cmath>
#include <limits>
#include <optional>
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

ui::ChartKind readChartKind(Parsed& args)
{
    const auto key = args.option("chart");
    if (!key)
        throw InputError("chart: missing --chart (one of " + chartKeys() + ")");
    const auto kind = ui::parseChartKind(*key);
    if (!kind)
        throw InputError("--chart: unknown chart '" + printableInput(*key) + "'" +
                         nearOrChoices(*key, valueWords(Values::Chart)));
    return *kind;
}

std::string readImagePath(Parsed& args)
{
    const auto path = args.option("out");
    if (!path)
        throw InputError("chart: missing --out FILE.png, FILE.svg or FILE.pdf");
    ui::checkFigurePath(QString::fromStdString(*path), "--out");
    checkWritable(*path); // fail before a long run, not after
    return *path;
}

ui::FigureOptions readFigureOptions(Parsed& args)
{
    ui::FigureOptions options;
    const auto size = args.option("size");
    const auto width = args.integer("width", 200, 8000);
    const auto height = args.integer("height", 150, 8000);
    if (size && (width || height))
        throw InputError("--size: give either --size or --width/--height, not both");
    if (size)
        options.size = ui::parseFigureSize(*size, "--size");
    else if (width || height)
        options.size = ui::pixelFigureSize(int(width.value_or(1200)), int(height.value_or(800)));
    if (const auto dpi =
            args.integer("dpi", std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max())) {
        ui::checkDpi(*dpi);
        options.dpi = int(*dpi);
    }
    ui::checkChartRoom(options, size || !(width || height) ? "--size" : "--width/--height");
    return options;
}

// MODEL[:INTEGRATOR[:IMPACTS]], as the window's comparison (the main run's step).
std::optional<RunVariant> readComparison(Parsed& args)
{
    const auto text = args.option("compare");
    if (!text)
        return std::nullopt;
    std::vector<std::string> parts;
    std::string_view rest = *text;
    for (std::size_t colon; (colon = rest.find(':')) != std::string_view::npos; rest.remove_prefix(colon + 1))
        parts.emplace_back(rest.substr(0, colon));
    parts.emplace_back(rest);
    const std::string bad = "--compare: '" + printableInput(*text) + "'";
    if (parts.size() > 3)
        throw InputError(bad + " has too many parts (MODEL[:INTEGRATOR[:IMPACTS]])");
    RunVariant v;
    const auto model = parseModel(parts[0]);
    if (!model)
        throw InputError(bad + ": unknown model '" + printableInput(parts[0]) + "'" +
                         nearOrChoices(parts[0], valueWords(Values::Model)));
    v.model = *model;
    if (parts.size() > 1) {
        const auto integrator = parseIntegrator(parts[1]);
        if (!integrator)
            throw InputError(bad + ": unknown integrator '" + printableInput(parts[1]) + "'" +
                             nearOrChoices(parts[1], valueWords(Values::Integrator)));
        v.integrator = *integrator;
    }
    if (parts.size() > 2) {
        const auto impacts = parseImpactMode(parts[2]);
        if (!impacts)
            throw InputError(bad + ": unknown impacts '" + printableInput(parts[2]) + "'" +
                             nearOrChoices(parts[2], valueWords(Values::Impacts)));
        v.impacts = *impacts;
    }
    return v;
}

// Every state of the run into the chart's track, up to the first non-finite one.
ui::MotionTrack simulate(Simulation& sim, long long steps, int ball, std::ostream& err)
{
    const ConservationMeter meter(sim);
    ui::MotionTrack track;
    long long index = 0;
    bool healthy = true;
    // The street's charts (foot rate, speeds) read its layout at every state, and the
    // selected ball's lines end where it leaves at the foot.
    const std::optional<street::Layout> layout = sim.spec().scene == SceneId::Street
                                                     ? std::optional(street::Layout::fromParams(sim.spec().params))
                                                     : std::nullopt;
    runRecorded(
        sim, sim.start(), steps, 1,
        [&](const State& s) {
            healthy = healthy && s.p.allFinite() && s.v.allFinite();
            if (!healthy)
                return;
            ui::addState(track, index++, s, ball, meter.measure(s), layout ? &*layout : nullptr);
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

// The comparison run of `variant`, checked to start with the main run's balls.
std::unique_ptr<Simulation> comparisonOf(const RunSpec& spec, const State& start, const RunVariant& variant)
{
    std::unique_ptr<Simulation> other;
    try {
        other = makeSimulation(variantOf(spec, variant));
    } catch (const InputError& e) {
        throw InputError("--compare: " + std::string(e.what()));
    }
    if (other->start().t != start.t || other->start().size() != start.size())
        throw InputError("--compare: the two runs do not start at the same time with the same balls");
    return other;
}

// Steps of `other` that reach the main run's `steps`: steps dt / dt_c, rounded up (the
// allowance keeps 2000 * 1 / 1 from becoming 2001).
long long stepsToReach(const Simulation& sim, const Simulation& other, long long steps)
{
    const double ratio = sim.dt() / other.dt();
    return static_cast<long long>(std::ceil(static_cast<double>(steps) * ratio - 1e-9 * std::max(ratio, 1.0)));
}

// The closed form the window draws: none for a run from a given state, or for a ball or
// constants it does not cover.
std::unique_ptr<reference::Reference> closedFormOf(const RunSpec& spec, double tEnd, int ball)
{
    std::unique_ptr<reference::Reference> ref;
    if (spec.init)
        return ref;
    try {
        ref = reference::makeReference(spec, tEnd);
    } catch (const InputError&) {
    }
    if (ref && ball >= ref->balls())
        ref.reset();
    return ref;
}

ui::ReferenceMotion motionOf(const reference::Reference& r, int ball)
{
    const reference::Reference* ref = &r;
    return ui::ReferenceMotion{ui::RunDescription::tr("closed form"),
                               [ref, ball](double t) -> std::optional<ui::Kinematics> {
                                   ui::Kinematics k{ref->position(ball, t), ref->velocity(ball, t)};
                                   if (!k.p.allFinite() || !k.v.allFinite())
                                       return std::nullopt; // never drawn
                                   return k;
                               }};
}

void checkApplies(ui::ChartKind kind, const RunSpec& spec)
{
    if (ui::chartApplies(kind, spec))
        return;
    const std::string key = sceneInfo(spec.scene).key;
    if (kind == ui::ChartKind::Spin)
        throw InputError("--chart: the spin chart needs balls that turn: --model physical with mu > 0 and beta > -1, "
                         "or a start spin (w0, w1, w2, spin)");
    const bool street = kind == ui::ChartKind::FootRate || kind == ui::ChartKind::Speeds;
    throw InputError("--chart: the " + std::string(ui::chartKey(kind)) + " chart is for " +
                     (kind == ui::ChartKind::Momentum ? "two-balls and many-balls"
                      : street                        ? "the street"
                                                      : "many-balls") +
                     " only, not " + key);
}

struct ChartRequest {
    explicit ChartRequest(RunSetup s) : setup(std::move(s)) {}
    RunSetup setup;
    ui::ChartKind kind = ui::ChartKind::Position;
    std::string path;
    long long ballNumber = 1;
    ui::FigureOptions options;
    bool caption = false;
    std::optional<RunVariant> variant;
    std::optional<std::string> dataPath;
};

// Every option, checked before anything runs (an output that cannot be written, a size
// too large for a PNG, a chart the scene does not have).
ChartRequest readRequest(Parsed& args)
{
    ChartRequest r(readRunSetup(args));
    r.kind = readChartKind(args);
    r.path = readImagePath(args);
    r.ballNumber = args.integer("ball", 1, 4'000'000).value_or(1);
    r.options = readFigureOptions(args);
    r.caption = args.flag("caption");
    r.variant = readComparison(args);
    r.dataPath = args.option("data");
    if (QFileInfo(QString::fromStdString(r.path)).suffix().toLower() == "png")
        (void)r.options.pngPixels(); // a size too large for a PNG: refused before the run
    if (r.dataPath) {
        if (QFileInfo(QString::fromStdString(*r.dataPath)).suffix().toLower() != "csv")
            throw InputError("--data: " + printableInput(*r.dataPath) + " must end in .csv");
        checkWritable(*r.dataPath);
    }
    checkApplies(r.kind, r.setup.spec);
    return r;
}

} // namespace

int chartCommand(Parsed& args, std::ostream&, std::ostream& err)
{
    const ChartRequest request = readRequest(args);
    const RunSetup& setup = request.setup;
    const ui::ChartKind kind = request.kind;
    const long long ballNumber = request.ballNumber;
    const std::optional<RunVariant>& variant = request.variant;
    const std::optional<std::string>& dataPath = request.dataPath;
    const ui::FigureOptions& options = request.options;
    const auto sim = makeSimulation(setup.spec);
    const State start = sim->start();
    if (ballNumber > start.size())
        throw InputError("--ball: " + std::to_string(ballNumber) + " is outside [1, " + std::to_string(start.size()) +
                         "] (" + sim->scene().key + " has " + std::to_string(start.size()) + " ball(s))");
    const int ball = static_cast<int>(ballNumber - 1);
    const std::unique_ptr<Simulation> other = variant ? comparisonOf(setup.spec, start, *variant) : nullptr;
    const double tEnd = std::max(sim->dt() * static_cast<double>(setup.steps), sim->dt());
    const std::unique_ptr<reference::Reference> ref = closedFormOf(setup.spec, tEnd, ball);
    if (kind == ui::ChartKind::Difference && !ui::differenceDrawable(bool(other), bool(ref)))
        throw InputError("--chart: the difference chart needs --compare (or a scene with a closed form)");

    ui::ensureGuiApplication();
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        throw std::logic_error("chart: the process has a QCoreApplication; charts need a QApplication");
    const ui::MotionTrack track = simulate(*sim, setup.steps, ball, err);
    std::optional<ui::MotionTrack> compareTrack;
    if (other) // as many steps as reach the main run's end (as the window's comparison)
        compareTrack = simulate(*other, stepsToReach(*sim, *other, setup.steps), ball, err);
    const ConservationMeter meter(*sim);
    ui::ChartRecipe recipe;
    recipe.kind = kind;
    recipe.scene = &sim->scene();
    recipe.ball = ball;
    recipe.units = ui::chartUnitsOf(meter, setup.spec);
    recipe.tEnd = tEnd;
    recipe.run = &track;
    recipe.runName = QString::fromStdString(
        variantLabel(RunVariant{setup.spec.model, setup.spec.integrator, setup.spec.impacts, setup.spec.dt}));
    if (compareTrack) {
        recipe.comparison = &*compareTrack;
        recipe.comparisonName = QString::fromStdString(variantLabel(*variant));
    }
    const reference::Reference* r = ref.get();
    if (r)
        recipe.closedForm = motionOf(*r, ball);
    const ui::RunFacts facts{&sim->spec(), sim->dt()};
    const ui::RunFacts compareFacts{other ? &other->spec() : nullptr, other ? other->dt() : 0.0};
    if (request.caption)
        recipe.caption = ui::RunDescription::caption(facts, other ? &compareFacts : nullptr, bool(r));
    ui::exportChartFigure(recipe, QString::fromStdString(request.path), options);
    if (dataPath) {
        ui::ChartData data;
        data.run = &track;
        data.axes = sim->scene().axes;
        data.ball = ball;
        data.comparison = recipe.comparison;
        data.closedForm = recipe.closedForm ? &*recipe.closedForm : nullptr;
        data.timeUnit = sim->scene().timeUnit;
        data.lengthUnit = sim->scene().lengthUnit;
        data.perUnitMass = recipe.units.perUnitMass;
        data.spins = recipe.units.spins;
        data.streetBlocks = recipe.units.streetBlocks;
        data.comments =
            ui::RunDescription::comments(facts, other ? &compareFacts : nullptr, bool(r), ball, start.size());
        writeFileAtomically(*dataPath, [&](std::ostream& out) { ui::writeChartCsv(out, data); });
    }
    return 0;
}

} // namespace ab::cli
