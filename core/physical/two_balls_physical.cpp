// SPDX-License-Identifier: MIT
// Stage 3 in the physical model: two balls of radius r and masses m1, m2 in the box. Every
// centre stays at least r from each face (the walls a centre meets are at r and box - r)
// and 2r from the other centre; collisions follow eqs 2.4-2.11 for any masses, and with
// friction mu at every contact the balls turn (Walton's impulse, impacts.h).
#include "physical_models.h"
#include "physical_simulation.h"

namespace ab::physical {

std::unique_ptr<Simulation> makeTwoBalls(const RunSpec& spec, double dt)
{
    const ParamValues& v = spec.params;
    const double r = v.real("r");
    World w;
    w.g = v.real("g");
    w.dragLinear = v.real("b");
    w.dragQuadratic = v.real("c");
    w.mass = {v.real("m1"), v.real("m2")};
    w.radius = r;
    w.e = v.real("e");
    w.restSpeed = v.real("rest_speed");
    w.walls = boxWalls(r, v.real("box") - r, v.real("k"), v.real("mu"));
    w.spinRadius = r;
    w.inertia = v.real("inertia");
    w.beta = v.real("beta");
    w.pairMu = v.real("mu");
    State s;
    s.resize(2);
    s.p.col(0) = v.vector("p1");
    s.v.col(0) = v.vector("v1");
    s.p.col(1) = v.vector("p2");
    s.v.col(1) = v.vector("v2");
    s.w.setZero(3, 2);
    s.w.col(0) = v.vector("w1");
    s.w.col(1) = v.vector("w2");
    return makePhysicalSimulation(spec, dt, std::move(w), std::move(s), {"p1", "p2"});
}

} // namespace ab::physical
