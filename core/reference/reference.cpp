// SPDX-License-Identifier: MIT
#include "reference.h"

#include "bounce_reference.h"

#include "../params.h"

#include <algorithm>
#include <cmath>

namespace ab::reference {

double Reference::energy(double t) const
{
    double e = 0.0;
    for (int i = 0; i < balls(); ++i) {
        const double m = mass_[static_cast<std::size_t>(i)];
        e += 0.5 * m * velocity(i, t).squaredNorm() + m * g_ * position(i, t).y();
    }
    return e;
}

namespace {

void requireZero(const ParamValues& v, const char* key, const std::string& why)
{
    if (v.real(key) != 0.0)
        throw InputError(std::string(key) + ": " + formatNumber(v.real(key)) + " is not covered by the closed form (" +
                         why + "); set " + key + "=0");
}

class Bounce1d final : public Reference {
public:
    Bounce1d(const ParamValues& v, double horizon)
        : Reference({v.real("m")}, v.real("g")),
          bounce_(v.real("g"), v.real("k"), v.real("h0"), v.real("v0"), 0.0,
                  Drag{v.real("b") / v.real("m"), v.real("c") / v.real("m")}, horizon),
          drag_(v.real("b") > 0.0   ? "linear drag"
                : v.real("c") > 0.0 ? "quadratic drag"
                                    : "no drag")
    {
    }

    Eigen::Vector3d position(int, double t) const override { return {0.0, bounce_.height(t), 0.0}; }
    Eigen::Vector3d velocity(int, double t) const override { return {0.0, bounce_.velocity(t), 0.0}; }
    std::vector<double> impactTimes(double tEnd) const override { return bounce_.impactTimes(tEnd); }
    double lengthScale() const override { return bounce_.maxHeight() > 0.0 ? bounce_.maxHeight() : 1.0; }
    std::string description() const override
    {
        return "closed-form bounce (" + drag_ + "), Zeno time " + formatSignificant(bounce_.restTime(), 6) + " step";
    }

private:
    BounceReference bounce_;
    std::string drag_;
};

// One ball in a box, drag-free and frictionless: the height bounces on the floor, x and z
// move freely between their walls, each axis on its own.
struct BallInBox {
    BounceReference y;
    WallAxisReference x, z;

    Eigen::Vector3d position(double t) const { return {x.position(t), y.height(t), z.position(t)}; }
    Eigen::Vector3d velocity(double t) const { return {x.velocity(t), y.velocity(t), z.velocity(t)}; }
};

class Box3d final : public Reference {
public:
    Box3d(const ParamValues& v, double horizon)
        : Reference({v.real("m")}, v.real("g")),
          box_(v.real("box")), ball_{bounceOf(v, "p0", "v0", 0.0, horizon), axis(v, 0, 0.0, box_, v.real("k"), horizon),
                                     axis(v, 2, 0.0, box_, v.real("k"), horizon)}
    {
    }

    static BounceReference bounceOf(const ParamValues& v, const char* p, const char* vel, double floor, double horizon)
    {
        return {v.real("g"), v.real("k"), v.vector(p).y(), v.vector(vel).y(), floor, {}, horizon};
    }
    static WallAxisReference axis(const ParamValues& v, int a, double lo, double hi, double k, double horizon)
    {
        return {v.vector("p0")[a], v.vector("v0")[a], lo, hi, k, k, horizon};
    }

    Eigen::Vector3d position(int, double t) const override { return ball_.position(t); }
    Eigen::Vector3d velocity(int, double t) const override { return ball_.velocity(t); }
    std::vector<double> impactTimes(double tEnd) const override
    {
        std::vector<double> times = ball_.y.impactTimes(tEnd);
        for (const WallAxisReference* a : {&ball_.x, &ball_.z}) {
            const std::vector<double> more = a->impactTimes(tEnd);
            times.insert(times.end(), more.begin(), more.end());
        }
        std::sort(times.begin(), times.end());
        return times;
    }
    double lengthScale() const override { return std::max(box_, ball_.y.maxHeight()); }
    std::string description() const override
    {
        return "closed form, axes separate (bounce on y, walls on x and z), Zeno time " +
               formatSignificant(ball_.y.restTime(), 6) + " s";
    }

private:
    double box_;
    BallInBox ball_;
};

// The report's head-on meeting: ball 2 is ball 1 mirrored in the plane z = box/2, with
// equal masses. By symmetry they always meet on that plane, head-on along z, and each
// sees the other as a wall there with restitution e (eqs 2.6-2.7 with v2 = -v1 give
// v1'' = -e v1'). So ball 1 is a ball in a box whose z-walls are its own wall at r
// (restitution k) and the contact plane at box/2 - r (restitution e), or the other way
// round when it starts in the upper half; ball 2 is its mirror image.
class TwoBallsMirror final : public Reference {
public:
    TwoBallsMirror(const ParamValues& v, double horizon)
        : Reference({v.real("m1"), v.real("m2")}, v.real("g")), box_(v.real("box")),
          low_(v.vector("p1").z() < 0.5 * v.real("box")), ball_{bounce(v, horizon), xAxis(v, horizon),
                                                                zAxis(v, horizon)}
    {
    }

