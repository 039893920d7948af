// SPDX-License-Identifier: MIT
// The selected ball's path as the renderer draws it (ui/view/scene_renderer.*,
// resources/shaders/trace.vert): a band three pixels wide in the path's colour with a
// pixel's edge each side in a colour of the other lightness, across whatever the path
// runs over. Under xvfb-run (QT_QPA_PLATFORM=xcb): it needs OpenGL.
#include "support/opengl_platform.h"
#include "ui/charts/scene_layout.h"
#include "ui/video/offscreen_view.h"
#include "ui/view/view_frame.h"

#include "core/simulation.h"

#include <QGuiApplication>
#include <QtTest>

namespace {

constexpr int kSize = 240;
const QColor kBackground(0xec, 0xf0, 0xf5);
constexpr unsigned kBall = 0xd3541e;

// Stage 2's box seen along -z from in front of its middle (yaw 0, pitch 0), the eye 150 m
// from the plane z = 150 in which `trace` runs; the ball itself is drawn far off the path.
QImage draw(const std::vector<QVector3D>& trace)
{
    ab::RunSpec spec(ab::SceneId::Box3d);
    spec.model = ab::ModelKind::Physical;
    const ab::ui::SceneLayout layout = ab::ui::layoutFor(spec);
    ab::ui::OffscreenView view(QSize(kSize, kSize));
    view.initialize();
    ab::ui::CameraPose pose;
    pose.target = QVector3D(150.0f, 150.0f, 150.0f);
    pose.distance = 150.0f;
    view.setScene(layout, "m", {kBall}, 0, kBackground, pose);
    return view.render({290.0f, 290.0f, 150.0f}, trace);
}

// The run of one colour along a column (or a row) `offset` pixels right of (below) the
// image's middle, from the first pixel of `colour` on: how many pixels of it, and the
// pixels just before and after.
struct Crossing {
    int core = 0;
    QColor before, after;
};

Crossing cross(const QImage& image, bool column, const QColor& colour, int offset = 7)
{
    Crossing c;
    const auto at = [&](int k) {
        return QColor(column ? image.pixel(kSize / 2 + offset, k) : image.pixel(k, kSize / 2 + offset));
    };
    int k = 0;
    while (k < kSize && at(k).rgb() != colour.rgb())
        ++k;
    if (k == kSize)
        return c;
    c.before = at(k - 1);
    while (k < kSize && at(k).rgb() == colour.rgb()) {
        ++c.core;
        ++k;
    }
    c.after = at(k);
    return c;
}

} // namespace

class UiTrace : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        if (!testing::platformHasOpenGl())
            QSKIP(testing::kNeedsOpenGl);
    }

    // A path across the view, level and then upright: wherever it is crossed, three pixels
    // (or four, where the band's edge falls on a pixel's centre) of the path's colour, the
    // ball's darkened by 150 %, between white pixels; a one-pixel line was one pixel.
    void thePathIsABandThreePixelsWideWithALightEdge()
    {
        const QColor path = QColor::fromRgb(kBall).darker(150);
        QVERIFY(path.lightnessF() < 0.55); // a dark path: its edge is white
        const QImage level = draw({{60.0f, 150.0f, 150.0f}, {240.0f, 150.0f, 150.0f}});
        const Crossing across = cross(level, true, path);
        QVERIFY2(across.core >= 3 && across.core <= 4, qPrintable(QString::number(across.core)));
        QCOMPARE(across.before.rgb(), QColor(Qt::white).rgb());
        QCOMPARE(across.after.rgb(), QColor(Qt::white).rgb());
        const QImage upright = draw({{150.0f, 60.0f, 150.0f}, {150.0f, 240.0f, 150.0f}});
        const Crossing along = cross(upright, false, path);
        QVERIFY2(along.core >= 3 && along.core <= 4, qPrintable(QString::number(along.core)));
        QCOMPARE(along.before.rgb(), QColor(Qt::white).rgb());
        QCOMPARE(along.after.rgb(), QColor(Qt::white).rgb());
    }

    // A bend of 90 degrees leaves no notch at its outer corner: the two bands reach past
    // their shared point by half their width, so the corner's pixel is the path's colour.
    void aBendIsDrawnWithoutANotch()
    {
        const QColor path = QColor::fromRgb(kBall).darker(150);
        const QImage bend = draw({{60.0f, 150.0f, 150.0f}, {150.0f, 150.0f, 150.0f}, {150.0f, 240.0f, 150.0f}});
        // The bend's point is the view's centre, a pixel corner; the pixel down and right of
        // it (centre 0.5 px right and below) lies outside both bands' own lengths, inside the
        // 1.5 px each reaches past its end.
        QCOMPARE(bend.pixel(kSize / 2, kSize / 2), path.rgb());
    }

    // A path with one end behind the eye has no direction on screen: that segment is left
    // out, the rest drawn, nothing else disturbed.
    void aSegmentReachingBehindTheEyeIsLeftOut()
    {
        const QColor path = QColor::fromRgb(kBall).darker(150);
        const QImage image = draw({{60.0f, 150.0f, 150.0f}, {150.0f, 150.0f, 150.0f}, {150.0f, 150.0f, 400.0f}});
        const Crossing across = cross(image, true, path, -20); // the level segment, left of the bend
        QVERIFY2(across.core >= 3 && across.core <= 4, qPrintable(QString::number(across.core)));
        QCOMPARE(image.pixel(kSize - 5, kSize - 5), image.pixel(kSize - 5, kSize - 30));
    }
};

QTEST_MAIN(UiTrace)
#include "test_ui_trace.moc"
