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

// What `run` says on a terminal before writing a trajectory CSV of more than 100 MB: its size and what
// --every and --summary write instead; nothing for a smaller one. `states`: steps / every + 1
// rows of `balls` balls, each row t, ball and 6 numbers (9 with spins) of about 18
// characters in the shortest round-trip form.
std::optional<std::string> largeTrajectoryNote(long long balls, long long steps, long long every, bool spin);

} // namespace ab::cli
