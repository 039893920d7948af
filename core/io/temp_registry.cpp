// SPDX-License-Identifier: MIT
#include "temp_registry.h"

#include "atomic_file.h"

#include <atomic>
#include <climits>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace ab {

namespace tempfiles {

namespace {

// A slot is free (0), being filled or emptied (1), or names a temporary file (2). Only
// slots in state 2 are read by the signal handler.
struct Slot {
    std::atomic<int> state{0};
    char path[PATH_MAX];
};
static_assert(std::atomic<int>::is_always_lock_free, "read from a signal handler");

constexpr int kSlots = 64;
Slot slots[kSlots];

} // namespace

int add(const char* path) noexcept
{
    const std::size_t length = std::strlen(path);
    if (length >= PATH_MAX)
        return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = 0;
        if (slots[i].state.compare_exchange_strong(expected, 1)) {
            std::memcpy(slots[i].path, path, length + 1);
            slots[i].state.store(2, std::memory_order_release);
            return i;
        }
    }
    return -1;
}

void remove(int slot) noexcept
{
    if (slot < 0 || slot >= kSlots)
        return;
    slots[slot].state.store(1);
    slots[slot].state.store(0, std::memory_order_release);
}

} // namespace tempfiles

void removeTempFilesNow() noexcept
{
    for (tempfiles::Slot& s : tempfiles::slots)
        if (s.state.load(std::memory_order_acquire) == 2)
            ::unlink(s.path);
}

namespace {

// Removes the temporary files, then dies of the same signal (the parent sees how the
// process ended, as with no handler). Only async-signal-safe calls.
extern "C" void removeAndDie(int sig)
{
    removeTempFilesNow();
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    ::sigaction(sig, &dfl, nullptr);
    ::raise(sig);
}

void installUnlessIgnored(int sig)
{
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN)
        return; // e.g. nohup's SIGHUP: stays ignored
    struct sigaction sa {};
    sa.sa_handler = removeAndDie;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    ::sigaction(sig, &sa, nullptr);
}

} // namespace

void removeTempFilesOnSignals(bool alsoInterrupts)
{
    for (int sig : {SIGHUP, SIGQUIT, SIGPIPE})
        installUnlessIgnored(sig);
    if (alsoInterrupts)
        for (int sig : {SIGINT, SIGTERM})
            installUnlessIgnored(sig);
    std::signal(SIGXFSZ, SIG_IGN);
}

} // namespace ab
