// SPDX-License-Identifier: MIT
#include "orbit_camera.h"

#include <QtMath>

#include <algorithm>
#include <cmath>

namespace ab::ui {

void OrbitCamera::frame(const QVector3D& lo, const QVector3D& hi, float yawDeg, float pitchDeg, float aspect)
{
    target_ = (lo + hi) / 2.0f;
    fovY_ = kDefaultFovY;
    size_ = std::max((hi - lo).length(), 1e-6f);
    yaw_ = yawDeg;
    pitch_ = pitchDeg;
    // Each corner, at (x, y) across and z towards the eye from the target, fits when
    // |x| <= (d - z) tan(half width angle) and |y| <= (d - z) tan(half height angle).
    const float tanV = std::tan(qDegreesToRadians(fovY_) / 2.0f);
    const float tanH = tanV * std::max(aspect, 0.1f);
    distance_ = 1.0f;
    const QMatrix4x4 v = view(); // the orientation; the target sits at depth 1
    float needed = size_ * 1e-3f;
    for (int i = 0; i < 8; ++i) {
        const QVector3D corner(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
        const QVector3D c = v.map(corner);
        const float towardEye = c.z() + 1.0f;
        needed = std::max({needed, towardEye + std::abs(c.x()) / tanH, towardEye + std::abs(c.y()) / tanV});
    }
    distance_ = 1.08f * needed; // a margin for the labels beside the box
}

void OrbitCamera::fit(const std::vector<QVector3D>& points, float yawDeg, float pitchDeg, float aspect, float margin)
{
    if (points.empty())
        return;
    QVector3D lo = points.front(), hi = lo;
    for (const QVector3D& p : points) {
        lo = QVector3D(std::min(lo.x(), p.x()), std::min(lo.y(), p.y()), std::min(lo.z(), p.z()));
        hi = QVector3D(std::max(hi.x(), p.x()), std::max(hi.y(), p.y()), std::max(hi.z(), p.z()));
    }
    frame(lo, hi, yawDeg, pitchDeg, aspect); // a start that sees them all
    const float tanV = std::tan(qDegreesToRadians(fovY_) / 2.0f), tanH = tanV * std::max(aspect, 0.1f);
    // A point at depth d (from the eye) and (x, y) across stands at (x / (d tanH), y / (d tanV))
    // of the view's half-width and half-height. Each round moves the target to the middle of
    // the points' extents (at the target's depth, a shift s moves them by s / (D tan)) and
    // scales the distance D by their largest half-extent over 1 - margin; a few rounds settle it.
    for (int round = 0; round < 12; ++round) {
        const QMatrix4x4 v = view();
        float xLo = 1e9f, xHi = -1e9f, yLo = 1e9f, yHi = -1e9f;
        for (const QVector3D& p : points) {
            const QVector3D c = v.map(p);
            const float depth = std::max(-c.z(), 1e-3f * distance_);
            xLo = std::min(xLo, c.x() / (depth * tanH));
            xHi = std::max(xHi, c.x() / (depth * tanH));
            yLo = std::min(yLo, c.y() / (depth * tanV));
            yHi = std::max(yHi, c.y() / (depth * tanV));
        }
        const QVector3D right(v(0, 0), v(0, 1), v(0, 2)), up(v(1, 0), v(1, 1), v(1, 2));
        target_ += distance_ * (0.5f * (xLo + xHi) * tanH * right + 0.5f * (yLo + yHi) * tanV * up);
        const float half = std::max(0.5f * (xHi - xLo), 0.5f * (yHi - yLo));
        distance_ *= std::clamp(half / (1.0f - margin), 0.5f, 2.0f);
    }
}

void OrbitCamera::orbit(float dxPixels, float dyPixels)
{
    yaw_ = std::fmod(yaw_ - 0.4f * dxPixels, 360.0f);
    pitch_ = std::clamp(pitch_ + 0.4f * dyPixels, -89.0f, 89.0f);
}

void OrbitCamera::pan(float dxPixels, float dyPixels, QSize viewport)
{
    // One pixel moves the target by the size of a pixel at the target's distance.
    const float perPixel = distance_ / pixelsPerUnit(std::max(viewport.height(), 1));
    const QMatrix4x4 v = view();
    const QVector3D right(v(0, 0), v(0, 1), v(0, 2));
    const QVector3D up(v(1, 0), v(1, 1), v(1, 2));
    target_ += (-dxPixels * right + dyPixels * up) * perPixel;
}

void OrbitCamera::zoom(float wheelSteps)
{
    distance_ = std::clamp(distance_ * std::pow(0.85f, wheelSteps), size_ * 1e-3f, size_ * 50.0f);
}

void OrbitCamera::zoomTowards(const QVector3D& point, float wheelSteps)
{
    // A scaling about `point` by f = d'/d: the eye e -> p + f (e - p), the target
    // t -> p + f (t - p), so e - t scales by f and the view's direction is kept.
    const float before = distance_;
    zoom(wheelSteps);
    target_ = point + (distance_ / before) * (target_ - point);
}

void OrbitCamera::setPose(const QVector3D& target, float yawDeg, float pitchDeg, float distance, float sceneSize,
                          float fovYDeg)
{
    fovY_ = std::clamp(fovYDeg, 5.0f, 90.0f);
    size_ = std::max(sceneSize, 1e-6f);
    target_ = target;
    yaw_ = std::fmod(yawDeg, 360.0f);
    pitch_ = std::clamp(pitchDeg, -89.0f, 89.0f);
    distance_ = std::clamp(distance, size_ * 1e-3f, size_ * 50.0f);
}

void OrbitCamera::moveEye(const QVector3D& delta)
{
    setEye(eye() + delta);
}

void OrbitCamera::setEye(const QVector3D& e)
{
    const QVector3D d = e - target_;
    const float len = d.length();
    if (len < size_ * 1e-3f)
        return; // the eye cannot sit on the target
    distance_ = len;
    pitch_ = std::clamp(qRadiansToDegrees(std::asin(std::clamp(d.y() / len, -1.0f, 1.0f))), -89.0f, 89.0f);
    yaw_ = qRadiansToDegrees(std::atan2(d.x(), d.z()));
}

QVector3D OrbitCamera::eye() const
{
    const float yaw = qDegreesToRadians(yaw_);
    const float pitch = qDegreesToRadians(pitch_);
    const QVector3D dir(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    return target_ + distance_ * dir;
}

QMatrix4x4 OrbitCamera::view() const
{
    QMatrix4x4 m;
    m.lookAt(eye(), target_, QVector3D(0, 1, 0));
    return m;
}

QMatrix4x4 OrbitCamera::projection(float aspect) const
{
    // Near and far hug the scene so depth stays precise; the near plane never passes
    // behind the eye when it is inside the box.
    const float nearPlane = std::max(size_ * 1e-3f, (distance_ - size_) * 0.5f);
    const float farPlane = distance_ + 2.0f * size_;
    QMatrix4x4 m;
    m.perspective(fovY_, std::max(aspect, 1e-3f), nearPlane, farPlane);
    return m;
}

float OrbitCamera::pixelsPerUnit(int height) const
{
    return static_cast<float>(height) / (2.0f * std::tan(qDegreesToRadians(fovY_) / 2.0f));
}

bool OrbitCamera::project(const QVector3D& p, QSize viewport, QPointF& pixel) const
{
    const float aspect = float(viewport.width()) / float(std::max(viewport.height(), 1));
    const QVector4D clip = projection(aspect) * view() * QVector4D(p, 1.0f);
    if (clip.w() <= 0.0f)
        return false;
    const float x = clip.x() / clip.w();
    const float y = clip.y() / clip.w();
    pixel = QPointF((x + 1.0) * 0.5 * viewport.width(), (1.0 - y) * 0.5 * viewport.height());
    return true;
}

void OrbitCamera::ray(const QPointF& pixel, QSize viewport, QVector3D& origin, QVector3D& direction) const
{
    const float aspect = float(viewport.width()) / float(std::max(viewport.height(), 1));
    const QMatrix4x4 inverse = (projection(aspect) * view()).inverted();
    const float x = float(2.0 * pixel.x() / viewport.width() - 1.0);
    const float y = float(1.0 - 2.0 * pixel.y() / viewport.height());
    const QVector3D nearPoint = inverse.map(QVector3D(x, y, -1.0f));
    const QVector3D farPoint = inverse.map(QVector3D(x, y, 1.0f));
    origin = eye();
    direction = (farPoint - nearPoint).normalized();
}

} // namespace ab::ui
