// SPDX-License-Identifier: MIT
// The flight phase of the street engine (street_engine.h point 2a).
// 1. One ball's exact motion through a substep, split at every event, and its contacts with
//    the street's boxes (street_contact.h). Each ball's numbers depend on that ball alone, so
//    any thread may fly any ball with the same result.
// 2. Room. Most balls roll or bounce in the middle of the road, far from every box but the
//    one under them, yet each leg and each settle would look at every box near them. A ball
//    keeps its room: the distance from its centre to the second nearest of those boxes, less
//    r, measured whenever all of them are looked at, and made smaller by every move of the
//    centre since (|p1 - p0| after a leg, half an overlap when a pair parts it). A box farther
//    than r + the room cannot be touched before the centre has moved by the room (the
//    triangle inequality), nor can a box the x bins leave out (farther than Layout::binPad).
//    While a leg's farthest travel, |v| T + |a| T^2 / 2, stays below the room, only the
//    nearest box is looked at for faces; while the room is positive, settle has nothing to do
//    unless the nearest box is within r. Both skip only what the whole search would have
//    skipped, so the motion is the same bit for bit.

#include "street_engine.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace ab::street {

// The nearest of some boxes, and how far the next nearest is (point 2).
struct NearestBoxes {
    int item = -1;
    double first = kNever, second = kNever;
    void add(int k, double distance)
    {
        if (distance < first) {
            second = first;
            first = distance;
            item = k;
        } else {
            second = std::min(second, distance);
        }
    }
};

