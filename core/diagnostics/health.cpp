// SPDX-License-Identifier: MIT
#include "health.h"

#include "../broadphase/grid_geometry.h"
#include "../physical/physical_simulation.h"
#include "../physical/spring_contact.h"
#include "../stability/stability_limit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numeric>

namespace ab::diagnostics {

std::string_view healthKey(Health h)
{
    switch (h) {
    case Health::Ok:
        return "ok";
    case Health::Warning:
        return "warning";
    case Health::Failed:
        return "failed";
    }
    return "failed";
}

std::string HealthStatus::line() const
{
    return advice.empty() ? what : what + "; " + advice;
}

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

enum class Kind {
    NonFinite,
    Escaped,
    Backstop,
    Penetration,
    Energy,
    Overlap,
    Tunnel,
    Graze,
    Momentum,
    RepeatedSwap,
    Stuck,
    Count
};

// Three significant figures for messages.
std::string num(double x)
{
    return formatSignificant(x, 3);
}

// Where a centre may be: the floor and the walls as limits on the centre, infinite where
// the scene has no wall (bounce1d has only a floor; no scene has a ceiling). Walls are
// checked at any height, as both models do.
struct Walls {
    Eigen::Vector3d lo;
    Eigen::Vector3d hi;
};

Walls wallsOf(const RunSpec& spec)
{
    const ParamValues& p = spec.params;
    switch (spec.scene) {
    case SceneId::Bounce1d:
        return {{-infinity, 0.0, -infinity}, {infinity, infinity, infinity}};
    case SceneId::Box3d:
        return {{0.0, 0.0, 0.0}, {p.real("box"), infinity, p.real("box")}};
    case SceneId::TwoBalls: {
        // The report's walls meet the centre; the physical model keeps centres r inside.
        const double r = spec.model == ModelKind::Physical ? p.real("r") : 0.0;
        return {{r, r, r}, {p.real("box") - r, infinity, p.real("box") - r}};
    }
    case SceneId::ManyBalls: {
        const double limit = p.real("box") / 2.0 - p.real("r");
        return {{-limit, -limit, -limit}, {limit, infinity, limit}};
    }
    }
    throw std::logic_error("scene without walls");
}

// The wall a centre is furthest beyond, and by how much (0 when inside).
struct Beyond {
    double depth = 0.0;
    int axis = 1;
    bool low = true;
};

Beyond beyond(const Walls& w, const Eigen::Vector3d& p)
{
    Beyond b;
    for (int a = 0; a < 3; ++a) {
        if (w.lo[a] - p[a] > b.depth)
            b = {w.lo[a] - p[a], a, true};
        if (p[a] - w.hi[a] > b.depth)
            b = {p[a] - w.hi[a], a, false};
    }
    return b;
}

// Closest distance between two balls moving in straight lines over the step (s in [0, 1]).
double closestApproach(const Eigen::Vector3d& d0, const Eigen::Vector3d& d1)
{
    const Eigen::Vector3d m = d1 - d0;
    const double mm = m.squaredNorm();
    const double s = mm > 0.0 ? std::clamp(-d0.dot(m) / mm, 0.0, 1.0) : 0.0;
    return (d0 + s * m).norm();
}

} // namespace

struct HealthCheck::Impl {
    const Simulation& sim;
    const RunSpec& spec;
    bool report;
    double dt, g, r;
    Walls walls;
    double tolerance; // round-off allowance on lengths
    std::optional<physical::SpringFloor> spring;
    double springAllowance = infinity;
    std::vector<double> mass; // the physical model's masses (its World); empty: equal masses
    double spinInertia = 0.0; // q r^2 of I = q m r^2 (docs/spin.md); 0: the balls do not turn
    double e0 = 0.0;
    double energyScale = 0.0;
    HealthFigures fig;
    std::vector<HealthStatus> issues;
    std::vector<Kind> issueKinds; // of each issue
    std::array<std::array<bool, 3>, static_cast<std::size_t>(Kind::Count)> seen{};
    std::vector<char> escapedBall;
    Health level = Health::Ok; // of the step being checked
    double t = 0.0;            // of the state being checked
    long long pairChecks = 0;
    int sampledAbove = HealthCheck::defaultSampledAbove;
    // gridOverlaps' arrays, kept between steps.
    std::vector<std::uint32_t> cellOf, order, cellStart, cursor;

