// SPDX-License-Identifier: MIT
// Small helpers shared by the core tests: build a run from --set style assignments and
// collect the recorded states.
#pragma once

#include "core/simulation.h"

#include <initializer_list>
#include <string>
#include <vector>

namespace testing {

inline ab::RunSpec spec(ab::SceneId scene, std::initializer_list<std::string> assignments = {},
                        ab::ModelKind model = ab::ModelKind::Report)
{
    ab::RunSpec s(scene);
    s.model = model;
    for (const std::string& a : assignments)
        s.params.parseAssignment(a);
    return s;
}

// Every state from the start to `steps`, each final (recorded after its step).
inline std::vector<ab::State> record(const ab::RunSpec& spec, long long steps)
{
    auto sim = ab::makeSimulation(spec);
    std::vector<ab::State> states;
    ab::runRecorded(*sim, sim->start(), steps, 1, [&](const ab::State& s) { states.push_back(s); });
    return states;
}

} // namespace testing
