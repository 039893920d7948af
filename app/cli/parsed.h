// SPDX-License-Identifier: MIT
// One command's arguments as the parser (parser.h) read them: the operand and the values
// of the options the command's table (command_table.h) declares. The typed readers
// give a clear InputError for a malformed value.
#pragma once

#include "command_table.h"

#include "../../core/params.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ab::cli {

class Parsed {
public:
    Parsed(const CommandSpec& command, std::optional<std::string> operand,
           std::map<std::string, std::vector<std::string>> values)
        : command_(&command), operand_(std::move(operand)), values_(std::move(values))
    {
    }

    const std::string& command() const { return command_->name; }
    // The operand (SCENE, FIGURE); InputError naming `what` if none was given.
    std::string positional(const std::string& what) const;
    const std::optional<std::string>& positionalIfGiven() const { return operand_; }
    // `--name VALUE` (or `--name=VALUE`); the last one wins.
    std::optional<std::string> option(const std::string& name) const;
    // Every value of a repeatable option, in order.
    const std::vector<std::string>& options(const std::string& name) const;
    bool flag(const std::string& name) const;

    std::optional<double> real(const std::string& name) const;
    std::optional<long long> integer(const std::string& name, long long min, long long max) const;

private:
    // The option's values; a name the command's table does not declare is a logic error.
    const std::vector<std::string>& valuesOf(const std::string& name) const;

    const CommandSpec* command_;
    std::optional<std::string> operand_;
    std::map<std::string, std::vector<std::string>> values_;
};

// One line naming an unknown value and the values there are (the nearest as a suggestion):
// "--model: unknown value 'physicl' (did you mean physical?)".
[[noreturn]] void throwUnknownValue(const std::string& what, const std::string& value,
                                    const std::vector<std::string>& choices);

} // namespace ab::cli
