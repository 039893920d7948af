// SPDX-License-Identifier: MIT
#include "interrupt.h"

#include <atomic>

namespace ab {

namespace {

std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

} // namespace

void requestInterrupt() noexcept
{
    requested.store(true, std::memory_order_relaxed);
}

bool interruptRequested() noexcept
{
    return requested.load(std::memory_order_relaxed);
}

} // namespace ab
