// SPDX-License-Identifier: MIT
// The trajectory CSV of the contract: `t,ball,x,y,z,vx,vy,vz`, one row per ball per
// recorded state, full precision; a run with rotation adds `wx,wy,wz` after them.
#pragma once

#include "../state.h"

#include <filesystem>
#include <ostream>

namespace ab {

// `spin`: with the columns wx,wy,wz (a state without spins writes zeros there).
void writeTrajectoryHeader(std::ostream& out, bool spin = false);
void writeTrajectoryRows(std::ostream& out, const State& s, bool spin = false);

// The balls at the first recorded time of a trajectory CSV (the start of a run resumed
// with --init), with their spins when the header has wx,wy,wz after vz. Throws
// InputError naming the file, line and column that is wrong.
State readFirstState(const std::filesystem::path& path);

} // namespace ab
