// SPDX-License-Identifier: MIT
#include "params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ab {

namespace {

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

std::string quoted(std::string_view s)
{
    return "'" + printableInput(s) + "'";
}

} // namespace

bool anyReportDefault(const std::vector<ParamSpec>& table)
{
    return std::any_of(table.begin(), table.end(), [](const ParamSpec& p) { return p.reportDefault(); });
}

namespace {

// std::from_chars over the whole trimmed text, with an optional leading '+'.
// Returns the error code, or std::errc::invalid_argument for anything but one number.
template <typename T> std::errc fromWholeText(std::string_view text, T& value)
{
    const std::string_view t = trim(text);
    const char* first = t.data();
    const char* last = t.data() + t.size();
    if (t.size() > 1 && *first == '+' && first[1] != '-')
        ++first;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (t.empty() || ptr != last)
        return std::errc::invalid_argument;
    return ec;
}

// A number from_chars found out of range is too small when its exponent is negative or,
// without one, when it has no non-zero digit before the point.
bool underflows(std::string_view text)
{
    const auto e = text.find_first_of("eE");
    if (e != std::string_view::npos)
        return text.find('-', e) != std::string_view::npos;
    const auto point = text.find('.');
    const std::string_view whole = text.substr(0, point);
    return whole.find_first_of("123456789") == std::string_view::npos;
}

} // namespace

double parseReal(std::string_view text, std::string_view what)
{
    double value = 0.0;
    const std::errc ec = fromWholeText(text, value);
    if (ec == std::errc::invalid_argument)
        throw InputError(Refusal{refusal::notANumber, {std::string(what), quoted(text)}});
    if (ec == std::errc::result_out_of_range)
        throw InputError(Refusal{underflows(text) ? refusal::tooSmallForDouble : refusal::tooLargeForDouble,
                                 {std::string(what), quoted(text)}});
    if (!std::isfinite(value))
        throw InputError(Refusal{refusal::notFinite, {std::string(what), quoted(text)}});
    return value;
}

long long parseInteger(std::string_view text, std::string_view what)
{
    long long value = 0;
    const std::errc ec = fromWholeText(text, value);
    if (ec == std::errc::invalid_argument)
        throw InputError(Refusal{refusal::notWhole, {std::string(what), quoted(text)}});
    if (ec == std::errc::result_out_of_range)
        throw InputError(Refusal{refusal::wholeTooLarge, {std::string(what), quoted(text)}});
    return value;
}

Eigen::Vector3d parseVector(std::string_view text, std::string_view what)
{
    Eigen::Vector3d v;
    std::string_view rest = text;
    for (int i = 0; i < 3; ++i) {
        const auto comma = rest.find(',');
        if ((i < 2) == (comma == std::string_view::npos))
            throw InputError(Refusal{refusal::notVector, {std::string(what), quoted(text)}});
        const std::string_view part = i < 2 ? rest.substr(0, comma) : rest;
        try {
            v[i] = parseReal(part, what);
        } catch (const InputError&) {
            throw InputError(Refusal{refusal::notFiniteVector, {std::string(what), quoted(text)}});
        }
        if (i < 2)
            rest = rest.substr(comma + 1);
    }
    return v;
}

std::string formatSignificant(double x, int digits)
{
    // std::to_chars, not printf: a Qt application sets the C locale from the environment.
    char buf[64];
    const auto end = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits);
    return std::string(buf, end.ptr);
}

std::string formatStep(double dt)
{
    // The shortest text that reads back is no longer than six significant digits': it has
    // six digits or fewer.
    const std::string shortest = formatNumber(dt);
    if (formatSignificant(dt, 6).size() >= shortest.size())
        return shortest;
    // dt = 1/k: k = round(1/dt), and k dt is 1 to round-off (a few ulps of 1).
    const double k = std::round(1.0 / dt);
    if (k >= 2.0 && k < 1e9 && std::abs(k * dt - 1.0) <= 4.0 * std::numeric_limits<double>::epsilon())
        return "1/" + formatNumber(k);
    return formatSignificant(dt, 6);
}

std::string formatNumber(double x)
{
    // std::to_chars is locale-independent (a Qt application sets the C locale from the
    // environment, where printf would write "0,9") and, without a precision, gives the
    // shortest text that reads back to the same double. Numbers from 1 up to 1e15 are
    // then written without an exponent (2000, not 2e+03).
    char buf[64];
    const auto shortest = std::to_chars(buf, buf + sizeof buf, x);
    std::string text(buf, shortest.ptr);
    const double magnitude = std::abs(x);
    if (magnitude >= 1.0 && magnitude < 1e15 && text.find('e') != std::string::npos) {
        const int digits = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
        const auto fixed = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits);
        text.assign(buf, fixed.ptr);
    }
    return text;
}

std::string formatValue(const ParamSpec& spec, const Eigen::Vector3d& value)
{
    switch (spec.kind) {
    case ParamKind::Real:
        return formatNumber(value[0]);
    case ParamKind::Integer:
        return std::to_string(static_cast<long long>(value[0]));
    case ParamKind::Vector:
        return formatNumber(value[0]) + "," + formatNumber(value[1]) + "," + formatNumber(value[2]);
    }
    return {};
}

std::string formatRange(const ParamSpec& spec)
{
    const bool integer = spec.kind == ParamKind::Integer;
    auto num = [&](double x) { return integer ? std::to_string(static_cast<long long>(x)) : formatNumber(x); };
    return std::string(spec.minExclusive ? "(" : "[") + num(spec.min) + ", " + num(spec.max) + "]";
}

