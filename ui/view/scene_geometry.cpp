// SPDX-License-Identifier: MIT
#include "scene_geometry.h"

#include "street_geometry.h"

#include "ui/charts/nice_ticks.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

const QColor axisColours[3] = {QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c), QColor(0x1f, 0x77, 0xb4)};
const QColor floorColour(0xdc, 0xe1, 0xe8);
const QColor gridColour(0xb4, 0xbc, 0xc8);
const QColor edgeColour(0x4a, 0x5a, 0x78);
const QColor wallColour(0x7f, 0x9c, 0xc8, 22);
// Slate grey: 3:1 or more on the light themes' view (4.1:1 on #ecf0f5) and on the dark ones'
// (4.4:1 on black, where #333333 was 1.7:1 and the scale vanished).
const QColor scaleColour(0x6b, 0x72, 0x80);

FlatVertex vertex(const QVector3D& p, const QColor& c)
{
    return {p.x(), p.y(), p.z(), float(c.redF()), float(c.greenF()), float(c.blueF()), float(c.alphaF())};
}

void line(std::vector<FlatVertex>& out, const QVector3D& a, const QVector3D& b, const QColor& c)
{
    out.push_back(vertex(a, c));
    out.push_back(vertex(b, c));
}

// Two triangles a-b-c, a-c-d.
void quad(std::vector<FlatVertex>& out, const QVector3D& a, const QVector3D& b, const QVector3D& c, const QVector3D& d,
          const QColor& colour)
{
    for (const QVector3D* p : {&a, &b, &c, &a, &c, &d})
        out.push_back(vertex(*p, colour));
}

QString number(double x)
{
    return QString::number(x, 'g', 6);
}

// The floor rectangle [x0, x1] x [z0, z1] at height y, with grid lines at nice spacing.
void addFloor(SceneGeometry& g, float x0, float x1, float z0, float z1, float y)
{
    quad(g.floor, {x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}, floorColour);
    const double step = niceTickStep(std::max(x1 - x0, z1 - z0), 10);
    for (double x = std::ceil(x0 / step) * step; x <= x1 + 1e-9 * step; x += step)
        line(g.lines, {float(x), y, z0}, {float(x), y, z1}, gridColour);
    for (double z = std::ceil(z0 / step) * step; z <= z1 + 1e-9 * step; z += step)
        line(g.lines, {x0, y, float(z)}, {x1, y, float(z)}, gridColour);
}

// Stage 1: a floor, and a vertical scale beside the ball with a labelled tick every
// nice step.
void addHeightScale(SceneGeometry& g, const SceneLayout& l, const QString& unit)
{
    const auto& lo = l.region.min();
    const auto& hi = l.region.max();
    const float top = float(hi.y());
    const float x = float(lo.x() * 0.45);
    const float tick = float((hi.x() - lo.x()) * 0.04);
    line(g.lines, {x, 0.0f, 0.0f}, {x, top, 0.0f}, scaleColour);
    const double step = niceTickStep(top, 8);
    for (double y = 0.0; y <= top + 1e-9 * step; y += step) {
        line(g.lines, {x - tick, float(y), 0.0f}, {x, float(y), 0.0f}, scaleColour);
        g.labels.push_back({QVector3D(x - 4.0f * tick, float(y), 0.0f), number(y), scaleColour});
    }
    g.labels.push_back({QVector3D(x, top * 1.06f, 0.0f),
                        QCoreApplication::translate("SceneGeometry", "y (%1)").arg(unit), axisColours[1]});
}

// Stages 2-4: the twelve edges (the three from the lowest corner in the axes' colours),
// faint side walls, and labels naming the axes and the side.
void addBox(SceneGeometry& g, const SceneLayout& l, const QString& unit)
{
    // Drawn `drawnInset` beyond the faces the centres meet (the floor and the four walls).
    const float in = float(l.drawnInset);
    const QVector3D lo(float(l.region.min().x()) - in, float(l.region.min().y()) - in, float(l.region.min().z()) - in);
    const QVector3D hi(float(l.region.max().x()) + in, float(l.region.max().y()), float(l.region.max().z()) + in);
    auto corner = [&](int i) {
        return QVector3D(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
    };
    for (int i = 0; i < 8; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            const int j = i | (1 << axis);
            if (j == i)
                continue;
            line(g.lines, corner(i), corner(j), i == 0 ? axisColours[axis] : edgeColour);
        }
    quad(g.walls, corner(0), corner(4), corner(6), corner(2), wallColour); // x = lo
    quad(g.walls, corner(1), corner(5), corner(7), corner(3), wallColour); // x = hi
    quad(g.walls, corner(0), corner(1), corner(3), corner(2), wallColour); // z = lo
    quad(g.walls, corner(4), corner(5), corner(7), corner(6), wallColour); // z = hi
    const float side = float(l.region.sizes().x()); // the box the centres move in, as its parameter says
    const char* names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        QVector3D end = corner(1 << axis);
        end[axis] += 0.06f * side;
        g.labels.push_back({end, QString::fromLatin1(names[axis]), axisColours[axis]});
    }
    g.labels.push_back({(corner(0) + corner(1)) / 2.0f - QVector3D(0, 0, 0.08f * side),
                        QCoreApplication::translate("SceneGeometry", "L = %1 %2").arg(number(side), unit), edgeColour});
}

} // namespace

SceneGeometry buildSceneGeometry(const SceneLayout& l, const QString& lengthUnit)
{
    SceneGeometry g;
    const auto& lo = l.region.min();
    const auto& hi = l.region.max();
    g.lo = QVector3D(float(lo.x()), float(lo.y()), float(lo.z()));
    g.hi = QVector3D(float(hi.x()), float(hi.y()), float(hi.z()));
    g.arrowStep = float(0.02 * (hi - lo).maxCoeff());
    const float y = float(l.floorY - l.drawnInset);
    if (l.street) {
        addStreetGeometry(g, *l.street, lengthUnit);
    } else if (l.walls) {
        const float in = float(l.drawnInset);
        addFloor(g, g.lo.x() - in, g.hi.x() + in, g.lo.z() - in, g.hi.z() + in, y);
        addBox(g, l, lengthUnit);
    } else {
        addFloor(g, g.lo.x(), g.hi.x(), g.lo.z(), g.hi.z(), y);
        addHeightScale(g, l, lengthUnit);
    }
    return g;
}

} // namespace ab::ui
