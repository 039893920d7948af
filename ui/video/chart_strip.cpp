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

std::vector<ChartKind> chartsFor(SceneId scene)
{
    std::vector<ChartKind> kinds;
    for (ChartKind k : allChartKinds())
        if (chartApplies(k, scene))
            kinds.push_back(k);
    return kinds;
}

ChartStrip::ChartStrip(const Simulation& sim, int ball, const std::vector<ChartKind>& kinds, const MotionTrack& track,
                       double tEnd, QSize size)
{
    if (kinds.empty())
        return;
    // As many charts as fit at kMinHeight pixels each (the first ones: position and
    // velocity come first), each drawn at least kMinHeight tall and scaled to its slot,
    // so the window's fonts keep their size relative to the plot.
    const int n = std::clamp(size.height() / kMinHeight, 1, int(kinds.size()));
    for (int i = 0; i < n; ++i) {
        const int top = size.height() * i / n, bottom = size.height() * (i + 1) / n;
        panels_.push_back(
            drawPanel(sim, ball, kinds[std::size_t(i)], track, tEnd, QRect(0, top, size.width(), bottom - top)));
    }
}

ChartStrip::Panel ChartStrip::drawPanel(const Simulation& sim, int ball, ChartKind kind, const MotionTrack& track,
                                        double tEnd, QRect rect)
{
    const ConservationMeter meter(sim);
    const double scale = std::min(1.0, double(rect.height()) / kMinHeight); // pixels per chart unit
    const QSizeF logical(rect.width() / scale, rect.height() / scale);
    MotionChart chart(kind);
    chart.configure(sim.scene(), ball, ChartUnits{meter.perUnitMass(), meter.hasSpring()});
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
