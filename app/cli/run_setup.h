// SPDX-License-Identifier: MIT
// The options every simulating command shares (run, chart, ...): scene, model,
// integrator, step, parameters, preset and start state, read into a RunSpec.
#pragma once

#include "args.h"

#include "../../core/simulation.h"

namespace ab::cli {

struct RunSetup {
    RunSpec spec;
    long long steps = 0;
    std::optional<std::string> presetKey;
};

// Reads SCENE and the run options from `args` (removing them); throws InputError.
RunSetup readRunSetup(Args& args);

} // namespace ab::cli
