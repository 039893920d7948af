// SPDX-License-Identifier: MIT
// What the street's charts count in a state (docs/street.md): how many balls have passed the
// foot of each block, and how many have left the run at the street's open foot.
#pragma once

#include "street_layout.h"

#include "../state.h"

#include <vector>

namespace ab::street {

struct Census {
    std::vector<int> pastFoot; // per block: balls whose centres are beyond that block's foot
    int left = 0;              // balls that left the run at the open foot (centre x > xFoot)
    int onStreet = 0;          // the others
};

// A ball has left the run once its centre is beyond the open foot; the engine keeps it there,
// at rest, and every front end leaves it out.
inline bool hasLeft(const Layout& layout, double x)
{
    return x > layout.xFoot;
}

Census census(const Layout& layout, const State& s);

} // namespace ab::street
