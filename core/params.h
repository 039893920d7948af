// SPDX-License-Identifier: MIT
// Parameter tables: every constant of a scene is described once, here, and every
// consumer (the CLI's `list` and `--set`, presets, the app's parameter panel) loops over
// the table instead of knowing names.
#pragma once

#include "input_error.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ab {

enum class ParamKind { Real, Integer, Vector };

// Which models read a parameter. The report model ignores what only the physical model
// uses, and the app hides controls that would do nothing.
enum ModelMask : unsigned { ReportModel = 1u, PhysicalModel = 2u, BothModels = 3u };

struct ParamSpec {
    std::string key;    // name used by --set, presets and the contract
    std::string symbol; // as written in the report or the textbook (plain text)
    std::string unit;   // "1" for dimensionless
    ParamKind kind = ParamKind::Real;
    Eigen::Vector3d defaultValue = Eigen::Vector3d::Zero(); // scalars use component 0
    double min = 0.0;                                       // per component, inclusive unless minExclusive
    double max = 0.0;                                       // per component, inclusive
    bool minExclusive = false;
    std::string equation; // equation or section of the report, e.g. "eq 2.3"
    std::string meaning;  // one line
    unsigned models = BothModels;

    bool usedBy(unsigned model) const { return (models & model) != 0; }
    // The default is the report's value: a constant of the report's own model. The physical
    // model's own constants (friction, the spring floor) and the street's, which the report
    // never reached, have this program's defaults.
    bool reportDefault() const { return usedBy(ReportModel); }
};

// Whether any of a table's constants is the report's (every stage but the street).
bool anyReportDefault(const std::vector<ParamSpec>& table);

// Values for one scene's table, in table order. Built from the defaults, changed only
// through set()/parse(), which validate, so a ParamValues is always in range.
class ParamValues {
public:
    explicit ParamValues(const std::vector<ParamSpec>* table);

    const std::vector<ParamSpec>& table() const { return *table_; }

    double real(std::string_view key) const;
    long long integer(std::string_view key) const;
    Eigen::Vector3d vector(std::string_view key) const;
    Eigen::Vector3d raw(std::size_t index) const { return values_[index]; }

    // Validates against the spec; throws InputError naming the key and the range.
    void set(std::string_view key, const Eigen::Vector3d& value);
    // Parses text ("0.9", "12", "2,20,2") for the key and sets it; throws InputError.
    void parse(std::string_view key, std::string_view text);
    // Parses "NAME=VALUE" as given to --set.
    void parseAssignment(std::string_view assignment);

    std::optional<std::size_t> indexOf(std::string_view key) const;
    const ParamSpec& spec(std::string_view key) const;
    bool isDefault(std::size_t index) const { return values_[index] == (*table_)[index].defaultValue; }

    friend bool operator==(const ParamValues& a, const ParamValues& b)
    {
        return a.table_ == b.table_ && a.values_ == b.values_;
    }

private:
    const std::vector<ParamSpec>* table_;
    std::vector<Eigen::Vector3d> values_;
};

// The NAME of a --set "NAME=VALUE", blanks around it dropped; empty when there is no '='.
std::string_view assignmentName(std::string_view assignment);

// Parsing helpers shared by --set, presets and the app's fields. All throw InputError
// with `what` (a parameter or option name) in the message.
double parseReal(std::string_view text, std::string_view what);
long long parseInteger(std::string_view text, std::string_view what);
Eigen::Vector3d parseVector(std::string_view text, std::string_view what);

// Text from a file or a command line made safe to quote in a one-line message: newline,
// tab and return as \n \t \r, other control characters and bytes that are not UTF-8 as
// \xNN (so no terminal escape sequence passes), C1 controls as \u0080..\u009f; cut after
// `max` characters with "…".
std::string printableInput(std::string_view text, std::size_t max = 80);

// Checks one value against its spec without storing it; returns the error text or nothing.
std::optional<std::string> checkValue(const ParamSpec& spec, const Eigen::Vector3d& value);
std::optional<Refusal> checkRefusal(const ParamSpec& spec, const Eigen::Vector3d& value); // the same, to translate

// Formats a value as the user would type it back ("0.9", "12", "2,20,2"), shortest
// representation that reads back exactly.
std::string formatValue(const ParamSpec& spec, const Eigen::Vector3d& value);
std::string formatNumber(double x);
// A time step for a reader (a figure's caption): formatNumber where that takes at most six
// significant digits ("0.01"), else "1/k" where dt is 1/k to round-off ("1/60" for
// 0.016666666666666666), else six significant digits.
std::string formatStep(double dt);
// `digits` significant digits for messages ("34.58", "1.2e-05"), whatever the locale.
std::string formatSignificant(double x, int digits);
std::string formatRange(const ParamSpec& spec);

} // namespace ab
