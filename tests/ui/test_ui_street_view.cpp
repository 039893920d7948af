// SPDX-License-Identifier: MIT
// The street (stage 5) as OpenGL draws it, in a real X server (Xvfb, Mesa llvmpipe): the
// foot shot sees the asphalt of the road up the hill and the sky above the houses; a ball
// on the road is drawn in its colour, one that has left beyond the open foot is not.
// Skipped where the platform has no OpenGL (offscreen, minimal).
#include "support/opengl_platform.h"
#include "ui/charts/scene_layout.h"
#include "ui/video/offscreen_view.h"
#include "ui/view/street_camera.h"

#include <QGuiApplication>
#include <QtTest>

using namespace ab;
using namespace ab::ui;

namespace {

const QColor sky(0xec, 0xf0, 0xf5);

RunSpec streetSpec(double radius)
{
    RunSpec spec(SceneId::Street);
    spec.params.parse("n", "2");
    spec.params.parse("r", QString::number(radius).toStdString());
    return spec;
}

QPoint pixelOf(const OffscreenView& view, const QVector3D& p)
{
    QPointF at;
    if (!view.camera().project(p, view.size(), at))
        return {-1, -1};
    return at.toPoint();
}

// Grey: the three channels within 30 of each other, neither white nor black.
bool grey(const QColor& c)
{
    const int hi = std::max({c.red(), c.green(), c.blue()}), lo = std::min({c.red(), c.green(), c.blue()});
    return hi - lo < 30 && hi > 40 && hi < 200;
}

bool reddish(const QColor& c)
{
    return c.red() > 120 && c.red() > 2 * c.green() && c.red() > 2 * c.blue();
}

} // namespace

class UiStreetView : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<OffscreenView> view_;
    SceneLayout layout_;

    void open(double radius, StreetShot shot)
    {
        if (!testing::platformHasOpenGl())
            QSKIP(testing::kNeedsOpenGl);
        layout_ = layoutFor(streetSpec(radius));
        view_ = std::make_unique<OffscreenView>(QSize(640, 480));
        view_->initialize();
        const CameraPose pose = streetPose(*layout_.street, shot, 640.0f / 480.0f);
        view_->setScene(layout_, "m", {0xd62728, 0xd62728}, -1, sky, pose);
    }

private slots:
    void footShotSeesTheRoadUpTheHill()
    {
        open(0.03, StreetShot::Foot);
        const QImage image = view_->render({}, {});
        if (!qEnvironmentVariableIsEmpty("AB_STREET_IMAGES"))
            image.save(qEnvironmentVariable("AB_STREET_IMAGES") + "/foot.png");
        const street::Layout& s = *layout_.street;
        // The road's centre half-way down each block, just off the painted centre line.
        for (int k = 0; k < s.blocks; ++k) {
            const double x = 0.5 * (s.blockStartX[std::size_t(k)] + s.blockFootX[std::size_t(k)]) + 1.5;
            const QPoint p = pixelOf(*view_, QVector3D(float(x), float(s.roadY(x)), 2.5f));
            QVERIFY2(image.rect().contains(p), qPrintable(QString("block %1 out of the picture").arg(k + 1)));
            QVERIFY2(grey(image.pixelColor(p)), qPrintable(image.pixelColor(p).name()));
        }
        // Just above the back wall at the top of the hill: the sky.
        const QPoint above = pixelOf(*view_, QVector3D(float(s.xTop) - 3.0f, float(s.houseTop + 5.0), 0.0f));
        QVERIFY(image.rect().contains(above));
        QCOMPARE(image.pixelColor(above), sky);
    }

    void ballBeyondTheFootIsNotDrawn()
    {
        // Two balls of 1 m in red: one on the road 10 m above the foot, one parked 3 m past it,
        // between the camera and the street, 3 m to the side (clear of the "foot" label).
        open(1.0, StreetShot::Foot);
        const street::Layout& s = *layout_.street;
        const float onRoad = float(s.xFoot) - 10.0f, gone = float(s.xFoot) + 3.0f;
        const std::vector<float> xyz = {onRoad, float(s.roadY(onRoad)) + 1.0f, 0.0f, gone, 1.0f, 3.0f};
        const QImage image = view_->render(xyz, {});
        if (!qEnvironmentVariableIsEmpty("AB_STREET_IMAGES"))
            image.save(qEnvironmentVariable("AB_STREET_IMAGES") + "/foot-balls.png");
        const QPoint drawn = pixelOf(*view_, QVector3D(xyz[0], xyz[1], xyz[2]));
        const QPoint hidden = pixelOf(*view_, QVector3D(xyz[3], xyz[4], xyz[5]));
        QVERIFY(image.rect().contains(drawn) && image.rect().contains(hidden));
        QVERIFY2(reddish(image.pixelColor(drawn)), qPrintable(image.pixelColor(drawn).name()));
        QVERIFY2(!reddish(image.pixelColor(hidden)), qPrintable(image.pixelColor(hidden).name()));
        // The same ball moved 4 m back onto the road is drawn.
        std::vector<float> back = xyz;
        back[3] = float(s.xFoot) - 1.0f;
        const QImage again = view_->render(back, {});
        const QPoint now = pixelOf(*view_, QVector3D(back[3], back[4], back[5]));
        QVERIFY2(reddish(again.pixelColor(now)), qPrintable(again.pixelColor(now).name()));
    }
};

QTEST_MAIN(UiStreetView)
#include "test_ui_street_view.moc"
