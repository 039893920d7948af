// SPDX-License-Identifier: MIT
// The 3D view: the balls as lit spheres in their colours, the floor with contact
// shadows, the box or the height scale, and the selected ball's trace (the report's
// Figure 2.6). Left drag orbits, right or middle drag (or Shift+left) pans, the wheel
// zooms, a click selects a ball; with keyboard focus the arrow keys move the camera as
// in the report and Escape hands the keys back to the window.
// A QOpenGLWindow shown through QWidget::createWindowContainer, not a QOpenGLWidget:
// with a QOpenGLWidget in it, Qt recomposes the whole window in OpenGL for every frame,
// which under software OpenGL (llvmpipe, 1400x900 window) cost about 19 ms a frame
// against 6 ms for a window of its own (measured on a 2-core machine).
// Never created on the offscreen or minimal platforms (no GL context there).
#pragma once

#include "orbit_camera.h"
#include "scene_geometry.h"
#include "scene_renderer.h"
#include "street_camera.h"
#include "view_frame.h" // ballColours

#include <QElapsedTimer>
#include <QOpenGLWindow>
#include <QPainter>
#include <QWidget>

#include <functional>
#include <optional>
#include <vector>

namespace ab::ui {

class BallView : public QOpenGLWindow {
    Q_OBJECT
public:
    BallView();
    ~BallView() override;

    // False on platforms without OpenGL windows (offscreen, minimal).
    static bool available();
    // The widget that shows this window inside the main window (owns the view).
    QWidget* container() const { return container_; }
    bool hasKeyFocus() const { return keyFocus_; }

    // A new scene or run: geometry, ball radius and colours. The camera is framed anew
    // when the region changes (or `reframe`), so the view adapts to each scene's size.
    void setScene(const SceneLayout& layout, const QString& lengthUnit, std::vector<unsigned> colours, bool reframe);
    // Ball centres, x y z per ball, and where the balls turn their orientations (Frame::q,
    // kOrientationFloats per ball), which turn each ball's pattern; empty: plain balls. A
    // frame holding a non-finite number is not drawn.
    void setBalls(const std::vector<float>& xyz, const std::vector<float>& orientations = {});
    // A comparison run's ball centres, drawn ghosted, and the legend that says which run
    // is which ("solid: report, ghost: physical rk4"); empty `xyz` and `legend`: none.
    // In the vertical-only scene both runs move on one line, so the ghosts are drawn
    // beside it (ghostOffset() along x), never over the solid balls.
    void setGhosts(const std::vector<float>& xyz, const QString& legend);
    float ghostOffset() const;
    QString ghostLegend() const { return ghostLegend_; }
    void setSelected(int ball);
    void setTrace(std::vector<QVector3D> points);
    const std::vector<QVector3D>& trace() const { return trace_; }
    // The balls' colours (0xRRGGBB, one per ball) and the clear colour, for the window's theme.
    void setColours(std::vector<unsigned> colours);
    void setBackground(const QColor& colour);
    // Lecture mode: the labels, the height scale's numbers and the smallest drawn ball
    // grow by `scale` (1 on the desktop).
    void setPresentationScale(double scale);
    double presentationScale() const { return scale_; }
    // The smallest radius a ball is drawn with, in pixels: a few balls stay large enough
    // to follow from the back of a hall (a 0.5 m ball in the 300 m box is otherwise a dot).
    float minimumBallPixels() const;
    void resetView();
    // Turns the camera about the vertical through the target (the window's turntable).
    void turn(float yawDegrees);
    // Places the camera (a preset's view); it then stays until the user moves it.
    void setCameraPose(const QVector3D& target, float yawDeg, float pitchDeg, float distance,
                       float fovYDeg = OrbitCamera::kDefaultFovY);

    // The street's camera shots (stage 5): placed at once, the flood shot then follows the
    // front of the flood with every frame; moving the camera by hand leaves the shot
    // (streetShotChanged). Outside the street it does nothing.
    void setStreetShot(std::optional<StreetShot> shot);
    std::optional<StreetShot> streetShot() const { return shot_; }

    const OrbitCamera& camera() const { return camera_; }
    int selected() const { return selected_; }
    // Window pixel of ball `ball` of the current frame; false when it is not in view.
    bool ballPixel(int ball, QPointF& pixel) const;
    // Window pixel of the centre of ghost `ball` (offset included); false when none or out of view.
    bool ghostPixel(int ball, QPointF& pixel) const;
    QString glError() const { return glError_; }

signals:
    void ballPicked(int ball);
    // Wall time of the last paint, and the time since the one before it, in milliseconds.
    void framePainted(double paintMs, double intervalMs);
    // Escape: the window should take the keys back.
    void keysReleased();
    // The street's shot changed: set, framed anew, or left by moving the camera by hand.
    void streetShotChanged();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    bool event(QEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void focusInEvent(QFocusEvent* e) override;
    void focusOutEvent(QFocusEvent* e) override;
    void exposeEvent(QExposeEvent* e) override;

private:
    void releaseGl();
    void frameScene();
    RenderInputs renderInputs() const;
    void uploadPending();
    void paintOverlay(QPainter& p);
    int pick(const QPointF& pixel) const;
    float drawnRadius(const QVector3D& centre) const;
    QVector3D ballAt(int i) const;
    // Whether ball i is not drawn (it left the street at its open foot).
    bool hidden(int i) const;
    // The camera moved by hand: it keeps its place, and leaves the street's shot.
    void userMovedCamera();
    // A camera move by hand, move(camera, t) scaled by t in [0, 1]: on the street the eye
    // stops short of the road, the kerbs, the houses and the cars (moveWhileClear).
    void moveCameraByHand(const std::function<void(OrbitCamera&, float)>& move);
    // Zooms by `steps` towards what the window pixel `at` shows on the street (the target
    // elsewhere, and where the pixel shows the sky).
    void zoomTowards(const QPointF& at, float steps);
    void placeStreetShot();

    OrbitCamera camera_;
    SceneRenderer renderer_;
    SceneLayout layout_;
    SceneGeometry geometry_;
    std::optional<StreetSolids> solids_; // on the street: where the camera may not go
    std::vector<unsigned> colours_;
    QColor background_{0xec, 0xf0, 0xf5};
    std::vector<float> balls_;
    std::vector<float> orientations_;
    std::vector<QVector3D> trace_;
    std::vector<float> ghosts_; // as drawn: offset already applied
    QString ghostLegend_;
    int selected_ = 0;
    bool geometryDirty_ = false, coloursDirty_ = false, ballsDirty_ = false, traceDirty_ = false, ghostsDirty_ = false;
    QString glError_;
    QPoint pressPos_, lastPos_;
    Qt::MouseButton dragButton_ = Qt::NoButton;
    QElapsedTimer sincePaint_;
    QWidget* container_ = nullptr;
    bool keyFocus_ = false;
    bool framePending_ = true;
    bool cameraMoved_ = false;
    double scale_ = 1.0;
    std::optional<StreetShot> shot_;
};

} // namespace ab::ui
