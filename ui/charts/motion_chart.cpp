// SPDX-License-Identifier: MIT
#include "motion_chart.h"

#include "ui/i18n/core_text.h"

#include <QGraphicsSceneResizeEvent>

#include "downsample.h"
#include "nice_ticks.h"

#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

// [lo, hi] widened to whole ticks, which fall on multiples of the step (zero among them).
// Fixed ticks: Qt places them at min + i (max - min) / (n - 1), exact at the ends, where its
// dynamic ticks add the step up from the bottom and label a zero at the top of a range
// [-0.5, 0] as "-2.77556e-17".
void setNiceRange(QValueAxis* axis, double lo, double hi, int ticks)
{
    if (!(hi > lo))
        return;
    const double step = niceTickStep(hi - lo, ticks);
    const double bottom = std::floor(lo / step) * step, top = std::ceil(hi / step) * step;
    axis->setTickType(QValueAxis::TicksFixed);
    axis->setTickCount(std::max(2, int(std::lround((top - bottom) / step)) + 1));
    axis->setLabelFormat(tickLabelFormat(step, std::max(std::abs(bottom), std::abs(top))));
    axis->setRange(bottom, top);
}

} // namespace

MotionChart::MotionChart(ChartKind kind, const ChartLook& look)
    : kind_(kind), look_(look), legend_(new ChartLegend(this)), timeAxis_(new QValueAxis), valueAxis_(new QValueAxis),
      cursor_(new QLineSeries)
{
    setTheme(QChart::ChartThemeLight); // before the fonts: a theme resets them
    legend()->hide();                  // drawn by legend_, with each line's pen
    addAxis(timeAxis_, Qt::AlignBottom);
    addAxis(valueAxis_, Qt::AlignLeft);
    auto add = [this](QLineSeries* s) {
        addSeries(s);
        s->attachAxis(timeAxis_);
        s->attachAxis(valueAxis_);
        return s;
    };
    for (int a = 0; a < maxLines; ++a) {
        lines_[a] = add(new QLineSeries);
        overlays_[a] = add(new QLineSeries);
        if (a < 3)
            references_[a] = add(new QLineSeries);
    }
    if (kind == ChartKind::Activity) {
        // Impacts per unit of time on a second axis, on the right: their scale has
        // nothing to do with a number of balls.
        rateAxis_ = new QValueAxis;
        addAxis(rateAxis_, Qt::AlignRight);
        for (QLineSeries* s : {lines_[1], overlays_[1]}) {
            s->detachAxis(valueAxis_);
            s->attachAxis(rateAxis_);
        }
        rateAxis_->setLabelFormat("%g");
        // One set of grid lines, the left axis's: the right's (0-180 beside 0-160) fell between them.
        rateAxis_->setGridLineVisible(false);
        rateAxis_->setMinorGridLineVisible(false);
        rateAxis_->setLinePenColor(lineColour(kind, 1));
        rateAxis_->setLabelsColor(lineColour(kind, 1).darker(120));
        valueAxis_->setLinePenColor(lineColour(kind, 0));
        valueAxis_->setLabelsColor(lineColour(kind, 0).darker(120));
    }
    add(cursor_);
    cursor_->setPen(cursorPen(look_)); // after addSeries: adding applies the theme's pen
    applyPens();
    applyTimeRange();
    timeAxis_->setLabelFormat("%g");
    valueAxis_->setLabelFormat("%g");
    applyFonts();
    followLegendStyle();
}

void MotionChart::applyPens()
{
    for (int a = 0; a < maxLines; ++a) {
        lines_[a]->setPen(linePen(kind_, a, a, LineFamily::Run, look_));
        overlays_[a]->setPen(linePen(kind_, a, a, LineFamily::Comparison, look_));
        overlays_[a]->setProperty(comparisonOfProperty, lineColour(kind_, a, LineFamily::Run));
        if (a < 3)
            references_[a]->setPen(linePen(kind_, a, a, LineFamily::ClosedForm, look_));
    }
}

