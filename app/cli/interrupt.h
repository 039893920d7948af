// SPDX-License-Identifier: MIT
// Ctrl+C during a long command: the command stops between steps, removes its temporary
// file and exits with status 130, so no half-written file is left behind.
#pragma once

#include <stdexcept>

namespace ab::cli {

class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("interrupted") {}
};

void installInterruptHandler();
bool interrupted();
void throwIfInterrupted();

} // namespace ab::cli
