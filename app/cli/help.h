// SPDX-License-Identifier: MIT
// The help amazeballs-cli prints: the list of commands, and one command's usage with its
// options, their units and defaults, both from the command table.
#pragma once

#include "command_table.h"

#include <iosfwd>
#include <string>

namespace ab::cli {

void printUsage(std::ostream& out);
void printCommandHelp(const CommandSpec& command, std::ostream& out);

// "--steps N" or "--summary": how an option is written.
std::string optionSynopsis(const OptionSpec& o);
// The option's help with its default: "the run's length in steps, 1 to 4e9 (default: ...)".
std::string optionText(const OptionSpec& o);
// What the program says about its exit status (help and man page).
const std::vector<std::pair<int, std::string>>& exitStatuses();

} // namespace ab::cli