    Impl(const Simulation& s, const State& start)
        : sim(s), spec(s.spec()), report(spec.model == ModelKind::Report), dt(s.dt()), g(spec.params.real("g")),
          r(spec.params.indexOf("r") ? spec.params.real("r") : 0.0), walls(wallsOf(spec))
    {
        double scale = 1.0;
        for (int a = 0; a < 3; ++a)
            if (std::isfinite(walls.hi[a]) && std::isfinite(walls.lo[a]))
                scale = std::max(scale, walls.hi[a] - walls.lo[a]);
        if (start.size() > 0 && start.p.allFinite())
            scale = std::max(scale, start.p.cwiseAbs().maxCoeff());
        tolerance = 1e-9 * scale;
        if (spec.scene == SceneId::Bounce1d && !report &&
            physical::contactLawOf(spec) != physical::ContactLaw::Impulse) {
            spring = physical::springFloorFor(spec);
        }
        // The spring floor's energies stay per unit mass: its allowance below takes them so.
        if (const physical::World* world = physical::worldOf(s); world && !spring) {
            mass = world->mass;
            spinInertia = world->inertia * world->spinRadius * world->spinRadius;
        }
        e0 = energy(start);
        // Gains are relative to the start energy, or to that of the balls raised by the
        // scene's size when the start holds less (a ball at rest on the floor).
        double totalMass = std::max(start.size(), 1);
        if (!mass.empty())
            totalMass = std::accumulate(mass.begin(), mass.end(), 0.0);
        energyScale = std::max(e0, g * scale * totalMass);
        if (spring)
            springAllowance = 2.0 * physical::maxCompression(*spring, e0);
        escapedBall.assign(static_cast<std::size_t>(start.size()), 0);
    }

    double potential(double y) const { return spring ? spring->potential(y) : g * (y - walls.lo.y()); }

    // sum m (|v|^2 / 2 + q r^2 |w|^2 / 2 + potential): with the physical model's masses where
    // it has them (two balls of different masses share the energy, not the energy per unit
    // mass), else per unit mass (the report's and many-balls' equal masses, the spring
    // floor's one ball). A turning ball's rotational energy I |w|^2 / 2 = m q r^2 |w|^2 / 2
    // (docs/spin.md) counts: friction trades it with the translation's.
    double energy(const State& s) const
    {
        const bool turning = spinInertia > 0.0 && s.w.cols() == s.size();
        double e = 0.0;
        for (int i = 0; i < s.size(); ++i) {
            const double m = static_cast<std::size_t>(i) < mass.size() ? mass[static_cast<std::size_t>(i)] : 1.0;
            const double spin = turning ? 0.5 * spinInertia * s.w.col(i).squaredNorm() : 0.0;
            e += m * (0.5 * s.v.col(i).squaredNorm() + spin + potential(s.p(1, i)));
        }
        return e;
    }

    std::string at() const { return " at t = " + num(t) + " " + sim.scene().timeUnit; }
    std::string length(double x) const { return num(x) + " " + sim.scene().lengthUnit; }

    // Records a problem the first time its kind is met at this level; the text is built
    // only then.
    template <typename Describe> void raise(Kind kind, Health h, Describe describe)
    {
        level = std::max(level, h);
        bool& first = seen[static_cast<std::size_t>(kind)][static_cast<std::size_t>(h)];
        if (first)
            return;
        first = true;
        HealthStatus status{h, {}, {}, t, {}};
        describe(status.what, status.advice, status.finding);
        issues.push_back(std::move(status));
        issueKinds.push_back(kind);
    }

