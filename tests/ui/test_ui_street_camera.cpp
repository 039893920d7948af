// SPDX-License-Identifier: MIT
// The street's camera moved by hand (stage 5), without OpenGL: the wheel, the keys and the
// mouse never take the eye into the road, a kerb, a house or a car (a notch that would jump
// it through a house front stops it at the wall), the wheel zooms towards the point under
// the pointer and keeps that point where it is in the picture, and a label behind the hill
// is known to be hidden. Hand-worked geometry of the default street (3 blocks of 80 m at
// 17 deg with flat crossings of 14 m, a roadway 12 m wide, sidewalks 3 m, kerbs 0.15 m).
#include "support/street_states.h"

#include "ui/view/orbit_camera.h"
#include "ui/view/street_camera.h"
#include "ui/view/street_geometry.h"

#include <QtTest>

#include <memory>

using namespace ab;
using namespace ab::ui;
using testing::defaultStreet;

namespace {

const QSize kView(800, 600);

std::shared_ptr<const street::Layout> streetLayout(int cars = 0)
{
    return std::make_shared<const street::Layout>(street::Layout::fromParams(testing::streetSpec(10, cars).params));
}

OrbitCamera footShot(const street::Layout& s)
{
    const CameraPose pose = streetPose(s, StreetShot::Foot, float(kView.width()) / float(kView.height()));
    OrbitCamera camera;
    camera.setPose(pose, 400.0f);
    return camera;
}

// The eye's height over the road under it (m).
float overRoad(const street::Layout& s, const QVector3D& eye)
{
    return eye.y() - float(s.roadY(double(eye.x())));
}

// One wheel notch in, towards what the centre of the picture shows, as the view zooms.
void notchIn(OrbitCamera& camera, const StreetSolids& solids, QPointF at = QPointF(400, 300))
{
    QVector3D origin, direction;
    camera.ray(at, kView, origin, direction);
    const auto point = solids.hit(origin, direction);
    QVERIFY(point);
    moveWhileClear(
        camera, [&](OrbitCamera& c, float t) { c.zoomTowards(*point, t); },
        [&](const QVector3D& eye) { return solids.clear(eye); });
}

} // namespace

class UiStreetCamera : public QObject {
    Q_OBJECT

private slots:
    void zoomingInFromTheFootShotStopsHalfAMetreOverTheRoad()
    {
        const auto s = streetLayout();
        const StreetSolids solids(s);
        OrbitCamera camera = footShot(*s);
        // Unchecked, eight notches towards the shot's target take the eye under the road: the
        // straight line from the eye, 1.5 m over the flat street, to the target rises at 6 deg
        // (half-way between the foot and the roofs at the top) and passes under the lowest
        // block, which rises at 17 deg.
        OrbitCamera free = camera;
        free.zoom(8.0f);
        QVERIFY2(overRoad(*s, free.eye()) < 0.0f, qPrintable(QString::number(overRoad(*s, free.eye()))));
        const float start = (camera.eye() - camera.target()).length();
        for (int notch = 0; notch < 60; ++notch) {
            notchIn(camera, solids);
            QVERIFY2(
                overRoad(*s, camera.eye()) >= kStreetEyeClearance - 1e-3f,
                qPrintable(QString("notch %1: %2 m over the road").arg(notch + 1).arg(overRoad(*s, camera.eye()))));
        }
        // It came as near as it may: 5 cm further along the line of sight is too near the road.
        QVector3D origin, direction;
        camera.ray(QPointF(400, 300), kView, origin, direction);
        QVERIFY(!solids.clear(camera.eye() + 0.05f * direction));
        QVERIFY((camera.eye() - camera.target()).length() < 0.1f * start);
    }

    void theWheelKeepsThePointUnderThePointerInPlace()
    {
        const auto s = streetLayout();
        const StreetSolids solids(s);
        OrbitCamera camera = footShot(*s);
        const QPointF pointer(520, 180); // up the street, right of the centre line
        QVector3D origin, direction;
        camera.ray(pointer, kView, origin, direction);
        const auto point = solids.hit(origin, direction);
        QVERIFY(point);
        for (int notch = 0; notch < 5; ++notch) {
            notchIn(camera, solids, pointer);
            QPointF now;
            QVERIFY(camera.project(*point, kView, now));
            QVERIFY2((now - pointer).manhattanLength() < 1.0,
                     qPrintable(QString("(%1, %2)").arg(now.x()).arg(now.y())));
        }
    }

