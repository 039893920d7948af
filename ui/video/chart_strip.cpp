// SPDX-License-Identifier: MIT
#include "chart_strip.h"

#include "core/diagnostics/conservation.h"

#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QLineSeries>
#include <QPainter>
#include <QValueAxis>

#include <algorithm>

namespace ab::ui {

std::vector<ChartKind> chartsFor(const RunSpec& spec)
{
    std::vector<ChartKind> kinds;
    for (ChartKind k : allChartKinds())
        if (chartApplies(k, spec))
            kinds.push_back(k);
    return kinds;
}

ChartStrip::ChartStrip(const Simulation& sim, int ball, const std::vector<ChartKind>& kinds, const MotionTrack& track,
                       double tEnd, QSize size)
{
    if (kinds.empty())
        return;
    // As many charts as fit at the height each needs to read whole (readableHeight: a
    // velocity chart's rotated axis title sets it, which 220 pixels cut to "velocity
    // (unit/st..."), the first ones first: position and velocity. Each is drawn at least
    // that tall and scaled to its slot, so the window's fonts keep their size relative to
    // the plot and no text is cut.
    const ConservationMeter meter(sim);
    std::vector<int> need;
    for (ChartKind kind : kinds) {
        MotionChart probe(kind);
        probe.configure(sim.scene(), ball, chartUnitsOf(meter, sim.spec()));
        need.push_back(std::max(kMinHeight, readableHeight(probe, size.width())));
    }
    std::size_t n = 1;
    for (int tallest = need[0]; n < kinds.size(); ++n) {
        tallest = std::max(tallest, need[n]);
        if (int(n + 1) * tallest > size.height())
            break;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const int top = size.height() * int(i) / int(n), bottom = size.height() * int(i + 1) / int(n);
        panels_.push_back(
            drawPanel(sim, ball, kinds[i], track, tEnd, QRect(0, top, size.width(), bottom - top), need[i]));
    }
}

ChartStrip::Panel ChartStrip::drawPanel(const Simulation& sim, int ball, ChartKind kind, const MotionTrack& track,
                                        double tEnd, QRect rect, int need)
{
    const ConservationMeter meter(sim);
    const double scale = std::min(1.0, double(rect.height()) / need); // pixels per chart unit
    const QSizeF logical(rect.width() / scale, rect.height() / scale);
    MotionChart chart(kind);
    chart.configure(sim.scene(), ball, chartUnitsOf(meter, sim.spec()));
    chart.setTimeSpan(tEnd);
    // Laid out at its size before the lines go in (the time ticks follow the plot's width).
    QGraphicsScene scene;
    scene.addItem(&chart);
    chart.setGeometry(QRectF(QPointF(0, 0), logical));
    scene.setSceneRect(QRectF(QPointF(0, 0), logical));
    if (chart.layout())
        chart.layout()->activate();
    chart.showTrack(track, int(logical.width()));
    if (chart.layout())
        chart.layout()->activate();

    Panel panel;
    panel.rect = rect;
    panel.image = QImage(rect.size(), QImage::Format_ARGB32_Premultiplied);
    panel.image.fill(Qt::white);
    {
        QPainter p(&panel.image);
        p.setRenderHint(QPainter::Antialiasing);
        p.setRenderHint(QPainter::TextAntialiasing);
        scene.render(&p, QRectF(QPointF(0, 0), QSizeF(rect.size())), scene.sceneRect());
    }
    QLineSeries* line = chart.line(chart.shownAxes().front());
    const double lo = chart.valueAxis()->min(), hi = chart.valueAxis()->max();
    const QPointF a = chart.mapToPosition(QPointF(0.0, lo), line);
    const QPointF b = chart.mapToPosition(QPointF(std::max(tEnd, 1e-12), hi), line);
    panel.t0 = 0.0;
    panel.x0 = a.x() * scale;
    panel.t1 = std::max(tEnd, 1e-12);
    panel.x1 = b.x() * scale;
    panel.top = std::min(a.y(), b.y()) * scale;
    panel.bottom = std::max(a.y(), b.y()) * scale;
    panel.pen = chart.cursorLine()->pen();
    panel.pen.setWidthF(std::max(1.5, 2.0 * scale));
    scene.removeItem(&chart);
    return panel;
}

void ChartStrip::paint(QPainter& p, QPoint origin, double t) const
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    for (const Panel& panel : panels_) {
        const QPoint at = origin + panel.rect.topLeft();
        p.drawImage(at, panel.image);
        // Linear time axis: x = x0 + (t - t0) (x1 - x0) / (t1 - t0).
        const double x = panel.x0 + (t - panel.t0) * (panel.x1 - panel.x0) / (panel.t1 - panel.t0);
        p.setPen(panel.pen);
        p.drawLine(QPointF(at.x() + x, at.y() + panel.top), QPointF(at.x() + x, at.y() + panel.bottom));
    }
    p.restore();
}

} // namespace ab::ui
