// SPDX-License-Identifier: MIT
#include "cli/cli.h"
#include "cli/interrupt.h"

#include <iostream>

int main(int argc, char** argv)
{
    std::ios::sync_with_stdio(false);
    ab::cli::installInterruptHandler();
    return ab::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
