// SPDX-License-Identifier: MIT
#include "view_frame.h"

#include "street_camera.h"

#include "core/random.h"
#include "ui/theme/contrast.h"

#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ab::ui {

std::vector<unsigned> ballColours(const RunSpec& spec, int balls)
{
    std::vector<unsigned> colours(static_cast<std::size_t>(std::max(balls, 0)));
    static constexpr unsigned fixed[] = {0xe4572e, 0x2e86de};
    if (balls <= 2) {
        for (int i = 0; i < balls; ++i)
            colours[static_cast<std::size_t>(i)] = fixed[i];
        return colours;
    }
    const long long seed = spec.params.indexOf("seed") ? spec.params.integer("seed") : 0;
    SplitMix64 rng(static_cast<std::uint64_t>(seed) ^ 0xC0105EEDull);
    for (unsigned& c : colours) {
        const QColor q = QColor::fromHsvF(float(rng.uniform()), float(0.55 + 0.4 * rng.uniform()),
                                          float(0.75 + 0.25 * rng.uniform()));
        c = q.rgb() & 0xffffffu;
    }
    return colours;
}

void frameSceneCamera(OrbitCamera& camera, const SceneGeometry& geometry, const SceneLayout& layout, float aspect)
{
    // The report's WebGL camera stands at (100, 50, 50) from the centre: yaw about 63
    // degrees, pitch about 24. The vertical scene is seen from the side, the street from
    // its foot (the advert's shot).
    if (layout.street) {
        const CameraPose pose = streetPose(*layout.street, StreetShot::Foot, aspect);
        camera.setPose(pose, (geometry.hi - geometry.lo).length());
    } else if (layout.walls)
        camera.frame(geometry.lo, geometry.hi, 63.0f, 24.0f, aspect);
    else
        camera.frame(geometry.lo, geometry.hi, 0.0f, 8.0f, aspect);
}

float smallestBallPixels(const SceneLayout& layout, int viewHeight, double scale)
{
    // A crowd keeps small dots (they would cover each other); up to a dozen balls are at
    // least 1/90 of the view's height in radius (12 px of 1080), all larger in lecture mode.
    // The street's 3 cm balls on a 300 m street are a twentieth of a pixel from its foot:
    // a dot 2.5 pixels in radius shows each one, and the flood's shape.
    const double pixels = layout.street        ? 2.5
                          : layout.balls > 100 ? 2.0
                          : layout.balls > 12  ? 5.0
                                               : std::max(5.0, viewHeight / 90.0);
    return float(pixels * scale);
}

