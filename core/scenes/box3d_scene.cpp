// SPDX-License-Identifier: MIT
// Stage 2: one ball in an open-top box (report 2.2.2, Appendices B and C).
#include "scene_tables.h"

namespace ab::scenes {

SceneInfo makeBox3d()
{
    SceneInfo s;
    s.id = SceneId::Box3d;
    s.key = "box3d";
    s.stage = 2;
    s.title = "One ball in a box";
    s.reportRef = "2.2.2, Appendix B, Appendix C (propagation), Figures 2.6-2.7";
    s.summary = "The ball is thrown sideways inside a 300 x 300 x 300 box with one corner at the origin and y up. "
                "Five faces are checked (no ceiling); a hit reverses the velocity along that face's axis and "
                "shrinks it by k, while the other axes fly on (eqs 2.17-2.22).";
    s.axes = 3;
    s.ballCount = 1;
    s.timeUnit = "s";
    s.lengthUnit = "m";
    s.reportDt = 0.01;
    s.reportSteps = 6000;
    s.params = {
        real("g", "g", "m/s^2", 9.82, 0.0, 1e6, "eq 2.19", "magnitude of gravity (down is -y)"),
        real("k", "k", "1", 0.9, 0.0, 1.0, "eq 2.17", "coefficient of restitution at floor and walls"),
        positive(real("box", "L", "m", 300.0, 0.0, 1e9, "2.2.2", "side of the cubic box (corner at the origin)")),
        vector("p0", "p0", "m", {2.0, 20.0, 2.0}, 0.0, 1e9, "Appendix B", "start position (x, y, z), y up"),
        vector("v0", "v0", "m/s", {10.0, 0.0, 15.0}, -1e6, 1e6, "Appendix B", "start velocity (x, y, z)"),
        integer("max_bounces", "count_max", 50, 0, 1e9, "2.2.2",
                "the report zeroes the ball once more than this many floor and wall contacts have happened",
                ReportModel),
        positive(real("m", "m", "kg", 1.0, 0.0, 1e9, "2.1.2, 3.1",
                      "mass of the ball; with drag it sets the terminal speed sqrt(m g / c)", PhysicalModel)),
        real("b", "b", "kg/s", 0.0, 0.0, 1e9, "3.1 (air resistance)", "linear air drag, force -b v (0: none)",
             PhysicalModel),
        real("c", "c", "kg/m", 0.0, 0.0, 1e9, "3.1 (air resistance)", "quadratic air drag, force -c |v| v (0: none)",
             PhysicalModel),
        frictionParam(false),
        betaParam(),
        inertiaParam(),
        spinRadiusParam("m"),
        startSpinParam("w0", "rad/s", "start angular velocity of the ball (x, y, z), right-hand rule"),
        real("rest_speed", "v_rest", "m/s", 0.0, 0.0, 1e6, "2.2.2 (Zeno)",
             "a floor impact slower than this does not rebound: the ball rests (0: bounce to the Zeno time)",
             PhysicalModel),
    };
    s.crossCheck = [](const ParamValues& v) {
        const double box = v.real("box");
        const Eigen::Vector3d p = v.vector("p0");
        if (p.x() > box || p.z() > box)
            refuse(refusal::outsideBox, {"p0", formatValue(v.spec("p0"), p), formatNumber(box)});
    };
    s.equations = {
        {"2.17", "v[new] = -k v[old]", "along the axis of the wall that was hit"},
        {"2.18", "p[new] = p[old] + v[new] dt", "that axis moves with the NEW velocity"},
        {"2.19", "v[new] = v[old] + g dt", "y: gravity, Euler step"},
        {"2.20", "p[new] = p[old] + v[new] dt", "y: moves with the new velocity (semi-implicit)"},
        {"2.21", "v[new] = v[old]", "the remaining horizontal axis is unchanged"},
        {"2.22", "p[new] = p[old] + v[new] dt", "and moves on"},
    };
    s.notes = {
        {"Appendix B", "One branch per step, in this order: floor y <= 0, wall x <= 0, wall x >= box, wall "
                       "z <= 0, wall z >= box, else free flight. A corner hit is handled one face per step."},
        {"eqs 2.18-2.22", "The equations and the refactored function propagation (Appendix C) move the "
                          "position with the new velocity; the older listing of Appendix B uses the old one. "
                          "The product follows the equations."},
        {"Appendix B", "At the floor the new vertical velocity is -k v - g dt (g the magnitude; the code adds grav dt "
                       "with grav = -9.82) and the position restarts from the "
                       "floor, p[new] = v[new] dt; the contact state's stored coordinate is set to the face it hit."},
        {"Appendix B", "Every contact adds one to a counter; once it exceeds max_bounces the state the step "
                       "started from and every later state are set to zero."},
    };
    return s;
}

} // namespace ab::scenes
