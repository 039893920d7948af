// SPDX-License-Identifier: MIT
#include "street_census.h"

#include <algorithm>
#include <cmath>

namespace ab::street {

Census census(const Layout& layout, const State& s)
{
    Census c;
    c.pastFoot.assign(layout.blockFootX.size(), 0);
    for (int i = 0; i < s.size(); ++i) {
        const double x = s.p(0, i);
        for (std::size_t k = 0; k < layout.blockFootX.size(); ++k)
            if (x > layout.blockFootX[k])
                ++c.pastFoot[k];
        if (hasLeft(layout, x)) {
            ++c.left;
            continue;
        }
        ++c.onStreet;
        c.maxSpeed = std::max(c.maxSpeed, s.v.col(i).norm());
    }
    return c;
}

std::vector<int> speedHistogram(const Layout& layout, const State& s, int bins, double top)
{
    std::vector<int> counts(static_cast<std::size_t>(std::max(bins, 1)), 0);
    const double width = top / static_cast<double>(counts.size());
    for (int i = 0; i < s.size(); ++i) {
        if (hasLeft(layout, s.p(0, i)))
            continue;
        const double u = width > 0.0 ? s.v.col(i).norm() / width : 0.0;
        const auto k = static_cast<std::size_t>(std::clamp(std::floor(u), 0.0, static_cast<double>(counts.size() - 1)));
        ++counts[k];
    }
    return counts;
}

} // namespace ab::street
