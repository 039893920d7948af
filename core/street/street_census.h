// SPDX-License-Identifier: MIT
// What the street's charts and its status line count in a state (docs/street.md): how many
// balls have passed the foot of each block, how many have left the run at the street's
// open foot, and the distribution of the speeds of those still on the street.
#pragma once

#include "street_layout.h"

#include "../state.h"

#include <vector>

namespace ab::street {

struct Census {
    std::vector<int> pastFoot; // per block: balls whose centres are beyond that block's foot
    int left = 0;              // balls that left the run at the open foot (centre x > xFoot)
    int onStreet = 0;          // the others
    double maxSpeed = 0.0;     // over the balls on the street
};

// A ball has left the run once its centre is beyond the open foot; the engine keeps it there,
// at rest, and every front end leaves it out.
inline bool hasLeft(const Layout& layout, double x)
{
    return x > layout.xFoot;
}

Census census(const Layout& layout, const State& s);

// Counts of the speeds |v| of the balls on the street in `bins` equal bins over
// [0, top] (a speed above top falls in the last bin).
std::vector<int> speedHistogram(const Layout& layout, const State& s, int bins, double top);

} // namespace ab::street
