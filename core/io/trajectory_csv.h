// SPDX-License-Identifier: MIT
// The trajectory CSV of the contract: `t,ball,x,y,z,vx,vy,vz`, one row per ball per
// recorded state, full precision.
#pragma once

#include "../state.h"

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace ab {

void writeTrajectoryHeader(std::ostream& out);
void writeTrajectoryRows(std::ostream& out, const State& s);

// The balls at the first recorded time of a trajectory CSV (the start of a run resumed
// with --init). Throws InputError naming the file, line and column that is wrong.
// The file must be a regular file (see input_file.h); the header exactly
// t,ball,x,y,z,vx,vy,vz, every row 8 columns, lines at most 1024 characters, at most
// 4,000,000 balls: memory stays bounded whatever the file holds.
State readFirstState(const std::filesystem::path& path);

// The same reader over text or any source of bytes (`read` fills up to `size` bytes and
// returns how many, 0 at the end); messages begin with `where`.
using ByteSource = std::function<std::size_t(char* into, std::size_t size)>;
State parseFirstState(std::string_view text, const std::string& where);
State parseFirstState(const ByteSource& read, const std::string& where);

} // namespace ab