float footAsFloat(double xFoot)
{
    // The largest float not above the foot: a frame's x (a float) is beyond it exactly when,
    // read back as a double, it is beyond the foot, as the census counts (street::hasLeft).
    // Rounded to nearest, the foot may come out above itself, and the balls the engine retired
    // a few micrometres past it would be drawn at the foot for ever.
    float f = float(xFoot);
    if (double(f) > xFoot)
        f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

RenderInputs sceneRenderInputs(const OrbitCamera& camera, const SceneLayout& layout, QSize size, int selected,
                               const QColor& background, double scale)
{
    RenderInputs in;
    const float aspect = float(size.width()) / float(std::max(size.height(), 1));
    in.viewport = size;
    in.view = camera.view();
    in.projection = camera.projection(aspect);
    in.pixelsPerUnit = camera.pixelsPerUnit(size.height());
    in.radius = float(layout.ballRadius);
    in.minPixels = smallestBallPixels(layout, size.height(), scale);
    in.traceWidth = float(3.0 * scale);                   // larger in lecture mode, as the text
    in.selected = layout.balls > 1 ? selected : -1;       // one ball needs no marking
    in.floorY = float(layout.floorY - layout.drawnInset); // the drawn floor, where the shadows lie
    // A few balls get a cue that darkens as they come down; a crowd (thousands, piling up
    // on the floor) only where a ball is within a diameter of it: the cues of the layers
    // above would lie under the bottom layer's balls, and under software OpenGL drawing
    // them costs an eighth of the frame at 10,000 balls.
    constexpr int crowd = 2'000;
    in.fadeHeight = layout.balls > crowd ? float(2.0 * layout.ballRadius)
                                         : float(std::max(6.0 * layout.ballRadius, 0.08 * layout.region.sizes().y()));
    in.background = background;
    if (layout.street) {
        // The floor cues lie on the plane y = floorY, which the sloping street is not; the
        // balls that left at the open foot are not drawn.
        in.shadows = false;
        in.hideBeyondX = footAsFloat(layout.street->xFoot);
    }
    return in;
}

LabelInk labelInk(const QColor& colour, const QColor& background)
{
    const bool dark = relativeLuminance(background) < 0.18; // as withContrast tells dark from light
    const QColor halo = dark ? QColor(0, 0, 0) : QColor(255, 255, 255);
    constexpr int alpha = 220; // the scene shows faintly through the halo
    // The text stands 7:1 against the halo as drawn over the brightest scene (a dark halo) or
    // the darkest (a light one): the composite a H + (1 - a) S, black over white (255 - a) or
    // white over black (a). Against the opaque halo only, high contrast's grey read 5.6:1 on
    // the halo over its dark view.
    const int worst = dark ? 255 - alpha : alpha;
    QColor text = withContrast(colour, QColor(worst, worst, worst), 7.0);
    QColor veil = halo;
    veil.setAlpha(alpha);
    return {text, veil};
}

void drawHaloText(QPainter& p, const QPointF& at, const QString& text, const QColor& colour, Qt::Alignment align,
                  const QColor& background)
{
    const QFontMetricsF fm(p.font());
    const QRectF box = fm.boundingRect(text);
    QPointF origin = at;
    if (align & Qt::AlignRight)
        origin.rx() -= box.width();
    else if (align & Qt::AlignHCenter)
        origin.rx() -= box.width() / 2.0;
    origin.ry() += fm.ascent() / 2.0 - 1.0; // vertically centred on `at`
    // On a whole pixel: the outline is drawn unhinted and antialiased, and from a baseline
    // between pixels the one-pixel bars of t and f spread over two rows at half strength
    // ("lop, 70.2 m above lhe fool" in the foot shot).
    origin = QPointF(std::round(origin.x()), std::round(origin.y()));
    QPainterPath path;
    path.addText(origin, p.font(), text);
    const double halo = std::max(3.0, fm.height() / 6.0);
    const LabelInk ink = labelInk(colour, background);
    p.setPen(QPen(ink.halo, halo, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
    p.fillPath(path, ink.text);
}

void drawBottomHint(QPainter& p, QSize size, const QString& text, const QColor& colour, const QColor& background)
{
    const double room = size.width() - 24.0; // 12 px margins
    const QFontMetricsF asSet(p.font());
    QStringList lines{text};
    if (asSet.horizontalAdvance(text) > room)
        lines = text.split(QStringLiteral("; "));
    double widest = 0.0;
    for (const QString& line : lines)
        widest = std::max(widest, asSet.horizontalAdvance(line));
    p.save();
    if (widest > room && room > 0.0) {
        QFont smaller = p.font();
        smaller.setPointSizeF(std::max(6.0, smaller.pointSizeF() * room / widest));
        p.setFont(smaller);
    }
    const QFontMetricsF fm(p.font());
    const double bottom = size.height() - 0.7 * fm.height(); // the last line's middle
    for (qsizetype k = 0; k < lines.size(); ++k)
        drawHaloText(p, QPointF(12.0, bottom - double(lines.size() - 1 - k) * fm.height()), lines[k], colour,
                     Qt::AlignLeft, background);
    p.restore();
}

void paintSceneLabels(QPainter& p, const OrbitCamera& camera, QSize size, const SceneGeometry& geometry,
                      const SceneLayout& layout, const std::vector<float>& balls, const QFont& font,
                      const QColor& background, const std::function<bool(const QVector3D&)>& hidden)
{
    p.setRenderHint(QPainter::Antialiasing);
    p.setFont(font);
    QPointF at;
    const QFontMetricsF fm(font);
    for (const SceneLabel& label : geometry.labels) {
        // A label whose point is out of view is not drawn: moved in, it would name the wrong place
        // (the top's label in a corner of the flood shot, the top far above the picture).
        if (!camera.project(label.at, size, at) || at.x() < 0.0 || at.x() > size.width() || at.y() < 0.0 ||
            at.y() > size.height() || (hidden && hidden(label.at)))
            continue;
        // A label whose point is in view is read whole: moved in from the edge it would cross
        // (drawn centred on its point, across and up and down).
        // Within [half, extent - half], or the middle where the view is narrower than the label.
        auto inside = [](double v, double half, double extent) {
            return std::clamp(v, std::min(half, extent / 2.0), std::max(extent - half, extent / 2.0));
        };
        if (label.above)
            at.setY(at.y() - 0.5 * fm.height() - 2.0); // its text's middle, clear of the line
        at.setX(inside(at.x(), fm.horizontalAdvance(label.text) / 2.0 + 3.0, size.width()));
        at.setY(inside(at.y(), fm.height() / 2.0 + 3.0, size.height()));
        drawHaloText(p, at, label.text, label.colour, Qt::AlignHCenter, background);
    }
    // The vertical scene reads its height off the scale: label the ball with it, beside the
    // ball as drawn (its projected radius, or the smallest drawn size) and half a line clear.
    const QVector3D centre = balls.size() >= 3 ? QVector3D(balls[0], balls[1], balls[2]) : QVector3D();
    QPointF rim;
    if (!layout.walls && !layout.street && balls.size() >= 3 && camera.project(centre, size, at) &&
        camera.project(centre + QVector3D(0.0f, float(layout.ballRadius), 0.0f), size, rim)) {
        const double radius =
            std::max(QLineF(at, rim).length(), double(smallestBallPixels(layout, size.height(), 1.0)));
        drawHaloText(p, at + QPointF(radius + 0.5 * QFontMetricsF(font).height(), 0.0),
                     QStringLiteral("y = %1").arg(double(balls[1]), 0, 'f', 1), QColor(0x20, 0x20, 0x20), Qt::AlignLeft,
                     background);
    }
}

} // namespace ab::ui