    // What to change when the method itself misbehaves (energy, divergence): sets the
    // finding's remedy and returns it in the command line's words.
    std::string methodAdvice(Finding& f) const
    {
        if (report)
            return advise(f, Remedy::ReportSmallerDt);
        const Integrator i = spec.integrator;
        if (spring) {
            const double omega = physical::contactFrequency(*spring, e0);
            const double limit = stability::theoreticalLimit(i);
            f.integrator = i;
            f.dtOmega = dt * omega;
            if (i == Integrator::Euler)
                return advise(f, Remedy::SpringEuler);
            if (std::isfinite(limit)) {
                f.limit = limit;
                f.dtLimit = limit / omega;
                return advise(f, Remedy::SpringLimit);
            }
            return advise(f, Remedy::SmallerDt);
        }
        if (i == Integrator::Euler)
            return advise(f, Remedy::EulerAddsEnergy);
        return advise(f, Remedy::SmallerDt);
    }

    std::string impactAdvice(Finding& f) const
    {
        if (report && spec.scene == SceneId::ManyBalls)
            return advise(f, Remedy::ReportOnePerFrame);
        if (report)
            return advise(f, Remedy::ReportStepEnd);
        if (spec.impacts == ImpactMode::StepEnd)
            return advise(f, Remedy::LocatedOrSmallerDt);
        return advise(f, Remedy::SmallerDt);
    }

    // The remedy kept in the finding, returned in the command line's words.
    static std::string advise(Finding& f, Remedy r)
    {
        f.remedy = r;
        return remedyText(f);
    }

    // A state is non-finite when a number in it is, or when its energy overflows (a speed
    // beyond 1e154): nothing after it can be shown.
    bool checkFinite(const State& a, double e)
    {
        if (std::isfinite(a.t) && a.p.allFinite() && a.v.allFinite() && std::isfinite(e))
            return true;
        fig.nonfinite = true;
        raise(Kind::NonFinite, Health::Failed, [&](std::string& what, std::string& advice, Finding& f) {
            f.kind = FindingKind::NonFinite;
            what = "the state became non-finite (overflow)" + at();
            advice = methodAdvice(f);
        });
        return false;
    }

    void checkEnergy(const State& a, double e)
    {
        if (!(energyScale > 0.0))
            return; // no gravity and no motion: nothing can gain energy
        // On the spring floor the energy is compared in flight: inside the spring the
        // integrator's error in the stored energy comes and goes with the step.
        if (spring && a.p(1, 0) < 0.0)
            return;
        const double gain = (e - e0) / energyScale;
        fig.maxEnergyGain = std::max(fig.maxEnergyGain, gain);
        if (gain <= 1e-6)
            return;
        const Health h = gain > 0.1 ? Health::Failed : Health::Warning;
        raise(Kind::Energy, h, [&](std::string& what, std::string& advice, Finding& f) {
            f.kind = FindingKind::Energy;
            f.amount = 100.0 * gain;
            what = "energy " + num(f.amount) + "% above its start" + at() + energyCause(f);
            advice = methodAdvice(f);
        });
    }

    std::string energyCause(Finding& f) const
    {
        if (!report)
            return {};
        switch (spec.scene) {
        case SceneId::Bounce1d:
            f.rule = ReportRule::ExplicitEulerGain;
            return " (eq 2.16 moves the position with the old velocity: explicit Euler adds g^2 dt^2 / 2 per step "
                   "of flight)";
        case SceneId::Box3d:
        case SceneId::TwoBalls:
            f.rule = ReportRule::FloorRuleGain;
            return " (the floor rule v' = -k v - g dt of Appendix B adds a step of gravity to each rebound)";
        case SceneId::ManyBalls:
            f.rule = ReportRule::PushAndWallGravity;
            return " (Appendix D's push of one radius along the normal and its extra gravity at a side wall)";
        }
        return {};
    }