void MotionChart::restyleRunLines()
{
    // The run's first shown line is solid, the next ones dash-dot and dash-dot-dot: only
    // the style changes, the colour and width stay as the theme or lecture mode set them
    // (and the pen ui/theme/appearance.cpp scales from, kept as "ab_basePen", follows).
    for (int a = 0; a < maxLines; ++a) {
        const auto at = std::find(shownAxes_.begin(), shownAxes_.end(), a);
        const int order = at == shownAxes_.end() ? 0 : int(at - shownAxes_.begin());
        const Qt::PenStyle style = linePen(kind_, a, order, LineFamily::Run, look_).style();
        QPen pen = lines_[a]->pen();
        if (pen.style() == style)
            continue;
        pen.setStyle(style);
        lines_[a]->setPen(pen);
        const QVariant base = lines_[a]->property("ab_basePen");
        if (base.canConvert<QPen>()) {
            QPen b = base.value<QPen>();
            b.setStyle(style);
            lines_[a]->setProperty("ab_basePen", QVariant::fromValue(b));
        }
    }
}

void MotionChart::applyFonts()
{
    setTitleFont(look_.font(font(), look_.titlePt, true));
    const QFont labels = look_.font(font(), look_.textPt);
    for (QValueAxis* axis : {timeAxis_, valueAxis_, rateAxis_}) {
        if (!axis)
            continue;
        axis->setLabelsFont(labels);
        axis->setTitleFont(labels);
    }
    legend()->setFont(labels); // hidden, but what a theme or lecture mode scales (followLegendStyle)
    legend_->setFonts(labels, look_.font(font(), look_.captionPt));
    legend_->setSampleLength(look_.px(look_.textPt) * 2.6);
    fitTitle();
    placeLegend();
}

void MotionChart::configure(const SceneInfo& scene, int ball, const ChartUnits& units)
{
    static const char* axisNames[5][3] = {{"x", "y", "z"},
                                          {"vx", "vy", "vz"},
                                          {"px", "py", "pz"},
                                          {"\u0394x", "\u0394y", "\u0394z"},
                                          {"\u03c9x", "\u03c9y", "\u03c9z"}};
    spins_ = units.spins;
    meanOver_ = units.energyMeanOver;
    chooseLines(scene.axes, units);
    QString names[maxLines];
    nameChart(scene, ball, units, names);
    fitTitle();
    timeAxis_->setTitleText(tr("t (%1)").arg(coreText(scene.timeUnit)));
    for (int a = 0; a < maxLines; ++a) {
        const bool shown = std::find(shownAxes_.begin(), shownAxes_.end(), a) != shownAxes_.end();
        lines_[a]->clear();
        if (a < 3 && names[a].isEmpty())
            names[a] = QString::fromUtf8(axisNames[kind_ == ChartKind::Velocity     ? 1
                                                   : kind_ == ChartKind::Momentum   ? 2
                                                   : kind_ == ChartKind::Difference ? 3
                                                   : kind_ == ChartKind::Spin       ? 4
                                                                                    : 0][a]);
        baseNames_[a] = names[a];
        lines_[a]->setVisible(shown);
        overlays_[a]->clear();
        if (a < 3)
            references_[a]->clear();
    }
    diffT_.clear();
    restyleRunLines();
    applyNames();
    haveRange_ = false;
    rateHi_ = 0.0;
    // A closed form belongs to the run it was made for: the caller sets the new run's
    // (setReference) after this, and the old one must not stretch the new value axis.
    reference_.reset();
    setNiceRange(valueAxis_, 0.0, 1.0, 6);
    if (rateAxis_)
        setNiceRange(rateAxis_, 0.0, 1.0, 6);
    sampleReference();
    placeCursor();
}

void MotionChart::setTimeSpan(double tEnd)
{
    if (!(std::isfinite(tEnd) && tEnd > 0.0))
        return;
    tEnd_ = tEnd;
    applyTimeRange();
    sampleReference();
}

void MotionChart::applyTimeRange()
{
    // About one labelled tick per 80 pixels of plot width (5 before the first layout).
    const double width = plotArea().width();
    const int ticks = width > 0.0 ? std::clamp(int(width / 80.0), 3, 10) : 5;
    setNiceRange(timeAxis_, 0.0, tEnd_, ticks);
}