namespace {

constexpr int kMaxEvents = 32; // events a ball may meet in one substep; the rest of it is flown plainly
// A ball rests on a face while its centre is this close to r from the face (relative to r)
// and it moves off it no faster than this (m/s).
constexpr double kRestGap = 1e-9;
constexpr double kLeaveSpeed = 1e-9;
// Taken off a measured room (relative to r): far above the round-off of a distance between
// points some hundred metres from the origin (point 2).
constexpr double kRoomSlack = 1e-9;
constexpr int kSettleSweeps = 3; // sweeps of settle over the boxes near a ball, at most

// The event that ends a leg of the motion.
enum class Event { None, Face, Leave, Roll };

// A leg of a ball's motion: its constant acceleration, and on a face the face's normal and
// the resting motion there.
struct Leg {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    Resting rest;
};

// When the leg ends (within tau), why, and the face met.
struct LegEnd {
    double tau;
    Event event = Event::None;
    FaceRef hit;
};

// What the ball does in this leg: on its face while it still rests there (set exactly on the
// contact, the velocity into the face taken away), else in flight under gravity.
Leg legMotion(const Layout& layout, const Surface& surface, double r, Eigen::Vector3d& p, Eigen::Vector3d& v,
              const Eigen::Vector3d& w, FaceRef& sup)
{
    Leg leg;
    leg.a = Eigen::Vector3d(0.0, -surface.g, 0.0);
    if (!sup.valid())
        return leg;
    const Box& box = layout.boxes[static_cast<std::size_t>(sup.item)];
    leg.n = faceNormal(box, sup.face);
    const double gap = faceGap(box, sup.face, p, r);
    const double off = v.dot(leg.n);
    if (std::abs(gap) > kRestGap * r + 1e-12 || off > kLeaveSpeed || !overFace(box, sup.face, box.toLocal(p), 1e-12)) {
        sup = FaceRef{}; // lifted off (a pair's impulse), or past the face's edge
        return leg;
    }
    p -= gap * leg.n; // exactly in contact
    v -= off * leg.n; // the face takes what presses on it
    leg.rest = restingMotion(v, w, leg.n, surface);
    leg.a = leg.rest.a;
    return leg;
}

// The earliest face of the boxes `items` the ball meets within end.tau (St5: the root of
// d0 + b t + q t^2 in each box's frame, where the faces are coordinate planes), its centre
// then over the face. Returns the nearest of those boxes, by squared distance.
NearestBoxes nextFace(const Layout& layout, std::span<const std::uint16_t> items, double r, const Eigen::Vector3d& p,
                      const Eigen::Vector3d& v, const Eigen::Vector3d& a, const FaceRef& sup, LegEnd& end)
{
    const double T = end.tau;
    const double reach = r + T * v.norm() + 0.5 * T * T * a.norm(); // the farthest the ball gets in T
    NearestBoxes nearest;
    for (std::uint16_t item : items) {
        const Box& box = layout.boxes[item];
        const Eigen::Vector3d lp = box.toLocal(p);
        const double out2 = box.outside(lp).squaredNorm();
        nearest.add(item, out2);
        if (out2 > reach * reach)
            continue; // out of reach in this leg
        const Eigen::Vector3d lv = box.rotateIn(v), la = box.rotateIn(a);
        for (int face = 0; face < 6; ++face) {
            if (sup.valid() && sup.item == item && sup.face == face)
                continue;
            const int k = face >> 1;
            const double side = faceSide(face);
            const double d0 = side * lp[k] - box.half[k] - r; // St5
            if (d0 < -0.5 * r)
                continue; // the centre is not outside this face: another face or an edge holds it
            const double when = physical::manyballs::timeToWall(d0, side * lv[k], 0.5 * side * la[k], end.tau);
            if (!(when <= end.tau) || !overFace(box, face, lp + when * lv + 0.5 * when * when * la, 1e-12))
                continue;
            if (when < end.tau || end.event == Event::None)
                end = LegEnd{when, Event::Face, FaceRef{item, face}};
        }
    }
    return nearest;
}

// For a ball resting on a face: when its centre passes the face's edge (its box coordinate
// l(t) = l0 + (e_k.v) t + (e_k.a) t^2 / 2 reaching +-h_k), and when it starts to roll.
void nextOnFace(const Layout& layout, const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Leg& leg,
                const FaceRef& sup, LegEnd& end)
{
    const Box& box = layout.boxes[static_cast<std::size_t>(sup.item)];
    const Eigen::Vector3d local = box.toLocal(p);
    for (int k = 0; k < 3; ++k) {
        if (k == sup.axis())
            continue;
        const Eigen::Vector3d e = box.axis(k);
        const double lv = e.dot(v), la = e.dot(leg.a);
        for (double side : {1.0, -1.0}) {
            const double when =
                physical::manyballs::timeToWall(box.half[k] - side * local[k], -side * lv, -0.5 * side * la, end.tau);
            if (when < end.tau)
                end = LegEnd{when, Event::Leave, FaceRef{}};
        }
    }
    if (leg.rest.rollAt < end.tau)
        end = LegEnd{leg.rest.rollAt, Event::Roll, FaceRef{}};
}

// What ends a leg does to the ball: leaving the face, rolling from now on, or an impact
// (street_contact.h point 3), after which a ball that stopped on a face rests on it.
void endLeg(const Layout& layout, const Surface& surface, double r, Eigen::Vector3d& p, Eigen::Vector3d& v,
            Eigen::Vector3d& w, FaceRef& sup, const Leg& leg, const LegEnd& end, long long& impacts)
{
    switch (end.event) {
    case Event::None:
        return;
    case Event::Leave:
        sup = FaceRef{};
        return;
    case Event::Roll: {
        // Rolling: the state that keeps the angular momentum about the contact point (S4).
        const Eigen::Vector3d vt = v - v.dot(leg.n) * leg.n;
        v = physical::rollingVelocity(vt, w, leg.n, surface.friction.q, r);
        w = rollingSpin(v, w, leg.n, r);
        return;
    }
    case Event::Face: {
        const Box& box = layout.boxes[static_cast<std::size_t>(end.hit.item)];
        const Eigen::Vector3d fn = faceNormal(box, end.hit.face);
        p -= faceGap(box, end.hit.face, p, r) * fn; // on the face: round-off of the root taken out
        bool approached = false;
        const bool bounces = impactAlong(v, w, fn, surface, fn.y() > 0.0, approached);
        if (bounces)
            ++impacts;
        if (approached && !bounces)
            sup = end.hit; // it rests on the face from here (only faces gravity presses on stop a ball)
        return;
    }
    }
}

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
    Room& room = room_[static_cast<std::size_t>(i)];
    const double r = settings_.radius;
    double t = 0.0;
    for (int step = 0; step < kMaxEvents && t < h; ++step) {
        const Eigen::Vector3d from = b.p;
        const Leg leg = legMotion(layout_, surface_, r, b.p, b.v, b.w, sup);
        LegEnd end{h - t, Event::None, FaceRef{}};
        if (step < kMaxEvents - 1) { // the last leg flies the rest of the substep without events
            const double T = end.tau;
            if (room.room > T * b.v.norm() + 0.5 * T * T * leg.a.norm()) {
                if (room.nearest >= 0) { // every other box beyond reach (point 2)
                    const auto own = static_cast<std::uint16_t>(room.nearest);
                    nextFace(layout_, std::span(&own, 1), r, b.p, b.v, leg.a, sup, end);
                }
            } else {
                const NearestBoxes near = nextFace(layout_, layout_.itemsNear(b.p.x()), r, b.p, b.v, leg.a, sup, end);
                room = Room{std::min(std::sqrt(near.second), layout_.binPad()) - (1.0 + kRoomSlack) * r, near.item};
            }
            if (sup.valid())
                nextOnFace(layout_, b.p, b.v, leg, sup, end);
        }
        // The exact motion for tau: constant acceleration (St4), the spin at its rate.
        const double tau = end.tau;
        b.p += tau * b.v + 0.5 * tau * tau * leg.a;
        b.v += tau * leg.a;
        if (sup.valid())
            b.w = leg.rest.rolling ? rollingSpin(b.v, b.w, leg.n, r) : Eigen::Vector3d(b.w + tau * leg.rest.alpha);
        t = end.event == Event::None ? h : t + tau;
        endLeg(layout_, surface_, r, b.p, b.v, b.w, sup, leg, end, impacts);
        room.room -= (b.p - from).norm();
    }
    settle(i, impacts);
}

