// SPDX-License-Identifier: MIT
// Every command of amazeballs-cli and every option it takes, with its value, unit and
// default: the one table the parser (parser.h), `help`, the man page and the shell
// completions (docgen.h) are all made from.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace ab::cli {

class Parsed;

// What a value is completed from in a shell (and listed as in the man page).
enum class Values {
    None,
    File,
    Scene,
    Assignment,
    Preset,
    Model,
    Integrator,
    Impacts,
    Broadphase,
    Chart,
    Case,
    Figure,
    Command
};

struct OptionSpec {
    OptionSpec(std::string n, std::string v, std::string h, std::string f = "", bool r = false,
               Values vs = Values::None)
        : name(std::move(n)), value(std::move(v)), help(std::move(h)), fallback(std::move(f)), repeatable(r), values(vs)
    {
    }

    std::string name;     // without the leading "--"
    std::string value;    // its placeholder ("N", "FILE.csv"); empty for a flag
    std::string help;     // what it does, with its unit
    std::string fallback; // the default in words; empty when it has none
    bool repeatable = false;
    Values values = Values::None;

    bool flag() const { return value.empty(); }
};

struct CommandSpec {
    std::string name;
    std::string operand; // "SCENE", "FIGURE", "COMMAND" or empty
    bool operandOptional = false;
    Values operandValues = Values::None;
    std::string summary; // one line, for the list of commands
    std::string details; // a paragraph for `help COMMAND` and the man page
    std::vector<OptionSpec> options;
    int (*fn)(Parsed&, std::ostream&, std::ostream&) = nullptr;

    const OptionSpec* option(std::string_view name) const;
    // "run SCENE [options]"
    std::string synopsis() const;
};

const std::vector<CommandSpec>& commandTable();
// nullptr when no command has that name.
const CommandSpec* findCommand(std::string_view name);
std::vector<std::string> commandNames();

// The words a value of this kind is one of (scene keys, model keys, ...); empty for free text.
std::vector<std::string> valueWords(Values v);

} // namespace ab::cli
