// SPDX-License-Identifier: MIT
// Tick spacing a reader takes in at a glance, shared by the charts and the 3D view's scales.
#pragma once

#include <algorithm>
#include <cmath>

namespace ab::ui {

// 1, 2 or 5 times a power of ten, giving about `ticks` intervals over `span`.
inline double niceTickStep(double span, int ticks)
{
    if (!(span > 0.0) || !std::isfinite(span))
        return 1.0;
    const double raw = span / std::max(ticks, 1);
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * decade * (1.0 + 1e-9))
            return m * decade;
    return 10.0 * decade;
}

} // namespace ab::ui
