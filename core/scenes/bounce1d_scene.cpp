// SPDX-License-Identifier: MIT
// Stage 1: one ball bouncing on a floor, vertical axis only (report 2.2.1, Appendix A).
#include "scene_tables.h"

namespace ab::scenes {

SceneInfo makeBounce1d()
{
    SceneInfo s;
    s.id = SceneId::Bounce1d;
    s.key = "bounce1d";
    s.stage = 1;
    s.title = "A ball bouncing in one dimension";
    s.reportRef = "2.1.1, 2.2.1, Appendix A, Figure 2.5";
    s.summary = "A ball falls from rest and bounces on a floor. Flight follows dv/dt = -g and dx/dt = v "
                "(eqs 2.1-2.2); an impact reverses and shrinks the velocity, v1 = -k v0 (eq 2.3). The bounces come "
                "ever faster (Zeno behaviour), so the report stops the ball after a fixed number of bounces.";
    s.axes = 1;
    s.ballCount = 1;
    s.timeUnit = "step";
    s.lengthUnit = "unit";
    s.reportDt = 1.0;
    s.reportSteps = 2000;
    s.params = {
        real("g", "g", "unit/step^2", 0.0982, 0.0, 1e6, "eq 2.1, 2.15",
             "magnitude of gravity; the report's code scales 9.82 to 0.0982 per step^2 with dt = 1"),
        real("k", "k", "1", 0.6, 0.0, 1.0, "eq 2.3, 2.13", "coefficient of restitution at the floor: v1 = -k v0"),
        real("h0", "h0", "unit", 2000.0, 0.0, 1e9, "Appendix A", "start height of the ball above the floor"),
        real("v0", "v0", "unit/step", 0.0, -1e6, 1e6, "Appendix A", "start vertical velocity, up positive"),
        integer("max_bounces", "count_max", 10, 0, 1e9, "2.2.1",
                "the report zeroes the ball once more than this many bounces have happened (against Zeno)",
                ReportModel),
        positive(real("m", "m", "kg", 1.0, 0.0, 1e9, "2.1.2, 3.1",
                      "mass of the ball; with drag it sets the terminal speed sqrt(m g / c)", PhysicalModel)),
        real("b", "b", "kg/step", 0.0, 0.0, 1e9, "3.1 (air resistance)", "linear air drag, force -b v (0: none)",
             PhysicalModel),
        real("c", "c", "kg/unit", 0.0, 0.0, 1e9, "3.1 (air resistance)", "quadratic air drag, force -c |v| v (0: none)",
             PhysicalModel),
        real("rest_speed", "v_rest", "unit/step", 0.0, 0.0, 1e6, "2.2.1 (Zeno)",
             "an impact slower than this does not rebound: the ball rests (0: bounce to the Zeno time)", PhysicalModel),
        spinRadiusParam("unit"),
        inertiaParam(),
        real("w0", "w0", "rad/step", 0.0, -1e6, 1e6, "free rotation: w constant in flight",
             "start spin about the vertical axis, up positive (right-hand rule): the only spin a ball moving on one "
             "axis can have; the floor's contact point has no lever on it, so it stays",
             PhysicalModel),
        integer("contact", "contact", 0, 0, 2, "report 1.2",
                "floor contact of the physical model: 0 impulse v1 = -k v0 (eq 2.3), 1 linear spring-dashpot, "
                "2 Hertz spring with damping; springs take their damping from k",
                PhysicalModel),
        real("contact_time", "t_c", "step", 5.0, 1e-6, 1e6, "report 1.2",
             "duration of one spring contact (contact 1 or 2); with k it sets stiffness and damping", PhysicalModel),
        real("stiffness", "k_s", "1/step^2", 0.0, 0.0, 1e12, "report 1.2",
             "spring stiffness per unit mass (Hertz: per unit^1/2); 0 takes it from contact_time", PhysicalModel),
    };
    s.equations = {
        {"2.1", "-g = dv/dt", "free flight: gravity is the only force"},
        {"2.2", "v = dx/dt", "position changes with velocity"},
        {"2.3", "v1 = -k v0", "at the floor the velocity reverses and shrinks by k"},
        {"2.12", "v'' = v' + g dt", "explicit Euler step of the velocity (g signed, down negative)"},
        {"2.13", "v[new] = -k v[old]", "floor hit: bounce, no gravity in that step"},
        {"2.14", "p[new] = v[new] dt", "floor hit: leave the floor with the new velocity"},
        {"2.15", "v[new] = v[old] + g dt", "free fall"},
        {"2.16", "p[new] = p[old] + v[old] dt", "free fall: position moves with the OLD velocity"},
    };
    s.notes = {
        {"eq 2.16", "The report prints p[new] = p[old] * v[old] * dt; its code (and intent) is "
                    "p[new] = p[old] + v[old] dt, which is what runs here."},
        {"Appendix A", "A floor hit is p <= 0 and v <= 0 at the start of a step. That step also sets the "
                       "stored position of the contact state to 0, and when the bounce counter exceeds "
                       "max_bounces the contact state and every later state are set to zero."},
        {"2.2.1", "The code counts time in steps (dt = 1) with gravity 0.0982 per step^2; the text's "
                  "g = 9.82 is the same physics with the step read as 0.1 s."},
        {"1.2", "Before settling on a coefficient of restitution the report considered spring equations for the "
                "bounce. The physical model offers them as `contact` 1 (y'' = -g - k_s y - c_s v below the floor) "
                "and 2 (Hertz, y'' = -g + k_h d^1.5 - c_h d^0.25 v with d = -y); their damping gives the "
                "restitution k and their stiffness the contact time t_c, and a stiff spring makes the ODE stiff."},
    };
    return s;
}

} // namespace ab::scenes
