// SPDX-License-Identifier: MIT
#include "args.h"

#include <algorithm>

namespace ab::cli {

std::string Args::positional(const std::string& what)
{
    for (auto it = args_.begin(); it != args_.end(); ++it) {
        if (it->rfind("--", 0) == 0)
            break; // positionals come first
        std::string value = *it;
        args_.erase(it);
        return value;
    }
    throw InputError(command_ + ": missing " + what);
}

std::vector<std::string> Args::options(const std::string& name)
{
    // One pass that keeps what is not ours: linear in the arguments, however many there are.
    std::vector<std::string> values;
    std::vector<std::string> rest;
    rest.reserve(args_.size());
    const std::string flagText = "--" + name;
    for (std::size_t i = 0; i < args_.size(); ++i) {
        if (args_[i] == flagText) {
            if (i + 1 >= args_.size())
                throw InputError(flagText + ": missing value");
            values.push_back(std::move(args_[++i]));
        } else if (args_[i].size() > flagText.size() && args_[i].compare(0, flagText.size(), flagText) == 0 &&
                   args_[i][flagText.size()] == '=') {
            values.push_back(args_[i].substr(flagText.size() + 1));
        } else {
            rest.push_back(std::move(args_[i]));
        }
    }
    args_ = std::move(rest);
    return values;
}

std::optional<std::string> Args::option(const std::string& name)
{
    std::vector<std::string> values = options(name);
    if (values.empty())
        return std::nullopt;
    return values.back();
}

bool Args::flag(const std::string& name)
{
    const std::string flagText = "--" + name;
    const auto kept = std::remove(args_.begin(), args_.end(), flagText);
    const bool found = kept != args_.end();
    args_.erase(kept, args_.end());
    return found;
}

std::optional<double> Args::real(const std::string& name)
{
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    return parseReal(*text, "--" + name);
}

std::optional<long long> Args::integer(const std::string& name, long long min, long long max)
{
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    const long long value = parseInteger(*text, "--" + name);
    if (value < min || value > max)
        throw InputError("--" + name + ": " + std::to_string(value) + " is outside [" + std::to_string(min) + ", " +
                         std::to_string(max) + "]");
    return value;
}

void Args::finish() const
{
    if (args_.empty())
        return;
    const std::string& a = args_.front();
    if (a.rfind("--", 0) == 0)
        throw InputError(command_ + ": unknown option '" + printableInput(a) + "'");
    throw InputError(command_ + ": unexpected argument '" + printableInput(a) + "'");
}

} // namespace ab::cli
