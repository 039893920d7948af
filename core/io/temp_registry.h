// SPDX-License-Identifier: MIT
// The temporary files being written now, in fixed storage a signal handler may read:
// removeTempFilesNow() unlinks them without allocating or locking.
#pragma once

namespace ab::tempfiles {

// Registers a path (copied); returns its slot, or -1 when the path is too long or all
// slots are taken (the file is then written without removal on a signal).
int add(const char* path) noexcept;
// Forgets a slot (-1 is ignored).
void remove(int slot) noexcept;

} // namespace ab::tempfiles
