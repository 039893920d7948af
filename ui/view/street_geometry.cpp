// SPDX-License-Identifier: MIT
#include "street_geometry.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>

namespace ab::ui {

namespace {

using street::Box;
using street::ItemKind;

// Towards the light: from above, downhill (+x) and the near side, so that the faces the
// foot shot and the side shot look at are lit.
const QVector3D kLight = QVector3D(0.45f, 0.8f, 0.4f).normalized();
const QColor asphalt(0x5c, 0x60, 0x66), crossingGrey(0x80, 0x84, 0x8a), concrete(0xc8, 0xc4, 0xbb),
    brick(0x9a, 0x5b, 0x4a), paint(0xf4, 0xf4, 0xf0), yellow(0xf2, 0xc1, 0x1d), kerbEdge(0x3a, 0x3c, 0x40),
    footRed(0xd6, 0x27, 0x28), windowBlue(0x3b, 0x4a, 0x5e), labelInk(0x20, 0x24, 0x2c);
// San Francisco's painted terraces, and the parked cars.
constexpr std::array<unsigned, 7> housePaint = {0xe8d5b5, 0xc9dbe6, 0xf2c6b4, 0xd8e4c4, 0xe6c9de, 0xf3e3a6, 0xbfd3c1};
constexpr std::array<unsigned, 6> carPaint = {0xb03a2e, 0x2e6da4, 0xe6e6e6, 0x2f2f33, 0x3f8f5f, 0xd9a23a};

constexpr float kLift = 0.05f; // road markings above the road (m): clear of it in the depth buffer at 300 m

FlatVertex vertex(const QVector3D& p, const QColor& c)
{
    return {p.x(), p.y(), p.z(), float(c.redF()), float(c.greenF()), float(c.blueF()), float(c.alphaF())};
}

QVector3D q(const Eigen::Vector3d& v)
{
    return QVector3D(float(v.x()), float(v.y()), float(v.z()));
}

// `colour` lit from kLight by a face of outward normal n: a third ambient, the rest Lambert,
// so a face turned from the light is still read as the block it belongs to.
QColor shaded(const QColor& colour, const QVector3D& n)
{
    const float k = 0.55f + 0.45f * std::max(QVector3D::dotProduct(n.normalized(), kLight), 0.0f);
    return QColor::fromRgbF(colour.redF() * k, colour.greenF() * k, colour.blueF() * k, colour.alphaF());
}

// Two triangles a-b-c, a-c-d, flat-shaded by the normal (b - a) x (d - a).
void quad(std::vector<FlatVertex>& out, const QVector3D& a, const QVector3D& b, const QVector3D& c, const QVector3D& d,
          const QColor& colour)
{
    const QColor lit = shaded(colour, QVector3D::crossProduct(b - a, d - a));
    for (const QVector3D* p : {&a, &b, &c, &a, &c, &d})
        out.push_back(vertex(*p, lit));
}

// The six faces of a box in its own frame (centre, turn about z, half extents), each lit by
// its outward normal: face (axis a, side s) has the corners whose coordinate a is s.
void box(std::vector<FlatVertex>& out, const Box& b, const QColor& colour)
{
    auto corner = [&](double sx, double sy, double sz) {
        return q(b.toWorld(Eigen::Vector3d(sx * b.half.x(), sy * b.half.y(), sz * b.half.z())));
    };
    for (double s : {-1.0, 1.0}) {
        // Corners listed counter-clockwise seen from outside, so (b - a) x (d - a) points out.
        quad(out, corner(s, -1, -s), corner(s, 1, -s), corner(s, 1, s), corner(s, -1, s), colour); // x = s
        quad(out, corner(-s, s, -1), corner(-s, s, 1), corner(s, s, 1), corner(s, s, -1), colour); // y = s
        quad(out, corner(-1, -s, s), corner(1, -s, s), corner(1, s, s), corner(-1, s, s), colour); // z = s
    }
}

Box axisBox(ItemKind kind, const QVector3D& lo, const QVector3D& hi)
{
    const Eigen::Vector3d a(lo.x(), lo.y(), lo.z()), b(hi.x(), hi.y(), hi.z());
    return Box(kind, -1, (a + b) / 2.0, 0.0, (b - a) / 2.0);
}

// A strip of road marking from x0 to x1 (along the road under them) between z0 and z1.
void marking(std::vector<FlatVertex>& out, const street::Layout& s, double x0, double x1, double z0, double z1,
             const QColor& colour)
{
    const auto y0 = float(s.roadY(x0)) + kLift, y1 = float(s.roadY(x1)) + kLift;
    quad(out, {float(x0), y0, float(z1)}, {float(x1), y1, float(z1)}, {float(x1), y1, float(z0)},
         {float(x0), y0, float(z0)}, colour);
}

// The road's markings: a dashed double yellow centre line down each block (3 m dashes,
// 3 m gaps) and a zebra band (0.5 m bars, 0.5 m apart) at both ends of every crossing.
void addMarkings(SceneGeometry& g, const street::Layout& s)
{
    const double run = s.blockLength * std::cos(s.slope);
    for (int k = 0; k < s.blocks; ++k) {
        const double x0 = s.blockStartX[std::size_t(k)];
        for (double x = x0 + 1.0; x + 3.0 <= x0 + run; x += 6.0)
            for (double z : {-0.12, 0.12})
                marking(g.floor, s, x, x + 3.0, z - 0.05, z + 0.05, yellow);
    }
    auto zebra = [&](double x0, double x1) {
        for (double z = -0.5 * s.width + 0.6; z + 0.5 <= 0.5 * s.width - 0.4; z += 1.0)
            marking(g.floor, s, x0, x1, z, z + 0.5, paint);
    };
    std::vector<double> starts = {s.xTop};
    for (int k = 0; k + 1 < s.blocks; ++k)
        starts.push_back(s.blockFootX[std::size_t(k)]);
    for (double x0 : starts) {
        const double band = std::min(3.0, 0.3 * s.crossing);
        zebra(x0 + 0.5, x0 + 0.5 + band);
        zebra(x0 + s.crossing - 0.5 - band, x0 + s.crossing - 0.5);
    }
}

// One house of the terrace on side `side` (-1 or +1) from x0 to x1: its front on the
// sidewalk's outer edge, its ground below the road, its roof 7, 9 or 11 m (by `index`) above
// the road's higher end and the kerb.
Box houseBox(const street::Layout& s, double x0, double x1, int index, double side)
{
    const double front = 0.5 * s.width + s.sidewalk;
    const double low = std::min(s.roadY(x0), s.roadY(x1)), high = std::max(s.roadY(x0), s.roadY(x1));
    const double roof = high + s.kerb + 7.0 + 2.0 * (index % 3);
    const double z0 = side > 0 ? front : -front - 3.0, z1 = side > 0 ? front + 3.0 : -front;
    return axisBox(ItemKind::House, QVector3D(float(x0), float(low - 3.0), float(z0)),
                   QVector3D(float(x1), float(roof), float(z1)));
}

// Houses 8 m wide, the first starting behind the back wall, to the foot: house(x0, x1,
// index, side) for each, the far side (-z) first.
template <class House> void forEachHouse(const street::Layout& s, House house)
{
    const double start = s.xTop - 3.0, width = 8.0;
    int index = 0;
    for (double x = start; x < s.xFoot - 0.5; x += width, ++index) {
        const double x1 = std::min(x + width, s.xFoot);
        house(x, x1, index, -1.0);
        house(x, x1, index + 3, 1.0);
    }
}

// A house of the terrace (houseBox) with two rows of windows on its front.
void addHouse(std::vector<FlatVertex>& out, const street::Layout& s, double x0, double x1, int index, double side)
{
    const Box b = houseBox(s, x0, x1, index, side);
    box(out, b, QColor::fromRgb(housePaint[std::size_t(index) % housePaint.size()]));
    const double high = std::max(s.roadY(x0), s.roadY(x1)), roof = b.centre.y() + b.half.y();
    const double zFront = side > 0 ? b.centre.z() - b.half.z() : b.centre.z() + b.half.z();
    const auto zf = float(zFront - 0.04 * side); // on the front, towards the street
    for (int row = 0; row < 2; ++row) {
        const double y0 = high + s.kerb + 2.2 + 2.6 * row, y1 = y0 + 1.4;
        if (y1 > roof - 0.5)
            break;
        for (double f : {0.22, 0.62}) {
            const double a = x0 + f * (x1 - x0), c = a + 0.22 * (x1 - x0);
            const QVector3D p0(float(a), float(y0), zf), p1(float(c), float(y0), zf), p2(float(c), float(y1), zf),
                p3(float(a), float(y1), zf);
            if (side > 0)
                quad(out, p0, p3, p2, p1, windowBlue); // faces -z, the street
            else
                quad(out, p0, p1, p2, p3, windowBlue);
        }
    }
}

void addHouses(SceneGeometry& g, const street::Layout& s)
{
    forEachHouse(s, [&](double x0, double x1, int index, double side) {
        addHouse(side > 0 ? g.cutaway : g.floor, s, x0, x1, index, side);
    });
}

// The flat street beyond the open foot, 60 m of it, where the balls that left the run
// lie (not drawn): the foot shot's camera stands on it.
void addBeyondTheFoot(SceneGeometry& g, const street::Layout& s)
{
    const auto x0 = float(s.xFoot), x1 = x0 + 60.0f, road = float(0.5 * s.width),
               across = float(0.5 * s.width + s.sidewalk);
    quad(g.floor, {x0, 0.0f, road}, {x1, 0.0f, road}, {x1, 0.0f, -road}, {x0, 0.0f, -road}, asphalt);
    for (float side : {-1.0f, 1.0f}) {
        const float k = float(s.kerb);
        const QVector3D a(x0, k, side * road), b(x1, k, side * road), c(x1, k, side * across), d(x0, k, side * across);
        if (side > 0)
            quad(g.floor, a, d, c, b, concrete); // counter-clockwise from above: facing up
        else
            quad(g.floor, a, b, c, d, concrete);
    }
}

void addKerbsAndLabels(SceneGeometry& g, const street::Layout& s, const QString& unit)
{
    auto line = [&](const QVector3D& a, const QVector3D& b, const QColor& c) {
        g.lines.push_back(vertex(a, c));
        g.lines.push_back(vertex(b, c));
    };
    // The kerbs' top edges, where the sidewalks meet the roadway, from the top to the foot.
    const double step = 2.0;
    for (double x = s.xTop; x < s.xFoot - 1e-9; x += step) {
        const double x1 = std::min(x + step, s.xFoot);
        for (double side : {-1.0, 1.0}) {
            const auto z = float(side * 0.5 * s.width);
            line({float(x), float(s.roadY(x) + s.kerb) + 0.01f, z}, {float(x1), float(s.roadY(x1) + s.kerb) + 0.01f, z},
                 kerbEdge);
        }
    }
    const auto across = float(0.5 * s.width + s.sidewalk);
    const auto foot = float(s.xFoot);
    line({foot, kLift, -across}, {foot, kLift, across}, footRed);
    // Just over the foot's line, not on it, from any distance.
    g.labels.push_back(
        {QVector3D(foot, kLift, 0.0f), QCoreApplication::translate("SceneGeometry", "foot"), footRed, true});
    g.labels.push_back({QVector3D(float(s.xTop), float(s.height + kTopLabelHeight), 0.0f),
                        QCoreApplication::translate("SceneGeometry", "top, %1 %2 above the foot")
                            .arg(QString::number(s.height, 'f', 1), unit),
                        labelInk});
    // The hopper's floor: where the lowest layer of balls starts.
    const Eigen::Vector3d a(s.hopper.x0, s.roadY(s.hopper.x0) + s.hopper.lift, s.hopper.z0);
    const Eigen::Vector3d b(s.hopper.x1, s.roadY(s.hopper.x1) + s.hopper.lift, s.hopper.z1);
    const QColor rim(0x6a, 0x3d, 0x9a);
    line(q(a), {float(b.x()), float(b.y()), float(a.z())}, rim);
    line({float(b.x()), float(b.y()), float(a.z())}, q(b), rim);
    line(q(b), {float(a.x()), float(a.y()), float(b.z())}, rim);
    line({float(a.x()), float(a.y()), float(b.z())}, q(a), rim);
}

QColor itemColour(const Box& b, std::size_t index)
{
    switch (b.kind) {
    case ItemKind::Road:
        return asphalt;
    case ItemKind::Crossing:
        return crossingGrey;
    case ItemKind::Sidewalk:
        return concrete;
    case ItemKind::Car:
        return QColor::fromRgb(carPaint[index % carPaint.size()]);
    case ItemKind::BackWall:
        return brick;
    case ItemKind::House:
        return concrete; // not drawn as one block: the terrace stands in for it
    }
    return concrete;
}

} // namespace

std::vector<Box> streetSolids(const street::Layout& s)
{
    std::vector<Box> solids;
    for (const Box& b : s.boxes)
        if (b.kind != ItemKind::House)
            solids.push_back(b);
    forEachHouse(
        s, [&](double x0, double x1, int index, double side) { solids.push_back(houseBox(s, x0, x1, index, side)); });
    return solids;
}

void addStreetGeometry(SceneGeometry& g, const street::Layout& s, const QString& lengthUnit)
{
    for (std::size_t i = 0; i < s.boxes.size(); ++i) {
        const Box& b = s.boxes[i];
        if (b.kind != ItemKind::House)
            box(g.floor, b, itemColour(b, i));
    }
    addMarkings(g, s);
    addHouses(g, s);
    addBeyondTheFoot(g, s);
    addKerbsAndLabels(g, s, lengthUnit);
}

} // namespace ab::ui
