// SPDX-License-Identifier: MIT
// The health check (health.h): its set-up, the energy of a state, advice, the checks of a
// state's numbers and energy, and the order the checks take in a step. The places, pairs
// and angular momentum are health_place.cpp, health_pairs.cpp and health_spin.cpp.
#include "health_parts.h"

#include "../physical/physical_simulation.h"
#include "../physical/spring_contact.h"
#include "../stability/stability_limit.h"

#include <algorithm>
#include <cmath>
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

HealthCheck::Impl::Impl(const Simulation& s, const State& start)
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
    if (spec.scene == SceneId::Bounce1d && !report && physical::contactLawOf(spec) != physical::ContactLaw::Impulse) {
        spring = physical::springFloorFor(spec);
    }
    // The spring floor's energies stay per unit mass: its allowance below takes them so.
    if (const physical::World* world = physical::worldOf(s); world && !spring) {
        mass = world->mass;
        spinInertia = world->inertia * world->spinRadius * world->spinRadius;
        lever = world->spinRadius;
    } else if ((spec.scene == SceneId::ManyBalls || spec.scene == SceneId::Street) && !report) {
        // The many-balls engine's equal balls, per unit mass: I = q r^2 (docs/spin.md).
        spinInertia = spec.params.real("inertia") * r * r;
        lever = r;
    }
    if (spec.scene == SceneId::Street) {
        streetLayout.emplace(street::Layout::fromParams(spec.params));
        overlapAllowance = 1e-2;
    }
    setUpAngularMomentum();
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

// sum m (|v|^2 / 2 + q r^2 |w|^2 / 2 + potential): with the physical model's masses where
// it has them (two balls of different masses share the energy, not the energy per unit
// mass), else per unit mass (the report's and many-balls' equal masses, the spring
// floor's one ball). A turning ball's rotational energy I |w|^2 / 2 = m q r^2 |w|^2 / 2
// (docs/spin.md) counts: friction trades it with the translation's.
double HealthCheck::Impl::energy(const State& s) const
{
    const bool turning = spinInertia > 0.0 && s.w.cols() == s.size();
    // On the street a ball past the foot has left the run: what it took with it is
    // State::energyLeft (its energy at the step's end it left in), counted once.
    double e = s.energyLeft;
    for (int i = 0; i < s.size(); ++i) {
        if (streetLayout && street::hasLeft(*streetLayout, s.p(0, i)))
            continue;
        const double m = static_cast<std::size_t>(i) < mass.size() ? mass[static_cast<std::size_t>(i)] : 1.0;
        const double spin = turning ? 0.5 * spinInertia * s.w.col(i).squaredNorm() : 0.0;
        e += m * (0.5 * s.v.col(i).squaredNorm() + spin + potential(s.p(1, i)));
    }
    return e;
}

// What to change when the method itself misbehaves (energy, divergence): sets the
// finding's remedy and returns it in the command line's words.
std::string HealthCheck::Impl::methodAdvice(Finding& f) const
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

std::string HealthCheck::Impl::impactAdvice(Finding& f) const
{
    if (report && spec.scene == SceneId::ManyBalls)
        return advise(f, Remedy::ReportOnePerFrame);
    if (report)
        return advise(f, Remedy::ReportStepEnd);
    if (spec.scene == SceneId::Street)
        return advise(f, Remedy::StreetContacts);
    if (spec.impacts == ImpactMode::StepEnd)
        return advise(f, Remedy::LocatedOrSmallerDt);
    return advise(f, Remedy::SmallerDt);
}

// The remedy kept in the finding, returned in the command line's words.
std::string HealthCheck::Impl::advise(Finding& f, Remedy r)
{
    f.remedy = r;
    return remedyText(f);
}

// A state is non-finite when a number in it is, or when its energy overflows (a speed
// beyond 1e154): nothing after it can be shown.
bool HealthCheck::Impl::checkFinite(const State& a, double e)
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

void HealthCheck::Impl::checkEnergy(const State& a, double e)
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

std::string HealthCheck::Impl::energyCause(Finding& f) const
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
    case SceneId::Street: // the street has no report model
        break;
    }
    return {};
}

Health HealthCheck::Impl::check(const State& b, const State& a)
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
        if (streetLayout)
            checkStreet(a, i);
    }
    checkEnergy(a, e);
    checkPairs(b, a);
    if (angularChecked) {
        markNearBalls(b, a);
        for (int i = 0; i < a.size(); ++i)
            checkAngularMomentum(b, a, i);
    }
    return level;
}

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