const std::vector<double>& MotionChart::column(const MotionTrack& track, int line)
{
    switch (kind_) {
    case ChartKind::Position:
        return track.p(line);
    case ChartKind::Velocity:
        return track.v(line);
    case ChartKind::Energy: {
        // Where the balls turn, line 0 is the kinetic energy of translation and line 4 of
        // rotation; line 5 is what the balls that left the street took with them.
        const std::vector<double>* parts[maxLines] = {spins_ ? &track.translation() : &track.kinetic(),
                                                      &track.potential(),
                                                      &track.energy(),
                                                      &track.spring(),
                                                      &track.rotation(),
                                                      &track.left()};
        if (meanOver_ <= 0)
            return *parts[line];
        derived_.resize(parts[line]->size()); // the mean a ball: the sum over the n balls / n
        std::transform(parts[line]->begin(), parts[line]->end(), derived_.begin(),
                       [n = double(meanOver_)](double sum) { return sum / n; });
        return derived_;
    }
    case ChartKind::Spin:
        return track.w(line);
    case ChartKind::Momentum:
        return track.momentum(line);
    case ChartKind::Difference:
        return track.p(line);
    case ChartKind::Activity:
        if (line == 0)
            return track.moving();
        // Impacts counted over the last 1/100 of the planned run: long enough to hold
        // several impacts at the report's 150 balls, short enough to show how they die out.
        derived_ = impactRate(track, tEnd_ / 100.0);
        return derived_;
    case ChartKind::FootRate:
        // Counted over the last 1/60 of the planned run (half a second of the street's
        // 30 s): the flood's front passes a foot in a few seconds.
        derived_ = passingRate(track.t(), track.pastFoot(line), tEnd_ / 60.0);
        return derived_;
    case ChartKind::Speeds:
        return track.speed(line);
    }
    throw std::logic_error("chart kind without data");
}

void MotionChart::applyNames()
{
    // The difference chart overlays nothing: its lines are the run minus the other one.
    const bool comparing = !compareName_.isEmpty() && kind_ != ChartKind::Difference;
    for (int a = 0; a < maxLines; ++a) {
        const bool shown = std::find(shownAxes_.begin(), shownAxes_.end(), a) != shownAxes_.end();
        lines_[a]->setName(comparing ? baseNames_[a] + " (" + mainName_ + ")" : baseNames_[a]);
        overlays_[a]->setName(baseNames_[a] + " (" + compareName_ + ")");
        overlays_[a]->setVisible(comparing && shown);
        if (!comparing)
            overlays_[a]->clear();
        if (a < 3)
            references_[a]->setName(baseNames_[a] + " (" + (reference_ ? reference_->name : tr("closed form")) + ")");
    }
    updateLegend();
}

void MotionChart::setComparison(const QString& mainName, const QString& compareName)
{
    if (mainName == mainName_ && compareName == compareName_)
        return;
    mainName_ = mainName;
    compareName_ = compareName;
    applyNames();
}

void MotionChart::showComparisonTrack(const MotionTrack& track, int columns)
{
    if (compareName_.isEmpty())
        return;
    if (kind_ == ChartKind::Difference) {
        drawDifference(&track);
        return;
    }
    drawTrack(track, columns, overlays_);
}

void MotionChart::showTrack(const MotionTrack& track, int columns)
{
    if (kind_ == ChartKind::Difference) {
        keepDifferenceRun(track, columns);
        if (compareName_.isEmpty())
            drawDifference(nullptr); // against the closed form; a comparison comes next
        return;
    }
    drawTrack(track, columns, lines_);
}

