// SPDX-License-Identifier: MIT
// Files are written whole or not at all: into a temporary file beside the target, then
// renamed over it, so a reader never sees a half-written file.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace ab {

// Calls `write` with a stream to a temporary file in the target's folder, then renames it
// to `path`. Throws InputError naming the path when the folder is not writable or the
// write fails; the target is then untouched and no temporary file is left behind.
void writeFileAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

// Checks early (before a long run) that `path` can be written, with the same message
// writeFileAtomically would give; creates nothing.
void checkWritable(const std::filesystem::path& path);

} // namespace ab