std::optional<Refusal> checkRefusal(const ParamSpec& spec, const Eigen::Vector3d& value)
{
    const int n = spec.kind == ParamKind::Vector ? 3 : 1;
    for (int i = 0; i < n; ++i) {
        const double x = value[i];
        if (!std::isfinite(x))
            return Refusal{refusal::valueNotFinite, {spec.key}};
        if (spec.kind == ParamKind::Integer && x != std::floor(x))
            return Refusal{refusal::notWhole, {spec.key, formatNumber(x)}};
        const bool below = spec.minExclusive ? x <= spec.min : x < spec.min;
        if (below || x > spec.max) {
            const std::string shown = spec.kind == ParamKind::Integer && std::abs(x) < 9e15
                                          ? std::to_string(static_cast<long long>(x))
                                          : formatNumber(x);
            const std::string range =
                formatRange(spec) + (spec.unit == "1" || spec.unit.empty() ? std::string() : " " + spec.unit);
            if (n == 3)
                return Refusal{refusal::componentOutsideRange, {spec.key, shown, std::string(1, "xyz"[i]), range}};
            return Refusal{refusal::outsideRange, {spec.key, shown, range}};
        }
    }
    return std::nullopt;
}

std::optional<std::string> checkValue(const ParamSpec& spec, const Eigen::Vector3d& value)
{
    if (auto r = checkRefusal(spec, value))
        return refusalMessage(*r);
    return std::nullopt;
}

ParamValues::ParamValues(const std::vector<ParamSpec>* table) : table_(table)
{
    values_.reserve(table->size());
    for (const ParamSpec& spec : *table)
        values_.push_back(spec.defaultValue);
}

std::optional<std::size_t> ParamValues::indexOf(std::string_view key) const
{
    for (std::size_t i = 0; i < table_->size(); ++i)
        if ((*table_)[i].key == key)
            return i;
    return std::nullopt;
}

namespace {

// The length of the valid UTF-8 sequence at text[i], or 0 when the byte starts none.
std::size_t utf8Length(std::string_view text, std::size_t i)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b = byte(i);
    const std::size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > text.size())
        return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((byte(i + k) & 0xC0) != 0x80)
            return 0;
    if (n == 2 && b < 0xC2)
        return 0; // overlong
    return n;
}

} // namespace

std::string printableInput(std::string_view text, std::size_t max)
{
    std::string out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < text.size();) {
        if (chars == max)
            return out + "\xE2\x80\xA6"; // "…", the cut
        ++chars;
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t n = utf8Length(text, i);
        char buf[8];
        if (c == '\n' || c == '\t' || c == '\r') {
            out += c == '\n' ? "\\n" : c == '\t' ? "\\t" : "\\r";
        } else if (n == 0 || c < 0x20 || c == 0x7F) {
            std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(c)); // a control or a stray byte
            out += buf;
        } else if (n == 2 && c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0) {
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(text[i + 1]) & 0xFFu); // C1 control
            out += buf;
        } else {
            out.append(text.substr(i, n));
        }
        i += n == 0 ? 1 : n;
    }
    return out;
}

const ParamSpec& ParamValues::spec(std::string_view key) const
{
    const auto i = indexOf(key);
    if (!i)
        throw InputError("unknown parameter '" + printableInput(key) + "'");
    return (*table_)[*i];
}

double ParamValues::real(std::string_view key) const
{
    return values_[*indexOf(spec(key).key)][0];
}

long long ParamValues::integer(std::string_view key) const
{
    return static_cast<long long>(values_[*indexOf(spec(key).key)][0]);
}

Eigen::Vector3d ParamValues::vector(std::string_view key) const
{
    return values_[*indexOf(spec(key).key)];
}

void ParamValues::set(std::string_view key, const Eigen::Vector3d& value)
{
    const ParamSpec& s = spec(key);
    Eigen::Vector3d v = value;
    if (s.kind != ParamKind::Vector)
        v[1] = v[2] = 0.0;
    if (auto r = checkRefusal(s, v))
        throw InputError(std::move(*r));
    values_[*indexOf(key)] = v;
}

void ParamValues::parse(std::string_view key, std::string_view text)
{
    const ParamSpec& s = spec(key);
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    switch (s.kind) {
    case ParamKind::Real:
        v[0] = parseReal(text, s.key);
        break;
    case ParamKind::Integer: {
        // Kept as a double: beyond 2^53 a whole number would be rounded, so it is refused.
        constexpr long long exact = (1LL << 53) - 1;
        const long long n = parseInteger(text, s.key);
        if (n > exact || n < -exact)
            throw InputError(Refusal{refusal::beyondExact, {s.key, quoted(text)}});
        v[0] = static_cast<double>(n);
        break;
    }
    case ParamKind::Vector:
        v = parseVector(text, s.key);
        break;
    }
    set(key, v);
}

void ParamValues::parseAssignment(std::string_view assignment)
{
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0)
        throw InputError("--set: '" + printableInput(assignment) + "' is not NAME=VALUE");
    parse(trim(assignment.substr(0, eq)), assignment.substr(eq + 1));
}

std::string_view assignmentName(std::string_view assignment)
{
    const auto eq = assignment.find('=');
    return eq == std::string_view::npos ? std::string_view() : trim(assignment.substr(0, eq));
}

} // namespace ab
