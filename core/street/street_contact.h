// SPDX-License-Identifier: MIT
// A ball against the street's boxes (street_layout.h), per unit mass (docs/street.md).
//
// 1. Faces. Face f of a box has the outward normal n = s e_a (axis a, side s = +-1) and
//    the plane n.x = n.c + h_a. A centre moving with constant acceleration, p(t) = p + v t
//    + a t^2 / 2, is r from that plane when
//        d(t) = n.(p(t) - c) - h_a - r = d0 + (n.v) t + (n.a / 2) t^2 = 0        (St5)
//    whose earliest root in the step is exact (timeToWall); the impact counts when the
//    centre then lies over the face (its two other box coordinates within the box).
// 2. Edges and corners are met by the closest point of the box (clamp the centre's box
//    coordinates to the box): a centre nearer than r is moved out along p - closest,
//    and an approach along that normal is an impact.
// 3. An impact along n: the normal velocity v_n becomes -e v_n (eq 2.3), or 0 when the
//    rebound is slower than the rest speed and gravity presses the ball on the face
//    (the ball then rests on it); along the face Walton's impulse (S9-S10) with the
//    normal impulse (1 + e) |v_n|.
// 4. Resting on a face (normal n, N = -n.g the normal force per unit mass, g_t = g + N n
//    gravity's part along the face), the slip u = v - r w x n (S1) decides:
//      rolling (u = 0, and mu N >= q |g_t| / (1 + q)):  a = g_t / (1 + q), w = n x v / r
//        + (w.n) n                                                            (St1, St3)
//      sliding (direction s = u/|u|):  a = g_t - mu N s,  dw/dt = mu N (n x s) / (q r),
//        du/dt = g_t - (1 + 1/q) mu N s                                          (St2)
//    A sliding ball rolls once u reaches zero: at t* = |u| / ((1 + 1/q) mu N - g_t.s)
//    when that is positive (S3 on a slope). Smooth balls (no friction) slide with a = g_t.
#pragma once

#include "street_layout.h"

#include "../physical/many_balls_walls.h"

#include <Eigen/Geometry>

namespace ab::street {

using physical::manyballs::Friction;
using physical::manyballs::kNever;

// A face of a box: item index, axis and side (a face is 2 a + (s > 0)).
struct FaceRef {
    int item = -1;
    int face = 0;
    bool valid() const { return item >= 0; }
    int axis() const { return face >> 1; }
};

// The side s of face `face` along its axis: +1 or -1.
inline double faceSide(int face)
{
    return (face & 1) != 0 ? 1.0 : -1.0;
}

inline Eigen::Vector3d faceNormal(const Box& b, int face)
{
    return faceSide(face) * b.axis(face >> 1);
}

// d of St5 at p: the distance of the centre from the face's plane less r (negative: overlap).
inline double faceGap(const Box& b, int face, const Eigen::Vector3d& p, double r)
{
    const int a = face >> 1;
    return faceSide(face) * b.toLocal(p)[a] - b.half[a] - r;
}

// The centre lies over the face: its other two box coordinates within the box (grown by `slack`).
inline bool overFace(const Box& b, int face, const Eigen::Vector3d& local, double slack)
{
    const int a = face >> 1;
    for (int k = 0; k < 3; ++k)
        if (k != a && std::abs(local[k]) > b.half[k] + slack)
            return false;
    return true;
}

// What the street's contacts read: restitution, rest speed, gravity, friction.
struct Surface {
    double e = 1.0;
    double restSpeed = 0.0;
    double g = 9.82;
    Friction friction;
    bool rough = false;
};

// An impact along the outward normal n (point 3). Returns true when the ball rebounds,
// false when it stops on the face (it then rests there if `canRest`) or was not approaching.
// `approached` is set when the ball moved towards the face.
inline bool impactAlong(Eigen::Vector3d& v, Eigen::Vector3d& w, const Eigen::Vector3d& n, const Surface& s,
                        bool canRest, bool& approached)
{
    const double vn = v.dot(n);
    approached = vn < 0.0;
    if (!approached)
        return false;
    const double rebound = -s.e * vn;
    const bool bounces = !(canRest && rebound < s.restSpeed);
    const double after = bounces ? rebound : 0.0;
    v += (after - vn) * n; // v_n'' = -e v_n' (eq 2.3), or 0 at rest
    if (s.rough)
        physical::manyballs::waltonAtPlane(v, w, n, after - vn, s.friction);
    return bounces;
}

// The motion of a ball resting on a face for a while (point 4): its acceleration, the rate
// of its spin (sliding), whether it rolls, and when a sliding ball starts to roll.
struct Resting {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    Eigen::Vector3d alpha = Eigen::Vector3d::Zero();
    bool rolling = false;
    double rollAt = kNever;
};

Resting restingMotion(const Eigen::Vector3d& v, const Eigen::Vector3d& w, const Eigen::Vector3d& n, const Surface& s);

// The spin of a ball rolling at v on a face of normal n, its spin about n kept (S4).
inline Eigen::Vector3d rollingSpin(const Eigen::Vector3d& v, const Eigen::Vector3d& w, const Eigen::Vector3d& n,
                                   double r)
{
    return n.cross(v) / r + w.dot(n) * n;
}

// A push out of a box that lifts the centre by `rise` (an edge met at the substep's end rather
// than at its time, or a ball a pair pushed into the box) gives it g rise of potential energy
// per unit mass that no force paid for: the ball pays it from its speed, v^2 -> v^2 - 2 g rise
// as far as it has it, its direction kept, so that no push makes energy.
inline void payForRise(Eigen::Vector3d& v, double rise, double g)
{
    const double v2 = v.squaredNorm();
    if (!(rise > 0.0) || !(v2 > 0.0))
        return;
    v *= std::sqrt(std::max(0.0, 1.0 - 2.0 * g * rise / v2));
}

} // namespace ab::street
