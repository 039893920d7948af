// SPDX-License-Identifier: MIT
// The difference chart: the run's position minus the comparison run's at the same time,
// per axis, or minus the closed form when there is no comparison.
#include "motion_chart.h"

#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

// The value of `column` at time `t`, linear between the samples around it (exact at a
// sample); nothing outside the recorded span.
std::optional<double> valueAt(const std::vector<double>& times, const std::vector<double>& column, double t)
{
    if (times.empty() || t < times.front() || t > times.back())
        return std::nullopt;
    const auto after = std::lower_bound(times.begin(), times.end(), t);
    const auto i = static_cast<std::size_t>(after - times.begin());
    if (times[i] == t)
        return column[i];
    // t0 < t < t1: x = x0 + (x1 - x0) (t - t0) / (t1 - t0).
    const double t0 = times[i - 1], t1 = times[i];
    return column[i - 1] + (column[i] - column[i - 1]) * (t - t0) / (t1 - t0);
}

} // namespace

void MotionChart::keepDifferenceRun(const MotionTrack& track, int columns)
{
    // Evenly spaced samples, at most four a pixel column: a difference is smooth where
    // the runs agree and the point is where they part, so no min-max thinning is needed.
    diffT_.clear();
    for (auto& c : diffRun_)
        c.clear();
    const std::size_t n = track.size();
    if (n == 0)
        return;
    const std::size_t wanted = std::max<std::size_t>(2, 4 * static_cast<std::size_t>(std::max(columns, 1)));
    const std::size_t every = std::max<std::size_t>(1, (n + wanted - 1) / wanted);
    for (std::size_t i = 0; i < n; i += every) {
        diffT_.push_back(track.t()[i]);
        for (int a = 0; a < 3; ++a)
            diffRun_[a].push_back(track.p(a)[i]);
    }
    if ((n - 1) % every != 0) { // the last sample too: the chart reaches the run's end
        diffT_.push_back(track.t().back());
        for (int a = 0; a < 3; ++a)
            diffRun_[a].push_back(track.p(a).back());
    }
    if (std::isfinite(diffT_.back()) && diffT_.back() > tEnd_)
        setTimeSpan(diffT_.back());
}

void MotionChart::drawDifference(const MotionTrack* comparison)
{
    applyTimeRange();
    for (int a : shownAxes_) {
        QList<QPointF> points;
        points.reserve(static_cast<qsizetype>(diffT_.size()));
        for (std::size_t i = 0; i < diffT_.size(); ++i) {
            std::optional<double> other;
            if (comparison)
                other = valueAt(comparison->t(), comparison->p(a), diffT_[i]);
            else if (reference_)
                if (const std::optional<Kinematics> k = reference_->at(diffT_[i]))
                    other = k->p[a];
            const double d = other ? diffRun_[a][i] - *other : NAN;
            if (std::isfinite(d))
                points.append(QPointF(diffT_[i], d));
        }
        if (!points.isEmpty()) {
            const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                                      [](const QPointF& l, const QPointF& r) { return l.y() < r.y(); });
            updateValueRange(lo->y(), hi->y());
        }
        lines_[static_cast<std::size_t>(a)]->replace(points);
    }
    placeCursor();
}

} // namespace ab::ui
