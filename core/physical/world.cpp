// SPDX-License-Identifier: MIT
#include "world.h"

#include "../params.h"

namespace ab::physical {

Wall floorWall(double y, double k, double mu)
{
    return Wall{1, y, 1.0, k, mu, "floor"};
}

std::vector<Wall> boxWalls(double lo, double hi, double k, double mu)
{
    return {floorWall(lo, k, mu), Wall{0, lo, 1.0, k, mu, "wall x = 0"}, Wall{0, hi, -1.0, k, mu, "wall x = box"},
            Wall{2, lo, 1.0, k, mu, "wall z = 0"}, Wall{2, hi, -1.0, k, mu, "wall z = box"}};
}

const Wall* restingOn(const World& w, const Eigen::Vector3d& p, const Eigen::Vector3d& v)
{
    for (const Wall& wall : w.walls)
        if (w.supports(wall) && wall.gap(p) == 0.0 && wall.normalSpeed(v) == 0.0)
            return &wall;
    return nullptr;
}

bool World::anyRough() const
{
    if (roughPairs() && balls() > 1)
        return true;
    for (const Wall& wall : walls)
        if (rough(wall))
            return true;
    return false;
}

namespace {

Eigen::Vector3d freeAcceleration(const World& w, int i, const Eigen::Vector3d& v)
{
    Eigen::Vector3d a = w.gravity();
    if (w.hasDrag()) // F = -b v - c |v| v, divided by the mass
        a -= (w.dragLinear + w.dragQuadratic * v.norm()) / w.mass[static_cast<std::size_t>(i)] * v;
    return a;
}

} // namespace

Eigen::Vector3d acceleration(const World& w, int i, const Eigen::Vector3d& v, const Wall* support)
{
    Eigen::Vector3d a = freeAcceleration(w, i, v);
    if (!support)
        return a;
    // Resting contact: the normal force N/m equals the acceleration pressing into the wall
    // and cancels it.
    if (-support->side * a[support->axis] <= 0.0)
        return a;
    a[support->axis] = 0.0;
    return a;
}

double pressing(const World& w, int i, const Eigen::Vector3d& v, const Wall& wall)
{
    return -wall.side * freeAcceleration(w, i, v)[wall.axis];
}

KineticPotential energyParts(const World& w, const Vec3Array& p, const Vec3Array& v)
{
    // E = sum 1/2 m |v|^2 + m g y: the work gravity -m g does on the way down to y = 0.
    KineticPotential e;
    for (int i = 0; i < w.balls(); ++i) {
        const double m = w.mass[static_cast<std::size_t>(i)];
        e.kinetic += 0.5 * m * v.col(i).squaredNorm();
        e.potential += m * w.g * p(1, i);
    }
    return e;
}

KineticPotential energyParts(const World& w, const State& s)
{
    KineticPotential e = energyParts(w, s.p, s.v);
    if (s.spins()) // E_rot = 1/2 I |w|^2 with I = q m r^2
        for (int i = 0; i < w.balls(); ++i)
            e.rotational += 0.5 * w.inertia * w.mass[static_cast<std::size_t>(i)] * w.spinRadius * w.spinRadius *
                            s.w.col(i).squaredNorm();
    return e;
}

double energy(const World& w, const Vec3Array& p, const Vec3Array& v)
{
    const KineticPotential e = energyParts(w, p, v);
    return e.kinetic + e.potential;
}

double energy(const World& w, const State& s)
{
    const KineticPotential e = energyParts(w, s);
    return e.kinetic + e.potential + e.rotational;
}

} // namespace ab::physical
