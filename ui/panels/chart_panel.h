// SPDX-License-Identifier: MIT
// The live charts, stacked: position and velocity against time for the selected ball,
// energy, momentum and activity of the whole scene (each only where it applies), a ball chooser, and a context menu on
// each chart to export it (PNG, SVG) or the data behind all of them (CSV). The chart last clicked or hovered is the
// "current" one that Ctrl+E exports.
// Where the panel is too short for every shown chart at a readable height (a chart's
// labels would be cut), the charts are split into pages of as many as fit, one tab each
// ("Position + Velocity", "Energy + Momentum"); a chart off the current page keeps its
// wish to be shown (chartShown) and is drawn again when its page is chosen.
#pragma once

#include "ui/charts/motion_chart.h"

#include <QWidget>

#include <array>
#include <vector>

class QChartView;
class QComboBox;
class QLabel;
class QSpinBox;
class QTabBar;
class QVBoxLayout;

namespace ab::ui {

enum class ExportFormat { Png, Svg, Pdf, Csv };

class ChartPanel : public QWidget {
    Q_OBJECT
public:
    explicit ChartPanel(QWidget* parent = nullptr);

    // A new run of `scene` with `balls` balls, following ball `ball`, planned to `tEnd`.
    void configure(const SceneInfo& scene, int balls, int ball, double tEnd, const ChartUnits& units = {});
    // The View menu's wish: shown when on and the chart applies to the scene; a chart
    // that does not apply keeps the wish for the next scene it does.
    void setChartShown(ChartKind kind, bool on);
    bool chartShown(ChartKind kind) const;
    void showTrack(const MotionTrack& track);
    void setCursorTime(std::optional<double> t);
    // The seam for closed forms (core/reference/): drawn dashed; nullptr removes it.
    void setReference(const ReferenceMotion* reference);
    // The seam for a comparison run (MotionChart::setComparison): an empty `compareName`
    // removes its lines from every chart.
    void setComparison(const QString& mainName, const QString& compareName);
    void showComparisonTrack(const MotionTrack& track);
    // One chart's slot at a time, so that a playing window can spread a refresh of the
    // panel over several frames: the track, the comparison's (when not null) and the
    // cursor of slot `slot` in [0, kSlots). False for a slot whose chart is hidden, which
    // is left alone.
    static constexpr std::size_t kSlots = 9; // one per ChartKind
    bool refreshSlot(std::size_t slot, const MotionTrack& track, const MotionTrack* comparison,
                     std::optional<double> cursor);

    MotionChart* chart(ChartKind kind) const;
    QChartView* chartView(ChartKind kind) const;
    // The chart last pointed at while it is on the page shown, else the page's first: what
    // "Export current chart" exports.
    ChartKind currentChart() const;
    // The charts the scene shows (applying and wished for), in order, on any page.
    std::vector<ChartKind> shownCharts() const;
    // The pages' tabs (hidden while every shown chart fits on one page).
    // The pages of charts: tabs, or a list of them where the tabs do not fit whole
    // (pagesMenu); the tab bar keeps the current page either way.
    QTabBar* pages() const { return pages_; }
    QComboBox* pagesMenu() const { return pagesMenu_; }
    // The smallest height at which a chart keeps its title, legend and axis labels whole,
    // at the current chart font.
    int readableChartHeight() const;
    // Whether the chart is on the current page (and shown).
    bool onCurrentPage(ChartKind kind) const;
    static QString chartName(ChartKind kind); // "Position", translated

signals:
    void pageChanged();

    void ballRequested(int ball);
    void exportRequested(ab::ui::ChartKind kind, ab::ui::ExportFormat format);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    // Splits the shown charts into pages that fit the panel's height.
    void paginate();
    void showPage(int page);
    // The page tabs and the list that stands in for them, under the ball's row.
    void addPages(QVBoxLayout* layout);
    bool shown(std::size_t slot) const { return wanted_[slot] && applies_[slot]; }
    static constexpr std::size_t kinds = kSlots;
    // How many points a track is thinned to for the chart in `slot`.
    int columns(std::size_t slot) const;
    // Whether the chart in `slot` can be drawn now (the difference chart needs a
    // comparison or a closed form), and the views shown as the wishes and that say.
    bool available(std::size_t slot) const;
    void applyVisibility();
    // Lines up the plot areas of the charts shown (alignPlotAreas), after the layout settles.
    void scheduleAlignment();
    bool alignmentPending_ = false;
    std::array<bool, kinds> available_{};
    bool comparing_ = false;
    bool closedForm_ = false;
    std::array<MotionChart*, kinds> charts_{};
    std::array<QChartView*, kinds> views_{};
    std::array<QWidget*, kinds> holders_{}; // each view in a holder: the page hides the holder
    std::array<int, kinds> page_{};
    QTabBar* pages_;
    QComboBox* pagesMenu_; // the pages where the tabs do not fit whole
    std::array<bool, kinds> applies_{};
    std::array<bool, kinds> wanted_{};
    QSpinBox* ball_;
    QLabel* ballCount_;
    QLabel* hint_;
    ChartKind current_ = ChartKind::Position;
    bool updating_ = false;
};

} // namespace ab::ui
