// SPDX-License-Identifier: MIT
#include "street_census.h"

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
        if (hasLeft(layout, x))
            ++c.left;
        else
            ++c.onStreet;
    }
    return c;
}

} // namespace ab::street
