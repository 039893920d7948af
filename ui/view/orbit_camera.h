// SPDX-License-Identifier: MIT
// The 3D view's camera: it orbits a target point (yaw about the vertical, pitch above
// the floor), zooms by distance and pans the target. The arrow keys move the eye sideways
// in world x and z as the report's WebGL program does (Appendix D), still looking at the
// target. Also projects points to pixels and pixels to rays, for labels and picking.
#pragma once

#include <QMatrix4x4>
#include <QPointF>
#include <QSize>
#include <QVector3D>

#include <cmath>
#include <vector>

namespace ab::ui {

// Where a camera stands: the point it looks at, its turn about the vertical and above the
// floor (degrees), and its distance from the target (OrbitCamera::setPose takes these).
struct CameraPose {
    QVector3D target;
    float yaw = 0.0f, pitch = 0.0f, distance = 1.0f;
    float fovY = 40.0f; // the vertical field of view, degrees (a long lens: less)
};

class OrbitCamera {
public:
    static constexpr float kDefaultFovY = 40.0f;

    // Looks at the centre of the box [lo, hi] from `yawDeg`, `pitchDeg`, far enough to see
    // all of it in a view of aspect `aspect` (width / height).
    void frame(const QVector3D& lo, const QVector3D& hi, float yawDeg, float pitchDeg, float aspect);
    // Looks from `yawDeg`, `pitchDeg` at `points`, the target placed and the distance chosen so
    // that they fill a view of aspect `aspect` with `margin` of its half-width and half-height
    // to spare: a long diagonal (the street from the side) is not framed by its bounding box,
    // whose empty corners left most of the picture bare.
    void fit(const std::vector<QVector3D>& points, float yawDeg, float pitchDeg, float aspect, float margin = 0.05f);

    void orbit(float dxPixels, float dyPixels);
    void turn(float yawDegrees) { yaw_ = std::fmod(yaw_ + yawDegrees, 360.0f); }
    void pan(float dxPixels, float dyPixels, QSize viewport);
    void zoom(float wheelSteps);
    // Zooms as zoom() does, but towards `point` (the one under the pointer): the eye and the
    // target both move towards it by the zoom's factor, so it stays where it is in the picture.
    void zoomTowards(const QVector3D& point, float wheelSteps);
    // Moves the eye by `delta` in world coordinates and keeps looking at the target.
    void moveEye(const QVector3D& delta);
    // Puts the camera at a saved pose (a preset's); pitch is kept within +-89 degrees as
    // orbit() keeps it, distance within the zoom's limits for a scene of size `sceneSize`.
    // `fovYDeg` is the vertical field of view (framing always uses the default 40 degrees).
    void setPose(const QVector3D& target, float yawDeg, float pitchDeg, float distance, float sceneSize,
                 float fovYDeg = kDefaultFovY);
    void setPose(const CameraPose& pose, float sceneSize)
    {
        setPose(pose.target, pose.yaw, pose.pitch, pose.distance, sceneSize, pose.fovY);
    }

    QVector3D eye() const;
    QVector3D target() const { return target_; }
    float distance() const { return distance_; }
    float yaw() const { return yaw_; }
    float pitch() const { return pitch_; }
    float fovY() const { return fovY_; }
    float sceneSize() const { return size_; }

    QMatrix4x4 view() const;
    QMatrix4x4 projection(float aspect) const;
    // Pixels per world unit at unit distance in a viewport `height` pixels tall.
    float pixelsPerUnit(int height) const;

    // Window pixel (origin top-left) of world point `p`; false when behind the eye.
    bool project(const QVector3D& p, QSize viewport, QPointF& pixel) const;
    // The ray from the eye through window pixel `pixel`: origin and unit direction.
    void ray(const QPointF& pixel, QSize viewport, QVector3D& origin, QVector3D& direction) const;

private:
    void setEye(const QVector3D& eye);

    QVector3D target_{0, 0, 0};
    float yaw_ = 60.0f;   // degrees, about +y, 0 looks along -z
    float pitch_ = 20.0f; // degrees above the horizontal
    float distance_ = 10.0f;
    float fovY_ = kDefaultFovY;
    float size_ = 1.0f; // the framed box's diagonal, for near/far and step sizes
};

// Applies `move(camera, t)`, a camera move scaled by t in [0, 1], as far as the eye stays
// where `clear(eye)` allows (the street: out of the road, the kerbs, the houses and the cars).
// The move is walked in 16 parts, since one wheel notch can carry the eye through a house
// front 3 m deep, and the first part that leaves the clear is bisected to 1/16384 of the
// move. An eye that already stands where it may not moves freely: the way out is not barred.
template <class Move, class Clear> void moveWhileClear(OrbitCamera& camera, Move move, Clear clear)
{
    const OrbitCamera start = camera;
    const auto movedBy = [&](float t) {
        OrbitCamera c = start;
        move(c, t);
        return c;
    };
    if (!clear(start.eye())) {
        camera = movedBy(1.0f);
        return;
    }
    constexpr int kParts = 16;
    float lo = 0.0f, hi = 0.0f;
    for (int k = 1; k <= kParts && hi == 0.0f; ++k) {
        const float t = float(k) / float(kParts);
        (clear(movedBy(t).eye()) ? lo : hi) = t;
    }
    if (hi == 0.0f) {
        camera = movedBy(1.0f);
        return;
    }
    for (int i = 0; i < 10; ++i) {
        const float mid = 0.5f * (lo + hi);
        (clear(movedBy(mid).eye()) ? lo : hi) = mid;
    }
    camera = movedBy(lo);
}

} // namespace ab::ui
