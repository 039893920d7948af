// SPDX-License-Identifier: MIT
// Ctrl+C or SIGTERM during a command: the core's interrupt request is set, the command
// stops within a step (the loops poll it), removes its temporary file and exits with
// status 130, so no half-written file is left behind. A second signal ends the process
// at once, after removing the temporary files. SIGHUP, SIGQUIT and SIGPIPE remove them
// and end the process by that signal (core/io/atomic_file.h).
#pragma once

#include "../../core/interrupt.h"

namespace ab::cli {

using ab::Interrupted;

void installInterruptHandler();
bool interrupted();
void throwIfInterrupted();

} // namespace ab::cli
