// SPDX-License-Identifier: MIT
// The charts of the window and of `amazeballs-cli chart`, from one code path: position
// or velocity against time for the selected ball, one line per axis the scene has
// (bounce1d: y alone); and what the whole scene conserves: kinetic, potential (and
// spring) and total energy, total momentum per axis (scenes of two or more balls), and
// the number of moving balls with the impacts per unit of time (many-balls). All are
// downsampled for drawing, with a time cursor, and a dashed closed form beside the
// position and velocity when one is given. A comparison run's lines (the same scene
// computed another way) are overlaid, dotted and in a darker family of colours, on every
// chart; the difference chart draws the run minus the comparison (or minus the closed
// form when there is no comparison), per axis. The legend and an optional caption are
// drawn below the plot (chart_legend.h), each entry in its line's own pen.
#pragma once

#include "chart_legend.h"
#include "chart_style.h"
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

enum class ChartKind { Position, Velocity, Energy, Momentum, Activity, Difference, Spin, FootRate, Speeds };

const std::vector<ChartKind>& allChartKinds();
// "position", "velocity", "energy", "momentum", "activity", "difference", "spin",
// "foot-rate", "speeds"
std::string_view chartKey(ChartKind kind);
std::optional<ChartKind> parseChartKind(std::string_view key);
// Whether the chart means something for the scene: momentum needs two balls or more
// (one ball's momentum only shows gravity and the walls), activity needs many. The
// difference chart applies to every scene but is drawn only beside a comparison run or
// a closed form (differenceDrawable). The spin chart needs balls that turn: ask
// chartApplies with the run's ChartUnits. The foot-rate and speed charts are the street's.
bool chartApplies(ChartKind kind, SceneId scene);
bool differenceDrawable(bool comparing, bool closedForm);

// What the energy and momentum charts are measured with (ConservationMeter's answers).
struct ChartUnits {
    bool perUnitMass = true; // the report model's equal masses; false: the physical model's kg
    bool spring = false;     // the spring floor: its energy gets a line of its own
    bool spins = false;      // the balls turn: kinetic energy splits into translation and rotation, and
                             // the spin chart applies
    int streetBlocks = 0;    // the street's blocks (stage 5): the foot-rate chart's lines follow footBlocks()
    int energyMeanOver = 0;  // > 0: the energy chart draws the mean a ball, the meter's sums over this many
                             // balls divided by it (the street's n: its sums run to millions)
};

// What `meter` measures the run's charts with.
ChartUnits chartUnitsOf(const ConservationMeter& meter);
// The same for the run `spec` describes: the street's blocks too.
ChartUnits chartUnitsOf(const ConservationMeter& meter, const RunSpec& spec);
// chartApplies for the run the units are of: the spin chart only where the balls turn.
bool chartApplies(ChartKind kind, SceneId scene, const ChartUnits& units);
// chartApplies for the run `spec` describes (its balls turn: ballsTurn).
bool chartApplies(ChartKind kind, const RunSpec& spec);

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
    static constexpr int maxLines = 6; // the energy chart's parts on the street
    explicit MotionChart(ChartKind kind, const ChartLook& look = ChartLook::window());

    ChartKind kind() const { return kind_; }
    const ChartLook& look() const { return look_; }
    // Axes, titles and units for `scene`, ball `ball` (0-based); clears the lines and the
    // closed form (set the new run's with setReference).
    void configure(const SceneInfo& scene, int ball, const ChartUnits& units = {});
    // The time axis spans [0, tEnd] (the planned run), growing if the run goes past it.
    void setTimeSpan(double tEnd);
    // Redraws the lines from `track`, at most about 4 points per pixel column.
    void showTrack(const MotionTrack& track, int columns);
    void setCursorTime(std::optional<double> t);
    // The seam for closed forms: drawn dashed over the time span; nullptr removes it.
    void setReference(const ReferenceMotion* reference, int columns = 600);
    bool hasReference() const { return reference_.has_value(); }
    // The seam for a comparison run: the legend names both runs ("y (report)", "y
    // (physical rk4)") and showComparisonTrack draws the second one's lines. An empty
    // `compareName` removes the overlay.
    void setComparison(const QString& mainName, const QString& compareName);
    void showComparisonTrack(const MotionTrack& track, int columns);
    bool hasComparison() const { return !compareName_.isEmpty(); }
    // A caption under the legend (how the figure was made); empty: none.
    void setCaption(const QString& caption);
    // Room added left and right of the plot (pixels), so that charts stacked in a column
    // have their plot areas at one x (alignPlotAreas); 0 for a chart alone.
    void setPlotInset(int left, int right);
    int plotInsetLeft() const { return insetLeft_; }
    int plotInsetRight() const { return insetRight_; }
    // The legend as drawn: one entry per line of the run, then one per family of lines
    // (the run, the closed form, the comparison) when there are several, each with the pen
    // it stands for.
    const std::vector<LegendEntry>& legendEntries() const { return legend_->entries(); }
    ChartLegend* legendItem() const { return legend_; }

    // The lines drawn. Position, velocity: the axes, {1} for a vertical-only scene, {0,
    // 1, 2} otherwise; momentum and spin {0, 1, 2} (x, y, z; spin {1} for a vertical-only
    // scene). Foot rate: one line per charted block (footBlocks); speeds: the 10th, 50th
    // and 90th percentiles and the fastest. Energy: 0 kinetic (of translation where the balls turn), 1 potential,
    // 2 total, 3 spring (when the spring floor is on), 4 rotation (where the balls turn). Activity: 0 moving balls
    // (left axis), 1 impacts per unit of time (right axis). Difference: the position axes.
    const std::vector<int>& shownAxes() const { return shownAxes_; }
    QValueAxis* valueAxis() const { return valueAxis_; }
    QValueAxis* rateAxis() const { return rateAxis_; } // activity only, else nullptr
    QLineSeries* line(int index) const { return lines_[static_cast<std::size_t>(index)]; }
    QLineSeries* referenceLine(int index) const { return references_[static_cast<std::size_t>(index)]; }
    QLineSeries* comparisonLine(int index) const { return overlays_[static_cast<std::size_t>(index)]; }
    QLineSeries* cursorLine() const { return cursor_; }

