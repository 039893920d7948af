// SPDX-License-Identifier: MIT
// amazeballs-cli's arguments through CLI11: a parser made from a command's table
// (command_table.h), and the reading of one command's arguments into Parsed. Every
// failure is one InputError line in the contract's style, with a suggestion where a name
// is near a known one.
#pragma once

#include "parsed.h"

#include <memory>

namespace CLI {
class App;
}

namespace ab::cli {

// `-h` or `--help` among a command's arguments.
struct HelpRequested {};

// The CLI11 parser of one command: its operand, its options, -h/--help.
std::unique_ptr<CLI::App> makeParser(const CommandSpec& command);

// Throws InputError for an unknown option, an option without its value or with one it does
// not take, and an argument too many; HelpRequested when the arguments ask for help.
Parsed parseCommand(const CommandSpec& command, const std::vector<std::string>& args);

// What the program itself was asked before any command (parseTopLevel).
struct TopLevel {
    bool help = false;
    bool version = false;
    std::vector<std::string> rest; // the command and its arguments
};

// The program's own options (--help, --version) up to the command; InputError for an
// unknown one.
TopLevel parseTopLevel(const std::vector<std::string>& args);
std::unique_ptr<CLI::App> makeTopLevelParser();

} // namespace ab::cli