    std::string wallName(const Beyond& b, Finding& f) const
    {
        f.wallAxis = b.axis;
        f.wallFace = b.low ? walls.lo[b.axis] : walls.hi[b.axis];
        if (b.axis == 1)
            return "the floor";
        const double face = b.low ? walls.lo[b.axis] : walls.hi[b.axis];
        return std::string("the ") + "xyz"[b.axis] + " = " + num(face) + " wall";
    }

    void checkPlace(const State& b, const State& a, int i)
    {
        const Beyond where = beyond(walls, a.p.col(i));
        fig.maxPenetration = std::max(fig.maxPenetration, where.depth);
        if (where.depth <= tolerance)
            return;
        if (spring) {
            if (where.depth > springAllowance)
                escape(i, [&](Finding& f) {
                    f.kind = FindingKind::SpringEscaped;
                    f.amount = where.depth;
                    return "ball went " + length(where.depth) + " into the floor spring" + at() +
                           ", twice deeper than its energy allows (fell through the floor)";
                });
            else if (where.depth >= 0.5 * springAllowance * physical::kBackstopFactor * (1.0 - 1e-9))
                // Held by the spring floor's backstop: no solution of the ODE gets there,
                // so the integrator is unstable at this step.
                raise(Kind::Backstop, Health::Failed, [&](std::string& what, std::string& advice, Finding& f) {
                    f.kind = FindingKind::Backstop;
                    f.balls = {i};
                    f.amount = where.depth;
                    f.bound = 0.5 * springAllowance;
                    what = "ball reached the floor spring's backstop, " + length(where.depth) + " deep" + at() +
                           ", 1.5 times deeper than its energy allows (" + length(0.5 * springAllowance) +
                           "): the step is beyond the method's stability, and the backstop held the ball";
                    advice = methodAdvice(f);
                });
            else if (where.depth > 0.5 * springAllowance * 1.01)
                // Over 1% deeper than the start's energy can compress the spring: the
                // method's error, beyond the truncation error of a step that resolves the
                // contact.
                raise(Kind::Penetration, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
                    f.kind = FindingKind::SpringPenetration;
                    f.balls = {i};
                    f.amount = where.depth;
                    f.bound = 0.5 * springAllowance;
                    what = "ball went " + length(where.depth) + " into the floor spring" + at() +
                           ", deeper than its energy allows (" + length(0.5 * springAllowance) + ")";
                    advice = methodAdvice(f);
                });
            return;
        }
        // One step's travel, and for the report's stage 4 the push of one radius.
        const double travel = dt * std::max(b.v.col(i).norm(), a.v.col(i).norm()) + g * dt * dt +
                              (report && spec.scene == SceneId::ManyBalls ? r : 0.0);
        if (where.depth > travel + tolerance) {
            escape(i, [&](Finding& f) {
                f.kind = FindingKind::Escaped;
                f.amount = where.depth;
                return "ball " + std::to_string(i) + " is " + length(where.depth) + " beyond " + wallName(where, f) +
                       at() + " (left the box)" + escapeCause(b, i, where, f);
            });
            return;
        }
        raise(Kind::Penetration, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
            f.kind = FindingKind::Penetration;
            f.balls = {i};
            f.amount = where.depth;
            what = "ball " + std::to_string(i) + " is " + length(where.depth) + " beyond " + wallName(where, f) + at() +
                   pushCause(f);
            advice = impactAdvice(f);
        });
    }

    std::string pushCause(Finding& f) const
    {
        if (!(report && spec.scene == SceneId::ManyBalls))
            return {};
        f.rule = ReportRule::UnclampedPush;
        return " (Appendix D pushes a colliding ball one radius along the normal without clamping it into the "
               "box; the next frame's wall check puts it back)";
    }

    std::string escapeCause(const State& b, int i, const Beyond& where, Finding& f) const
    {
        if (!(report && where.axis != 1 && (spec.scene == SceneId::Box3d || spec.scene == SceneId::TwoBalls) &&
              b.p(1, i) <= 0.0))
            return {};
        f.rule = ReportRule::OneFacePerStep;
        return ": the report handles one face per step, the floor first (Appendix B), so a ball on the floor "
               "never meets a wall";
    }

    template <typename Describe> void escape(int i, Describe describe)
    {
        if (!escapedBall[static_cast<std::size_t>(i)]) {
            escapedBall[static_cast<std::size_t>(i)] = 1;
            ++fig.escaped;
        }
        raise(Kind::Escaped, Health::Failed, [&](std::string& what, std::string& advice, Finding& f) {
            f.balls = {i};
            what = describe(f);
            advice = spring ? methodAdvice(f) : impactAdvice(f);
        });
    }

    void checkStuck(const State& b, const State& a, int i)
    {
        // Appendix D moves only balls above the floor: one resting on it that is hit keeps
        // its new velocity and never moves again.
        if (!(report && spec.scene == SceneId::ManyBalls) || b.p(1, i) > walls.lo.y() || a.p.col(i) != b.p.col(i) ||
            a.v.col(i).isZero())
            return;
        raise(Kind::Stuck, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
            f.kind = FindingKind::Stuck;
            f.balls = {i};
            f.amount = a.v.col(i).norm();
            f.rule = ReportRule::OnlyAboveFloor;
            what = "ball " + std::to_string(i) + " lies on the floor with speed " + num(f.amount) + at() +
                   " but does not move: Appendix D updates only balls above the floor";
            advice = advise(f, Remedy::ReportPhysical);
        });
    }

    void checkPair(const State& b, const State& a, int i, int j)
    {
        const double contact = 2.0 * r;
        const Eigen::Vector3d d0 = b.p.col(i) - b.p.col(j);
        const Eigen::Vector3d d1 = a.p.col(i) - a.p.col(j);
        const double overlap = contact - d1.norm();
        if (overlap > 1e-9 * r) {
            fig.maxOverlap = std::max(fig.maxOverlap.value_or(0.0), overlap);
            raise(Kind::Overlap, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
                f.kind = FindingKind::Overlap;
                f.balls = {i, j};
                f.amount = overlap;
                what = "balls " + std::to_string(i) + " and " + std::to_string(j) + " overlap by " + length(overlap) +
                       at();
                advice = impactAdvice(f);
            });
            if (report && spec.scene == SceneId::TwoBalls && d0.norm() < contact)
                raise(Kind::RepeatedSwap, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
                    f.kind = FindingKind::RepeatedSwap;
                    f.balls = {i, j};
                    f.rule = ReportRule::SwapWithoutTest;
                    what = "the balls still overlap after a swap" + at() +
                           ": Appendix C swaps velocities with no test that the balls approach, so the swap repeats";
                    advice = advise(f, Remedy::ReportPhysical);
                });
        } else if (d0.norm() >= contact && freeFlight(b, a, i) && freeFlight(b, a, j)) {
            // Both flew freely (equal gravity keeps their relative motion straight), so
            // their distance in the step is that of the straight path from d0 to d1. Where
            // it dips below the contact distance neither saw the other: by more than a
            // tenth of a radius they passed through each other (failed); a shallower dip
            // is a grazing contact the step missed (warning), as a model that finds
            // contacts at the step's end and separates overlaps by moving the centres
            // may leave at speed.
            const double closest = closestApproach(d0, d1);
            const double depth = contact - closest;
            if (depth > 0.1 * r)
                raise(Kind::Tunnel, Health::Failed, [&](std::string& what, std::string& advice, Finding& f) {
                    f.kind = FindingKind::Tunnel;
                    f.balls = {i, j};
                    f.amount = closest;
                    f.bound = contact;
                    what = "balls " + std::to_string(i) + " and " + std::to_string(j) +
                           " passed through each other within one step" + at() + " (closest approach " +
                           length(closest) + ", contact at " + length(contact) + ")";
                    advice = impactAdvice(f);
                });
            else if (depth > 1e-3 * r)
                raise(Kind::Graze, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
                    f.kind = FindingKind::Graze;
                    f.balls = {i, j};
                    f.amount = closest;
                    f.bound = depth;
                    what = "balls " + std::to_string(i) + " and " + std::to_string(j) +
                           " grazed within one step without colliding" + at() + " (closest approach " +
                           length(closest) + ", " + length(depth) + " inside the contact distance)";
                    advice = impactAdvice(f);
                });
        }
        fig.maxOverlap = std::max(fig.maxOverlap.value_or(0.0), 0.0);
    }

    // Only gravity changed the ball's velocity in the step: no wall, no other ball.
    bool freeFlight(const State& b, const State& a, int i) const
    {
        const Eigen::Vector3d change = a.v.col(i) - b.v.col(i) + Eigen::Vector3d(0.0, g * dt, 0.0);
        return change.norm() <= 1e-9 * (b.v.col(i).norm() + g * dt);
    }

    // Momentum of a two-ball contact: away from the walls only gravity changes it.
    void checkMomentum(const State& b, const State& a)
    {
        const double contact = 2.0 * r;
        const bool touching = (b.p.col(0) - b.p.col(1)).norm() < contact || (a.p.col(0) - a.p.col(1)).norm() < contact;
        if (!touching)
            return;
        for (int i = 0; i < 2; ++i) {
            const double travel = dt * std::max(b.v.col(i).norm(), a.v.col(i).norm()) + g * dt * dt;
            for (const State* s : {&b, &a})
                for (int axis = 0; axis < 3; ++axis)
                    if (s->p(axis, i) - walls.lo[axis] <= travel || walls.hi[axis] - s->p(axis, i) <= travel)
                        return; // a wall may have acted in this step: not measurable
        }
        const double scale = b.v.col(0).norm() + b.v.col(1).norm();
        if (!(scale > 0.0))
            return;
        const Eigen::Vector3d gravity(0.0, -2.0 * g * dt, 0.0);
        const double error = ((a.v.col(0) + a.v.col(1)) - (b.v.col(0) + b.v.col(1)) - gravity).norm() / scale;
        fig.maxMomentumError = std::max(fig.maxMomentumError.value_or(0.0), error);
        if (error <= 1e-9)
            return;
        raise(Kind::Momentum, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
            f.kind = FindingKind::Momentum;
            f.balls = {0, 1};
            f.amount = 100.0 * error;
            if (report)
                f.rule = ReportRule::SwapScaledByE;
            what = "momentum changed by " + num(f.amount) + "% of the pair's speeds in a contact" + at() +
                   (report ? " (Appendix C scales both swapped velocities by e)" : "");
            advice = advise(f, report ? Remedy::ReportMomentum : Remedy::SmallerDt);
        });
    }

    void checkPairs(const State& b, const State& a)
    {
        const int n = a.size();
        if (n < 2 || !(r > 0.0))
            return;
        if (n <= 256) {
            for (int i = 0; i < n; ++i)
                for (int j = i + 1; j < n; ++j)
                    checkPair(b, a, i, j);
            if (spec.scene == SceneId::TwoBalls)
                checkMomentum(b, a);
            return;
        }
        // Many balls: overlaps on a grid of cells 2r wide; every 10th step beyond 1e5.
        if (n > sampledAbove && pairChecks++ % 10 != 0)
            return;
        gridOverlaps(b, a);
    }

    void gridOverlaps(const State& b, const State& a)
    {
        // Counting sort into cells at least 2r wide over the balls' bounding cube
        // (broadphase::GridGeometry: two centres closer than 2r lie in the same or adjacent
        // cells), then each ball against the 27 cells around it, each pair once (j > i):
        // O(N + cells) a step, no allocation once the arrays have grown.
        const int n = a.size();
        const double lo = a.p.minCoeff(), hi = a.p.maxCoeff(); // a cube holding every centre
        const broadphase::GridGeometry geo(lo, std::max(hi - lo, 2.0 * r), 2.0 * r,
                                           4 * static_cast<std::size_t>(n) + 64);
        cellOf.resize(static_cast<std::size_t>(n));
        order.resize(static_cast<std::size_t>(n));
        cellStart.assign(geo.cellCount() + 1, 0);
        for (int i = 0; i < n; ++i) {
            const std::uint32_t c = geo.cellOf(a.p(0, i), a.p(1, i), a.p(2, i));
            cellOf[static_cast<std::size_t>(i)] = c;
            ++cellStart[c + 1];
        }
        for (std::size_t c = 1; c < cellStart.size(); ++c)
            cellStart[c] += cellStart[c - 1];
        cursor.assign(cellStart.begin(), cellStart.end() - 1);
        for (int i = 0; i < n; ++i)
            order[cursor[cellOf[static_cast<std::size_t>(i)]]++] = static_cast<std::uint32_t>(i);
        for (int i = 0; i < n; ++i) {
            const int cx = geo.coord(a.p(0, i)), cy = geo.coord(a.p(1, i)), cz = geo.coord(a.p(2, i));
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const std::uint32_t c = geo.cell(cx + dx, cy + dy, cz + dz);
                        for (std::uint32_t k = cellStart[c]; k < cellStart[c + 1]; ++k)
                            if (const int j = static_cast<int>(order[k]); j > i)
                                checkPair(b, a, i, j);
                    }
        }
    }

    Health check(const State& b, const State& a)
    {
        level = Health::Ok;
        t = a.t;
        ++fig.steps;
        const double e = energy(a);
        if (!checkFinite(a, e))
            return level;
        if (escapedBall.size() != static_cast<std::size_t>(a.size()))
            escapedBall.assign(static_cast<std::size_t>(a.size()), 0);
        for (int i = 0; i < a.size(); ++i) {
            checkPlace(b, a, i);
            checkStuck(b, a, i);
        }
        checkEnergy(a, e);
        checkPairs(b, a);
        return level;
    }
};