protected:
    void resizeEvent(QGraphicsSceneResizeEvent* event) override;

private:
    void applyFonts();
    void fitTitle(); // the longest of titleForms_ that fits the chart's width
    void applyPens();
    void restyleRunLines();
    // The drawn legend follows what a theme or lecture mode sets on QLegend (hidden: its
    // font and label colour) and on the lines' pens.
    void followLegendStyle();
    void updateLegend();
    void placeLegend();
    // The difference chart: the run's positions at up to 4 samples a column, then minus
    // the comparison (interpolated at the same times) or the closed form.
    void keepDifferenceRun(const MotionTrack& track, int columns);
    void drawDifference(const MotionTrack* comparison);
    void applyTimeRange();
    void updateValueRange(double lo, double hi);
    void updateRateRange(double hi);
    void placeCursor();
    void applyNames();
    // The lines the chart draws (shownAxes_) for a scene of `sceneAxes` axes (1 or 3) and `units`
    // (motion_chart_titles.cpp).
    void chooseLines(int sceneAxes, const ChartUnits& units);
    // Its title forms, value axis title and line names (`names`, maxLines of them; those left
    // empty are the axes' x, y, z), for ball `ball` of `scene`.
    void nameChart(const SceneInfo& scene, int ball, const ChartUnits& units, QString* names);
    // The energy chart's part of nameChart, its energy in `energyUnit`.
    void nameEnergy(const SceneInfo& scene, const ChartUnits& units, const QString& energyUnit, QString* names);
    // The foot-rate chart's line names, for a street of `blocks` blocks.
    static void nameFeet(QString* names, int blocks);
    // The lines of `track` into `series`, widening the axes to hold them.
    void drawTrack(const MotionTrack& track, int columns, const std::array<QLineSeries*, maxLines>& series);
    void sampleReference();
    const std::vector<double>& column(const MotionTrack& track, int line);
    double component(const Kinematics& k, int axis) const;

    ChartKind kind_;
    ChartLook look_;
    ChartLegend* legend_;
    QValueAxis* timeAxis_;
    QValueAxis* valueAxis_;
    QValueAxis* rateAxis_ = nullptr;
    std::array<QLineSeries*, maxLines> lines_{};
    std::array<QLineSeries*, 3> references_{};
    std::array<QLineSeries*, maxLines> overlays_{};
    std::array<QString, maxLines> baseNames_;
    QString mainName_, compareName_, who_;
    QStringList titleForms_; // the title, then shorter forms of it, longest first
    QLineSeries* cursor_;
    std::vector<int> shownAxes_;
    bool spins_ = false; // the energy chart splits kinetic energy (ChartUnits::spins)
    int meanOver_ = 0;   // ChartUnits::energyMeanOver
    double tEnd_ = 1.0;
    std::optional<double> cursorT_;
    std::optional<ReferenceMotion> reference_;
    int referenceColumns_ = 600;
    double lo_ = 0.0, hi_ = 0.0;
    bool haveRange_ = false;
    double rateHi_ = 0.0;
    std::vector<double> derived_; // a line worked out from the track: a rate, or the energy a ball
    std::vector<double> diffT_;
    std::array<std::vector<double>, 3> diffRun_;
    int insetLeft_ = 0, insetRight_ = 0;
};

// Lines up the plot areas of charts stacked in one column and as wide: each chart's plot
// starts where the widest value axis' labels leave the plot of the chart that has them, and
// ends where the narrowest plot ends, so one time is at one x down the column and the
// charts' cursors make one line. A lone chart has no inset.
void alignPlotAreas(const std::vector<MotionChart*>& charts);

// The height `chart` needs at `width` pixels to read whole: its title, the legend's rows,
// the time axis's labels and title, and a plot at least as tall as the value axis's title
// is long (Qt Charts cuts a longer one to "...") and six tick labels high. The chart panel
// pages its charts by it, and an exported clip stacks as many as fit at it.
int readableHeight(const MotionChart& chart, int width);

} // namespace ab::ui
