// SPDX-License-Identifier: MIT
#include "street_camera.h"

#include "street_geometry.h"

#include "core/street/street_census.h"

#include <QtMath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ab::ui {

namespace {

// The pose that looks from `eye` at `target`: OrbitCamera's eye is target + d (cos p sin y,
// sin p, cos p cos y), so d = |eye - target|, p = asin(dy / d), y = atan2(dx, dz).
CameraPose lookFrom(const QVector3D& eye, const QVector3D& target)
{
    const QVector3D d = eye - target;
    const float len = std::max(d.length(), 1e-3f);
    return {target, qRadiansToDegrees(std::atan2(d.x(), d.z())),
            qRadiansToDegrees(std::asin(std::clamp(d.y() / len, -1.0f, 1.0f))), len};
}

} // namespace

StreetSolids::StreetSolids(std::shared_ptr<const street::Layout> street)
    : street_(std::move(street)), boxes_(streetSolids(*street_))
{
}

bool StreetSolids::clear(const QVector3D& eye) const
{
    const Eigen::Vector3d p(eye.x(), eye.y(), eye.z());
    if (p.y() < street_->roadY(p.x()) + kStreetEyeClearance)
        return false;
    // Box::outside is the vector from the box's nearest point: its norm, the distance.
    return std::none_of(boxes_.begin(), boxes_.end(), [&](const street::Box& b) {
        return b.outside(b.toLocal(p)).squaredNorm() < double(kStreetEyeClearance * kStreetEyeClearance);
    });
}

std::optional<QVector3D> StreetSolids::hit(const QVector3D& origin, const QVector3D& direction) const
{
    const Eigen::Vector3d o(origin.x(), origin.y(), origin.z()), d(direction.x(), direction.y(), direction.z());
    double nearest = std::numeric_limits<double>::infinity();
    for (const street::Box& b : boxes_) {
        // The slab test in the box's frame: o + t d is inside on axis i for t between
        // (-h_i - o_i) / d_i and (h_i - o_i) / d_i; inside the box for t in [tIn, tOut].
        const Eigen::Vector3d lo = b.toLocal(o), ld = b.rotateIn(d);
        double tIn = 0.0, tOut = nearest;
        for (int i = 0; i < 3 && tIn <= tOut; ++i) {
            if (std::abs(ld[i]) < 1e-12) {
                if (std::abs(lo[i]) > b.half[i])
                    tOut = -1.0; // parallel to this slab and outside it
                continue;
            }
            const double t1 = (-b.half[i] - lo[i]) / ld[i], t2 = (b.half[i] - lo[i]) / ld[i];
            tIn = std::max(tIn, std::min(t1, t2));
            tOut = std::min(tOut, std::max(t1, t2));
        }
        if (tIn <= tOut && tIn > 0.0)
            nearest = tIn;
    }
    // The flat street past the foot, y = 0: o_y + t d_y = 0.
    if (d.y() < 0.0) {
        const double t = -o.y() / d.y();
        const Eigen::Vector3d p = o + t * d;
        if (t > 0.0 && t < nearest && p.x() >= street_->xFoot &&
            std::abs(p.z()) <= 0.5 * street_->width + street_->sidewalk)
            nearest = t;
    }
    if (!std::isfinite(nearest))
        return std::nullopt;
    return origin + float(nearest) * direction;
}

bool StreetSolids::hides(const QVector3D& eye, const QVector3D& point) const
{
    const float reach = (point - eye).length();
    if (reach <= 0.5f)
        return false;
    const auto first = hit(eye, (point - eye) / reach);
    return first && (*first - eye).length() < reach - 0.5f;
}

bool ballHidden(const street::Layout& street, float x)
{
    return street::hasLeft(street, double(x));
}

