// SPDX-License-Identifier: MIT
// The fixed description of a physical-model scene: gravity, air drag, the balls' masses,
// contact radius and moment of inertia, the walls and the restitution and friction at
// each contact (rough spheres: docs/spin.md). A
// world holds any number of balls; the time stepping (stepped_simulation.cpp) and the
// event-driven motion (event_simulation.cpp) both read it, and so do the impact rules
// (impacts.h), so every scene shares one set of physics.
#pragma once

#include "../state.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace ab::physical {

// A plane that keeps ball centres on one side: p[axis] >= position (side +1, the floor
// and the walls at 0) or p[axis] <= position (side -1, the walls at `box`). `position`
// is where a centre touches it, so a ball of radius r meets the floor y = 0 at y = r.
struct Wall {
    int axis = 1;
    double position = 0.0;
    double side = 1.0;
    double k = 1.0;  // restitution of the normal velocity (eq 2.3), 0..1
    double mu = 0.0; // Coulomb friction coefficient between ball and wall
    std::string name;

    // Inward unit normal n (from the wall towards the free side).
    Eigen::Vector3d normal() const
    {
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        n[axis] = side;
        return n;
    }

    // Signed distance of a centre from the wall: > 0 free, 0 touching, < 0 inside.
    double gap(const Eigen::Vector3d& p) const { return side * (p[axis] - position); }
    // Velocity along the inward normal: > 0 moving away, < 0 approaching.
    double normalSpeed(const Eigen::Vector3d& v) const { return side * v[axis]; }
};

struct World {
    double g = 0.0;             // magnitude of gravity, down is -y
    double dragLinear = 0.0;    // b in F = -b v
    double dragQuadratic = 0.0; // c in F = -c |v| v
    std::vector<double> mass;   // one per ball
    double radius = 0.0;        // two centres touch at 2 radius (scenes with 2+ balls)
    double e = 1.0;             // ball-ball restitution (eq 2.5)
    double restSpeed = 0.0;     // impacts on a floor slower than this do not rebound
    std::vector<Wall> walls;
    // Rotation (docs/spin.md). Every ball has I = inertia m spinRadius^2; its contact point
    // with a wall of inward normal n is at -spinRadius n from the centre (for point-contact
    // stages too: the radius is the lever arm of friction, not the contact geometry).
    double spinRadius = 0.0; // r of I = q m r^2 (0: the balls do not turn)
    double inertia = 0.4;    // q: 2/5 a solid ball, 2/3 a hollow one
    double beta = -1.0;      // tangential restitution, -1 smooth .. 1 superball (Walton)
    double pairMu = 0.0;     // Coulomb friction between two balls

    int balls() const { return static_cast<int>(mass.size()); }
    // Friction acts at this wall: a Coulomb coefficient, surfaces that are not smooth
    // (beta > -1) and balls that can turn. Otherwise the contact is smooth and nothing
    // along it changes, exactly as without rotation.
    bool rough(const Wall& wall) const { return wall.mu > 0.0 && beta > -1.0 && spinRadius > 0.0; }
    bool roughPairs() const { return pairMu > 0.0 && beta > -1.0 && spinRadius > 0.0; }
    // Any contact with friction: spin can change during the run.
    bool anyRough() const;
    bool hasDrag() const { return dragLinear > 0.0 || dragQuadratic > 0.0; }
    Eigen::Vector3d gravity() const { return {0.0, -g, 0.0}; }
    // Gravity presses a ball against this wall (the floor): the wall can hold it at rest.
    bool supports(const Wall& w) const { return g > 0.0 && w.axis == 1 && w.side > 0.0; }
};

// The floor at height `y` and, unless `floorOnly`, the four side walls at `lo` and `hi`
// on x and z (no ceiling: the box is open at the top), all with restitution k and
// friction mu. `lo`/`hi` are where a centre touches (r and box - r for balls of radius r).
std::vector<Wall> boxWalls(double lo, double hi, double k, double mu);
Wall floorWall(double y, double k, double mu);

// The wall ball `p`, `v` rests on: touching a supporting wall exactly with no normal
// velocity (the impact rules put a resting ball there). Null when it is not resting.
const Wall* restingOn(const World& w, const Eigen::Vector3d& p, const Eigen::Vector3d& v);

// Acceleration of ball i at velocity v (Newton's second law with gravity and drag,
// a = g - (b + c |v|) v / m). On a supporting wall the contact force cancels the part
// that presses into it. Friction is not in it: it depends on the spin (rolling.h, rates).
Eigen::Vector3d acceleration(const World& w, int i, const Eigen::Vector3d& v, const Wall* support);
// The acceleration pressing ball i at velocity v into `wall` (N/m of a resting ball; <= 0
// when nothing presses it there).
double pressing(const World& w, int i, const Eigen::Vector3d& v, const Wall& wall);

// Kinetic and potential energy (zero at y = 0) of every ball, summed over the balls.
struct KineticPotential {
    double kinetic = 0.0;    // of translation, sum m |v|^2 / 2
    double potential = 0.0;  // sum m g y
    double rotational = 0.0; // sum I |w|^2 / 2 (0 without spin)
};
KineticPotential energyParts(const World& w, const Vec3Array& p, const Vec3Array& v);
// With the rotation of a state that spins.
KineticPotential energyParts(const World& w, const State& s);
// Their sum.
double energy(const World& w, const Vec3Array& p, const Vec3Array& v);
// Translation, rotation and potential.
double energy(const World& w, const State& s);

} // namespace ab::physical
