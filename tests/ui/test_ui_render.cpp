// SPDX-License-Identifier: MIT
// The 3D view in a real X server (Xvfb, Mesa llvmpipe): the framebuffer shows each ball
// in its colour where the simulation puts it, projected with the view's own camera
// matrices, and the image is not blank; a click selects the ball under it; with keyboard
// focus the arrow keys move the camera as the report's program does, in lecture mode too,
// where they otherwise walk the equations; a comparison run's
// balls are drawn ghosted beside the solid ones. Skipped where the
// platform has no OpenGL windows (offscreen, minimal).
#include "support/opengl_platform.h"
#include "ui/charts/scene_layout.h"
#include "ui/lecture/lecture_mode.h"
#include "ui/main_window.h"
#include "ui/panels/stage_navigator.h"
#include "ui/view/ball_view.h"

#include "tests/support/sim_helpers.h"

#include <QApplication>
#include <QGuiApplication>
#include <QLabel>
#include <QRegularExpression>
#include <QtTest>

#include <set>

using ab::SceneId;
using ab::ui::MainWindow;

namespace {

// Window pixel of world point p, from the camera's own view and projection matrices.
QPointF projectWithCamera(const ab::ui::BallView& view, const QVector3D& p)
{
    const float aspect = float(view.width()) / float(view.height());
    const QVector4D clip = view.camera().projection(aspect) * view.camera().view() * QVector4D(p, 1.0f);
    const QVector3D ndc = clip.toVector3DAffine();
    return QPointF((ndc.x() + 1.0) * 0.5 * view.width(), (1.0 - ndc.y()) * 0.5 * view.height());
}

// The ball's centre in the current frame of the run, as the worker recorded it.
QVector3D ballCentre(MainWindow& w, int ball)
{
    QVector3D c;
    w.controller().engine().read([&](const ab::ui::Recording&, const ab::ui::Frame& f) {
        const auto i = std::size_t(3 * ball);
        c = QVector3D(f.p[i], f.p[i + 1], f.p[i + 2]);
    });
    return c;
}

// A lit ball is its own colour scaled by the light: compare hues, not exact values.
bool looksLike(const QColor& pixel, QRgb ballRgb)
{
    const QColor ball = QColor::fromRgb(ballRgb);
    if (pixel.saturationF() < 0.3f)
        return false;
    const int dh = std::abs(pixel.hsvHue() - ball.hsvHue());
    return std::min(dh, 360 - dh) < 25;
}

// Waits until the view has drawn what it holds now.
void waitForFrame(ab::ui::BallView* view)
{
    QSignalSpy painted(view, &ab::ui::BallView::framePainted);
    view->requestUpdate();
    QTRY_VERIFY_WITH_TIMEOUT(painted.count() >= 1, 10000);
}

} // namespace

class UiRender : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> window_;

    MainWindow& open(SceneId scene)
    {
        const QString platform = QGuiApplication::platformName();
        if (platform == "offscreen" || platform == "minimal")
            return *window_; // the caller skips
        window_ = std::make_unique<MainWindow>();
        window_->resize(1400, 900);
        window_->show();
        window_->showScene(scene);
        return *window_;
    }

