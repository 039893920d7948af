// SPDX-License-Identifier: MIT
// The report's figures redrawn from the report model: the line plots (2.5, 2.7), a figure's
// title and caption, and its export (the 3D figures are in figure_projection.cpp).
#include "report_figures.h"

#include "figure_parts.h"

#include "ui/charts/chart_export.h"

#include "core/io/atomic_file.h"
#include "ui/charts/nice_ticks.h"
#include "ui/charts/scene_layout.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace figure_parts {

// Ticks at whole multiples of a nice step within [lo, hi].
std::vector<double> ticks(double lo, double hi, int count)
{
    const double step = niceTickStep(hi - lo, count);
    std::vector<double> out;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
        out.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
    return out;
}

} // namespace figure_parts

using namespace figure_parts;

namespace {

SceneId sceneOf(ReportFigure f)
{
    switch (f) {
    case ReportFigure::Bounce1d:
        return SceneId::Bounce1d;
    case ReportFigure::BoxTrajectory:
    case ReportFigure::BoxVelocity:
        return SceneId::Box3d;
    case ReportFigure::ManyBalls:
        return SceneId::ManyBalls;
    }
    throw std::logic_error("unknown report figure");
}

// ---- Line plots (2.5, 2.7) ---------------------------------------------------------------

struct Panel {
    QString title, xLabel, yLabel;
    const std::vector<double>* x;
    std::vector<double> y;
};

std::pair<double, double> finiteRange(const std::vector<double>& v)
{
    double lo = 0.0, hi = 0.0; // every panel shows its zero line
    for (double x : v)
        if (std::isfinite(x)) {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
    if (hi - lo <= 0.0)
        hi = lo + 1.0;
    return {lo, hi};
}

void drawPanel(QPainter& p, const QRectF& area, const Panel& panel)
{
    const QFontMetricsF fm(p.font());
    const double h = fm.height();
    const QRectF plot = area.adjusted(fm.horizontalAdvance("-00000") + 2.0 * h, 1.6 * h, -h, -2.4 * h);
    // Plain variables, not structured bindings: the lambda below captures them, which
    // clang before 16 refuses for bindings.
    const auto xRange = finiteRange(*panel.x);
    const double x0 = xRange.first, x1 = xRange.second;
    const auto yRange = finiteRange(panel.y);
    double y0 = yRange.first, y1 = yRange.second;
    const double tick = niceTickStep(y1 - y0, 5); // the value axis ends on ticks
    y0 = std::floor(y0 / tick) * tick;
    y1 = std::ceil(y1 / tick) * tick;
    const auto at = [&](double x, double y) {
        return QPointF(plot.left() + (x - x0) / (x1 - x0) * plot.width(),
                       plot.bottom() - (y - y0) / (y1 - y0) * plot.height());
    };
    p.setPen(QPen(grid, 1.0));
    for (double t : ticks(x0, x1, 8)) {
        p.drawLine(at(t, y0), at(t, y1));
        p.setPen(ink);
        p.drawText(QRectF(at(t, y0).x() - 3 * h, plot.bottom() + 0.2 * h, 6 * h, h), Qt::AlignCenter,
                   QString::number(t, 'g', 6));
        p.setPen(QPen(grid, 1.0));
    }
    for (double t : ticks(y0, y1, 5)) { // the same step as `tick`: same span, same count
        p.drawLine(at(x0, t), at(x1, t));
        p.setPen(ink);
        p.drawText(QRectF(plot.left() - 6.3 * h, at(x0, t).y() - 0.5 * h, 6 * h, h), Qt::AlignRight | Qt::AlignVCenter,
                   QString::number(t, 'g', 6));
        p.setPen(QPen(grid, 1.0));
    }
    // The series, broken where a value is not finite (never drawn as a number).
    QPainterPath path;
    bool pen = false;
    for (std::size_t i = 0; i < panel.y.size(); ++i) {
        const double x = (*panel.x)[i], y = panel.y[i];
        if (!std::isfinite(x) || !std::isfinite(y)) {
            pen = false;
            continue;
        }
        pen ? path.lineTo(at(x, y)) : path.moveTo(at(x, y));
        pen = true;
    }
    p.save();
    p.setClipRect(plot.adjusted(-1, -1, 1, 1));
    p.setPen(QPen(line, std::max(1.5, h / 8.0)));
    p.drawPath(path);
    p.restore();
    p.setPen(QPen(ink, 1.0));
    p.drawRect(plot);
    QFont bold = p.font();
    bold.setBold(true);
    p.save();
    p.setFont(bold);
    p.drawText(QRectF(plot.left(), area.top(), plot.width(), 1.4 * h), Qt::AlignCenter, panel.title);
    p.restore();
    p.drawText(QRectF(plot.left(), plot.bottom() + 1.2 * h, plot.width(), h), Qt::AlignCenter, panel.xLabel);
    p.save();
    p.translate(area.left() + 0.2 * h, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2, 0, plot.height(), h), Qt::AlignCenter, panel.yLabel);
    p.restore();
}

std::vector<Panel> panelsOf(const FigureData& d)
{
    const SceneInfo& info = sceneInfo(d.spec.scene);
    const QString time = ReportFigures::tr("t (%1)").arg(qs(info.timeUnit));
    const QString speed = qs(info.lengthUnit) + "/" + qs(info.timeUnit);
    const auto component = [&](const std::vector<Eigen::Vector3d>& v, int axis) {
        std::vector<double> out(v.size());
        std::transform(v.begin(), v.end(), out.begin(), [axis](const Eigen::Vector3d& x) { return x[axis]; });
        return out;
    };
    if (d.figure == ReportFigure::Bounce1d)
        return {{ReportFigures::tr("Position"), time, ReportFigures::tr("height y (%1)").arg(qs(info.lengthUnit)), &d.t,
                 component(d.p, 1)},
                {ReportFigures::tr("Velocity"), time, ReportFigures::tr("v (%1)").arg(speed), &d.t, component(d.v, 1)}};
    std::vector<Panel> panels;
    const char* names[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        panels.push_back({ReportFigures::tr("Velocity along %1").arg(QLatin1String(names[a])), time,
                          ReportFigures::tr("v%1 (%2)").arg(QLatin1String(names[a]), speed), &d.t, component(d.v, a)});
    return panels;
}

void paintPanels(QPainter& p, const QRectF& area, const FigureData& d)
{
    const std::vector<Panel> panels = panelsOf(d);
    const double h = area.height() / double(panels.size());
    for (std::size_t i = 0; i < panels.size(); ++i)
        drawPanel(p, QRectF(area.left(), area.top() + double(i) * h, area.width(), h), panels[i]);
}

void paintTitleAndCaption(QPainter& p, const QRectF& area, const FigureData& d, QRectF& body)
{
    const QFontMetricsF fm(p.font());
    const double h = fm.height();
    const SceneInfo& info = sceneInfo(d.spec.scene);
    const QString source =
        ReportFigures::tr("Redrawn from the report model with the report's constants: stage %1, %2 steps "
                          "of %3 %4.")
            .arg(info.stage)
            .arg(d.steps)
            .arg(info.reportDt)
            .arg(qs(info.timeUnit));
    const QRectF captionBox(area.left() + h, area.bottom() - 3.2 * h, area.width() - 2 * h, 3.0 * h);
    p.setPen(ink);
    QFont italic = p.font();
    italic.setItalic(true);
    p.save();
    p.setFont(italic);
    p.drawText(captionBox, Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap,
               QStringLiteral("%1\n%2").arg(figureCaption(d.figure), source));
    p.restore();
    body = area.adjusted(0.5 * h, 0.5 * h, -0.5 * h, -3.6 * h);
}

} // namespace

const std::vector<ReportFigure>& allReportFigures()
{
    static const std::vector<ReportFigure> all{ReportFigure::Bounce1d, ReportFigure::BoxTrajectory,
                                               ReportFigure::BoxVelocity, ReportFigure::ManyBalls};
    return all;
}

std::string_view figureNumber(ReportFigure figure)
{
    switch (figure) {
    case ReportFigure::Bounce1d:
        return "2.5";
    case ReportFigure::BoxTrajectory:
        return "2.6";
    case ReportFigure::BoxVelocity:
        return "2.7";
    case ReportFigure::ManyBalls:
        return "3.1";
    }
    throw std::logic_error("unknown report figure");
}

std::optional<ReportFigure> parseReportFigure(std::string_view number)
{
    for (ReportFigure f : allReportFigures())
        if (figureNumber(f) == number)
            return f;
    return std::nullopt;
}

QString figureCaption(ReportFigure figure)
{
    switch (figure) {
    case ReportFigure::Bounce1d:
        return ReportFigures::tr("Figure 2.5: Velocity and position of a bouncing ball in 1D");
    case ReportFigure::BoxTrajectory:
        return ReportFigures::tr("Figure 2.6: Position of the ball in 3D");
    case ReportFigure::BoxVelocity:
        return ReportFigures::tr("Figure 2.7: The ball's velocity along x, y and z");
    case ReportFigure::ManyBalls:
        return ReportFigures::tr("Figure 3.1: Final simulation of 200 balls");
    }
    throw std::logic_error("unknown report figure");
}

FigureData computeFigure(ReportFigure figure)
{
    FigureData d;
    d.figure = figure;
    d.spec = RunSpec(sceneOf(figure)); // the report model with the report's constants
    if (figure == ReportFigure::ManyBalls)
        d.spec.params.set("n", Eigen::Vector3d(200, 0, 0)); // the figure shows 200 (the code starts 150)
    d.steps = sceneInfo(d.spec.scene).reportSteps;
    const auto sim = makeSimulation(d.spec);
    const bool track = figure != ReportFigure::ManyBalls;
    d.last = runRecorded(*sim, sim->start(), d.steps, 1, [&](const State& s) {
        if (!track)
            return;
        if (s.halted && !d.halt)
            d.halt = d.t.size();
        d.t.push_back(s.t);
        d.p.emplace_back(s.p.col(0));
        d.v.emplace_back(s.v.col(0));
    });
    return d;
}

void paintFigure(QPainter& painter, const QRectF& area, const FigureData& data, int textPx)
{
    painter.save();
    painter.fillRect(area, Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setPixelSize(textPx > 0 ? textPx : std::max(11, int(std::min(area.height(), area.width()) / 55.0)));
    painter.setFont(font);
    QRectF body;
    paintTitleAndCaption(painter, area, data, body);
    switch (data.figure) {
    case ReportFigure::Bounce1d:
    case ReportFigure::BoxVelocity:
        paintPanels(painter, body, data);
        break;
    case ReportFigure::BoxTrajectory:
        paintTrajectory(painter, body, data);
        break;
    case ReportFigure::ManyBalls:
        paintBalls(painter, body, data);
        break;
    }
    painter.restore();
}

QImage renderFigure(const FigureData& data, QSize size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    paintFigure(painter, QRectF(QPointF(0, 0), QSizeF(size)), data);
    return image;
}

void exportFigure(const FigureData& data, const QString& path, QSize size)
{
    const FigureOptions options{pixelFigureSize(size.width(), size.height()), int(kSceneDpi)};
    writeFigureFile(path, options, figureCaption(data.figure),
                    [&](QPainter& p, const QRectF& area) { paintFigure(p, area, data); });
}

void exportFigure(const FigureData& data, const QString& path, const FigureOptions& options)
{
    // Text in points of the final size: 8 pt in print, 16 pt on a slide (scene units
    // are 1/144 inch, two to the point).
    const int textPx = int(std::lround((options.size.slide ? 16.0 : 8.0) * kSceneDpi / 72.0));
    writeFigureFile(path, options, figureCaption(data.figure),
                    [&](QPainter& p, const QRectF& area) { paintFigure(p, area, data, textPx); });
}

} // namespace ab::ui
