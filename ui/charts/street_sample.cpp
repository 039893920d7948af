// SPDX-License-Identifier: MIT
#include "street_sample.h"

#include "core/street/street_census.h"

#include <algorithm>
#include <cmath>

namespace ab::ui {

std::vector<int> footBlocks(int blocks)
{
    std::vector<int> out;
    for (int k = 0; k < blocks && k < kFootLines; ++k)
        out.push_back(k);
    if (blocks > kFootLines)
        out.back() = blocks - 1;
    return out;
}

StreetSample measureStreet(const street::Layout& layout, const State& s)
{
    StreetSample out;
    const street::Census c = street::census(layout, s);
    const std::vector<int> blocks = footBlocks(layout.blocks);
    for (std::size_t i = 0; i < blocks.size(); ++i)
        out.pastFoot[i] = double(c.pastFoot[std::size_t(blocks[i])]);
    out.onStreet = double(c.onStreet);
    std::vector<double> speeds;
    speeds.reserve(std::size_t(std::max(c.onStreet, 0)));
    for (int i = 0; i < s.size(); ++i)
        if (!street::hasLeft(layout, s.p(0, i)))
            speeds.push_back(s.v.col(i).norm());
    if (speeds.empty())
        return out;
    // The q-quantile as the element of rank floor(q (n - 1)) (nearest rank from below);
    // nth_element puts it in place in O(n), the larger ranks after the smaller ones.
    const double quantiles[3] = {0.1, 0.5, 0.9};
    for (int k = 0; k < 3; ++k) {
        const auto rank = static_cast<std::ptrdiff_t>(std::floor(quantiles[k] * double(speeds.size() - 1)));
        std::nth_element(speeds.begin(), speeds.begin() + rank, speeds.end());
        out.speed[std::size_t(k)] = speeds[std::size_t(rank)];
    }
    out.speed[3] = *std::max_element(speeds.begin(), speeds.end());
    return out;
}

std::vector<double> passingRate(const std::vector<double>& t, const std::vector<double>& past, double window)
{
    std::vector<double> rate(t.size(), 0.0);
    std::size_t from = 0;
    for (std::size_t i = 1; i < t.size() && i < past.size(); ++i) {
        while (from + 1 < i && t[from + 1] <= t[i] - window)
            ++from;
        const double span = t[i] - t[from];
        rate[i] = span > 0.0 ? (past[i] - past[from]) / span : 0.0;
    }
    if (rate.size() > 1)
        rate[0] = rate[1]; // no interval ends at the start: show the first one's rate
    return rate;
}

} // namespace ab::ui
