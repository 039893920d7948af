// SPDX-License-Identifier: MIT
// The trajectory CSV of the contract: `t,ball,x,y,z,vx,vy,vz`, one row per ball per
// recorded state, full precision.
#pragma once

#include "../state.h"

#include <filesystem>
#include <ostream>

namespace ab {

void writeTrajectoryHeader(std::ostream& out);
void writeTrajectoryRows(std::ostream& out, const State& s);

// The balls at the first recorded time of a trajectory CSV (the start of a run resumed
// with --init). Throws InputError naming the file, line and column that is wrong.
State readFirstState(const std::filesystem::path& path);

} // namespace ab
