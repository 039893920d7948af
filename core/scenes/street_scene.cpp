// SPDX-License-Identifier: MIT
// Stage 5: balls down a steep street, the report's basic idea (chapter 3.1), which its
// rules never reached: the physical model only (docs/street.md).
#include "scene_tables.h"

#include "../street/street_layout.h"

namespace ab::scenes {

namespace {

ParamSpec withDefault(ParamSpec spec, double value)
{
    spec.defaultValue = Eigen::Vector3d(value, 0.0, 0.0);
    return spec;
}

std::vector<ParamSpec> streetParams()
{
    return {
        integer("n", "N", 10000, 1, 1e6, "3.1", "number of balls released from the hopper above the top",
                PhysicalModel),
        positive(real("r", "r", "m", 0.03, 0.0, 1.0, "3.1", "ball radius (a superball: 3 cm)", PhysicalModel)),
        positive(real("slope", "theta", "deg", 17.0, 0.0, 60.0, "St1-St2",
                      "slope of every block (17 deg: a 31 % grade, San Francisco's steepest)", PhysicalModel)),
        integer("blocks", "B", 3, 1, 20, "3.1", "road blocks, with a flat crossing between two", PhysicalModel),
        positive(real("block_length", "L", "m", 80.0, 0.0, 1000.0, "3.1", "length of a block along the road",
                      PhysicalModel)),
        positive(real("crossing", "C", "m", 14.0, 0.0, 200.0, "St4",
                      "length of each flat crossing (the top one too); the flood leaves its lower edge as projectiles",
                      PhysicalModel)),
        positive(real("width", "W", "m", 12.0, 0.0, 100.0, "3.1", "roadway between the kerbs", PhysicalModel)),
        real("kerb", "h_k", "m", 0.15, 0.0, 2.0, "3.1",
             "height of the kerbs: the sidewalks stand this far above the road", PhysicalModel),
        real("sidewalk", "S", "m", 3.0, 0.0, 20.0, "3.1", "width of each sidewalk, between kerb and house fronts",
             PhysicalModel),
        integer("cars", "cars", 0, 0, 2000, "3.1", "parked cars (boxes) along the kerbs, spread over the blocks",
                PhysicalModel),
        real("g", "g", "m/s^2", 9.82, 0.0, 100.0, "St1", "magnitude of gravity (down is -y)", PhysicalModel),
        real("e", "e", "1", 0.8, 0.0, 1.0, "eq 2.3, St5",
             "restitution of every impact, with the street and between balls (a superball: 0.8-0.9)", PhysicalModel),
        withDefault(frictionParam(true), 0.6), // superball rubber grips: the balls roll and spin
        withDefault(betaParam(), 0.4),
        inertiaParam(),
        real("rest_height", "h_rest", "m", 0.001, 0.0, 10.0, "v_rest = sqrt(2 g h_rest)",
             "an impact whose rebound would rise less than this ends in contact: the ball rolls or slides on",
             PhysicalModel),
        real("speed", "v_max", "m/s", 0.5, 0.0, 100.0, "3.1",
             "start velocities: each component uniform in [-speed, speed] (gravity and slope do the rest)",
             PhysicalModel),
        integer("seed", "seed", 2014, 0, 9007199254740992.0, "3.1", "seed of the start positions and velocities",
                PhysicalModel),
    };
}

} // namespace

SceneInfo makeStreet()
{
    SceneInfo s;
    s.id = SceneId::Street;
    s.key = "street";
    s.stage = 5;
    s.title = "Balls down a steep street";
    s.reportRef = "3.1, Figure 1";
    s.summary = "The report's basic idea: balls bouncing down a steep street, as in Sony's advert, set going by "
                "gravity, slope and rotation. A hopper above the top releases them; they roll, slide and jump down "
                "the blocks, over the flat crossings, between kerbs and house fronts, and leave at the foot. The "
                "report built the box to test its functions and never reached the street, so only the physical "
                "model has it.";
    s.axes = 3;
    s.ballCount = 0;
    s.timeUnit = "s";
    s.lengthUnit = "m";
    s.reportDt = 1.0 / 60.0;
    s.reportSteps = 1800;
    s.params = streetParams();
    s.crossCheck = [](const ParamValues& v) {
        const double r = v.real("r");
        if (v.real("width") < 8.0 * r)
            refuse(refusal::streetTooNarrow, {formatNumber(v.real("width")), formatNumber(r)});
        const auto cars = static_cast<int>(v.integer("cars"));
        const int slots = street::Layout::carSlots(static_cast<int>(v.integer("blocks")), v.real("block_length"));
        if (cars > slots)
            refuse(refusal::carsDoNotFit, {std::to_string(cars), std::to_string(slots)});
        if (cars > 0 && v.real("width") < 2.0 * street::kCarWidth + 16.0 * r)
            refuse(refusal::carsTooWide, {formatNumber(v.real("width"))});
    };
    s.equations = {
        {"St1", "a = g sin(theta) / (1 + q),  r omega = v", "a ball rolling without slipping down a block"},
        {"St2", "a = g (sin(theta) - mu cos(theta)),  domega/dt = mu g cos(theta) / (q r)",
         "a ball sliding down a block, its spin growing"},
        {"St3", "mu >= q tan(theta) / (1 + q)", "friction holds a ball set down on a block: it rolls (St1)"},
        {"St4", "p(t) = p0 + v0 t + g t^2 / 2", "a ball that leaves a crossing's edge flies as a projectile"},
        {"St5", "d(t) = n.p(t) - c - r = d0 + (n.v) t + (n.g / 2) t^2 = 0",
         "it lands when its centre is r from the road's plane: the earliest root"},
        {"St6", "v_n' = -e v_n,  Walton's tangential impulse (S9-S10)", "every impact, with the street or a ball"},
    };
    s.notes = {
        {"3.1", "\"The basic idea was that the balls would bounce down a street like the picture from Sony's advert; "
                "the simulation was done in a simplified environment, a box, to establish that the basic functions "
                "work.\" The report's rules have no slope, kerb or crossing: this stage is the physical model's."},
        {"3.1", "\"Originally gravity, slope and rotation were to give the balls their initial speed and direction.\" "
                "Here the balls start almost at rest above the top block, each velocity component at most v_max "
                "(speed, 0.5 m/s by default): gravity and slope do the rest."},
    };
    return s;
}

} // namespace ab::scenes
