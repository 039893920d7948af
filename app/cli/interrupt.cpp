// SPDX-License-Identifier: MIT
#include "interrupt.h"

#include <csignal>

namespace ab::cli {

namespace {

volatile std::sig_atomic_t flag = 0;

extern "C" void onSignal(int)
{
    flag = 1;
}

} // namespace

void installInterruptHandler()
{
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
}

bool interrupted()
{
    return flag != 0;
}

void throwIfInterrupted()
{
    if (interrupted())
        throw Interrupted();
}

} // namespace ab::cli
