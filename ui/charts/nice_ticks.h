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

// A printf format for tick labels `step` apart up to `largest` in size: "%g", except that
// whole steps past a million are written out ("6000000", not "%g"'s "6e+06", which a
// lecture hall does not read as six million).
inline const char* tickLabelFormat(double step, double largest)
{
    return largest >= 1e6 && largest < 1e12 && step >= 1.0 && step == std::floor(step) ? "%.0f" : "%g";
}

} // namespace ab::ui
