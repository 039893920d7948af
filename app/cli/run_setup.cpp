// SPDX-License-Identifier: MIT
#include "run_setup.h"

#include "suggest.h"

#include "../../core/io/preset.h"
#include "../../core/io/trajectory_csv.h"

#include <cmath>

namespace ab::cli {

namespace {

template <typename E>
E readEnum(Parsed& args, const std::string& name, std::optional<E> (*parse)(std::string_view), E fallback,
           Values choices)
{
    const auto text = args.option(name);
    if (!text)
        return fallback;
    const auto value = parse(*text);
    if (!value)
        throwUnknownValue("--" + name, *text, valueWords(choices));
    return *value;
}

constexpr long long kMaxSteps = 4'000'000'000LL;

// The run's length: --steps, or the whole steps of --dt to reach --t-end, or the preset's
// or scene's; a length of no step, or of more than kMaxSteps, is refused.
long long readSteps(Parsed& args, const RunSpec& spec, std::optional<long long> presetSteps)
{
    const auto steps = args.integer("steps", 1, kMaxSteps);
    const auto tEnd = args.real("t-end");
    if (steps && tEnd)
        throw InputError("--steps and --t-end: give one of them, not both");
    if (steps)
        return *steps;
    if (!tEnd)
        return presetSteps.value_or(defaultSteps(spec.scene, spec.model));
    const double dt = spec.dt.value_or(defaultDt(spec.scene, spec.model));
    const double start = spec.init ? spec.init->t : 0.0;
    if (*tEnd <= start)
        throw InputError("--t-end: " + formatNumber(*tEnd) + " is not after the start time " + formatNumber(start) +
                         " (a run needs at least one step)");
    // Whole steps to reach t-end; a ratio within round-off of an integer is that integer.
    // Compared as a double before any conversion: a ratio beyond the limit (or infinite)
    // has no integer to convert to.
    const double n = (*tEnd - start) / dt;
    if (!(n <= static_cast<double>(kMaxSteps)))
        throw InputError("--t-end: " + formatNumber(*tEnd) + " needs more than 4e9 steps of " + formatNumber(dt));
    const double rounded = std::round(n);
    const double whole = std::abs(n - rounded) < 1e-9 * std::max(1.0, n) ? rounded : std::ceil(n);
    if (whole < 1.0 || start + dt == start)
        throw InputError("--t-end: " + formatNumber(*tEnd) + " gives no step of " + formatNumber(dt) +
                         " from the start time " + formatNumber(start));
    return static_cast<long long>(whole);
}

} // namespace

const SceneInfo* readSceneOperand(Parsed& args)
{
    const std::vector<std::string> keys = valueWords(Values::Scene);
    const std::string key = args.positional("SCENE (one of " + joined(keys) + ")");
    const SceneInfo* info = findScene(key);
    if (!info)
        throw InputError("unknown scene '" + printableInput(key) + "'" + nearOrChoices(key, keys));
    return info;
}

void applyAssignment(RunSpec& spec, const std::string& assignment)
{
    const std::string name(assignmentName(assignment));
    if (!name.empty() && !spec.params.indexOf(name)) {
        const std::string near = didYouMean(name, sceneInfo(spec.scene).paramKeys());
        throw InputError("--set: unknown parameter '" + printableInput(name) + "' for " + sceneInfo(spec.scene).key +
                         (near.empty() ? " (amazeballs-cli list names them)" : near));
    }
    spec.params.parseAssignment(assignment);
}

RunSetup readRunSetup(Parsed& args)
{
    const SceneInfo* info = readSceneOperand(args);
    RunSetup setup{RunSpec(info->id), 0, std::nullopt};
    RunSpec& spec = setup.spec;

    std::optional<long long> presetSteps;
    if (const auto preset = args.option("preset")) {
        const Preset p = loadPreset(*preset);
        applyPreset(p, spec);
        presetSteps = p.steps;
        setup.presetKey = *preset;
    }
    spec.model = readEnum(args, "model", parseModel, spec.model, Values::Model);
    spec.integrator = readEnum(args, "integrator", parseIntegrator, spec.integrator, Values::Integrator);
    spec.impacts = readEnum(args, "impacts", parseImpactMode, spec.impacts, Values::Impacts);
    spec.broadphase = readEnum(args, "broadphase", parseBroadphase, spec.broadphase, Values::Broadphase);
    if (const auto t = args.integer("threads", 1, ab::kMaxThreads))
        spec.threads = static_cast<int>(*t);
    if (const auto dt = args.real("dt")) {
        if (*dt <= 0.0)
            throw InputError("--dt: " + formatNumber(*dt) + " must be positive");
        spec.dt = *dt;
    }
    std::optional<std::string> setN; // the --set that gave n, if one did
    for (const std::string& assignment : args.options("set")) {
        applyAssignment(spec, assignment);
        if (assignmentName(assignment) == "n")
            setN = assignment;
    }
    if (const auto init = args.option("init")) {
        State s = readFirstState(*init);
        if (info->ballCount == 0) {
            if (!spec.params.indexOf("n"))
                throw std::logic_error("scene with a variable ball count but no n");
            if (setN && spec.params.integer("n") != s.size())
                throw InputError("--set " + printableInput(*setN) + ": --init " + printableInput(*init) + " has " +
                                 std::to_string(s.size()) + " balls; give one or the other");
            spec.params.set("n", Eigen::Vector3d(s.size(), 0.0, 0.0));
        }
        spec.init = std::move(s);
    }
    setup.steps = readSteps(args, spec, presetSteps);
    return setup;
}

std::optional<std::string> largeTrajectoryNote(long long balls, long long steps, long long every, bool spin)
{
    const long long rows = balls * (steps / every + 1);
    const double megabytes = double(rows) * 18.0 * (spin ? 11.0 : 8.0) / 1e6;
    if (megabytes < 100.0)
        return std::nullopt;
    // Two significant figures: 594 reads "590".
    const double scale = std::pow(10.0, std::floor(std::log10(megabytes)) - 1.0);
    return "about " + formatNumber(std::round(megabytes / scale) * scale) + " MB of CSV (" + std::to_string(rows) +
           " rows: every ball at every " + (every > 1 ? "recorded " : "") +
           "step); --every K writes every K-th step, --summary a few lines";
}

} // namespace ab::cli
