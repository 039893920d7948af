// SPDX-License-Identifier: MIT
// `bench`: cost per ball-step of the many-balls scene on the benchmark workload
// (core/physical/many_balls_physical.h): `--repeats` runs from the workload's start, each
// 100 warm-up steps then `--steps` timed steps; the median run per ball and step.
// `--set NAME=VALUE` sets the rough balls' constants of the physical model (mu, beta,
// inertia, spin: docs/spin.md) on the same workload. `--scene street` times the street
// (core/street/street_engine.h) with its defaults from the hopper's release: 100 warm-up
// steps (1.7 s: the balls have landed and roll down block 1), then the timed steps.
#include "commands.h"

#include "bench_protocol.h"
#include "interrupt.h"

#include "../../core/io/atomic_file.h"
#include "../../core/physical/many_balls_physical.h"
#include "../../core/street/street_engine.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <ostream>

namespace ab::cli {

namespace {

constexpr int kWarmupSteps = 100;
constexpr int kAllPairsMax = 20'000;       // largest N the O(N^2) search is run for on request
constexpr int kAllPairsDefaultMax = 1'000; // ... and when no broadphase is named
const std::vector<int> kDefaultBalls{150, 1'000, 10'000, 100'000, 1'000'000};
const std::vector<int> kDefaultStreetBalls{10'000, 50'000, 250'000};

struct Case {
    SceneId scene;
    int balls;
    ModelKind model;
    Broadphase broadphase;
    int threads;
};

struct Row {
    Case c;
    BallStepTiming timing;
    std::optional<double> engineMiB; // physical model only
    double peakMiB = 0.0;
};

struct Options {
    std::vector<int> balls;
    std::vector<SceneId> scenes;
    std::optional<Broadphase> broadphase;
    ModelKind model = ModelKind::Physical;
    int threads = 1;
    int steps = 200;
    int repeats = 3;
    std::optional<std::string> out, markdown;
    std::vector<std::string> assignments; // --set, friction constants only
};

// The constants of rough balls that --set may change; the workload fixes everything else.
constexpr const char* kSettable[] = {"mu", "beta", "inertia", "spin"};

// Checks each --set against many-balls' table (range, form) and the keys bench takes.
std::vector<std::string> readAssignments(Parsed& args, ModelKind model, const std::vector<SceneId>& scenes)
{
    std::vector<std::string> out = args.options("set");
    if (std::find(scenes.begin(), scenes.end(), SceneId::Street) != scenes.end()) {
        if (scenes.size() > 1 && !out.empty())
            throw InputError("--set: give it with one --scene (its parameters differ)");
        RunSpec street(SceneId::Street);
        for (const std::string& a : out) {
            std::string key = a.substr(0, a.find('='));
            key.erase(0, key.find_first_not_of(" \t"));
            key.erase(key.find_last_not_of(" \t") + 1);
            if (key == "n")
                throw InputError("--set " + printableInput(a) + ": the street's ball count is --balls");
            street.params.parseAssignment(a); // names an unknown parameter or a bad value
        }
        return out;
    }
    RunSpec probe(SceneId::ManyBalls);
    probe.model = ModelKind::Physical;
    for (const std::string& a : out) {
        std::string key = a.substr(0, a.find('='));
        key.erase(0, key.find_first_not_of(" \t"));
        key.erase(key.find_last_not_of(" \t") + 1);
        if (std::find(std::begin(kSettable), std::end(kSettable), key) == std::end(kSettable))
            throw InputError("--set " + printableInput(a) +
                             ": bench sets only mu, beta, inertia and spin (the workload fixes the rest)");
        if (model != ModelKind::Physical)
            throw InputError("--set " + printableInput(a) + ": " + key +
                             " is a constant of the physical model; use it without --model report");
        probe.params.parseAssignment(a);
    }
    return out;
}

Options readOptions(Parsed& args)
{
    Options o;
    for (const std::string& text : args.options("balls")) {
        const long long n = parseInteger(text, "--balls");
        if (n < 1 || n > 4'000'000)
            throw InputError("--balls: " + std::to_string(n) + " is outside [1, 4000000]");
        o.balls.push_back(static_cast<int>(n));
    }
    if (o.balls.empty())
        o.balls = kDefaultBalls;
    if (const auto text = args.option("broadphase")) {
        o.broadphase = parseBroadphase(*text);
        if (!o.broadphase)
            throwUnknownValue("--broadphase", *text, valueWords(Values::Broadphase));
    }
    for (const std::string& text : args.options("scene")) {
        const SceneInfo* scene = findScene(text);
        if (!scene || (scene->id != SceneId::ManyBalls && scene->id != SceneId::Street))
            throw InputError("--scene: bench times many-balls and street, not '" + printableInput(text) + "'");
        if (std::find(o.scenes.begin(), o.scenes.end(), scene->id) == o.scenes.end())
            o.scenes.push_back(scene->id);
    }
    if (o.scenes.empty())
        o.scenes = {SceneId::ManyBalls};
    const bool street = std::find(o.scenes.begin(), o.scenes.end(), SceneId::Street) != o.scenes.end();
    if (args.options("balls").empty() && o.scenes == std::vector<SceneId>{SceneId::Street})
        o.balls = kDefaultStreetBalls;
    if (const auto text = args.option("model")) {
        const auto model = parseModel(*text);
        if (!model)
            throwUnknownValue("--model", *text, valueWords(Values::Model));
        o.model = *model;
    }
    o.threads = static_cast<int>(args.integer("threads", 1, ab::kMaxThreads).value_or(1));
    o.steps = static_cast<int>(args.integer("steps", 1, 1'000'000).value_or(o.steps));
    o.repeats = static_cast<int>(args.integer("repeats", 1, 99).value_or(o.repeats));
    o.out = args.option("out");
    o.markdown = args.option("markdown");
    o.assignments = readAssignments(args, o.model, o.scenes);
    if (street && (o.model != ModelKind::Physical || o.broadphase == Broadphase::AllPairs))
        throw InputError("--scene street: the street has the physical model and the grid only");
    if (o.model == ModelKind::Report && o.threads > 1)
        throw InputError("--threads: the report model updates its balls one after another on one thread; use "
                         "--threads 1 with --model report");
    if (o.broadphase == Broadphase::AllPairs)
        for (int n : o.balls)
            if (n > kAllPairsMax)
                throw InputError("--broadphase all-pairs: " + std::to_string(n) +
                                 " balls is too many for the O(N^2) "
                                 "search (at most " +
                                 std::to_string(kAllPairsMax) + "); use grid");
    return o;
}

// The cases in the order they run: each N with the grid, then all-pairs where it is asked
// for or, by default, small enough.
std::vector<Case> casesOf(const Options& o, std::ostream& err)
{
    std::vector<Case> cases;
    for (int n : o.balls)
        for (SceneId scene : o.scenes) {
            if (scene == SceneId::Street) {
                cases.push_back({scene, n, ModelKind::Physical, Broadphase::Grid, o.threads});
                continue;
            }
            if (!o.broadphase || *o.broadphase == Broadphase::Grid)
                cases.push_back({scene, n, o.model, Broadphase::Grid, o.threads});
            if (o.broadphase == Broadphase::AllPairs)
                cases.push_back({scene, n, o.model, Broadphase::AllPairs, o.threads});
            else if (!o.broadphase && n <= kAllPairsDefaultMax)
                cases.push_back({scene, n, o.model, Broadphase::AllPairs, o.threads});
            else if (!o.broadphase)
                err << "bench: all-pairs skipped for " << n << " balls (O(N^2); at most " << kAllPairsDefaultMax
                    << " by default, " << kAllPairsMax << " with --broadphase all-pairs)\n";
        }
    return cases;
}

// The street from its hopper's release, its defaults but n and the --set values; the engine
// steps in place.
Row measureStreet(const Case& c, const Options& o)
{
    RunSpec spec(SceneId::Street);
    spec.params.set("n", Eigen::Vector3d(c.balls, 0.0, 0.0));
    for (const std::string& a : o.assignments)
        spec.params.parseAssignment(a);
    spec.threads = c.threads;
    sceneInfo(SceneId::Street).crossCheck(spec.params);
    const double dt = defaultDt(SceneId::Street, ModelKind::Physical);
    const street::Layout layout = street::Layout::fromParams(spec.params);
    const street::Settings settings = street::Settings::fromSpec(spec, dt);
    const State start = street::hopperStart(layout, settings);
    street::Engine engine(layout, settings);
    Row row{c, {}, std::nullopt, 0.0};
    row.timing = timeBallSteps(
        c.balls, kWarmupSteps, o.steps, o.repeats, [&] { engine.load(start); }, [&] { engine.step(); },
        throwIfInterrupted);
    row.engineMiB = static_cast<double>(engine.bytes()) / (1024.0 * 1024.0);
    row.peakMiB = peakResidentMiB();
    return row;
}

Row measure(const Case& c, const Options& o)
{
    if (c.scene == SceneId::Street)
        return measureStreet(c, o);
    RunSpec spec = physical::benchmarkSpec(c.balls, c.model, c.broadphase, c.threads);
    for (const std::string& a : o.assignments)
        spec.params.parseAssignment(a);
    if (const double spin = spec.params.real("spin"); spin > 0.0)
        physical::randomSpins(*spec.init, spin, static_cast<std::uint64_t>(spec.params.integer("seed")));
    Row row{c, {}, std::nullopt, 0.0};
    if (c.model == ModelKind::Physical) {
        // The engine steps in place: the cost of the simulation itself, without the copy
        // into a State that the Simulation interface adds.
        physical::ManyBallsEngine engine(physical::ManyBallsSettings::fromSpec(spec, *spec.dt));
        row.timing = timeBallSteps(
            c.balls, kWarmupSteps, o.steps, o.repeats, [&] { engine.load(*spec.init); }, [&] { engine.step(); },
            throwIfInterrupted);
        row.engineMiB = static_cast<double>(engine.bytes()) / (1024.0 * 1024.0);
    } else {
        const auto sim = makeSimulation(spec);
        State s, next;
        row.timing = timeBallSteps(
            c.balls, kWarmupSteps, o.steps, o.repeats, [&] { s = sim->start(); },
            [&] {
                sim->step(s, next);
                std::swap(s, next);
            },
            throwIfInterrupted);
    }
    row.peakMiB = peakResidentMiB();
    return row;
}

std::string number(double x, const char* format)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, x);
    return buffer;
}

void writeCsv(std::ostream& out, const std::vector<Row>& rows)
{
    out << "balls,broadphase,threads,ns_per_ball_step,steps_per_second,model,cpu_ns_per_ball_step,engine_mib,"
           "peak_rss_mib,scene\n";
    for (const Row& r : rows)
        out << r.c.balls << "," << broadphaseKey(r.c.broadphase) << "," << r.c.threads << ","
            << number(r.timing.nsPerBallStep, "%.4g") << "," << number(r.timing.stepsPerSecond, "%.4g") << ","
            << modelKey(r.c.model) << "," << number(r.timing.cpuNsPerBallStep, "%.4g") << ","
            << (r.engineMiB ? number(*r.engineMiB, "%.1f") : "") << "," << number(r.peakMiB, "%.1f") << ","
            << sceneInfo(r.c.scene).key << "\n";
}

void writeMarkdown(std::ostream& out, const std::vector<Row>& rows, const Options& o)
{
    out << "| scene | balls | model | broadphase | threads | ns per ball-step | steps per second | CPU ns per "
           "ball-step | "
           "engine MiB | peak RSS MiB |\n"
           "| --- | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const Row& r : rows)
        out << "| " << sceneInfo(r.c.scene).key << " | " << r.c.balls << " | " << modelKey(r.c.model) << " | "
            << broadphaseKey(r.c.broadphase) << " | " << r.c.threads << " | " << number(r.timing.nsPerBallStep, "%.1f")
            << " | " << number(r.timing.stepsPerSecond, "%.4g") << " | " << number(r.timing.cpuNsPerBallStep, "%.1f")
            << " | " << (r.engineMiB ? number(*r.engineMiB, "%.1f") : "-") << " | " << number(r.peakMiB, "%.0f")
            << " |\n";
    out << "\n"
        << "The median of " << o.repeats << " runs from the start, each " << kWarmupSteps << " warm-up steps then "
        << o.steps
        << " timed steps. ns per ball-step is wall time; CPU ns is the process's CPU time over the same steps, all "
           "threads together.";
    for (const std::string& a : o.assignments)
        out << " --set " << a;
    out << "\n";
}

} // namespace

int benchCommand(Parsed& args, std::ostream& out, std::ostream& err)
{
    const Options o = readOptions(args);
    if (o.out)
        checkWritable(*o.out);
    if (o.markdown)
        checkWritable(*o.markdown);
    std::vector<Row> rows;
    for (const Case& c : casesOf(o, err)) {
        rows.push_back(measure(c, o));
        const Row& r = rows.back();
        if (o.out) // progress; the CSV goes to the file
            out << sceneInfo(r.c.scene).key << ", " << r.c.balls << " balls, " << modelKey(r.c.model) << ", "
                << broadphaseKey(r.c.broadphase) << ", " << r.c.threads
                << " thread(s): " << number(r.timing.nsPerBallStep, "%.1f") << " ns per ball-step, "
                << number(r.timing.stepsPerSecond, "%.4g") << " steps per second, "
                << number(r.timing.cpuNsPerBallStep, "%.1f") << " ns CPU" << std::endl;
    }
    if (o.out)
        writeFileAtomically(*o.out, [&](std::ostream& file) { writeCsv(file, rows); });
    else
        writeCsv(out, rows);
    if (o.markdown)
        writeFileAtomically(*o.markdown, [&](std::ostream& file) { writeMarkdown(file, rows, o); });
    return 0;
}

} // namespace ab::cli