void Engine::pushOut(Ball& b, FaceRef& sup, int item, const Eigen::Vector3d& local, Eigen::Vector3d away, double dist,
                     long long& impacts) const
{
    const Box& box = layout_.boxes[static_cast<std::size_t>(item)];
    const double r = settings_.radius;
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
    const Eigen::Vector3d n = box.rotateOut(away); // a unit vector turned into the world
    b.p += (r - dist) * n;
    bool approached = false;
    const bool onFace = faces == 1 && n.y() > 0.0;
    if (impactAlong(b.v, b.w, n, surface_, onFace, approached))
        ++impacts;
    else if (approached && onFace)
        sup = FaceRef{item, 2 * axis + (away[axis] > 0.0 ? 1 : 0)};
    payForRise(b.v, (r - dist) * n.y(), settings_.g);
}

bool Engine::restsOnSupport(int i) const
{
    const FaceRef& sup = support_[static_cast<std::size_t>(i)];
    return sup.valid() && std::abs(faceGap(layout_.boxes[static_cast<std::size_t>(sup.item)], sup.face,
                                           balls_[static_cast<std::size_t>(i)].p, settings_.radius)) <=
                              kRestGap * settings_.radius + 1e-12;
}

Engine::SweepCount Engine::settleSweep(int i, NearestBoxes& near, long long& impacts)
{
    Ball& b = balls_[static_cast<std::size_t>(i)];
    FaceRef& sup = support_[static_cast<std::size_t>(i)];
    const double r = settings_.radius;
    SweepCount count;
    for (std::uint16_t item : layout_.itemsNear(b.p.x())) {
        const Box& box = layout_.boxes[item];
        const Eigen::Vector3d local = box.toLocal(b.p);
        Eigen::Vector3d away = box.outside(local);
        double dist = away.norm();
        near.add(item, dist);
        if (!(dist < r * (1.0 - 1e-12)))
            continue;
        ++count.close;
        if (sup.item == item && restsOnSupport(i))
            continue; // resting on this box's face
        pushOut(b, sup, item, local, away, dist, impacts);
        ++count.pushed;
    }
    return count;
}

bool Engine::settle(int i, long long& impacts)
{
    // Edges and corners (point 2 of street_contact.h), and any overlap a pair left: the
    // centre is moved out along the normal from the closest point of each box it is within
    // r of, and a ball moving in along that normal meets it.
    const Ball& b = balls_[static_cast<std::size_t>(i)];
    const FaceRef& sup = support_[static_cast<std::size_t>(i)];
    Room& room = room_[static_cast<std::size_t>(i)];
    const double r = settings_.radius;
    // Nothing to do with a box when the ball rests on it, or when the centre is r or more
    // from it.
    const auto clearOf = [&](int item) {
        if (sup.item == item && restsOnSupport(i))
            return true;
        const Box& box = layout_.boxes[static_cast<std::size_t>(item)];
        return !(box.outside(box.toLocal(b.p)).norm() < r * (1.0 - 1e-12));
    };
    if (room.room > 0.0 && (room.nearest < 0 || clearOf(room.nearest)))
        return false; // no box within r (point 2)
    // A push out of one box can press the ball into another it is within r of (two boxes
    // meeting at an angle, the kerb beside the road): the sweep runs again while it pushed
    // with two boxes or more that close, three sweeps at most.
    bool changed = false;
    NearestBoxes near;
    for (int sweep = 0; sweep < kSettleSweeps; ++sweep) {
        near = NearestBoxes{};
        const SweepCount count = settleSweep(i, near, impacts);
        changed = changed || count.pushed > 0;
        if (count.pushed == 0 || count.close < 2)
            break;
    }
    // A push brought a box within r: no room until the next whole search.
    room = changed ? Room{} : Room{std::min(near.second, layout_.binPad()) - (1.0 + kRoomSlack) * r, near.item};
    return changed;
}

} // namespace ab::street
