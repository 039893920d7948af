// SPDX-License-Identifier: MIT
// Stage 2 in the physical model: a point ball in the open-top box [0, box]^3 (its centre
// meets the floor and the walls), restitution k and friction mu at every face; the ball
// of radius r turns (I = q m r^2) and friction acts at its contact point r below it.
#include "physical_models.h"
#include "physical_simulation.h"

namespace ab::physical {

std::unique_ptr<Simulation> makeBox3d(const RunSpec& spec, double dt)
{
    const ParamValues& v = spec.params;
    World w;
    w.g = v.real("g");
    w.dragLinear = v.real("b");
    w.dragQuadratic = v.real("c");
    w.mass = {v.real("m")};
    w.restSpeed = v.real("rest_speed");
    w.walls = boxWalls(0.0, v.real("box"), v.real("k"), v.real("mu"));
    w.spinRadius = v.real("r"); // the lever arm of friction; the contact is at the centre
    w.inertia = v.real("inertia");
    w.beta = v.real("beta");
    State s;
    s.resize(1);
    s.p.col(0) = v.vector("p0");
    s.v.col(0) = v.vector("v0");
    s.w = v.vector("w0");
    return makePhysicalSimulation(spec, dt, std::move(w), std::move(s), {"p0"});
}

} // namespace ab::physical
