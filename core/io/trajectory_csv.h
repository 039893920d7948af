// SPDX-License-Identifier: MIT
// The trajectory CSV of the contract: `t,ball,x,y,z,vx,vy,vz`, one row per ball per
// recorded state, full precision; a run with rotation adds `wx,wy,wz` after them.
#pragma once

#include "../state.h"

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace ab {

// `spin`: with the columns wx,wy,wz (a state without spins writes zeros there).
void writeTrajectoryHeader(std::ostream& out, bool spin = false);
void writeTrajectoryRows(std::ostream& out, const State& s, bool spin = false);

// The balls at the first recorded time of a trajectory CSV (the start of a run resumed
// with --init), with their spins when the header has wx,wy,wz after vz. Throws
// InputError naming the file, line and column that is wrong. The file must be a regular
// file (see input_file.h); the header exactly t,ball,x,y,z,vx,vy,vz (then wx,wy,wz for a
// spinning run), every row as many columns, lines at most 1024 characters, at most
// 4,000,000 balls: memory stays bounded whatever the file holds.
State readFirstState(const std::filesystem::path& path);

// The same reader over text or any source of bytes (`read` fills up to `size` bytes and
// returns how many, 0 at the end); messages begin with `where`.
using ByteSource = std::function<std::size_t(char* into, std::size_t size)>;
State parseFirstState(std::string_view text, const std::string& where);
State parseFirstState(const ByteSource& read, const std::string& where);

} // namespace ab
