// SPDX-License-Identifier: MIT
// The options every simulating command shares (run, chart, ...): scene, model,
// integrator, step, parameters, preset and start state, read into a RunSpec.
#pragma once

#include "parsed.h"

#include "../../core/simulation.h"

namespace ab::cli {

struct RunSetup {
    RunSpec spec;
    long long steps = 0;
    std::optional<std::string> presetKey;
};

// The scene the operand names; InputError (with the nearest keys) for an unknown one.
const SceneInfo* readSceneOperand(Parsed& args);
// One --set NAME=VALUE into the spec's parameters; an unknown NAME is refused with the
// scene's nearest parameter names.
void applyAssignment(RunSpec& spec, const std::string& assignment);

// Reads SCENE and the run options from `args` (removing them); throws InputError.
RunSetup readRunSetup(Parsed& args);

} // namespace ab::cli
