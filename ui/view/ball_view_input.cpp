// SPDX-License-Identifier: MIT
// The 3D view's input: a click picks a ball, the keys (Appendix D's arrows, + and -), the
// mouse and the wheel move the camera by hand, and on the street the camera stops short of
// the solid parts and zooms towards what is under the pointer.
#include "ball_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <cmath>
#include <limits>

namespace ab::ui {

void BallView::userMovedCamera()
{
    cameraMoved_ = true;
    if (shot_) {
        shot_.reset();
        emit streetShotChanged();
    }
}

void BallView::moveCameraByHand(const std::function<void(OrbitCamera&, float)>& move)
{
    if (solids_)
        moveWhileClear(camera_, move, [&](const QVector3D& eye) { return solids_->clear(eye); });
    else
        move(camera_, 1.0f);
    userMovedCamera();
    update();
}

void BallView::zoomTowards(const QPointF& at, float steps)
{
    QVector3D origin, direction;
    camera_.ray(at, size(), origin, direction);
    const auto point = solids_ ? solids_->hit(origin, direction) : std::nullopt;
    if (point)
        moveCameraByHand([&](OrbitCamera& c, float t) { c.zoomTowards(*point, t * steps); });
    else
        moveCameraByHand([&](OrbitCamera& c, float t) { c.zoom(t * steps); });
}

void BallView::turn(float yawDegrees)
{
    moveCameraByHand([&](OrbitCamera& c, float t) { c.turn(t * yawDegrees); });
}

int BallView::pick(const QPointF& pixel) const
{
    QVector3D origin, dir;
    camera_.ray(pixel, size(), origin, dir);
    int best = -1;
    float bestT = std::numeric_limits<float>::infinity();
    const int n = int(balls_.size() / 3);
    for (int i = 0; i < n; ++i) {
        // Ray-sphere: the nearest t >= 0 with |origin + t dir - c| = r.
        if (hidden(i))
            continue;
        const QVector3D c = ballAt(i);
        const float r = drawnRadius(c);
        const QVector3D oc = c - origin;
        const float b = QVector3D::dotProduct(oc, dir);
        const float miss2 = oc.lengthSquared() - b * b;
        if (miss2 > r * r || b < 0.0f)
            continue;
        const float t = b - std::sqrt(r * r - miss2);
        if (t < bestT) {
            bestT = t;
            best = i;
        }
    }
    return best;
}

bool BallView::event(QEvent* e)
{
    // With focus the arrow keys move the camera (the report's keys), so they must not
    // reach the window's shortcuts (Right steps the run elsewhere).
    if (e->type() == QEvent::ShortcutOverride) {
        const int key = static_cast<QKeyEvent*>(e)->key();
        if (key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Up || key == Qt::Key_Down ||
            key == Qt::Key_Escape) {
            e->accept();
            return true;
        }
    }
    return QOpenGLWindow::event(e);
}

void BallView::keyPressEvent(QKeyEvent* e)
{
    // Appendix D: left/right move the camera by -/+2 in x, up/down by -/+2 in z (box 100).
    const float step = geometry_.arrowStep;
    QVector3D eyeMove;
    float zoomSteps = 0.0f;
    switch (e->key()) {
    case Qt::Key_Left:
        eyeMove = {-step, 0, 0};
        break;
    case Qt::Key_Right:
        eyeMove = {step, 0, 0};
        break;
    case Qt::Key_Up:
        eyeMove = {0, 0, -step};
        break;
    case Qt::Key_Down:
        eyeMove = {0, 0, step};
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoomSteps = 1.0f;
        break;
    case Qt::Key_Minus:
        zoomSteps = -1.0f;
        break;
    case Qt::Key_Escape:
        emit keysReleased();
        return;
    default:
        QOpenGLWindow::keyPressEvent(e);
        return;
    }
    if (zoomSteps != 0.0f)
        zoomTowards(QPointF(0.5 * width(), 0.5 * height()), zoomSteps);
    else
        moveCameraByHand([&](OrbitCamera& c, float t) { c.moveEye(t * eyeMove); });
}

void BallView::focusInEvent(QFocusEvent* e)
{
    QOpenGLWindow::focusInEvent(e);
    keyFocus_ = true;
    update();
}

void BallView::focusOutEvent(QFocusEvent* e)
{
    QOpenGLWindow::focusOutEvent(e);
    keyFocus_ = false;
    update();
}

void BallView::mousePressEvent(QMouseEvent* e)
{
    pressPos_ = lastPos_ = e->position().toPoint();
    dragButton_ = e->button();
    if (dragButton_ == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier))
        dragButton_ = Qt::MiddleButton;
}

void BallView::mouseMoveEvent(QMouseEvent* e)
{
    const QPoint pos = e->position().toPoint();
    const QPoint d = pos - lastPos_;
    lastPos_ = pos;
    if (dragButton_ == Qt::LeftButton)
        moveCameraByHand([&](OrbitCamera& c, float t) { c.orbit(t * float(d.x()), t * float(d.y())); });
    else if (dragButton_ == Qt::RightButton || dragButton_ == Qt::MiddleButton)
        moveCameraByHand([&](OrbitCamera& c, float t) { c.pan(t * float(d.x()), t * float(d.y()), size()); });
}

void BallView::mouseReleaseEvent(QMouseEvent* e)
{
    const bool click = (e->position().toPoint() - pressPos_).manhattanLength() < 5;
    if (click && e->button() == Qt::LeftButton) {
        const int ball = pick(e->position());
        if (ball >= 0)
            emit ballPicked(ball);
    }
    dragButton_ = Qt::NoButton;
}

void BallView::mouseDoubleClickEvent(QMouseEvent* e)
{
    if (pick(e->position()) < 0)
        resetView();
}

void BallView::wheelEvent(QWheelEvent* e)
{
    zoomTowards(e->position(), float(e->angleDelta().y()) / 120.0f);
}

} // namespace ab::ui
