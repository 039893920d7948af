// SPDX-License-Identifier: MIT
#include "suggest.h"

#include <algorithm>
#include <limits>

namespace ab::cli {

std::size_t editDistance(std::string_view a, std::string_view b)
{
    // d[i][j]: edits from a[0..i) to b[0..j); the recurrence of Damerau's optimal string
    // alignment (Levenshtein's three edits plus a swap of two neighbouring letters).
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::size_t> d((n + 1) * (m + 1));
    auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
    for (std::size_t i = 0; i <= n; ++i)
        at(i, 0) = i;
    for (std::size_t j = 0; j <= m; ++j)
        at(0, j) = j;
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            std::size_t best = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                best = std::min(best, at(i - 2, j - 2) + 1);
            at(i, j) = best;
        }
    return at(n, m);
}

std::vector<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates)
{
    // Words longer than any name are not misspellings of one (and would cost n*m here).
    if (word.empty() || word.size() > 64)
        return {};
    const std::size_t threshold = std::max<std::size_t>(1, word.size() / 3);
    std::size_t best = std::numeric_limits<std::size_t>::max();
    std::vector<std::string> found;
    for (const std::string& c : candidates) {
        if (c == word)
            continue;
        const std::size_t d = editDistance(word, c);
        if (d > threshold || d > best)
            continue;
        if (d < best)
            found.clear();
        best = d;
        found.push_back(c);
    }
    // A word cut short ("--ste" for --steps) is near whatever it begins, however far in edits.
    if (word.size() >= 3)
        for (const std::string& c : candidates)
            if (c.size() > word.size() && c.compare(0, word.size(), word) == 0 &&
                std::find(found.begin(), found.end(), c) == found.end())
                found.push_back(c);
    if (found.size() > 3)
        found.clear(); // too many to be a suggestion
    return found;
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates, std::string_view prefix)
{
    const std::vector<std::string> near = nearest(word, candidates);
    if (near.empty())
        return "";
    std::string text = " (did you mean ";
    for (std::size_t i = 0; i < near.size(); ++i) {
        if (i > 0)
            text += i + 1 == near.size() ? " or " : ", ";
        text += std::string(prefix) + near[i];
    }
    return text + "?)";
}

std::string nearOrChoices(std::string_view word, const std::vector<std::string>& choices)
{
    const std::string near = didYouMean(word, choices);
    return near.empty() ? " (choose " + joined(choices) + ")" : near;
}

std::string joined(const std::vector<std::string>& words)
{
    std::string text;
    for (const std::string& w : words)
        text += (text.empty() ? "" : ", ") + w;
    return text;
}

} // namespace ab::cli
