// SPDX-License-Identifier: MIT
#include "downsample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace ab::ui {

namespace {

bool finite(double t, double y)
{
    return std::isfinite(t) && std::isfinite(y);
}

// Appends the column [begin, end): first, min, max, last (indices sorted, duplicates once).
void appendColumn(const std::vector<double>& t, const std::vector<double>& y, std::size_t begin, std::size_t end,
                  QList<QPointF>& out)
{
    std::size_t first = end, last = end, lo = end, hi = end;
    for (std::size_t i = begin; i < end; ++i) {
        if (!finite(t[i], y[i]))
            continue;
        if (first == end)
            first = i;
        last = i;
        if (lo == end || y[i] < y[lo])
            lo = i;
        if (hi == end || y[i] > y[hi])
            hi = i;
    }
    if (first == end)
        return;
    std::array<std::size_t, 4> picks{first, lo, hi, last};
    std::sort(picks.begin(), picks.end());
    const auto unique = std::unique(picks.begin(), picks.end());
    for (auto it = picks.begin(); it != unique; ++it)
        out.append(QPointF(t[*it], y[*it]));
}

} // namespace

QList<QPointF> downsampleMinMax(const std::vector<double>& t, const std::vector<double>& y, int columns,
                                std::size_t count)
{
    if (t.size() != y.size())
        throw std::logic_error("downsampleMinMax: series of different lengths");
    const std::size_t n = std::min(t.size(), count);
    const std::size_t cols = static_cast<std::size_t>(std::max(columns, 1));
    QList<QPointF> out;
    if (n <= 4 * cols) {
        out.reserve(static_cast<qsizetype>(n));
        for (std::size_t i = 0; i < n; ++i)
            if (finite(t[i], y[i]))
                out.append(QPointF(t[i], y[i]));
        return out;
    }
    out.reserve(static_cast<qsizetype>(4 * cols));
    for (std::size_t c = 0; c < cols; ++c)
        appendColumn(t, y, c * n / cols, (c + 1) * n / cols, out);
    return out;
}

} // namespace ab::ui