CameraPose streetPose(const street::Layout& s, StreetShot shot, float aspect, std::optional<float> front)
{
    // The near house fronts (cut away in the side shot) and the far houses' backs.
    const auto near = float(0.5 * s.width + s.sidewalk), far = near + 3.0f;
    switch (shot) {
    case StreetShot::Foot: {
        // The advert's shot: a long lens low on the flat street 45 m past the foot, looking
        // up the hill. Seen from there the road's top (xTop, height) and its foot (xFoot, 0)
        // are at elevations atan2(height - h, X - xTop) and atan2(-h, X - xFoot); the camera
        // aims half-way between them, and its field of view holds both with a quarter to
        // spare. A long lens flattens the depth: the whole hill stands up in the picture.
        const QVector3D eye(float(s.xFoot) + 45.0f, 1.5f, 0.0f);
        const float top = std::atan2(float(s.houseTop) - eye.y(), eye.x() - float(s.xTop));
        const float foot = std::atan2(-eye.y(), eye.x() - float(s.xFoot));
        const float aim = 0.5f * (top + foot), reach = 0.5f * float(s.xFoot - s.xTop);
        const QVector3D target = eye + reach * QVector3D(-std::cos(aim), std::sin(aim), 0.0f);
        CameraPose pose = lookFrom(eye, target);
        pose.fovY = std::clamp(1.25f * qRadiansToDegrees(top - foot), 10.0f, 40.0f);
        return pose;
    }
    case StreetShot::Side: {
        // From the +z side, 24 deg above and turned 25 deg downhill: the road shows its width,
        // and the flood on it, over the near houses (cut away); level with the street it was
        // a line. Framed on the street itself: the road's edges at the top, at each block's
        // ends and 20 m past the foot, the far houses' roofs over them, the back wall across
        // the top and the top's label.
        std::vector<QVector3D> points;
        auto across = [&](double x, double above) {
            for (float z : {-far, near})
                points.emplace_back(float(x), float(s.roadY(x) + above), z);
        };
        for (double x : {s.xTop, s.xFoot, s.xFoot + 20.0})
            across(x, 0.0);
        for (const street::Box& b : s.boxes) // the back wall across the top, up to the houses' height
            if (b.kind == street::ItemKind::BackWall)
                for (float z : {-1.0f, 1.0f})
                    for (float y : {-1.0f, 1.0f})
                        points.emplace_back(float(b.centre.x() - b.half.x()), float(b.centre.y() + y * b.half.y()),
                                            z * float(b.half.z()));
        for (std::size_t k = 0; k < s.blockStartX.size(); ++k) {
            across(s.blockStartX[k], 12.0);
            across(s.blockFootX[k], 0.0);
        }
        points.emplace_back(float(s.xTop), float(s.height + kTopLabelHeight + 2.0), 0.0f); // the top's label
        // A narrower view turns further downhill (up to 55 deg at aspect 0.85 and under), so that
        // the street runs across its height too instead of leaving it bare above and below.
        const float yaw = std::clamp(25.0f + 40.0f * (1.6f - aspect), 25.0f, 55.0f);
        OrbitCamera c;
        c.fit(points, yaw, 24.0f, aspect);
        return {c.target(), c.yaw(), c.pitch(), c.distance()};
    }
    case StreetShot::Flood: {
        // Ahead of the front and above it, over the near sidewalk, looking back up at it.
        const float x = front ? std::clamp(*front, float(s.xTop), float(s.xFoot)) : float(s.hopper.x1);
        const float ahead = std::min(x + 30.0f, float(s.xFoot) + 20.0f);
        const QVector3D target(x - 8.0f, float(s.roadY(x - 8.0)) + 1.0f, 0.0f);
        return lookFrom({ahead, float(s.roadY(ahead)) + 14.0f, 0.45f * float(s.width)}, target);
    }
    }
    return {};
}

std::optional<float> floodFront(const street::Layout& s, const std::vector<float>& xyz)
{
    std::vector<float> xs;
    xs.reserve(xyz.size() / 3);
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
        if (std::isfinite(xyz[i]) && !ballHidden(s, xyz[i]))
            xs.push_back(xyz[i]);
    if (xs.empty())
        return std::nullopt;
    // The element with xs.size() / 200 balls beyond it: the 99.5th percentile.
    const std::size_t k = xs.size() - 1 - xs.size() / 200;
    std::nth_element(xs.begin(), xs.begin() + std::ptrdiff_t(k), xs.end());
    return xs[k];
}

} // namespace ab::ui
