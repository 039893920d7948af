// SPDX-License-Identifier: MIT
// "did you mean ...?" for a misspelt command, option, scene, parameter or value: the
// candidates nearest to the word in Damerau-Levenshtein distance, when near enough.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ab::cli {

// Edits (insert, delete, substitute, swap two neighbours) that turn a into b: the optimal
// string alignment distance.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidates nearest to `word`: those at the smallest distance when it is within the
// threshold (a third of the word, at least 1), then those that begin with the word (three
// letters or more). Empty when none is near, or more than three are.
std::vector<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates);

// " (did you mean A?)", " (did you mean A or B?)" with each candidate after `prefix`
// ("--" for options), or "" when none is near.
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates, std::string_view prefix = "");

// didYouMean's suggestion, or " (choose a, b, c)" when none is near.
std::string nearOrChoices(std::string_view word, const std::vector<std::string>& choices);

// Comma-separated, for "(choose a, b, c)".
std::string joined(const std::vector<std::string>& words);

} // namespace ab::cli
