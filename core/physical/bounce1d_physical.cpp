// SPDX-License-Identifier: MIT
// Stage 1 in the physical model: a point ball on the floor y = 0, vertical axis only,
// with optional air drag and the physical rest rule instead of a bounce counter, or the
// floor as a spring (the contact option of the stability suite).
#include "physical_models.h"
#include "physical_simulation.h"
#include "spring_contact.h"

namespace ab::physical {

std::unique_ptr<Simulation> makeBounce1d(const RunSpec& spec, double dt)
{
    if (contactLawOf(spec) != ContactLaw::Impulse)
        return makeSpringBounce1d(spec, dt); // the floor as a spring (report 1.2)
    const ParamValues& v = spec.params;
    World w;
    w.g = v.real("g");
    w.dragLinear = v.real("b");
    w.dragQuadratic = v.real("c");
    w.mass = {v.real("m")};
    w.restSpeed = v.real("rest_speed");
    w.walls = {floorWall(0.0, v.real("k"), 0.0)};
    // Rotation: the ball moves on the vertical axis only, so its contact point has no
    // tangential velocity and the floor needs no friction; spin about the vertical stays.
    w.spinRadius = v.real("r");
    w.inertia = v.real("inertia");
    State s;
    s.resize(1);
    s.p(1, 0) = v.real("h0");
    s.v(1, 0) = v.real("v0");
    s.w.setZero(3, 1);
    s.w(1, 0) = v.real("w0");
    return makePhysicalSimulation(spec, dt, std::move(w), std::move(s), {"h0"});
}

} // namespace ab::physical