void MotionChart::drawTrack(const MotionTrack& track, int columns, const std::array<QLineSeries*, maxLines>& series)
{
    if (!track.empty() && std::isfinite(track.t().back()) && track.t().back() > tEnd_)
        setTimeSpan(track.t().back());
    else
        applyTimeRange(); // the plot may have been resized since
    // The selected ball's own lines end where it left the run (the street's foot); the
    // speeds where the last ball left the street.
    const bool ballsOwn = kind_ == ChartKind::Position || kind_ == ChartKind::Velocity || kind_ == ChartKind::Spin;
    const std::size_t count = ballsOwn                     ? track.ballSamples()
                              : kind_ == ChartKind::Speeds ? track.streetSamples()
                                                           : track.size();
    for (int a : shownAxes_) {
        const QList<QPointF> points = downsampleMinMax(track.t(), column(track, a), columns, count);
        if (!points.isEmpty()) {
            const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                                      [](const QPointF& l, const QPointF& r) { return l.y() < r.y(); });
            if (kind_ == ChartKind::Activity && a == 1)
                updateRateRange(hi->y());
            else
                updateValueRange(lo->y(), hi->y());
        }
        series[static_cast<std::size_t>(a)]->replace(points); // replace(), not append(): quadratic in Qt Charts 6.4
    }
    placeCursor();
}

void MotionChart::updateRateRange(double hi)
{
    // From zero (a rate is never negative), growing only, as the value axis.
    rateHi_ = std::max(rateHi_, hi);
    const int ticks = std::clamp(int(plotArea().height() / 40.0), 4, 8);
    setNiceRange(rateAxis_, 0.0, rateHi_ > 0.0 ? 1.05 * rateHi_ : 1.0, ticks);
}

void MotionChart::updateValueRange(double lo, double hi)
{
    // The range only grows during a run, so the axis does not jitter as points arrive.
    lo_ = haveRange_ ? std::min(lo_, lo) : lo;
    hi_ = haveRange_ ? std::max(hi_, hi) : hi;
    haveRange_ = true;
    // A little room above and below, never across zero (a height stays above the floor).
    const double pad = hi_ > lo_ ? 0.01 * (hi_ - lo_) : std::max(1.0, std::abs(hi_) * 0.1);
    const double lower = lo_ >= 0.0 ? std::max(0.0, lo_ - pad) : lo_ - pad;
    const double upper = hi_ <= 0.0 ? std::min(0.0, hi_ + pad) : hi_ + pad;
    // About one labelled tick per 40 pixels of plot height, so short charts stay legible.
    const int ticks = std::clamp(int(plotArea().height() / 40.0), 4, 8);
    setNiceRange(valueAxis_, lower, upper, ticks);
}

void MotionChart::setCursorTime(std::optional<double> t)
{
    if (t && !std::isfinite(*t))
        t.reset();
    if (t == cursorT_)
        return;
    cursorT_ = t;
    placeCursor();
}

void MotionChart::placeCursor()
{
    cursor_->setVisible(cursorT_.has_value()); // not even an empty element without one
    if (!cursorT_) {
        cursor_->clear();
        return;
    }
    cursor_->replace(QList<QPointF>{{*cursorT_, valueAxis_->min()}, {*cursorT_, valueAxis_->max()}});
}

double MotionChart::component(const Kinematics& k, int axis) const
{
    return kind_ == ChartKind::Velocity ? k.v[axis] : k.p[axis];
}

void MotionChart::setReference(const ReferenceMotion* reference, int columns)
{
    if (reference && reference->at)
        reference_ = *reference;
    else
        reference_.reset();
    referenceColumns_ = std::max(columns, 2);
    sampleReference();
}

void MotionChart::sampleReference()
{
    const bool drawn = reference_ && (kind_ == ChartKind::Position || kind_ == ChartKind::Velocity);
    if (!drawn)
        updateLegend();
    for (int a = 0; a < 3; ++a) {
        const bool shown = drawn && std::find(shownAxes_.begin(), shownAxes_.end(), a) != shownAxes_.end();
        QList<QPointF> points;
        for (int i = 0; shown && i <= 2 * referenceColumns_; ++i) {
            const double t = tEnd_ * i / (2.0 * referenceColumns_);
            const std::optional<Kinematics> k = reference_->at(t);
            if (k && std::isfinite(component(*k, a))) {
                points.append(QPointF(t, component(*k, a)));
                updateValueRange(points.back().y(), points.back().y());
            }
        }
        if (drawn)
            references_[a]->setName(baseNames_[a] + " (" + reference_->name + ")");
        references_[a]->replace(points);
    }
    if (drawn)
        updateLegend();
    placeCursor();
}

} // namespace ab::ui
