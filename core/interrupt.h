// SPDX-License-Identifier: MIT
// A process-wide request to stop, set from a signal handler (Ctrl+C, SIGTERM) and polled
// inside long loops, also within one step, so that a command ends promptly. Lock-free and
// async-signal-safe to set; nothing in the core sets it.
#pragma once

#include <stdexcept>

namespace ab {

class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("interrupted") {}
};

// Async-signal-safe.
void requestInterrupt() noexcept;
bool interruptRequested() noexcept;

inline void throwIfInterruptRequested()
{
    if (interruptRequested())
        throw Interrupted();
}

} // namespace ab