    Eigen::Vector3d position(int ball, double t) const override
    {
        Eigen::Vector3d p = ball_.position(t);
        if (ball == 1)
            p.z() = box_ - p.z();
        return p;
    }
    Eigen::Vector3d velocity(int ball, double t) const override
    {
        Eigen::Vector3d u = ball_.velocity(t);
        if (ball == 1)
            u.z() = -u.z();
        return u;
    }
    std::vector<double> impactTimes(double tEnd) const override
    {
        // Each wall impact of ball 1 has its mirror twin in ball 2; the meetings count once.
        std::vector<double> times;
        for (const std::vector<double>& own :
             {ball_.y.impactTimes(tEnd), ball_.x.impactTimes(tEnd), ball_.z.impactTimes(tEnd, !low_, low_)})
            for (double t : own)
                times.insert(times.end(), 2, t);
        const std::vector<double> meetings = ball_.z.impactTimes(tEnd, low_, !low_);
        times.insert(times.end(), meetings.begin(), meetings.end());
        std::sort(times.begin(), times.end());
        return times;
    }
    double lengthScale() const override { return std::max(box_, ball_.y.maxHeight()); }
    std::string description() const override
    {
        return "closed form of the mirror-symmetric head-on meeting (the other ball acts as a wall with restitution "
               "e), Zeno time " +
               formatSignificant(ball_.y.restTime(), 6) + " s";
    }

private:
    static BounceReference bounce(const ParamValues& v, double horizon)
    {
        const double r = v.real("r");
        return {v.real("g"), v.real("k"), v.vector("p1").y(), v.vector("v1").y(), r, {}, horizon};
    }
    static WallAxisReference xAxis(const ParamValues& v, double horizon)
    {
        const double r = v.real("r"), k = v.real("k");
        return {v.vector("p1").x(), v.vector("v1").x(), r, v.real("box") - r, k, k, horizon};
    }
    static WallAxisReference zAxis(const ParamValues& v, double horizon)
    {
        const double r = v.real("r"), k = v.real("k"), e = v.real("e"), mid = 0.5 * v.real("box");
        const double z = v.vector("p1").z(), vz = v.vector("v1").z();
        if (z < mid)
            return {z, vz, r, mid - r, k, e, horizon};
        return {z, vz, mid + r, v.real("box") - r, e, k, horizon};
    }

    double box_;
    bool low_;
    BallInBox ball_;
};

void requireMirror(const ParamValues& v)
{
    const double box = v.real("box");
    const Eigen::Vector3d p1 = v.vector("p1"), p2 = v.vector("p2"), v1 = v.vector("v1"), v2 = v.vector("v2");
    const Eigen::Vector3d mirrorP(p1.x(), p1.y(), box - p1.z()), mirrorV(v1.x(), v1.y(), -v1.z());
    const double tol = 1e-12 * std::max(box, 1.0);
    const double tolV = 1e-12 * std::max(v1.norm(), 1.0);
    if ((p2 - mirrorP).norm() > tol || (v2 - mirrorV).norm() > tolV)
        throw InputError("p2, v2: the closed form covers the symmetric head-on meeting only (p2 = p1 and v2 = v1 "
                         "mirrored in the plane z = box/2, as in the report)");
    if (v.real("m1") != v.real("m2"))
        throw InputError("m2: the closed form covers equal masses only (m1 = m2)");
}

} // namespace

std::unique_ptr<Reference> makeReference(const RunSpec& spec, double horizon)
{
    const ParamValues& v = spec.params;
    const std::string zeno = "it bounces to the Zeno time";
    switch (spec.scene) {
    case SceneId::Bounce1d:
        requireZero(v, "rest_speed", zeno);
        if (v.real("b") > 0.0 && v.real("c") > 0.0)
            throw InputError("b, c: the closed form covers one kind of drag at a time; set b=0 or c=0");
        return std::make_unique<Bounce1d>(v, horizon);
    case SceneId::Box3d:
    case SceneId::TwoBalls:
        for (const char* key : {"b", "c"})
            requireZero(v, key, "drag couples the axes");
        requireZero(v, "mu", "friction couples the axes");
        requireZero(v, "rest_speed", zeno);
        if (spec.scene == SceneId::Box3d)
            return std::make_unique<Box3d>(v, horizon);
        requireMirror(v);
        return std::make_unique<TwoBallsMirror>(v, horizon);
    case SceneId::ManyBalls:
        throw InputError("many-balls: there is no closed form for many colliding balls; use bounce1d, box3d or "
                         "two-balls");
    case SceneId::Street:
        throw InputError("street: there is no closed form for a flood of balls down a street; use bounce1d, box3d "
                         "or two-balls");
    }
    throw std::logic_error("scene without a reference");
}

} // namespace ab::reference