    void theArrowKeysStopTheEyeAtAHouseFront()
    {
        // Standing over the road in the middle of block 2, 3 m up, looking up the street; the
        // key Up moves the eye 2 m towards -z, where the sidewalk ends at z = -9 and the
        // houses' fronts stand.
        const auto s = streetLayout();
        const StreetSolids solids(s);
        const double x = 0.5 * (s->blockStartX[1] + s->blockFootX[1]);
        const auto road = float(s->roadY(x));
        OrbitCamera camera;
        camera.setPose(QVector3D(float(x) - 20.0f, road + 5.0f, 0.0f), 90.0f, 5.0f, 20.0f, 400.0f);
        QVERIFY(solids.clear(camera.eye()));
        const auto front = float(0.5 * s->width + s->sidewalk);
        for (int key = 0; key < 10; ++key)
            moveWhileClear(
                camera,
                [](OrbitCamera& c, float t) {
                    c.moveEye({0.0f, 0.0f, -2.0f * t});
                },
                [&](const QVector3D& eye) { return solids.clear(eye); });
        QVERIFY2(camera.eye().z() >= -front + kStreetEyeClearance - 1e-3f,
                 qPrintable(QString::number(camera.eye().z())));
        QVERIFY2(camera.eye().z() < -front + kStreetEyeClearance + 0.05f,
                 qPrintable(QString::number(camera.eye().z())));
    }

    void aNotchThatWouldJumpAHouseStopsAtItsBack()
    {
        // Behind the +z terrace (fronts at z = 9, 3 m deep), 0.6 m off its back wall and 3 m
        // over the road, looking across the street: four notches (distance x 0.85^4 = 0.52,
        // 4.7 m nearer) would land the eye 1.1 m out over the sidewalk, clear, through the house.
        const auto s = streetLayout();
        const StreetSolids solids(s);
        const double x = 0.5 * (s->blockStartX[1] + s->blockFootX[1]);
        const auto road = float(s->roadY(x)), back = float(0.5 * s->width + s->sidewalk + 3.0);
        OrbitCamera camera;
        camera.setPose(QVector3D(float(x), road + 3.0f, 0.0f), 0.0f, 0.0f, back + 0.6f, 400.0f);
        QVERIFY(solids.clear(camera.eye()));
        OrbitCamera free = camera;
        free.zoom(4.0f);
        QVERIFY(solids.clear(free.eye()) && free.eye().z() < back - 3.0f);
        moveWhileClear(
            camera, [](OrbitCamera& c, float t) { c.zoom(4.0f * t); },
            [&](const QVector3D& eye) { return solids.clear(eye); });
        QVERIFY2(camera.eye().z() >= back + kStreetEyeClearance - 1e-3f, qPrintable(QString::number(camera.eye().z())));
    }

    void theEyeKeepsClearOfAParkedCar()
    {
        const auto s = streetLayout(6);
        const StreetSolids solids(s);
        const auto car = std::find_if(s->boxes.begin(), s->boxes.end(),
                                      [](const street::Box& b) { return b.kind == street::ItemKind::Car; });
        QVERIFY(car != s->boxes.end());
        const QVector3D centre(float(car->centre.x()), float(car->centre.y()), float(car->centre.z()));
        QVERIFY(!solids.clear(centre));
        // From 6 m above the car straight down at it: the wheel stops 0.5 m over its roof.
        OrbitCamera camera;
        camera.setPose(centre, 0.0f, 89.0f, 6.0f, 400.0f);
        for (int notch = 0; notch < 30; ++notch)
            notchIn(camera, solids);
        // Over the roof, in the car's frame (it stands on the sloping road, turned with it).
        const double overRoof =
            car->toLocal({camera.eye().x(), camera.eye().y(), camera.eye().z()}).y() - car->half.y();
        QVERIFY2(overRoof >= kStreetEyeClearance - 2e-3 && overRoof < kStreetEyeClearance + 0.05,
                 qPrintable(QString::number(overRoof)));
    }

    void anEyeAlreadyInsideMayMoveOut()
    {
        const auto s = streetLayout();
        const StreetSolids solids(s);
        OrbitCamera camera;
        camera.setPose(QVector3D(float(s->xFoot) - 5.0f, 0.0f, 0.0f), 90.0f, -20.0f, 10.0f, 400.0f); // under the road
        QVERIFY(!solids.clear(camera.eye()));
        const QVector3D before = camera.eye();
        moveWhileClear(
            camera, [](OrbitCamera& c, float t) { c.orbit(0.0f, 100.0f * t); }, // 40 deg up
            [&](const QVector3D& eye) { return solids.clear(eye); });
        QVERIFY(camera.eye().y() > before.y() + 5.0f);
        QVERIFY(solids.clear(camera.eye()));
    }

