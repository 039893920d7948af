// SPDX-License-Identifier: MIT
// Stage 4: N balls in a box, the WebGL model (report 2.3, Appendix D).
#include "scene_tables.h"

namespace ab::scenes {

SceneInfo makeManyBalls()
{
    SceneInfo s;
    s.id = SceneId::ManyBalls;
    s.key = "many-balls";
    s.stage = 4;
    s.title = "Many balls in a box";
    s.reportRef = "2.3, Appendix D, eqs 2.23-2.31, Figure 3.1";
    s.summary = "Many balls start in a small cube at the centre of a 100-wide box with random velocities. The "
                "report's WebGL model updates once per frame: walls reverse and damp the velocity, and ball pairs "
                "closer than 2.2 r collide along their normal with a fixed tangent (eqs 2.23-2.31).";
    s.axes = 3;
    s.ballCount = 0;
    s.timeUnit = "frame";
    s.lengthUnit = "unit";
    s.reportDt = 1.0;
    s.reportSteps = 1000;
    s.params = {
        integer("n", "N", 150, 1, 4e6, "2.3", "number of balls (the report's figure shows 200)"),
        positive(real("r", "r", "unit", 1.0, 0.0, 1e3, "Appendix D", "ball radius")),
        positive(real("box", "L", "unit", 100.0, 0.0, 1e7, "Appendix D",
                      "side of the box, centred at the origin; centres stay within box/2 - r of the centre")),
        real("g", "g", "unit/frame^2", 9.82 / 1000.0, 0.0, 1e3, "Appendix D",
             "gravity per frame; the code subtracts 9.82/1000 from dy each frame"),
        real("primary_loss", "k", "1", 0.9, 0.0, 1.0, "eq 2.3, Appendix D",
             "restitution of the velocity component normal to a wall or floor"),
        real("secondary_loss", "e", "1", 0.95, 0.0, 1.0, "eqs 2.28-2.31, Appendix D",
             "ball-ball restitution along the line of centres (the report also damps the components along a wall "
             "with it)"),
        integer("max_bounces", "count_max", 20, 3, 1e9, "Appendix D",
                "a ball with more bounces than this, near the floor, is put to rest on it", ReportModel),
        real("contact_factor", "c", "1", 2.2, 1.0, 10.0, "Appendix D",
             "two balls collide when their centres are closer than c r", ReportModel),
        integer("seed", "seed", 2014, 0, 9007199254740992.0, "Appendix D",
                "seed of the random start positions, velocities and colours"),
        real("rest_height", "h_rest", "unit", 0.02, 0.0, 1e3, "v_rest = sqrt(2 g h_rest)",
             "a rebound that would rise less than this ends at rest (restitution threshold), at walls and between "
             "balls",
             PhysicalModel),
        frictionParam(true),
        betaParam(),
        inertiaParam(),
        real("spin", "w_max", "rad/frame", 0.0, 0.0, 1e6, "free rotation: w constant in flight",
             "start spins: each component of every ball's w uniform in [-spin, spin], drawn from the seed (0: the "
             "balls start without spin)",
             PhysicalModel),
    };
    s.crossCheck = [](const ParamValues& v) {
        if (v.real("box") <= 2.0 * v.real("r"))
            refuse(refusal::noRoomInBox, {formatNumber(v.real("box")), formatNumber(v.real("r"))});
    };
    s.equations = {
        {"2.23", "n = p1 - p2 (normalised)", "normal along the line of centres"},
        {"2.24", "tz = (-(n.x 0.3) - (n.y 0.3)) / n.z", "z of a fixed tangent with x = y = 0.3"},
        {"2.25", "t = (0.3, 0.3, tz) (normalised)", "the tangent"},
        {"2.26", "V1t' = V1t''", "tangential parts kept"},
        {"2.27", "V2t' = V2t''", "tangential parts kept"},
        {"2.28", "e = (V2n'' - V1n'') / (V1n' - V2n')", "restitution along the normal"},
        {"2.29", "V1n' + V2n' = V1n'' + V2n''", "momentum along the normal"},
        {"2.30", "V2n'' = (e (V1n' - V2n') + V1n' + V2n') / 2", "ball 2's normal part after"},
        {"2.31", "V1n'' = V1n' + V2n' - V2n''", "ball 1's normal part after"},
    };
    s.notes = {
        {"eq 2.30", "The report prints it without the /2 that eq 2.6 and the code have; the /2 is used here."},
        {"eq 2.31", "The report prints v1n' + v2n' - v2n'; the intent (and code) is v1n' + v2n' - v2n''."},
        {"eqs 2.24-2.25", "The fixed tangent is undefined when n.z = 0. The product uses the same direction "
                          "written as t = (0.3 n.z, 0.3 n.z, -0.3 (n.x + n.y)), which equals the report's up to "
                          "sign (projections do not change) and tends to (0, 0, 1) as n.z -> 0; when n.x + n.y = 0 "
                          "too, every tz satisfies eq 2.24 and t = (1, 1, 0)/sqrt(2) is used."},
        {"Appendix D", "Velocities are normalised before the projection and the results get swapped speeds: "
                       "ball 1 leaves with 0.95 |v2|, ball 2 with 0.95 |v1|. A zero velocity stays zero."},
        {"Appendix D", "In the published code three.js's projectOnVector changes the vector it is called on, so "
                       "v1n and v1t are one object and the decomposition collapses; the product implements the "
                       "report's equations."},
        {"Appendix D", "The code's literal 49 and -48 are box/2 - r and one radius above the floor; its push of "
                       "1 unit along the normal is one radius. With the report's r = 1 they are the same."},
    };
    return s;
}

} // namespace ab::scenes