HealthCheck::HealthCheck(const Simulation& sim, const State& start, int sampledAbove)
    : impl_(std::make_unique<Impl>(sim, start))
{
    impl_->sampledAbove = sampledAbove;
}

HealthCheck::~HealthCheck() = default;
HealthCheck::HealthCheck(HealthCheck&&) noexcept = default;
HealthCheck& HealthCheck::operator=(HealthCheck&&) noexcept = default;

void HealthCheck::keepFindings(const HealthCheck& earlier, double upTo)
{
    Impl& to = *impl_;
    const Impl& from = *earlier.impl_;
    for (std::size_t i = 0; i < from.issues.size(); ++i) {
        const HealthStatus& status = from.issues[i];
        bool& seen = to.seen[static_cast<std::size_t>(from.issueKinds[i])][static_cast<std::size_t>(status.level)];
        if (status.t > upTo || seen)
            continue;
        seen = true;
        to.issues.push_back(status);
        to.issueKinds.push_back(from.issueKinds[i]);
    }
}

Health HealthCheck::check(const State& before, const State& after)
{
    return impl_->check(before, after);
}

const HealthFigures& HealthCheck::figures() const
{
    return impl_->fig;
}

const std::vector<HealthStatus>& HealthCheck::issues() const
{
    return impl_->issues;
}

HealthStatus HealthCheck::worst() const
{
    if (impl_->fig.nonfinite) // what stopped the run
        for (const HealthStatus& s : impl_->issues)
            if (s.finding.kind == FindingKind::NonFinite)
                return s;
    for (Health level : {Health::Failed, Health::Warning})
        for (const HealthStatus& s : impl_->issues)
            if (s.level == level)
                return s;
    return {};
}

} // namespace ab::diagnostics
