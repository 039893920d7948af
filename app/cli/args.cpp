// SPDX-License-Identifier: MIT
#include "args.h"

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
    std::vector<std::string> values;
    const std::string flagText = "--" + name;
    for (std::size_t i = 0; i < args_.size();) {
        if (args_[i] == flagText) {
            if (i + 1 >= args_.size())
                throw InputError(flagText + ": missing value");
            values.push_back(args_[i + 1]);
            args_.erase(args_.begin() + static_cast<long>(i), args_.begin() + static_cast<long>(i) + 2);
        } else if (args_[i].rfind(flagText + "=", 0) == 0) {
            values.push_back(args_[i].substr(flagText.size() + 1));
            args_.erase(args_.begin() + static_cast<long>(i));
        } else {
            ++i;
        }
    }
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
    bool found = false;
    for (std::size_t i = 0; i < args_.size();) {
        if (args_[i] == "--" + name) {
            found = true;
            args_.erase(args_.begin() + static_cast<long>(i));
        } else {
            ++i;
        }
    }
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