    void fitFillsTheViewWithThePointsNotTheirBox()
    {
        // A long thin diagonal, 270 m by 70 m: every point in view, the farthest within the
        // margin of an edge, and the picture's middle between their extents.
        std::vector<QVector3D> points;
        for (int i = 0; i <= 10; ++i)
            for (float z : {-9.0f, 9.0f})
                points.emplace_back(27.0f * float(i), 70.0f - 7.0f * float(i), z);
        for (const QSize size : {QSize(1600, 900), QSize(840, 990)}) {
            OrbitCamera c;
            const float aspect = float(size.width()) / float(size.height());
            c.fit(points, 40.0f, 24.0f, aspect, 0.05f);
            double xLo = 1e9, xHi = -1e9, yLo = 1e9, yHi = -1e9;
            for (const QVector3D& p : points) {
                QPointF at;
                QVERIFY(c.project(p, size, at));
                xLo = std::min(xLo, at.x()), xHi = std::max(xHi, at.x());
                yLo = std::min(yLo, at.y()), yHi = std::max(yHi, at.y());
            }
            QVERIFY(xLo >= 0.0 && yLo >= 0.0 && xHi <= size.width() && yHi <= size.height());
            // 5 % of the half-extent to spare on the side that binds: 2.5 % of the picture.
            const double spareX = std::min(xLo, size.width() - xHi) / size.width();
            const double spareY = std::min(yLo, size.height() - yHi) / size.height();
            QVERIFY2(std::min(spareX, spareY) < 0.03, qPrintable(QString("%1 %2").arg(spareX).arg(spareY)));
            QVERIFY(std::abs(xLo - (size.width() - xHi)) < 0.01 * size.width());   // centred across
            QVERIFY(std::abs(yLo - (size.height() - yHi)) < 0.01 * size.height()); // and up and down
        }
    }

    void theRayMeetsTheRoadAndTheSkyIsEmpty()
    {
        const auto s = streetLayout();
        const StreetSolids solids(s);
        // Straight down onto the middle of block 1: the road's surface.
        const double x = 0.5 * (s->blockStartX[0] + s->blockFootX[0]);
        const auto down = solids.hit(QVector3D(float(x), 100.0f, 1.0f), QVector3D(0.0f, -1.0f, 0.0f));
        QVERIFY(down);
        QVERIFY(std::abs(down->y() - float(s->roadY(x))) < 1e-3f);
        // Down onto the flat street 20 m past the foot (not a box: the ground there).
        const auto past = solids.hit(QVector3D(float(s->xFoot) + 20.0f, 10.0f, 0.0f), QVector3D(0.0f, -1.0f, 0.0f));
        QVERIFY(past && std::abs(past->y()) < 1e-4f);
        QVERIFY(!solids.hit(QVector3D(float(s->xFoot) + 20.0f, 10.0f, 0.0f), QVector3D(0.0f, 1.0f, 0.0f)));
    }

    void aLabelBehindTheHillIsHiddenAndSeenFromTheFootShot()
    {
        const auto s = streetLayout();
        const StreetSolids solids(s);
        const QVector3D topLabel(float(s->xTop), float(s->height + ab::ui::kTopLabelHeight), 0.0f);
        QVERIFY(!solids.hides(footShot(*s).eye(), topLabel));
        // Seen from the foot shot, 1.5 m over the flat street 45 m past the foot (x = 302.5), the
        // crest at the top block's upper end (x = 0, 70.2 m up) stands at atan(68.7 / 302.5) =
        // 12.8 deg; the middle of the top crossing, 0.3 m over the road 7 m beyond the crest, at
        // atan(69.0 / 309.5) = 12.6 deg: behind it. The top's label, 18 m over the crossing's far
        // end (x = -14), at atan(86.7 / 316.5) = 15.3 deg, is seen.
        const QVector3D onTopCrossing(float(0.5 * s->xTop), float(s->height) + 0.3f, 0.0f);
        QVERIFY(solids.hides(footShot(*s).eye(), onTopCrossing));
        // A point on the road is not hidden by the road itself.
        const double mid = 0.5 * (s->blockStartX[2] + s->blockFootX[2]);
        QVERIFY(!solids.hides(footShot(*s).eye(), QVector3D(float(mid), float(s->roadY(mid)), 0.0f)));
    }
};

QTEST_GUILESS_MAIN(UiStreetCamera)
#include "test_ui_street_camera.moc"
