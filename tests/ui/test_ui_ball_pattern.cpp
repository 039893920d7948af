// SPDX-License-Identifier: MIT
// The pattern on a ball that turns, as the renderer draws it (ui/view/scene_renderer.*,
// resources/shaders/ball.*): a ball of radius 60 px seen along the world z axis, with its
// pole (body z) towards the eye, away from it, or turned about the pole. Under xvfb-run
// (QT_QPA_PLATFORM=xcb): it needs OpenGL.
#include "support/opengl_platform.h"
#include "ui/charts/scene_layout.h"
#include "ui/video/offscreen_view.h"
#include "ui/view/view_frame.h"

#include "core/simulation.h"

#include <QGuiApplication>
#include <QtTest>

#include <cmath>
#include <numbers>

namespace {

constexpr int kSize = 240;

// A quaternion (x, y, z, w) for a turn by `angle` about the unit axis (ax, ay, az).
std::vector<float> turn(double angle, double ax, double ay, double az)
{
    const double s = std::sin(angle / 2.0);
    return {float(ax * s), float(ay * s), float(az * s), float(std::cos(angle / 2.0))};
}

// One ball of stage 2 at the box's centre, seen from +z (yaw 0, pitch 0) from a distance
// at which it is 60 px in radius: r d / tan(fov/2) fills half the view height at 60/120.
QImage draw(const std::vector<float>& orientation)
{
    ab::RunSpec spec(ab::SceneId::Box3d);
    spec.model = ab::ModelKind::Physical;
    const ab::ui::SceneLayout layout = ab::ui::layoutFor(spec);
    ab::ui::OffscreenView view(QSize(kSize, kSize));
    view.initialize();
    const QVector3D centre(150.0f, 150.0f, 150.0f);
    ab::ui::CameraPose pose;
    pose.target = centre;
    pose.distance = float(layout.ballRadius) * 5.0f;
    view.setScene(layout, "m", {0xd3541e}, -1, QColor(0xec, 0xf0, 0xf5), pose);
    return view.render({centre.x(), centre.y(), centre.z()}, {}, orientation);
}

// How white a pixel is: its smallest channel (the ball's orange has almost no blue; the
// pattern's white gores and cap are 85 % white).
int whiteness(const QImage& image, double dx, double dy)
{
    const QColor c = image.pixelColor(QPoint(int(kSize / 2 + dx), int(kSize / 2 - dy)));
    return std::min({c.red(), c.green(), c.blue()});
}

// The ball's screen radius in pixels, from its outline along the row through its centre.
int drawnRadius(const QImage& image)
{
    const QColor background = image.pixelColor(0, kSize / 2);
    int x = kSize / 2;
    while (x < kSize - 1 && image.pixelColor(x, kSize / 2) != background)
        ++x;
    return x - kSize / 2;
}

} // namespace

class UiBallPattern : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        if (!testing::platformHasOpenGl())
            QSKIP(testing::kNeedsOpenGl);
    }

    // Without orientations the ball is its own colour all over, as in a run that never
    // turns: at the six points where a turning ball's gores are mid-way (body angles 30 +
    // 60 k degrees) at most one is whitish, the highlight; the pattern makes three white.
    void aBallThatDoesNotTurnIsPlain()
    {
        const QImage plain = draw({});
        const QImage patterned = draw(turn(0.0, 0.0, 0.0, 1.0));
        const int r = drawnRadius(plain);
        QVERIFY2(r > 20, qPrintable(QString::number(r)));
        int plainWhite = 0, patternWhite = 0;
        for (int k = 0; k < 6; ++k) {
            const double a = (30.0 + 60.0 * k) * std::numbers::pi / 180.0;
            plainWhite += whiteness(plain, 0.6 * r * std::cos(a), 0.6 * r * std::sin(a)) > 100 ? 1 : 0;
            patternWhite += whiteness(patterned, 0.6 * r * std::cos(a), 0.6 * r * std::sin(a)) > 100 ? 1 : 0;
        }
        QVERIFY2(plainWhite <= 1, qPrintable(QString::number(plainWhite)));
        QCOMPARE(patternWhite, 3);
    }

    // The pole faces the eye: a dark cap at the centre; seen from the other side (a half
    // turn about x) the white cap. Around the pole six gores alternate: body angle phi is
    // white where sin(3 phi) > 0 (phi = 30 deg) and coloured where it is negative (90 deg).
    void thePatternShowsThePoleAndTheGores()
    {
        const QImage upright = draw(turn(0.0, 0.0, 0.0, 1.0));
        const int r = drawnRadius(upright);
        const QColor centre = upright.pixelColor(kSize / 2, kSize / 2);
        QVERIFY2(centre.lightness() < 70, qPrintable(centre.name()));
        const double rho = 0.6 * r, deg = std::numbers::pi / 180.0;
        QVERIFY(whiteness(upright, rho * std::cos(30 * deg), rho * std::sin(30 * deg)) > 150);
        QVERIFY(whiteness(upright, rho * std::cos(90 * deg), rho * std::sin(90 * deg)) < 90);
        const QImage flipped = draw(turn(std::numbers::pi, 1.0, 0.0, 0.0));
        QVERIFY2(whiteness(flipped, 0.0, 0.0) > 150, qPrintable(flipped.pixelColor(kSize / 2, kSize / 2).name()));
    }

    // A turn by 60 degrees about the pole carries each gore onto the next: the point at
    // 30 degrees, white before, is now at body angle -30 degrees, coloured; the one at 90
    // degrees (coloured) is at 30, white. Turned back, the ball looks as it did.
    void aTurnAboutThePoleSwapsTheGores()
    {
        const double deg = std::numbers::pi / 180.0;
        const QImage before = draw(turn(0.0, 0.0, 0.0, 1.0));
        const QImage turned = draw(turn(60 * deg, 0.0, 0.0, 1.0));
        const double rho = 0.6 * drawnRadius(before);
        for (double phi : {30.0, 90.0, 150.0}) {
            const double x = rho * std::cos(phi * deg), y = rho * std::sin(phi * deg);
            const int a = whiteness(before, x, y), b = whiteness(turned, x, y);
            QVERIFY2(std::abs(a - b) > 60, qPrintable(QString("at %1 deg: %2 then %3").arg(phi).arg(a).arg(b)));
        }
        const QImage around = draw(turn(360 * deg, 0.0, 0.0, 1.0));
        int differ = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                differ += std::abs(qGray(around.pixel(x, y)) - qGray(before.pixel(x, y))) > 8 ? 1 : 0;
        QVERIFY2(differ < kSize * kSize / 200, qPrintable(QString::number(differ))); // edge pixels at most
    }
};

QTEST_MAIN(UiBallPattern)
#include "test_ui_ball_pattern.moc"
