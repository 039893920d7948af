// SPDX-License-Identifier: MIT
#include "interrupt.h"

#include "../../core/io/atomic_file.h"

#include <csignal>

namespace ab::cli {

namespace {

// Async-signal-safe only: an atomic store, unlink, sigaction, raise.
extern "C" void onSignal(int sig)
{
    if (!interruptRequested()) {
        requestInterrupt();
        return;
    }
    removeTempFilesNow(); // the second signal: do not wait for the command
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    ::sigaction(sig, &dfl, nullptr);
    ::raise(sig);
}

} // namespace

void installInterruptHandler()
{
    removeTempFilesOnSignals(false);
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; // no SA_RESTART: a blocked write returns EINTR and the command sees the request
    ::sigaction(SIGINT, &sa, nullptr);
    ::sigaction(SIGTERM, &sa, nullptr);
}

bool interrupted()
{
    return interruptRequested();
}

void throwIfInterrupted()
{
    throwIfInterruptRequested();
}

} // namespace ab::cli
