// SPDX-License-Identifier: MIT
#include "run_setup.h"

#include "../../core/io/preset.h"
#include "../../core/io/trajectory_csv.h"

#include <cmath>

namespace ab::cli {

namespace {

std::string sceneKeys()
{
    std::string keys;
    for (const SceneInfo* s : allScenes())
        keys += (keys.empty() ? "" : ", ") + s->key;
    return keys;
}

template <typename E>
E readEnum(Args& args, const std::string& name, std::optional<E> (*parse)(std::string_view), E fallback,
           const char* choices)
{
    const auto text = args.option(name);
    if (!text)
        return fallback;
    const auto value = parse(*text);
    if (!value)
        throw InputError("--" + name + ": unknown value '" + printableInput(*text) + "' (choose " + choices + ")");
    return *value;
}

} // namespace

RunSetup readRunSetup(Args& args)
{
    const std::string sceneKey = args.positional("SCENE (one of " + sceneKeys() + ")");
    const SceneInfo* info = findScene(sceneKey);
    if (!info)
        throw InputError("unknown scene '" + printableInput(sceneKey) + "' (choose " + sceneKeys() + ")");
    RunSetup setup{RunSpec(info->id), 0, std::nullopt};
    RunSpec& spec = setup.spec;

    std::optional<long long> presetSteps;
    if (const auto preset = args.option("preset")) {
        const Preset p = loadPreset(*preset);
        applyPreset(p, spec);
        presetSteps = p.steps;
        setup.presetKey = *preset;
    }
    spec.model = readEnum(args, "model", parseModel, spec.model, "report, physical");
    std::string integrators;
    for (Integrator i : allIntegrators())
        integrators += (integrators.empty() ? "" : ", ") + std::string(integratorKey(i));
    spec.integrator = readEnum(args, "integrator", parseIntegrator, spec.integrator, integrators.c_str());
    spec.impacts = readEnum(args, "impacts", parseImpactMode, spec.impacts, "located, step-end");
    spec.broadphase = readEnum(args, "broadphase", parseBroadphase, spec.broadphase, "grid, all-pairs");
    if (const auto t = args.integer("threads", 1, 256))
        spec.threads = static_cast<int>(*t);
    if (const auto dt = args.real("dt")) {
        if (*dt <= 0.0)
            throw InputError("--dt: " + formatNumber(*dt) + " must be positive");
        spec.dt = *dt;
    }
    for (const std::string& assignment : args.options("set"))
        spec.params.parseAssignment(assignment);
    if (const auto init = args.option("init")) {
        State s = readFirstState(*init);
        if (info->ballCount == 0) {
            if (!spec.params.indexOf("n"))
                throw std::logic_error("scene with a variable ball count but no n");
            spec.params.set("n", Eigen::Vector3d(s.size(), 0.0, 0.0));
        }
        spec.init = std::move(s);
    }

    const auto steps = args.integer("steps", 0, 4'000'000'000LL);
    const auto tEnd = args.real("t-end");
    if (steps && tEnd)
        throw InputError("--steps and --t-end: give one of them, not both");
    const double dt = spec.dt.value_or(defaultDt(spec.scene, spec.model));
    if (steps) {
        setup.steps = *steps;
    } else if (tEnd) {
        const double start = spec.init ? spec.init->t : 0.0;
        if (*tEnd < start)
            throw InputError("--t-end: " + formatNumber(*tEnd) + " is before the start time " + formatNumber(start));
        // Whole steps to reach t-end; a ratio within round-off of an integer is that integer.
        const double n = (*tEnd - start) / dt;
        const double rounded = std::round(n);
        setup.steps = static_cast<long long>(std::abs(n - rounded) < 1e-9 * std::max(1.0, n) ? rounded : std::ceil(n));
        if (setup.steps > 4'000'000'000LL)
            throw InputError("--t-end: " + formatNumber(*tEnd) + " needs more than 4e9 steps of " + formatNumber(dt));
    } else {
        setup.steps = presetSteps.value_or(defaultSteps(spec.scene, spec.model));
    }
    return setup;
}

} // namespace ab::cli
