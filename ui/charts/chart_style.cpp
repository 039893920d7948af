// SPDX-License-Identifier: MIT
#include "chart_style.h"

#include "motion_chart.h"

#include <algorithm>

namespace ab::ui {

namespace {

// x, y, z in the colours of the 3D view's axis triad.
const QColor axisColours[3] = {QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c), QColor(0x1f, 0x77, 0xb4)};
// Kinetic (of translation where the balls turn), potential, total, spring, rotation (a
// deeper red beside translation's orange: the two parts of the kinetic energy), what left
// the street (a slate grey: energy out of the scene); and the activity chart's two lines.
const QColor energyColours[6] = {QColor(0xe6, 0x7e, 0x22), QColor(0x16, 0xa0, 0x85), QColor(0x8e, 0x44, 0xad),
                                 QColor(0x8c, 0x56, 0x4b), QColor(0xc0, 0x39, 0x2b), QColor(0x5d, 0x6d, 0x7e)};
const QColor activityColours[2] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28)};
// The street's: one hue per block's foot, down the hill; the speed percentiles in green, blue
// and violet, the fastest ball in red (three deepening blues were lifted to one bright blue
// on a dark plot, and darkened to one on the high-contrast white).
const QColor footColours[5] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c),
                               QColor(0x94, 0x67, 0xbd), QColor(0xd6, 0x27, 0x28)};
const QColor speedColours[4] = {QColor(0x1b, 0x9e, 0x77), QColor(0x21, 0x71, 0xb5), QColor(0x6a, 0x3d, 0x9a),
                                QColor(0xd6, 0x27, 0x28)};
// The comparison's family: each colour mixed half and half with a dark violet, so that
// its lines are darker and of another hue than the run's they lie on.
const QColor comparisonTint(0x4b, 0x00, 0x82);

QColor mix(const QColor& a, const QColor& b, double w)
{
    return QColor::fromRgbF(float(a.redF() * (1 - w) + b.redF() * w), float(a.greenF() * (1 - w) + b.greenF() * w),
                            float(a.blueF() * (1 - w) + b.blueF() * w));
}

QColor baseColour(ChartKind kind, int line)
{
    switch (kind) {
    case ChartKind::Energy:
        return energyColours[std::clamp(line, 0, 5)];
    case ChartKind::Activity:
        return activityColours[std::clamp(line, 0, 1)];
    case ChartKind::FootRate:
        return footColours[std::clamp(line, 0, 4)];
    case ChartKind::Speeds:
        return speedColours[std::clamp(line, 0, 3)];
    default:
        return axisColours[std::clamp(line, 0, 2)];
    }
}

} // namespace

ChartLook ChartLook::window()
{
    return ChartLook{};
}

ChartLook ChartLook::print(double pxPerPt)
{
    return ChartLook{true, pxPerPt, 8.0, 9.5, 7.5, 1.0};
}

ChartLook ChartLook::slide(double pxPerPt)
{
    return ChartLook{true, pxPerPt, 16.0, 20.0, 14.0, 2.5};
}

QFont ChartLook::font(const QFont& base, double pt, bool bold) const
{
    QFont f = base;
    // A figure's text is laid out in scene units (pxPerPt to the point of the final
    // size), so that it comes out at `pt` whatever the device's resolution.
    if (figure)
        f.setPixelSize(std::max(1, int(px(pt) + 0.5)));
    else
        f.setPointSizeF(pt);
    f.setBold(bold);
    return f;
}

QColor lineColour(ChartKind kind, int line, LineFamily family)
{
    const QColor base = baseColour(kind, line);
    switch (family) {
    case LineFamily::Run:
        return base;
    case LineFamily::ClosedForm:
        return base.darker(130);
    case LineFamily::Comparison:
        return mix(base, comparisonTint, 0.5);
    }
    return base;
}

QColor comparisonOnDark(const QColor& run)
{
    // Hue in degrees; the shorter way round the circle to violet (280), at most 60.
    constexpr double violet = 280.0, turn = 60.0;
    const double h = std::max(0.0, double(run.hslHueF())) * 360.0;
    double towards = violet - h;
    if (towards > 180.0)
        towards -= 360.0;
    if (towards < -180.0)
        towards += 360.0;
    // A violet run line (the total energy) turns on past magenta to red instead, so that
    // its comparison is still of another hue.
    double hue = std::abs(towards) < turn / 2 ? h + 1.5 * turn : h + std::clamp(towards, -turn, turn);
    hue = hue < 0.0 ? hue + 360.0 : hue >= 360.0 ? hue - 360.0 : hue;
    return QColor::fromHslF(float(hue / 360.0), 0.85f, 0.75f);
}

QPen linePen(ChartKind kind, int line, int order, LineFamily family, const ChartLook& look)
{
    // The run's lines differ in style too (solid, dash-dot, dash-dot-dot): told apart
    // in greyscale. The closed form is dashed, the comparison dotted.
    static const Qt::PenStyle runStyles[3] = {Qt::SolidLine, Qt::DashDotLine, Qt::DashDotDotLine};
    const bool total = kind == ChartKind::Energy && line == 2;
    double width = look.px(look.linePt);
    Qt::PenStyle style = Qt::SolidLine;
    switch (family) {
    case LineFamily::Run:
        style = total ? Qt::SolidLine : runStyles[std::clamp(order, 0, 2)];
        width *= total ? 1.25 : 1.0;
        break;
    case LineFamily::ClosedForm:
        style = Qt::DashLine;
        width *= 0.85;
        break;
    case LineFamily::Comparison:
        style = Qt::DotLine;
        width *= 1.1;
        break;
    }
    QPen pen(lineColour(kind, line, family), width, style);
    // Qt Charts draws a solid line segment by segment, each antialiased on its own: with flat
    // ends, a column holding a few segments shorter than a pixel (the track is thinned to its
    // least and greatest per column) came out at about 0.7 of the pen's colour, as each
    // segment covers only its share of the pixel and the shares blend rather than add. Round
    // ends overlap their neighbours. A dashed line is drawn as one path: flat dashes.
    pen.setCapStyle(style == Qt::SolidLine ? Qt::RoundCap : Qt::FlatCap);
    return pen;
}

QPen cursorPen(const ChartLook& look)
{
    // A bluish grey of its own (no other line or text is drawn in it), 0.72 of a run line.
    return QPen(QColor(0x60, 0x60, 0x66), look.px(0.72 * look.linePt));
}

} // namespace ab::ui
