// SPDX-License-Identifier: MIT
#include "parsed.h"

#include "suggest.h"

#include <stdexcept>

namespace ab::cli {

std::string Parsed::positional(const std::string& what) const
{
    if (!operand_)
        throw InputError(command() + ": missing " + what);
    return *operand_;
}

const std::vector<std::string>& Parsed::valuesOf(const std::string& name) const
{
    if (!command_->option(name))
        throw std::logic_error(command() + " reads --" + name + ", which its table does not declare");
    static const std::vector<std::string> none;
    const auto it = values_.find(name);
    return it == values_.end() ? none : it->second;
}

std::optional<std::string> Parsed::option(const std::string& name) const
{
    const std::vector<std::string>& v = valuesOf(name);
    if (v.empty())
        return std::nullopt;
    return v.back();
}

const std::vector<std::string>& Parsed::options(const std::string& name) const
{
    return valuesOf(name);
}

bool Parsed::flag(const std::string& name) const
{
    return !valuesOf(name).empty();
}

std::optional<double> Parsed::real(const std::string& name) const
{
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    return parseReal(*text, "--" + name);
}

std::optional<long long> Parsed::integer(const std::string& name, long long min, long long max) const
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

void throwUnknownValue(const std::string& what, const std::string& value, const std::vector<std::string>& choices)
{
    throw InputError(what + ": unknown value '" + printableInput(value) + "'" + nearOrChoices(value, choices));
}

} // namespace ab::cli
