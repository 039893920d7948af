// SPDX-License-Identifier: MIT
// A small reader over a command's arguments: options with values, repeated options,
// and a clear InputError for anything left over or malformed.
#pragma once

#include "../../core/params.h"

#include <optional>
#include <string>
#include <vector>

namespace ab::cli {

class Args {
public:
    Args(std::string command, std::vector<std::string> args) : command_(std::move(command)), args_(std::move(args)) {}

    // The next argument that is not an option, removed; InputError naming `what` if none.
    std::string positional(const std::string& what);
    // Removes `--name VALUE` (or `--name=VALUE`) and returns VALUE; the last one wins.
    std::optional<std::string> option(const std::string& name);
    // Every value of a repeatable option, in order.
    std::vector<std::string> options(const std::string& name);
    bool flag(const std::string& name);

    std::optional<double> real(const std::string& name);
    std::optional<long long> integer(const std::string& name, long long min, long long max);

    // Throws InputError for the first argument nobody asked for.
    void finish() const;

private:
    std::string command_;
    std::vector<std::string> args_;
};

} // namespace ab::cli
