// SPDX-License-Identifier: MIT
// Tick spacing a reader takes in at a glance, shared by the charts and the 3D view's scales.
#pragma once

#include <algorithm>
#include <cmath>

namespace ab::ui {

// The smallest of 1, 2 or 5 times a power of ten giving at most about `ticks` (+25%)
// intervals over `span`.
inline double niceTickStep(double span, int ticks)
{
    if (!(span > 0.0) || !std::isfinite(span))
        return 1.0;
    const double most = 1.25 * std::max(ticks, 1);
    const double decade = std::pow(10.0, std::floor(std::log10(span / most)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (span / (m * decade) <= most * (1.0 + 1e-9))
            return m * decade;
    return 10.0 * decade;
}

} // namespace ab::ui