private slots:
    void init()
    {
        if (!testing::platformHasOpenGl())
            QSKIP(testing::kNeedsOpenGl);
    }

    void cleanup() { window_.reset(); }

    void eachBallIsDrawnWhereTheSimulationPutsIt()
    {
        MainWindow& w = open(SceneId::TwoBalls);
        ab::ui::BallView* view = w.view();
        QVERIFY(view);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY(view->isExposed());
        // Let the balls fly apart from their start and come to a moment worth checking.
        for (int i = 0; i < 150; ++i)
            w.controller().stepOnce();
        QTRY_COMPARE_WITH_TIMEOUT(w.controller().status().steps, 150LL, 10000);
        w.controller().poll();
        waitForFrame(view);
        QVERIFY2(view->glError().isEmpty(), qPrintable(view->glError()));
        const QImage image = view->grabFramebuffer().scaled(view->size()); // device to window pixels
        QVERIFY(!image.isNull());

        const std::vector<unsigned> colours = ab::ui::ballColours(w.controller().spec(), 2);
        for (int ball = 0; ball < 2; ++ball) {
            const QVector3D centre = ballCentre(w, ball);
            const QPointF pixel = projectWithCamera(*view, centre);
            QVERIFY(QRectF(QPointF(0, 0), QSizeF(view->size())).contains(pixel));
            const QColor seen = image.pixelColor(pixel.toPoint());
            QVERIFY2(looksLike(seen, colours[std::size_t(ball)]),
                     qPrintable(QString("ball %1 at (%2, %3): pixel %4, ball colour #%5")
                                    .arg(ball + 1)
                                    .arg(pixel.x())
                                    .arg(pixel.y())
                                    .arg(seen.name())
                                    .arg(colours[std::size_t(ball)], 6, 16, QChar('0'))));
        }
        // The view's own projection agrees with the camera's matrices.
        QPointF own;
        QVERIFY(view->ballPixel(0, own));
        QVERIFY((own - projectWithCamera(*view, ballCentre(w, 0))).manhattanLength() < 1.0);
    }

    void aComparisonRunsBallIsDrawnGhostedBesideTheSolidOne()
    {
        MainWindow& w = open(SceneId::Bounce1d);
        ab::ui::BallView* view = w.view();
        QVERIFY(view);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ab::ui::RunOptions o = w.options();
        o.compare =
            ab::RunVariant{ab::ModelKind::Physical, ab::Integrator::SymplecticEuler, ab::ImpactMode::Located, {}};
        QVERIFY(w.applyOptions(o));
        QVERIFY(view->ghostLegend().contains("solid: report"));
        QVERIFY(view->ghostLegend().contains("ghost: physical symplectic-euler"));
        for (int i = 0; i < 150; ++i) // falling: about 1100 below the start height of 2000
            w.controller().stepOnce();
        QTRY_COMPARE_WITH_TIMEOUT(w.controller().status().steps, 150LL, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(w.controller().comparisonStatus().t, w.controller().status().t, 10000);
        w.controller().pause(); // redraws the panels and the view now
        w.controller().poll();
        waitForFrame(view);
        const QImage image = view->grabFramebuffer().scaled(view->size());
        QPointF solid, ghost;
        QVERIFY(view->ballPixel(0, solid));
        QVERIFY(view->ghostPixel(0, ghost));
        QVERIFY((solid - ghost).manhattanLength() > 4.0); // drawn beside the ball, not over it
        const QColor s = image.pixelColor(solid.toPoint());
        const QColor g = image.pixelColor(ghost.toPoint());
        const QColor background = image.pixelColor(4, image.height() / 2);
        const auto differ = [](const QColor& a, const QColor& b) {
            return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue()) > 24;
        };
        QVERIFY2(differ(g, background), qPrintable(g.name() + " is the background " + background.name()));
        QVERIFY2(differ(g, s), qPrintable(g.name() + " is the solid ball's " + s.name()));
        QVERIFY2(g.saturationF() < s.saturationF(), qPrintable(g.name() + " is not paler than " + s.name()));
    }

    void theImageIsNotBlank()
    {
        MainWindow& w = open(SceneId::ManyBalls);
        ab::ui::BallView* view = w.view();
        QVERIFY(view);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        waitForFrame(view);
        const QImage image = view->grabFramebuffer();
        std::set<QRgb> colours;
        for (int y = 0; y < image.height(); y += 4)
            for (int x = 0; x < image.width(); x += 4)
                colours.insert(image.pixel(x, y));
        QVERIFY2(colours.size() > 100, qPrintable(QString::number(colours.size())));
    }

    void theFrameRateIsShownWhilePlayingAndADashWhilePaused()
    {
        // Paused, the view draws only when moved: "0.5 fps" and "2 fps" by turns said nothing.
        MainWindow& w = open(SceneId::ManyBalls);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const auto* fps = w.findChild<QLabel*>("statusFps");
        QVERIFY(fps);
        w.controller().play();
        QTRY_VERIFY_WITH_TIMEOUT(fps->text().contains(QRegularExpression("^[0-9.<]")), 10000);
        w.controller().pause();
        QTRY_COMPARE(fps->text(), QString::fromUtf8("\u2013 fps"));
        QTest::qWait(1500); // a second and more of the clock: still the dash
        QCOMPARE(fps->text(), QString::fromUtf8("\u2013 fps"));
    }

    void theReportsBounceLimitEndsThePathWhereItStoppedTheBall()
    {
        // The report's stage 2 stops the ball after its contacts by setting its position to
        // the origin (Appendix B): the path ends where the ball was, at t = 35.32 s, not in a
        // straight line across the floor to the corner.
        MainWindow& w = open(SceneId::Box3d);
        ab::ui::BallView* view = w.view();
        QVERIFY(view);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.controller().setSpeed(10.0);
        w.controller().play();
        QTRY_VERIFY_WITH_TIMEOUT(w.controller().status().finished, 30000);
        w.controller().poll();
        const std::optional<double> halt = w.controller().status().haltedAt;
        QVERIFY(halt && *halt > 30.0 && *halt < 40.0);
        QTRY_VERIFY(!view->trace().empty());
        const std::vector<ab::State> fresh = testing::record(w.controller().spec(), 6000);
        const auto last = std::find_if(fresh.begin(), fresh.end(), [&](const ab::State& s) { return s.t >= *halt; });
        QVERIFY(last != fresh.begin() && last != fresh.end());
        QCOMPARE(last->p.col(0).norm(), 0.0); // the halted state: at the origin
        const ab::State& before = *(last - 1);
        const QVector3D end = view->trace().back();
        QVERIFY2((end - QVector3D(float(before.p(0, 0)), float(before.p(1, 0)), float(before.p(2, 0)))).length() <
                     1e-3f,
                 qPrintable(QString("%1 %2 %3").arg(end.x()).arg(end.y()).arg(end.z())));
    }

    void aClickSelectsTheBallUnderIt()
    {
        MainWindow& w = open(SceneId::TwoBalls);
        ab::ui::BallView* view = w.view();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        waitForFrame(view);
        QCOMPARE(w.controller().selectedBall(), 0);
        const QPoint pixel = projectWithCamera(*view, ballCentre(w, 1)).toPoint();
        QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, pixel);
        QTRY_COMPARE(w.controller().selectedBall(), 1);
        QCOMPARE(view->selected(), 1);
    }

    void arrowKeysMoveTheCameraAsTheReportAndNotTheRun()
    {
        MainWindow& w = open(SceneId::ManyBalls);
        ab::ui::BallView* view = w.view();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        waitForFrame(view);
        // Focus the view as a click does.
        view->container()->setFocus();
        view->requestActivate();
        QTRY_VERIFY(view->hasKeyFocus());
        const QVector3D before = view->camera().eye();
        QTest::keyClick(view, Qt::Key_Left); // Appendix D: camera.position.x -= 2 (box 100)
        const QVector3D after = view->camera().eye();
        QVERIFY(std::abs(after.x() - (before.x() - 2.0f)) < 1e-3f);
        QVERIFY(std::abs(after.z() - before.z()) < 1e-3f);
        QCOMPARE(w.controller().status().steps, 0LL); // Right/Left do not reach the transport
        QTest::keyClick(view, Qt::Key_Up);            // camera.position.z -= 2
        QVERIFY(std::abs(view->camera().eye().z() - (before.z() - 2.0f)) < 1e-3f);
    }

    void theStreetsCameraShotsAreOfferedOnTheStreetOnly()
    {
        // View > Street: ... did nothing in stages 1-4 but read as live; greyed out there now.
        MainWindow& w = open(SceneId::TwoBalls);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QList<QAction*> shots;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text().startsWith("Street: "))
                shots << a;
        QCOMPARE(shots.size(), 3);
        for (const QAction* a : shots)
            QVERIFY2(!a->isEnabled(), qPrintable(a->text()));
        w.showScene(SceneId::Street);
        for (const QAction* a : shots)
            QVERIFY2(a->isEnabled(), qPrintable(a->text()));
        shots[1]->trigger(); // from the side
        QVERIFY(w.view()->streetShot() == ab::ui::StreetShot::Side);
        w.showScene(SceneId::Bounce1d);
        for (const QAction* a : shots)
            QVERIFY2(!a->isEnabled(), qPrintable(a->text()));
    }

    void onTheStreetTheWheelStopsTheEyeOverTheRoad()
    {
        // The foot shot's target lies inside the hill: forty notches straight at it took the
        // eye under the road. Now the wheel zooms towards the road under the pointer and stops
        // the eye half a metre over it.
        MainWindow& w = open(SceneId::Street);
        ab::ui::BallView* view = w.view();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        waitForFrame(view);
        QVERIFY(view->streetShot() == ab::ui::StreetShot::Foot);
        const std::shared_ptr<const ab::street::Layout> street = ab::ui::layoutFor(w.controller().spec()).street;
        QVERIFY(street);
        const auto overRoad = [&] {
            const QVector3D eye = view->camera().eye();
            return eye.y() - float(street->roadY(double(eye.x())));
        };
        const QPointF centre(0.5 * view->width(), 0.5 * view->height());
        const float before = view->camera().distance();
        for (int notch = 0; notch < 40; ++notch) {
            QWheelEvent wheel(centre, view->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QCoreApplication::sendEvent(view, &wheel);
            QVERIFY2(overRoad() >= ab::ui::kStreetEyeClearance - 1e-3f,
                     qPrintable(QStringLiteral("notch %1: %2 m").arg(notch + 1).arg(overRoad())));
        }
        QVERIFY(view->camera().distance() < 0.2f * before);
        QVERIFY(!view->streetShot()); // moved by hand: the shot's button is let go
    }

    void aViewMadeSmallerFramesTheWholeBoxAgain()
    {
        // A view made smaller draws itself again with the whole box framed for its new shape.
        // (X exposes a window made larger, not one made smaller: the view asks for the frame
        // itself. A resize from inside Qt, as here, gets a frame either way; one from the
        // window manager, which left a cut picture, is not reproduced by this test.)
        MainWindow& w = open(SceneId::ManyBalls);
        ab::ui::BallView* view = w.view();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        waitForFrame(view);
        QTest::qWait(200); // nothing else asks for a frame from here on
        QSignalSpy painted(view, &ab::ui::BallView::framePainted);
        w.resize(900, 600);
        QTRY_VERIFY(view->width() < 600);
        QTRY_VERIFY_WITH_TIMEOUT(painted.count() >= 1, 5000);
        const Eigen::AlignedBox3d box = ab::ui::layoutFor(ab::RunSpec(SceneId::ManyBalls)).region;
        for (int k = 0; k < 8; ++k) {
            const Eigen::Vector3d c = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k));
            const QPointF at = projectWithCamera(*view, QVector3D(float(c.x()), float(c.y()), float(c.z())));
            QVERIFY2(at.x() >= 0 && at.y() >= 0 && at.x() <= view->width() && at.y() <= view->height(),
                     qPrintable(QStringLiteral("corner %1 at (%2, %3) in %4x%5")
                                    .arg(k)
                                    .arg(at.x())
                                    .arg(at.y())
                                    .arg(view->width())
                                    .arg(view->height())));
        }
    }

    void inLectureModeTheViewsArrowKeysMoveTheCameraNotTheWalk()
    {
        // Lecture mode's Left and Right walk the equations, but once a click gave the view
        // the keys they move the camera, as the view's hint says; Esc gives them back.
        MainWindow& w = open(SceneId::ManyBalls);
        ab::ui::LectureMode lecture;
        lecture.attach(&w, w.navigator());
        lecture.setActive(true);
        ab::ui::StageNavigator& nav = *w.navigator();
        ab::ui::BallView* view = w.view();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        waitForFrame(view);
        QApplication::setActiveWindow(&w);
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keyClick(&w, Qt::Key_Right); // the walk's first equation
        QCOMPARE(nav.revealed(), 1);
        view->container()->setFocus();
        view->requestActivate();
        QTRY_VERIFY(view->hasKeyFocus());
        const QVector3D before = view->camera().eye();
        for (int k = 0; k < 3; ++k)
            QTest::keyClick(view, Qt::Key_Left); // Appendix D: x -= 2 each
        QVERIFY(std::abs(view->camera().eye().x() - (before.x() - 6.0f)) < 1e-3f);
        QTest::keyClick(view, Qt::Key_Right);
        QVERIFY(std::abs(view->camera().eye().x() - (before.x() - 4.0f)) < 1e-3f);
        QCOMPARE(nav.current(), SceneId::ManyBalls); // the walk and the stage stay
        QCOMPARE(nav.revealed(), 1);
        QCOMPARE(w.controller().status().steps, 0LL);
        QTest::keyClick(view, Qt::Key_Escape); // the keys go back to the window
        QTRY_VERIFY(!view->hasKeyFocus());
        QTest::keyClick(&w, Qt::Key_Right);
        QCOMPARE(nav.revealed(), 2);
        QVERIFY(std::abs(view->camera().eye().x() - (before.x() - 4.0f)) < 1e-3f);
        lecture.setActive(false);
    }
};

QTEST_MAIN(UiRender)
#include "test_ui_render.moc"
