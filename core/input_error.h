// SPDX-License-Identifier: MIT
// The error raised for anything a user can get wrong, and the refusals the window
// translates: a refusal is one of refusalTexts(), an English sentence with %1, %2, ... for
// the names and values it quotes, and those values as typed. The core keeps no language
// but English; the window looks the sentence up in its own and fills the same values in.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ab {

struct Refusal {
    Refusal(std::string_view sentence, std::vector<std::string> values, std::shared_ptr<const Refusal> inner = nullptr);

    std::string_view text;         // one of refusalTexts()
    std::vector<std::string> args; // %1, %2, ... in order
    // A refusal quoted inside this one fills its last placeholder (a comparison that
    // the core refuses: "compare with %1: %2").
    std::shared_ptr<const Refusal> detail;
};

// %1 ... %9 of `text` replaced by args[0] ... args[8], in one pass (a value that itself
// holds "%2" stays as typed).
std::string fillRefusal(std::string_view text, const std::vector<std::string>& args);
std::string refusalMessage(const Refusal& r); // detail filled in as the last argument

// Raised for any input a user can get wrong (a value, a name, a file). The message names
// what was wrong and is meant to be shown as it is, on one line.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    explicit InputError(Refusal r);

    // The refusal it was made from, for the window to translate; null for messages
    // that only the command line and files give.
    const Refusal* refusal() const noexcept { return refusal_.get(); }
    std::shared_ptr<const Refusal> shared() const noexcept { return refusal_; }

private:
    std::shared_ptr<const Refusal> refusal_;
};

// Throws InputError(Refusal{text, args}); out of line, so that a check's throw stays small
// where it is inlined.
[[noreturn]] void refuse(std::string_view text, std::vector<std::string> args);

// Every sentence a Refusal may carry, for the window's translations and their test.
const std::vector<std::string_view>& refusalTexts();

namespace refusal {
inline constexpr std::string_view notANumber = "%1: %2 is not a number";
inline constexpr std::string_view tooSmallForDouble =
    "%1: %2 is too small for a double (below 4.9e-324); write 0 or a larger value";
inline constexpr std::string_view tooLargeForDouble = "%1: %2 is too large for a double (above 1.8e308)";
inline constexpr std::string_view notFinite = "%1: %2 is not a finite number";
inline constexpr std::string_view valueNotFinite = "%1: value is not a finite number";
inline constexpr std::string_view notWhole = "%1: %2 is not a whole number";
inline constexpr std::string_view wholeTooLarge = "%1: %2 is too large";
inline constexpr std::string_view beyondExact =
    "%1: %2 is beyond 2^53 - 1 = 9007199254740991, the largest whole number kept exactly";
inline constexpr std::string_view notVector = "%1: %2 is not a vector x,y,z of three numbers";
inline constexpr std::string_view notFiniteVector = "%1: %2 is not a vector x,y,z of three finite numbers";
inline constexpr std::string_view outsideRange = "%1: %2 is outside the allowed range %3";
inline constexpr std::string_view componentOutsideRange = "%1: %2 (%3 component) is outside the allowed range %4";
inline constexpr std::string_view outsideBox =
    "%1: %2 lies outside the box of side %3 m (x and z must be within [0, box])";
inline constexpr std::string_view noRoomInBox = "box: %1 leaves no room for a ball of radius %2 (box must exceed 2 r)";
inline constexpr std::string_view stepNotPositive = "dt: %1 must be positive";
inline constexpr std::string_view stepsOutside = "steps: %1 is outside [1, %2]";
inline constexpr std::string_view compareWith = "compare with %1: %2";
inline constexpr std::string_view streetTooNarrow =
    "width: %1 m leaves no room for balls of radius %2 m (width must be at least 8 r)";
inline constexpr std::string_view carsDoNotFit = "cars: %1 do not fit along these blocks; they hold at most %2";
inline constexpr std::string_view carsTooWide = "cars: a roadway of %1 m is too narrow for parked cars";
inline constexpr std::string_view compareStart =
    "compare with %1: the two runs do not start at the same time with the same balls";
} // namespace refusal

} // namespace ab
