// SPDX-License-Identifier: MIT
// Stage 3: two balls meeting in the box (report 2.1.2, Appendix C).
#include "scene_tables.h"

namespace ab::scenes {

SceneInfo makeTwoBalls()
{
    SceneInfo s;
    s.id = SceneId::TwoBalls;
    s.key = "two-balls";
    s.stage = 3;
    s.title = "Two balls colliding";
    s.reportRef = "2.1.2, Appendix C, eqs 2.4-2.11";
    s.summary = "Two balls start at opposite sides of the box and meet head-on along z. The textbook collision "
                "splits each velocity into a normal part along the line of centres and a tangential part: "
                "tangential parts are kept, normal parts follow momentum conservation and restitution e "
                "(eqs 2.4-2.11). The report's own code instead swaps the two velocities and scales them by 0.95.";
    s.axes = 3;
    s.ballCount = 2;
    s.timeUnit = "s";
    s.lengthUnit = "m";
    s.reportDt = 0.01;
    s.reportSteps = 6000;
    s.params = {
        real("g", "g", "m/s^2", 9.82, 0.0, 1e6, "eq 2.12", "magnitude of gravity (down is -y)"),
        real("k", "k", "1", 0.9, 0.0, 1.0, "eq 2.17", "coefficient of restitution at floor and walls"),
        real("e", "e", "1", 0.95, 0.0, 1.0, "eq 2.5",
             "ball-ball restitution; the report's code scales the swapped velocities by it"),
        positive(
            real("r", "r", "m", 1.0, 0.0, 1e6, "Appendix C", "ball radius; contact when centres are closer than 2r")),
        positive(real("box", "L", "m", 300.0, 0.0, 1e9, "2.2.2", "side of the cubic box (corner at the origin)")),
        vector("p1", "p1", "m", {2.0, 20.0, 2.0}, 0.0, 1e9, "Appendix C", "ball 1 start position"),
        vector("v1", "v1", "m/s", {10.0, 0.0, 15.0}, -1e6, 1e6, "Appendix C", "ball 1 start velocity"),
        vector("p2", "p2", "m", {2.0, 20.0, 298.0}, 0.0, 1e9, "Appendix C", "ball 2 start position"),
        vector("v2", "v2", "m/s", {10.0, 0.0, -15.0}, -1e6, 1e6, "Appendix C", "ball 2 start velocity"),
        integer("max_events", "count_max", 100, 0, 1e9, "Appendix C",
                "the report zeroes both velocities once more than this many contacts and swaps have happened",
                ReportModel),
        positive(real("m1", "m1", "kg", 1.0, 0.0, 1e9, "eq 2.4 (any masses)",
                      "mass of ball 1; momentum m1 v1 + m2 v2 is conserved in every collision", PhysicalModel)),
        positive(real("m2", "m2", "kg", 1.0, 0.0, 1e9, "eq 2.4 (any masses)", "mass of ball 2", PhysicalModel)),
        real("b", "b", "kg/s", 0.0, 0.0, 1e9, "3.1 (air resistance)",
             "linear air drag on each ball, force -b v (0: none)", PhysicalModel),
        real("c", "c", "kg/m", 0.0, 0.0, 1e9, "3.1 (air resistance)",
             "quadratic air drag on each ball, force -c |v| v (0: none)", PhysicalModel),
        frictionParam(true),
        betaParam(),
        inertiaParam(),
        startSpinParam("w1", "rad/s", "start angular velocity of ball 1 (x, y, z), right-hand rule"),
        startSpinParam("w2", "rad/s", "start angular velocity of ball 2 (x, y, z), right-hand rule"),
        real("rest_speed", "v_rest", "m/s", 0.0, 0.0, 1e6, "Zeno",
             "a floor impact slower than this does not rebound: the ball rests (0: bounce to the Zeno time)",
             PhysicalModel),
    };
    s.crossCheck = [](const ParamValues& v) {
        const double box = v.real("box");
        for (const char* key : {"p1", "p2"}) {
            const Eigen::Vector3d p = v.vector(key);
            if (p.x() > box || p.z() > box)
                refuse(refusal::outsideBox, {std::string(key), formatValue(v.spec(key), p), formatNumber(box)});
        }
    };
    s.equations = {
        {"2.4", "v1' + v2' = v1'' + v2''", "momentum is conserved (equal masses)"},
        {"2.5", "e = (v2n'' - v1n'') / (v1n' - v2n')", "restitution along the normal"},
        {"2.6", "v2n'' = (e (v1n' - v2n') + v1n' + v2n') / 2", "ball 2's normal velocity after"},
        {"2.7", "v1n'' = v1n' + v2n' - v2n''", "ball 1's normal velocity after"},
        {"2.8", "v1t' = v1t''", "smooth balls: tangential part kept"},
        {"2.9", "v2t' = v2t''", "smooth balls: tangential part kept"},
        {"2.10", "v1'' = v1t'' + v1n''", "ball 1's velocity after"},
        {"2.11", "v2'' = v2t'' + v2n''", "ball 2's velocity after"},
    };
    s.notes = {
        {"Appendix C", "The report's code does not use eqs 2.4-2.11 here: when the centres are closer than 2r "
                       "after a step it swaps the two velocities and multiplies them by 0.95 (e), with no test "
                       "that the balls approach, so the swap can repeat while they still overlap."},
        {"Appendix C", "The code's distance uses the y difference twice and no z difference; the product uses "
                       "the Euclidean distance the code intends."},
        {"Appendix C", "One counter, shared by both balls, counts every floor and wall contact and every swap; "
                       "once it exceeds max_events both velocities are set to zero in the state the step started "
                       "from and in every later state, while positions go on being computed."},
        {"Appendix C", "Each ball moves with the stage-2 rules (propagation). propagation works on a copy, so "
                       "unlike stage 2 the recorded contact state keeps its unclamped coordinate."},
    };
    return s;
}

} // namespace ab::scenes
