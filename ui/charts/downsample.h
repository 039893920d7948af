// SPDX-License-Identifier: MIT
// Long runs are drawn from a few points per pixel column, never cut short: each column
// keeps its first, lowest, highest and last sample in time order, so every bounce peak and
// the exact ends of the run survive. Non-finite samples are never drawn.
#pragma once

#include <QList>
#include <QPointF>

#include <cstddef>
#include <limits>
#include <vector>

namespace ab::ui {

// At most about 4 * `columns` points of (t[i], y[i]); all of them when that many or fewer.
// Only the first `count` samples where fewer are asked for.
QList<QPointF> downsampleMinMax(const std::vector<double>& t, const std::vector<double>& y, int columns,
                                std::size_t count = std::numeric_limits<std::size_t>::max());

} // namespace ab::ui
