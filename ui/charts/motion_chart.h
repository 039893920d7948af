// SPDX-License-Identifier: MIT
// The charts of the window and of `amazeballs-cli chart`, from one code path: position,
// velocity or energy against time for the selected ball, one line per axis the scene
// has (bounce1d: y alone), downsampled for drawing, a time cursor, and a dashed closed
// form beside the simulation when one is given.
#pragma once

#include "motion_track.h"

#include "core/scene.h"

#include <QChart>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

class QLineSeries;
class QValueAxis;

namespace ab::ui {

enum class ChartKind { Position, Velocity, Energy };

const std::vector<ChartKind>& allChartKinds();
std::string_view chartKey(ChartKind kind); // "position", "velocity", "energy"
std::optional<ChartKind> parseChartKind(std::string_view key);

// A closed-form motion (from core/reference/ where the core has one): the ball's
// position and velocity at time t, or nothing where the closed form does not apply.
struct Kinematics {
    Eigen::Vector3d p, v;
};
struct ReferenceMotion {
    QString name; // shown in the legend, e.g. "closed form"
    std::function<std::optional<Kinematics>(double t)> at;
};

class MotionChart : public QChart {
    Q_OBJECT
public:
    explicit MotionChart(ChartKind kind);

    ChartKind kind() const { return kind_; }
    // Axes, titles and units for `scene`, ball `ball` (0-based); clears the lines.
    void configure(const SceneInfo& scene, int ball);
    // The time axis spans [0, tEnd] (the planned run), growing if the run goes past it.
    void setTimeSpan(double tEnd);
    // Redraws the lines from `track`, at most about 4 points per pixel column.
    void showTrack(const MotionTrack& track, int columns);
    void setCursorTime(std::optional<double> t);
    // The seam for closed forms: drawn dashed over the time span; nullptr removes it.
    void setReference(const ReferenceMotion* reference, int columns = 600);
    bool hasReference() const { return reference_.has_value(); }

    // The axes drawn: {1} for a vertical-only scene, {0, 1, 2} otherwise; the energy
    // chart has one line, reported as axis 0.
    const std::vector<int>& shownAxes() const { return shownAxes_; }
    QLineSeries* line(int index) const { return lines_[static_cast<std::size_t>(index)]; }
    QLineSeries* referenceLine(int index) const { return references_[static_cast<std::size_t>(index)]; }
    QLineSeries* cursorLine() const { return cursor_; }

private:
    void applyFonts();
    void applyTimeRange();
    void updateValueRange(double lo, double hi);
    void placeCursor();
    void sampleReference();
    const std::vector<double>& column(const MotionTrack& track, int axis) const;
    double component(const Kinematics& k, int axis) const;

    ChartKind kind_;
    QValueAxis* timeAxis_;
    QValueAxis* valueAxis_;
    std::array<QLineSeries*, 3> lines_{};
    std::array<QLineSeries*, 3> references_{};
    QLineSeries* cursor_;
    std::vector<int> shownAxes_;
    double tEnd_ = 1.0;
    std::optional<double> cursorT_;
    std::optional<ReferenceMotion> reference_;
    int referenceColumns_ = 600;
    double lo_ = 0.0, hi_ = 0.0;
    bool haveRange_ = false;
};

} // namespace ab::ui
