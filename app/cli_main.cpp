// SPDX-License-Identifier: MIT
#include "cli/cli.h"
#include "cli/interrupt.h"

#include "../core/io/fd_stream.h"

#include <exception>
#include <iostream>
#include <unistd.h>

int main(int argc, char** argv)
{
    std::ios::sync_with_stdio(false);
    ab::cli::installInterruptHandler();
    // Every write to standard output is checked (a full disk, a closed pipe): the command
    // then stops with one line and exit status 4 (cli.h).
    ab::FdOStream out(STDOUT_FILENO, "standard output");
    const int status = ab::cli::run(std::vector<std::string>(argv + 1, argv + argc), out, std::cerr);
    // A command that failed after printing still hands over what it printed (a success has
    // flushed and checked already).
    try {
        out.flush();
    } catch (const std::exception&) {
    }
    return status;
}
