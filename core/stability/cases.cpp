// SPDX-License-Identifier: MIT
// The cases of the stability suite. Each returns its rows; rows of a model not in this
// build say so when run. A case for a model still to come is added as rows here and
// runs as soon as that model builds.
#include "case_rows.h"

#include "stability_limit.h"

#include "../physical/spring_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace ab::stability {

std::string num(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

const std::vector<Integrator> impulseIntegrators = {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet,
                                                    Integrator::Rk4, Integrator::Event};
const std::vector<Integrator> springIntegrators = {Integrator::Euler,         Integrator::SymplecticEuler,
                                                   Integrator::Verlet,        Integrator::Rk4,
                                                   Integrator::ImplicitEuler, Integrator::ImplicitMidpoint};

CaseRow reportRow(const std::string& name, const std::string& setting, SceneId scene,
                  std::vector<std::string> assignments, std::optional<double> dt, long long steps)
{
    CaseRow r;
    r.caseName = name;
    r.setting = setting;
    r.scene = scene;
    r.model = ModelKind::Report;
    r.assignments = std::move(assignments);
    r.dt = dt;
    r.steps = steps;
    return r;
}

// One physical row per integrator.
std::vector<CaseRow> physicalRows(const CaseRow& base, const std::vector<Integrator>& integrators)
{
    std::vector<CaseRow> rows;
    for (Integrator i : integrators) {
        CaseRow r = base;
        r.model = ModelKind::Physical;
        r.integrator = i;
        rows.push_back(r);
    }
    return rows;
}

// Physical rows whose start the model must refuse (the refusal is the outcome checked).
std::vector<CaseRow> refusedPhysicalRows(const CaseRow& base)
{
    std::vector<CaseRow> rows = physicalRows(base, {Integrator::SymplecticEuler});
    for (CaseRow& r : rows)
        r.expectRefusal = true;
    return rows;
}

void append(std::vector<CaseRow>& to, std::vector<CaseRow> rows)
{
    to.insert(to.end(), std::make_move_iterator(rows.begin()), std::make_move_iterator(rows.end()));
}

namespace {

// --- stiff spring -----------------------------------------------------------------

// Limits on the damped oscillator of the spring (zeta from k), measured as the tests do;
// kept once measured (the suite runs on one thread).
double dampedLimit(Integrator i, double zeta)
{
    static std::map<std::pair<int, double>, double> cache;
    const auto key = std::make_pair(static_cast<int>(i), zeta);
    if (!cache.count(key))
        cache[key] = measureStabilityLimit(i, {1000, 10.0, 1e-4, 1e4, zeta}).h;
    return cache[key];
}

// The steps a stiff-spring row takes, in h = dt omega: either side of the limit, or for
// the implicit methods (no limit) a moderate and a very large step.
std::vector<double> stepsAround(Integrator i, double limit)
{
    if (!std::isfinite(theoreticalLimit(i)))
        return {2.0, 1000.0};
    return {0.8 * limit, 1.25 * limit};
}

CaseRow stiffRow(const CaseRow& base, Integrator i, double h, double limit, ImpactMode impacts, double omega)
{
    CaseRow r = base;
    r.integrator = i;
    r.impacts = impacts;
    r.dt = h / omega;
    // Ten time units (rest comes at ~6), at least 2000 steps, at most 2e6.
    r.steps = std::clamp<long long>(static_cast<long long>(10.0 / *r.dt), 2000, 2'000'000);
    r.setting = std::string(impactModeKey(impacts)) + ", " + base.setting + ", dt omega " + num(h);
    if (std::isfinite(theoreticalLimit(i)))
        r.setting += " = " + num(h / limit) + " x its limit " + num(limit);
    return r;
}

std::vector<CaseRow> stiffSpring()
{
    // A ball dropped from 0.1 onto the spring bounces and comes to rest on it within
    // t ~ 6 (report units); resting there is where an unstable step shows. Each
    // integrator runs at 0.8 and 1.25 times its limit on the spring's damped oscillator
    // (explicit Euler is stable only below 2 zeta), the implicit ones at dt omega0 = 2
    // and 1000; each with the contact located and stepped across blindly.
    const double zeta = physical::dampingRatioForRestitution(0.6);
    std::vector<CaseRow> rows;
    for (int contact : {1, 2}) {
        for (const char* stiffness : {"1e1", "1e3", "1e5", "1e7", "1e9"}) {
            CaseRow base;
            base.caseName = "stiff-spring";
            base.scene = SceneId::Bounce1d;
            base.model = ModelKind::Physical;
            base.assignments = {"contact=" + std::to_string(contact), std::string("stiffness=") + stiffness, "h0=0.1",
                                "k=0.6"};
            base.setting = std::string(contact == 1 ? "linear" : "Hertz") + " stiffness " + stiffness;
            const RunSpec spec = buildSpec(base);
            const double omega =
                physical::contactFrequency(physical::springFloorFor(spec), physical::startEnergy(spec));
            for (Integrator i : springIntegrators) {
                const double limit = dampedLimit(i, zeta);
                for (double h : stepsAround(i, limit))
                    for (ImpactMode impacts : {ImpactMode::Located, ImpactMode::StepEnd})
                        rows.push_back(stiffRow(base, i, h, limit, impacts, omega));
            }
        }
    }
    return rows;
}

// --- the report's own runs, and their physical counterparts ----------------------------

std::vector<CaseRow> coarseStep()
{
    // Stage 1 at the report's step (1) and 10 and 100 times coarser, to the same end time.
    std::vector<CaseRow> rows;
    for (double dt : {1.0, 10.0, 100.0}) {
        const std::string setting = "stage 1, dt " + num(dt) + " step";
        const auto steps = static_cast<long long>(2000.0 / dt);
        CaseRow r = reportRow("coarse-step", setting, SceneId::Bounce1d, {}, dt, steps);
        r.probe = flightProbe;
        rows.push_back(r);
        append(rows, physicalRows(r, impulseIntegrators));
    }
    return rows;
}

std::vector<CaseRow> energyDrift()
{
    // k = 1 for a million steps: the report's scheme, the spring (undamped) with every
    // integrator at dt omega0 = 0.63 (t_c = 5), and the impulse model when it builds.
    CaseRow r = reportRow("energy-drift", "k = 1, 1e6 steps", SceneId::Bounce1d, {"k=1", "max_bounces=1000000000"}, 1.0,
                          1'000'000);
    r.probe = driftProbe;
    std::vector<CaseRow> rows{r};
    append(rows, physicalRows(r, impulseIntegrators));
    CaseRow spring = r;
    spring.assignments.push_back("contact=1");
    spring.setting = "k = 1, 1e6 steps, linear spring t_c = 5, dt omega0 = 0.63";
    append(rows, physicalRows(spring, springIntegrators));
    return rows;
}

std::vector<CaseRow> plastic()
{
    CaseRow r = reportRow("plastic", "k = 0", SceneId::Bounce1d, {"k=0"}, 1.0, 2000);
    std::vector<CaseRow> rows{r};
    append(rows, physicalRows(r, impulseIntegrators));
    for (int contact : {1, 2}) {
        CaseRow spring = r;
        spring.assignments.push_back("contact=" + std::to_string(contact));
        spring.setting = std::string("k = 0, ") + (contact == 1 ? "linear" : "Hertz") + " spring t_c = 5";
        append(rows, physicalRows(spring, springIntegrators));
    }
    return rows;
}

std::vector<CaseRow> zeno(double k)
{
    const std::string name = k == 0.9 ? "zeno-0.9" : "zeno-0.99";
    // Zeno's rest at 201.8 (1 + 2k / (1 - k)): 3834 for k = 0.9, 40158 for 0.99.
    const auto steps = static_cast<long long>(1.2 * 201.8 * (1.0 + 2.0 * k / (1.0 - k)));
    const std::string kSet = "k=" + num(k);
    CaseRow limited =
        reportRow(name, "k = " + num(k) + ", the report's bounce limit 10", SceneId::Bounce1d, {kSet}, 1.0, steps);
    limited.probe = zenoProbe;
    CaseRow unlimited = limited;
    unlimited.assignments.push_back("max_bounces=1000000000");
    unlimited.setting = "k = " + num(k) + ", no bounce limit";
    std::vector<CaseRow> rows{limited, unlimited};
    append(rows, physicalRows(unlimited, impulseIntegrators));
    CaseRow spring = unlimited;
    spring.assignments.push_back("contact=1");
    spring.setting = "k = " + num(k) + ", linear spring t_c = 5";
    append(rows, physicalRows(spring, springIntegrators));
    return rows;
}

std::vector<CaseRow> tinyStep()
{
    // dt = 1e-7 for 1e7 steps of free fall: what remains of the error is mostly round-off.
    CaseRow r = reportRow("tiny-step", "dt 1e-7, 1e7 steps of flight", SceneId::Bounce1d, {}, 1e-7, 10'000'000);
    r.probe = flightProbe;
    std::vector<CaseRow> rows{r};
    append(rows, physicalRows(r, impulseIntegrators));
    CaseRow spring = r;
    spring.assignments.push_back("contact=1");
    spring.setting = "dt 1e-7, 1e7 steps of flight, spring floor";
    append(rows, physicalRows(spring, springIntegrators));
    return rows;
}

State twoBallState(const Eigen::Vector3d& p1, const Eigen::Vector3d& v1, const Eigen::Vector3d& p2,
                   const Eigen::Vector3d& v2)
{
    State s;
    s.resize(2);
    s.p.col(0) = p1;
    s.v.col(0) = v1;
    s.p.col(1) = p2;
    s.v.col(1) = v2;
    return s;
}

std::vector<CaseRow> tunnelling()
{
    // Speeds at which one step crosses a good part of the box, all of it, and ten boxes;
    // and two balls closing by a whole ball (2 r) and by ten per step.
    std::vector<CaseRow> rows;
    for (double speed : {3e3, 3e4, 3e5}) {
        CaseRow r = reportRow("tunnelling",
                              "box3d, vx " + num(speed) + " m/s (" + num(speed * 0.01 / 300.0) + " x the box per step)",
                              SceneId::Box3d, {"v0=" + num(speed) + ",0,0", "p0=150,20,150"}, std::nullopt, 200);
        r.probe = jumpProbe;
        rows.push_back(r);
        append(rows, physicalRows(r, impulseIntegrators));
    }
    for (double speed : {100.0, 1000.0}) {
        const std::string v = num(speed);
        const double diameters = 2.0 * speed * 0.01 / 2.0;
        CaseRow r = reportRow("tunnelling",
                              "two-balls closing at " + num(2.0 * speed) + " m/s (" + num(diameters) +
                                  (diameters == 1.0 ? " diameter" : " diameters") + " per step)",
                              SceneId::TwoBalls, {"p1=150,20,100", "p2=150,20,200", "v1=0,0," + v, "v2=0,0,-" + v},
                              std::nullopt, 100);
        rows.push_back(r);
        append(rows, physicalRows(r, impulseIntegrators));
    }
    CaseRow many = reportRow("tunnelling", "many-balls, two balls closing at 30 per frame (15 diameters per step)",
                             SceneId::ManyBalls, {"n=2", "g=0"}, std::nullopt, 100);
    many.init = twoBallState({-20, 0, 0}, {15, 0, 0}, {20, 0, 0}, {-15, 0, 0});
    rows.push_back(many);
    append(rows, physicalRows(many, impulseIntegrators));
    return rows;
}

std::vector<CaseRow> densePacking()
{
    // 1000 balls of radius 1 in a box of 24: volume fraction 0.3 (the report's default is 0.0006).
    CaseRow r = reportRow("dense-packing", "n 1000 in a box of 24 (volume fraction 0.30), settling", SceneId::ManyBalls,
                          {"n=1000", "box=24"}, std::nullopt, 200);
    std::vector<CaseRow> rows{r};
    CaseRow denser = r;
    // 20^3 balls on the start lattice (spacing 2 r) fill a box of 40 exactly: pi/6 = 0.52.
    denser.assignments = {"n=8000", "box=40"};
    denser.setting = "n 8000 in a box of 40 (volume fraction 0.52), settling";
    append(rows, physicalRows(denser, impulseIntegrators));
    return rows;
}

std::vector<CaseRow> degenerate()
{
    std::vector<CaseRow> rows;
    CaseRow same = reportRow("degenerate", "two-balls at the same centre", SceneId::TwoBalls,
                             {"p2=2,20,2", "v2=10,0,15"}, std::nullopt, 300);
    rows.push_back(same);
    // The physical model refuses an overlapping start (it could not tell the balls apart).
    append(rows, refusedPhysicalRows(same));
    CaseRow sameMany = reportRow("degenerate", "many-balls, two at the same centre (normal 0)", SceneId::ManyBalls,
                                 {"n=2"}, std::nullopt, 300);
    sameMany.init = twoBallState({0, 0, 0}, {0.3, 0, 0}, {0, 0, 0}, {-0.2, 0.1, 0});
    rows.push_back(sameMany);
    append(rows, physicalRows(sameMany, impulseIntegrators));
    CaseRow flat = reportRow("degenerate", "many-balls, contact normal with z = 0 (fixed-tangent rule)",
                             SceneId::ManyBalls, {"n=2", "g=0"}, std::nullopt, 300);
    flat.init = twoBallState({-3, 0, 0}, {0.5, 0, 0}, {3, 0, 0}, {-0.5, 0, 0});
    rows.push_back(flat);
    CaseRow flatDiagonal = flat;
    flatDiagonal.init = twoBallState({-3, 3, 0}, {0.5, -0.5, 0}, {3, -3, 0}, {-0.5, 0.5, 0});
    flatDiagonal.setting = "many-balls, normal (1, -1, 0) / sqrt 2: n.x + n.y = 0 as well";
    rows.push_back(flatDiagonal);
    // The report starts balls anywhere in [-9, 9]^3; here they start where radius 49.99
    // leaves room, within 0.01 of the centre.
    CaseRow big = reportRow("degenerate", "many-balls, radius 49.99 in a box of 100", SceneId::ManyBalls,
                            {"n=2", "r=49.99"}, std::nullopt, 300);
    big.init = twoBallState({0, 0.005, 0}, {0.3, 0, 0.1}, {0.004, 0, 0}, {-0.2, 0, 0});
    rows.push_back(big);
    append(rows, physicalRows(big, impulseIntegrators));
    CaseRow bigTwo = reportRow("degenerate", "two-balls, radius 150 in a box of 300", SceneId::TwoBalls, {"r=150"},
                               std::nullopt, 300);
    rows.push_back(bigTwo);
    // Two balls of radius 150 cannot both keep r from every wall of a 300 box: refused.
    append(rows, refusedPhysicalRows(bigTwo));
    return rows;
}

std::vector<CaseRow> extremeConstants()
{
    std::vector<CaseRow> rows;
    CaseRow noGravity =
        reportRow("extreme-constants", "g = 0, thrown down at 10", SceneId::Bounce1d, {"g=0", "v0=-10"}, 1.0, 2000);
    rows.push_back(noGravity);
    append(rows, physicalRows(noGravity, impulseIntegrators));
    CaseRow springNoGravity = noGravity;
    springNoGravity.assignments.push_back("contact=1");
    springNoGravity.setting = "g = 0, thrown down at 10, linear spring";
    append(rows, physicalRows(springNoGravity, {Integrator::Verlet, Integrator::ImplicitEuler}));
    CaseRow heavy = reportRow("extreme-constants", "g = 1e6", SceneId::Bounce1d, {"g=1e6"}, 1.0, 2000);
    rows.push_back(heavy);
    append(rows, physicalRows(heavy, impulseIntegrators));
    CaseRow springHeavy = heavy;
    springHeavy.assignments.push_back("contact=1");
    springHeavy.setting = "g = 1e6, linear spring t_c = 5";
    append(rows, physicalRows(springHeavy, {Integrator::Verlet, Integrator::ImplicitEuler}));
    CaseRow gain =
        reportRow("extreme-constants", "k = 1.5 (would gain energy)", SceneId::Bounce1d, {"k=1.5"}, 1.0, 2000);
    gain.expectRefusal = true;
    rows.push_back(gain);
    CaseRow one = reportRow("extreme-constants", "N = 1", SceneId::ManyBalls, {"n=1"}, std::nullopt, 1000);
    rows.push_back(one);
    append(rows, physicalRows(one, impulseIntegrators));
    CaseRow million = reportRow("extreme-constants", "N = 1,000,000 (a box of 200: the start lattice of 100^3 sites)",
                                SceneId::ManyBalls, {"n=1000000", "box=200"}, std::nullopt, 10);
    million.skip = "the report's model tests every pair, 5e11 tests per frame";
    rows.push_back(million);
    CaseRow millionPhysical = million;
    millionPhysical.skip.clear();
    append(rows, physicalRows(millionPhysical, {Integrator::SymplecticEuler}));
    return rows;
}

} // namespace

const std::vector<StabilityCase>& stabilityCases()
{
    static const std::vector<StabilityCase> cases = {
        {"stiff-spring", "spring floor stiffness 1e1..1e9, every integrator just below and above its limit",
         stiffSpring},
        {"coarse-step", "stage 1 at the report's step and 10 and 100 times coarser", coarseStep},
        {"energy-drift", "k = 1 over a million steps: energy drift per method", energyDrift},
        {"plastic", "k = 0: the ball must stop at the floor", plastic},
        {"zeno-0.9", "k = 0.9 down to rest: chatter, sinking, rest time", [] { return zeno(0.9); }},
        {"zeno-0.99", "k = 0.99 down to rest: chatter, sinking, rest time", [] { return zeno(0.99); }},
        {"tiny-step", "dt = 1e-7 for 1e7 steps: round-off growth", tinyStep},
        {"tunnelling", "speeds at which one step crosses a wall or a whole ball", tunnelling},
        {"dense-packing", "many balls at a high volume fraction, settling under gravity", densePacking},
        {"degenerate", "same centres, a normal with z = 0, a radius as large as the box", degenerate},
        {"extreme-constants", "g = 0, g = 1e6, k > 1, N = 1 and N = 1,000,000", extremeConstants},
        {"spin-energy-drift", "rough superballs, k = e = 1 and beta = 1, over a million steps: energy drift",
         spinEnergyDrift},
        {"spin-large-mu", "rough balls with mu = 10: every contact sticks", spinLargeMu},
        {"spin-backspin-wall", "a fast ball with back-spin against a wall", spinBackspinWall},
        {"street-elastic", "the street at 45 deg, mu = 0, e = beta = 1: energy kept to round-off", streetElastic},
        {"street-kerb-crossing", "balls fast enough to cross a kerb or the road many times in one step",
         streetKerbCrossing},
        {"street-advert", "the advert's 250,000 balls down the street", streetAdvert},
    };
    return cases;
}

const StabilityCase* findCase(const std::string& name)
{
    for (const StabilityCase& c : stabilityCases())
        if (c.name == name)
            return &c;
    return nullptr;
}

} // namespace ab::stability
