// SPDX-License-Identifier: MIT
// The report figures drawn in 3D (2.6, 3.1): a camera as the window's orbit camera, projected
// by hand onto the figure's painter so that the PDF and SVG exports stay vector drawings.
#include "figure_parts.h"

#include "ui/charts/scene_layout.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QRadialGradient>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <numeric>

namespace ab::ui::figure_parts {

namespace {

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

} // namespace

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

} // namespace ab::ui::figure_parts
