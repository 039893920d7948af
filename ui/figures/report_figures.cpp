// SPDX-License-Identifier: MIT
#include "report_figures.h"

#include "ui/charts/chart_export.h"

#include "core/io/atomic_file.h"
#include "ui/charts/nice_ticks.h"
#include "ui/charts/scene_layout.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QPainter>
#include <QPainterPath>
#include <QRadialGradient>
#include <QSvgGenerator>

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <numbers>
#include <numeric>

namespace ab::ui {

namespace {

// The context the figures' strings are translated in.
struct ReportFigures {
    Q_DECLARE_TR_FUNCTIONS(ReportFigures)
};

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

const QColor ink(0x22, 0x22, 0x22);
const QColor grid(0xdd, 0xdd, 0xdd);
const QColor line(0x00, 0x72, 0xbd); // MATLAB's first line colour, as in the report's plots

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

// Ticks at whole multiples of a nice step within [lo, hi].
std::vector<double> ticks(double lo, double hi, int count)
{
    const double step = niceTickStep(hi - lo, count);
    std::vector<double> out;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
        out.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
    return out;
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

// ---- Projected 3D (2.6, 3.1) -------------------------------------------------------------

// A camera looking at `target` from yaw (about +y, 0 looks along -z) and pitch above the
// floor, as the window's orbit camera; perspective divides by depth, orthographic does not.
struct Camera {
    Eigen::Vector3d eye, right, up, forward;
    bool perspective = false;

    Camera(const Eigen::Vector3d& target, double yawDeg, double pitchDeg, double distance, bool persp)
        : perspective(persp)
    {
        const double yaw = yawDeg * std::numbers::pi / 180.0, pitch = pitchDeg * std::numbers::pi / 180.0;
        const Eigen::Vector3d back(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
        eye = target + distance * back;
        forward = -back;
        right = forward.cross(Eigen::Vector3d::UnitY()).normalized();
        up = right.cross(forward);
    }
    double depth(const Eigen::Vector3d& x) const { return forward.dot(x - eye); }
    // Image-plane coordinates, y up; 1 / depth per length unit in perspective.
    QPointF image(const Eigen::Vector3d& x) const
    {
        const Eigen::Vector3d d = x - eye;
        const double s = perspective ? 1.0 / forward.dot(d) : 1.0;
        return {right.dot(d) * s, up.dot(d) * s};
    }
};

// Maps image-plane coordinates into `area` so that all of `box` fits, centred.
struct Fit {
    QPointF centre, origin;
    double scale = 1.0;

    Fit(const Camera& cam, const Eigen::AlignedBox3d& box, const QRectF& area)
    {
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (int i = 0; i < 8; ++i) {
            const QPointF q = cam.image(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)));
            x0 = std::min(x0, q.x());
            x1 = std::max(x1, q.x());
            y0 = std::min(y0, q.y());
            y1 = std::max(y1, q.y());
        }
        scale = 0.9 * std::min(area.width() / std::max(x1 - x0, 1e-12), area.height() / std::max(y1 - y0, 1e-12));
        origin = QPointF((x0 + x1) / 2, (y0 + y1) / 2);
        centre = area.center();
    }
    QPointF operator()(const QPointF& q) const
    {
        return {centre.x() + scale * (q.x() - origin.x()), centre.y() - scale * (q.y() - origin.y())};
    }
};

void drawBox(QPainter& p, const Camera& cam, const Fit& fit, const Eigen::AlignedBox3d& box)
{
    p.setPen(QPen(QColor(0x66, 0x66, 0x66), 1.2));
    for (int a = 0; a < 8; ++a)
        for (int b = a + 1; b < 8; ++b)
            if (std::popcount(unsigned(a ^ b)) == 1) // corners differing in one axis: an edge
                p.drawLine(fit(cam.image(box.corner(Eigen::AlignedBox3d::CornerType(a)))),
                           fit(cam.image(box.corner(Eigen::AlignedBox3d::CornerType(b)))));
}

// Tick labels along three bottom or vertical edges of the box, on the sides facing the
// eye (x along the front, z along the near side, y up the far vertical), MATLAB-style.
void drawAxes(QPainter& p, const Camera& cam, const Fit& fit, const Eigen::AlignedBox3d& box, const QString& unit)
{
    const QFontMetricsF fm(p.font());
    const double h = fm.height();
    const Eigen::Vector3d lo = box.min(), hi = box.max(), size = hi - lo;
    const auto near = [&](int a) { return cam.eye[a] > box.center()[a] ? hi[a] : lo[a]; };
    const auto outward = [&](int a) { return (cam.eye[a] > box.center()[a] ? 1.0 : -1.0) * 0.07 * size[a]; };
    struct Edge {
        int axis;
        Eigen::Vector3d base, offset; // a point of the edge (its own axis free) and where labels go
    };
    const Edge edges[] = {
        {0, {0, lo.y(), near(2)}, {0, 0, outward(2)}},
        {2, {near(0), lo.y(), 0}, {outward(0), 0, 0}},
        {1, {lo.x() + hi.x() - near(0), 0, near(2)}, {-outward(0), 0, 0}},
    };
    const char* names[] = {"x", "y", "z"};
    p.setPen(ink);
    for (const Edge& e : edges) {
        for (double t : ticks(lo[e.axis], hi[e.axis], 3)) {
            Eigen::Vector3d x = e.base + e.offset;
            x[e.axis] = t;
            const QPointF at = fit(cam.image(x));
            p.drawText(QRectF(at.x() - 3 * h, at.y() - 0.5 * h, 6 * h, h), Qt::AlignCenter, QString::number(t));
        }
        Eigen::Vector3d mid = e.base + 2.4 * e.offset;
        mid[e.axis] = (lo[e.axis] + hi[e.axis]) / 2;
        const QPointF at = fit(cam.image(mid));
        QFont bold = p.font();
        bold.setBold(true);
        p.save();
        p.setFont(bold);
        p.drawText(QRectF(at.x() - 4 * h, at.y() - 0.5 * h, 8 * h, h), Qt::AlignCenter,
                   QStringLiteral("%1 (%2)").arg(QLatin1String(names[e.axis]), unit));
        p.restore();
    }
}

void paintTrajectory(QPainter& p, const QRectF& area, const FigureData& d)
{
    const SceneLayout layout = layoutFor(d.spec);
    const Eigen::AlignedBox3d& box = layout.region;
    // Seen from the front right and above, y up: x runs to the right, z towards the reader.
    const Camera cam(box.center(), -50.0, 25.0, 3.0 * box.diagonal().norm(), false);
    const Fit fit(cam, box, area.adjusted(area.width() * 0.05, 0, -area.width() * 0.05, 0));
    drawBox(p, cam, fit, box);
    drawAxes(p, cam, fit, box, qs(sceneInfo(d.spec.scene).lengthUnit));
    // The path up to where the report's counter stops the ball; its listing then zeroes
    // the position, which is not a place the ball goes to, so the line ends there.
    const std::size_t end = d.halt.value_or(d.p.size());
    QPainterPath path;
    for (std::size_t i = 0; i < end; ++i) {
        const QPointF at = fit(cam.image(d.p[i]));
        i == 0 ? path.moveTo(at) : path.lineTo(at);
    }
    const double h = QFontMetricsF(p.font()).height();
    p.setPen(QPen(line, std::max(1.5, h / 8.0)));
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
    if (end == 0)
        return;
    const QPointF start = fit(cam.image(d.p.front())), stop = fit(cam.image(d.p[end - 1]));
    p.setBrush(line);
    p.drawEllipse(start, h / 4, h / 4);
    p.drawEllipse(stop, h / 4, h / 4);
    p.setPen(ink);
    p.drawText(start + QPointF(h / 2, -h / 3), ReportFigures::tr("start"));
    if (d.halt) // to the left of the stop, clear of the path that comes in from the walls
        p.drawText(QRectF(stop.x() - 30 * h, stop.y() - 1.4 * h, 29.5 * h, h), Qt::AlignRight | Qt::AlignVCenter,
                   ReportFigures::tr("stopped by the counter, t = %1 %2")
                       .arg(d.t[end - 1])
                       .arg(qs(sceneInfo(d.spec.scene).timeUnit)));
}

void paintBalls(QPainter& p, const QRectF& area, const FigureData& d)
{
    const SceneLayout layout = layoutFor(d.spec);
    const Eigen::AlignedBox3d& box = layout.region;
    // From the side the report's WebGL camera stands on ((100, 50, 50) from the centre,
    // Appendix D: yaw 63 degrees), higher and farther, so that the eye is not in the plane
    // of the box's top face, which would fold the top edges onto one line.
    const Camera cam(box.center(), 63.0, 30.0, 2.4 * box.sizes().maxCoeff(), true);
    const Fit fit(cam, box, area);
    // The floor, lightly filled, then the box's edges, then the balls far to near.
    QPolygonF floor;
    for (int c : {0, 1, 5, 4})
        floor << fit(cam.image(box.corner(Eigen::AlignedBox3d::CornerType(c))));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0xee, 0xf0, 0xf3));
    p.drawPolygon(floor);
    drawBox(p, cam, fit, box);
    const State& s = d.last;
    std::vector<int> order(static_cast<std::size_t>(s.size()));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return cam.depth(s.p.col(a)) > cam.depth(s.p.col(b)); });
    p.setPen(Qt::NoPen);
    for (int i : order) {
        const Eigen::Vector3d c = s.p.col(i);
        if (!c.allFinite() || cam.depth(c) <= 0.0)
            continue;
        const QPointF at = fit(cam.image(c));
        const double r = fit.scale * layout.ballRadius / cam.depth(c);
        // A distinct hue per ball (the report gives each ball a random colour).
        const QColor colour = QColor::fromHsvF(float(std::fmod(0.61803398875 * i, 1.0)), 0.7f, 0.95f);
        QRadialGradient shade(at, r, at - QPointF(0.35 * r, 0.35 * r)); // lit from the upper left
        shade.setColorAt(0.0, colour.lighter(160));
        shade.setColorAt(0.7, colour);
        shade.setColorAt(1.0, colour.darker(170));
        p.setBrush(shade);
        p.drawEllipse(at, r, r);
    }
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
