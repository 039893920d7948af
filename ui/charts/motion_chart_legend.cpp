// SPDX-License-Identifier: MIT
// The motion charts' legend and caption (chart_legend.h), in a band below the time axis:
// which entries the chart's lines get, and the chart's margin that makes room for them.
#include "motion_chart.h"

#include <QFontMetrics>
#include <QGraphicsSceneResizeEvent>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace ab::ui {

void MotionChart::followLegendStyle()
{
    connect(legend(), &QLegend::fontChanged, this, [this](const QFont& f) {
        QFont caption = f;
        const double ratio = look_.captionPt / look_.textPt;
        if (f.pointSizeF() > 0)
            caption.setPointSizeF(f.pointSizeF() * ratio);
        else
            caption.setPixelSize(std::max(1, int(f.pixelSize() * ratio + 0.5)));
        legend_->setFonts(f, caption);
        placeLegend();
    });
    connect(legend(), &QLegend::labelColorChanged, this, [this](const QColor& c) {
        legend_->setTextColour(c);
        updateLegend();
    });
    for (int a = 0; a < maxLines; ++a)
        for (QLineSeries* s : {lines_[a], overlays_[a], a < 3 ? references_[a] : nullptr})
            if (s)
                connect(s, &QXYSeries::penChanged, this, [this] { updateLegend(); });
}

void MotionChart::resizeEvent(QGraphicsSceneResizeEvent* event)
{
    QChart::resizeEvent(event);
    fitTitle();
    placeLegend();
}

void MotionChart::fitTitle()
{
    // Qt Charts cuts a title wider than the chart to "...": the longest of its forms that
    // fits is shown instead (a narrow panel, lecture mode's font), the shortest where none
    // does. A chart not laid out yet shows the whole title.
    if (titleForms_.isEmpty())
        return;
    // Qt Charts lays the title out in the margins' room less the text document's own margins.
    const double room = size().width() - margins().left() - margins().right() - 24.0;
    QString shown = size().width() < 1.0 ? titleForms_.front() : titleForms_.back();
    const QFontMetricsF fm(titleFont());
    for (const QString& form : titleForms_)
        if (fm.horizontalAdvance(form) <= room) {
            shown = form;
            break;
        }
    if (title() != shown)
        setTitle(shown);
}

void MotionChart::setCaption(const QString& caption)
{
    legend_->setCaption(caption);
    placeLegend();
}

void MotionChart::placeLegend()
{
    // The legend and the caption take a band at the bottom, below the time axis: the
    // chart's bottom margin is made as tall as they are.
    const double side = look_.figure ? look_.px(4.0) : 6.0;
    const double width = std::max(size().width() - 2.0 * side, 10.0);
    const double h = legend_->layout(width);
    const double gap = look_.figure ? look_.px(3.0) : 3.0;
    const int edge = look_.figure ? int(look_.px(3.0)) : 4;
    setMargins(
        QMargins(edge + insetLeft_, edge, edge + (look_.figure ? 0 : 4) + insetRight_, int(std::ceil(h + 2.0 * gap))));
    legend_->setPos(side, size().height() - h - gap);
}

void MotionChart::setPlotInset(int left, int right)
{
    if (left == insetLeft_ && right == insetRight_)
        return;
    insetLeft_ = left;
    insetRight_ = right;
    placeLegend();
}

void alignPlotAreas(const std::vector<MotionChart*>& charts)
{
    // The plot's edges without the inset: the left edge moves right by the inset's left,
    // the right edge left by its right.
    std::vector<double> left, right;
    for (const MotionChart* c : charts) {
        left.push_back(c->plotArea().left() - c->plotInsetLeft());
        right.push_back(c->plotArea().right() + c->plotInsetRight());
    }
    if (charts.size() < 2) {
        for (MotionChart* c : charts)
            c->setPlotInset(0, 0);
        return;
    }
    const double l = *std::max_element(left.begin(), left.end());
    const double r = *std::min_element(right.begin(), right.end());
    for (std::size_t i = 0; i < charts.size(); ++i)
        charts[i]->setPlotInset(int(std::lround(l - left[i])), int(std::lround(right[i] - r)));
}

void MotionChart::updateLegend()
{
    const bool comparing = !compareName_.isEmpty() && kind_ != ChartKind::Difference;
    const bool closedForm = reference_ && (kind_ == ChartKind::Position || kind_ == ChartKind::Velocity);
    std::vector<LegendEntry> entries;
    if (shownAxes_.empty()) { // not configured yet
        legend_->setEntries({});
        return;
    }
    if (shownAxes_.size() == 1 && (comparing || closedForm)) {
        // One line a run: each entry names its run, in its own pen.
        const int a = shownAxes_.front();
        entries.push_back({lines_[a]->pen(), lines_[a]->name()});
        if (closedForm)
            entries.push_back({references_[a]->pen(), references_[a]->name()});
        if (comparing)
            entries.push_back({overlays_[a]->pen(), overlays_[a]->name()});
    } else {
        // One entry a line of the run, then one a family: its style in a neutral ink.
        if (comparing)
            entries.push_back({QPen(Qt::NoPen), mainName_ + ":"});
        for (int a : shownAxes_)
            entries.push_back({lines_[a]->pen(), baseNames_[a]});
        // The closed form's entry in the text's colour (it stands for every axis); the
        // comparison's in its first line's, as a theme shows it (its own violet family).
        auto family = [&](QPen pen, LineFamily f, const QString& name) {
            if (f == LineFamily::ClosedForm)
                pen.setColor(legend_->textColour());
            entries.push_back({pen, name});
        };
        if (closedForm)
            family(references_[shownAxes_.front()]->pen(), LineFamily::ClosedForm, reference_->name);
        if (comparing)
            family(overlays_[shownAxes_.front()]->pen(), LineFamily::Comparison, compareName_);
    }
    if (kind_ == ChartKind::Difference) {
        // What is subtracted from what, as a legend entry (it wraps; a title would be cut).
        const QString run = mainName_.isEmpty() ? tr("simulation") : mainName_;
        const QString other = !compareName_.isEmpty() ? compareName_ : reference_ ? reference_->name : QString();
        entries.push_back({QPen(Qt::NoPen), other.isEmpty() ? tr("(no comparison or closed form to subtract)")
                                                            : tr("= %1 minus %2").arg(run, other)});
    }
    legend_->setEntries(std::move(entries));
    placeLegend();
}

int readableHeight(const MotionChart& c, int width)
{
    const QFontMetrics title(c.titleFont()), legend(c.legend()->font());
    const QFontMetrics labels(c.valueAxis()->labelsFont()), axisTitle(c.valueAxis()->titleFont());
    int legendWidth = 0;
    for (QLegendMarker* m : c.legend()->markers())
        if (m->isVisible() && m->series()->isVisible())
            legendWidth += legend.horizontalAdvance(m->label()) + 2 * legend.height() + 8;
    width = std::max(width, 200);
    const int legendRows = std::max(1, (legendWidth + width - 1) / width);
    const int plot = std::max(axisTitle.horizontalAdvance(c.valueAxis()->titleText()) + 24, 6 * labels.height());
    // The legend is drawn in the chart's bottom margin, which is made as tall as it once
    // the chart is laid out; before that, its rows as estimated here.
    const int legendBand = std::max(int(1.5 * legend.height()) * legendRows, c.margins().bottom());
    return int(1.5 * title.height()) + legendBand + c.margins().top() + 2 * labels.height() + axisTitle.height() +
           plot + 24;
}

} // namespace ab::ui
