// SPDX-License-Identifier: MIT
// The flight phase of the street engine (street_engine.h point 2a): one ball's exact
// motion through a substep, split at every event, and its contacts with the street's boxes
// (street_contact.h). Each ball's numbers depend on that ball alone, so any thread may fly
// any ball with the same result.
#include "street_engine.h"

#include <algorithm>
#include <cmath>

namespace ab::street {

namespace {

constexpr int kMaxEvents = 32; // events a ball may meet in one substep; the rest of it is flown plainly
// A ball rests on a face while its centre is this close to r from the face (relative to r)
// and it moves this slowly off it (relative to the rest speed, or absolutely).
constexpr double kRestGap = 1e-9;
constexpr double kLeaveSpeed = 1e-9;

// The event that ends a leg of the motion.
enum class Event { None, Face, Leave, Roll };

} // namespace

Resting restingMotion(const Eigen::Vector3d& v, const Eigen::Vector3d& w, const Eigen::Vector3d& n, const Surface& s)
{
    Resting m;
    const Eigen::Vector3d g(0.0, -s.g, 0.0);
    const double normal = -n.dot(g);           // N / m: the face holds the ball against gravity
    const Eigen::Vector3d gt = g + normal * n; // gravity along the face
    if (!s.rough) {
        m.a = gt; // a smooth ball slides freely
        return m;
    }
    const Friction& f = s.friction;
    Eigen::Vector3d u = v - f.r * w.cross(n); // S1
    u -= u.dot(n) * n;
    const double slip = u.norm();
    const double grip = f.mu * normal; // the largest friction force per unit mass
    const double tiny = 1e-12 * (1.0 + v.norm());
    Eigen::Vector3d dir;
    if (slip <= tiny) {
        // Rolling holds while the friction it takes, q |g_t| / (1 + q), is at most mu N (St3).
        if (f.q * gt.norm() <= (1.0 + f.q) * grip) {
            m.a = gt / (1.0 + f.q); // St1
            m.rolling = true;
            return m;
        }
        dir = gt.normalized(); // it starts to slip the way gravity pulls
    } else {
        dir = u / slip;
    }
    m.a = gt - grip * dir;                                        // St2
    m.alpha = grip / (f.q * f.r) * n.cross(dir);                  // St2: torque r mu N (n x s) over q r^2
    const double shrink = (1.0 + 1.0 / f.q) * grip - gt.dot(dir); // -du/dt . s
    if (slip > tiny && shrink > 0.0)
        m.rollAt = slip / shrink;
    return m;
}

void Engine::findSupport(int i)
{
    Ball& b = balls_[static_cast<std::size_t>(i)];
    FaceRef& sup = support_[static_cast<std::size_t>(i)];
    sup = FaceRef{};
    const double r = settings_.radius;
    for (std::uint16_t item : layout_.itemsNear(b.p.x())) {
        const Box& box = layout_.boxes[item];
        const Eigen::Vector3d local = box.toLocal(b.p);
        for (int face = 0; face < 6; ++face) {
            const Eigen::Vector3d n = faceNormal(box, face);
            if (!(n.y() > 0.0))
                continue; // gravity does not press the ball on it
            const double gap = faceGap(box, face, b.p, r);
            if (std::abs(gap) <= kRestGap * r && overFace(box, face, local, 0.0) &&
                std::abs(b.v.dot(n)) <= kLeaveSpeed) {
                sup = FaceRef{item, face};
                return;
            }
        }
    }
}

void Engine::fly(int i, double h, long long& impacts)
{
    Ball& b = balls_[static_cast<std::size_t>(i)];
    FaceRef& sup = support_[static_cast<std::size_t>(i)];
    const double r = settings_.radius;
    const Eigen::Vector3d g(0.0, -surface_.g, 0.0);
    double t = 0.0;
    for (int leg = 0; leg < kMaxEvents && t < h; ++leg) {
        const double T = h - t;
        const bool last = leg == kMaxEvents - 1; // the rest of the substep without events
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        Resting rest;
        if (sup.valid()) {
            const Box& box = layout_.boxes[static_cast<std::size_t>(sup.item)];
            n = faceNormal(box, sup.face);
            const double gap = faceGap(box, sup.face, b.p, r);
            const double off = b.v.dot(n);
            if (std::abs(gap) > kRestGap * r + 1e-12 || off > kLeaveSpeed ||
                !overFace(box, sup.face, box.toLocal(b.p), 1e-12)) {
                sup = FaceRef{}; // lifted off (a pair's impulse), or past the face's edge
            } else {
                b.p -= gap * n; // exactly in contact
                b.v -= off * n; // the face takes what presses on it
                rest = restingMotion(b.v, b.w, n, surface_);
            }
        }
        const Eigen::Vector3d a = sup.valid() ? rest.a : g;
        // The earliest event within T: a face met (St5), the support's edge, rolling.
        double tau = T;
        Event event = Event::None;
        FaceRef hit;
        const double reach = r + T * b.v.norm() + 0.5 * T * T * a.norm(); // the farthest the ball gets in T
        for (std::uint16_t item : last ? std::span<const std::uint16_t>() : layout_.itemsNear(b.p.x())) {
            const Box& box = layout_.boxes[item];
            // The motion in the box's frame: the faces are its coordinate planes.
            const Eigen::Vector3d lp = box.toLocal(b.p);
            if ((lp.cwiseAbs() - box.half).cwiseMax(0.0).squaredNorm() > reach * reach)
                continue; // out of reach in this leg
            const Eigen::Vector3d lv = box.rotateIn(b.v), la = box.rotateIn(a);
            for (int face = 0; face < 6; ++face) {
                if (sup.valid() && sup.item == item && sup.face == face)
                    continue;
                const int k = face >> 1;
                const double side = (face & 1) != 0 ? 1.0 : -1.0;
                const double d0 = side * lp[k] - box.half[k] - r; // St5
                if (d0 < -0.5 * r)
                    continue; // the centre is not outside this face: another face or an edge holds it
                const double when = physical::manyballs::timeToWall(d0, side * lv[k], 0.5 * side * la[k], tau);
                if (!(when <= tau))
                    continue;
                if (!overFace(box, face, lp + when * lv + 0.5 * when * when * la, 1e-12))
                    continue;
                if (when < tau || event == Event::None) {
                    tau = when;
                    event = Event::Face;
                    hit = FaceRef{item, face};
                }
            }
        }
        if (sup.valid() && !last) {
            const Box& box = layout_.boxes[static_cast<std::size_t>(sup.item)];
            const Eigen::Vector3d local = box.toLocal(b.p);
            for (int k = 0; k < 3; ++k) {
                if (k == sup.axis())
                    continue;
                // The centre's box coordinate l(t) = l0 + (e_k.v) t + (e_k.a) t^2 / 2 reaches +-h_k.
                const Eigen::Vector3d e = box.axis(k);
                const double lv = e.dot(b.v), la = e.dot(a);
                for (double side : {1.0, -1.0}) {
                    const double when = physical::manyballs::timeToWall(box.half[k] - side * local[k], -side * lv,
                                                                        -0.5 * side * la, tau);
                    if (when < tau) {
                        tau = when;
                        event = Event::Leave;
                    }
                }
            }
            if (rest.rollAt < tau) {
                tau = rest.rollAt;
                event = Event::Roll;
            }
        }
        // The exact motion for tau: constant acceleration (St4), the spin at its rate.
        b.p += tau * b.v + 0.5 * tau * tau * a;
        b.v += tau * a;
        if (sup.valid()) {
            if (rest.rolling)
                b.w = rollingSpin(b.v, b.w, n, r);
            else
                b.w += tau * rest.alpha;
        }
        t += tau;
        switch (event) {
        case Event::None:
            t = h;
            break;
        case Event::Leave:
            sup = FaceRef{};
            break;
        case Event::Roll: {
            // Rolling: the state that keeps the angular momentum about the contact point (S4).
            const Eigen::Vector3d vt = b.v - b.v.dot(n) * n;
            b.v = physical::rollingVelocity(vt, b.w, n, surface_.friction.q, r);
            b.w = rollingSpin(b.v, b.w, n, r);
            break;
        }
        case Event::Face: {
            const Box& box = layout_.boxes[static_cast<std::size_t>(hit.item)];
            const Eigen::Vector3d fn = faceNormal(box, hit.face);
            b.p -= faceGap(box, hit.face, b.p, r) * fn; // on the face: round-off of the root taken out
            bool approached = false;
            const bool canRest = fn.y() > 0.0;
            const bool bounces = impactAlong(b.v, b.w, fn, surface_, canRest, approached);
            if (bounces)
                ++impacts;
            if (approached && !bounces)
                sup = hit; // it rests on the face from here (only faces gravity presses on stop a ball)
            break;
        }
        }
    }
    settle(i, impacts);
}

void Engine::settle(int i, long long& impacts)
{
    // Edges and corners (point 2 of street_contact.h), and any overlap a pair left: the
    // centre is moved out along the normal from the closest point of each box it is within
    // r of, and a ball moving in along that normal meets it.
    Ball& b = balls_[static_cast<std::size_t>(i)];
    FaceRef& sup = support_[static_cast<std::size_t>(i)];
    const double r = settings_.radius;
    for (std::uint16_t item : layout_.itemsNear(b.p.x())) {
        const Box& box = layout_.boxes[item];
        const Eigen::Vector3d local = box.toLocal(b.p);
        const Eigen::Vector3d closest = local.cwiseMax(-box.half).cwiseMin(box.half);
        Eigen::Vector3d away = local - closest;
        double dist = away.norm();
        if (!(dist < r * (1.0 - 1e-12)))
            continue;
        if (sup.valid() && sup.item == item && std::abs(faceGap(box, sup.face, b.p, r)) <= kRestGap * r + 1e-12)
            continue; // resting on this box's face
        int axis = -1;
        if (dist > 0.0) {
            away /= dist;
        } else {
            // The centre inside the box: out through the nearest face.
            const Eigen::Vector3d depth = box.half - local.cwiseAbs();
            depth.minCoeff(&axis);
            away = Eigen::Vector3d::Zero();
            away[axis] = local[axis] >= 0.0 ? 1.0 : -1.0;
            dist = -depth[axis];
        }
        int faces = 0;
        for (int k = 0; k < 3; ++k)
            if (away[k] != 0.0) {
                ++faces;
                axis = k;
            }
        Eigen::Vector3d n = box.toWorld(away) - box.toWorld(Eigen::Vector3d::Zero());
        n.normalize();
        b.p += (r - dist) * n;
        bool approached = false;
        const bool onFace = faces == 1 && n.y() > 0.0;
        if (impactAlong(b.v, b.w, n, surface_, onFace, approached))
            ++impacts;
        else if (approached && onFace)
            sup = FaceRef{item, 2 * axis + (away[axis] > 0.0 ? 1 : 0)};
    }
}

} // namespace ab::street
