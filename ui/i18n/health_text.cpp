// SPDX-License-Identifier: MIT
#include "health_text.h"

#include "core_text.h"

namespace ab::ui {

using diagnostics::FindingKind;
using diagnostics::Remedy;
using diagnostics::ReportRule;

QString figure(double x)
{
    return QString::number(x, 'g', 3);
}

QString FindingText::full() const
{
    QString text = rule.isEmpty() ? what : QStringLiteral("%1 (%2)").arg(what, rule);
    return remedy.isEmpty() ? text + "." : QStringLiteral("%1. %2").arg(text, remedy);
}

namespace {

// Ball numbers as the charts show them: the first ball is ball 1.
int ballOf(const diagnostics::Finding& f, std::size_t i)
{
    return i < f.balls.size() ? f.balls[i] + 1 : 1;
}

} // namespace

QString HealthText::what(const diagnostics::Finding& f, double t, const SceneInfo& scene)
{
    const QString unit = coreText(scene.lengthUnit),
                  at = QStringLiteral("%1 %2").arg(figure(t), coreText(scene.timeUnit));
    const auto length = [&unit](double x) { return QStringLiteral("%1 %2").arg(figure(x), unit); };
    const QString face = f.wallAxis == 1 ? tr("the floor")
                                         : tr("the %1 = %2 wall").arg(QChar("xyz"[f.wallAxis])).arg(figure(f.wallFace));
    switch (f.kind) {
    case FindingKind::NonFinite:
        return tr("The state became non-finite (an overflow) at t = %1").arg(at);
    case FindingKind::Escaped:
        return tr("Ball %1 is %2 beyond %3 at t = %4: it left the box")
            .arg(ballOf(f, 0))
            .arg(length(f.amount), face, at);
    case FindingKind::SpringEscaped:
        return tr("The ball went %1 into the floor spring at t = %2, twice deeper than its energy allows: it fell "
                  "through the floor")
            .arg(length(f.amount), at);
    case FindingKind::Backstop:
        return tr("The ball reached the floor spring's backstop, %1 deep at t = %2, 1.5 times deeper than its energy "
                  "allows (%3): the step is beyond the method's stability")
            .arg(length(f.amount), at, length(f.bound));
    case FindingKind::SpringPenetration:
        return tr("The ball went %1 into the floor spring at t = %2, deeper than its energy allows (%3)")
            .arg(length(f.amount), at, length(f.bound));
    case FindingKind::Penetration:
        return tr("Ball %1 is %2 beyond %3 at t = %4: the impact was found late")
            .arg(ballOf(f, 0))
            .arg(length(f.amount), face, at);
    case FindingKind::Energy:
        return tr("The energy is %1% above its start at t = %2").arg(figure(f.amount), at);
    case FindingKind::Overlap:
        return tr("Balls %1 and %2 overlap by %3 at t = %4")
            .arg(ballOf(f, 0))
            .arg(ballOf(f, 1))
            .arg(length(f.amount), at);
    case FindingKind::Tunnel:
        return tr("Balls %1 and %2 passed through each other within one step at t = %3 (closest approach %4, contact "
                  "at %5)")
            .arg(ballOf(f, 0))
            .arg(ballOf(f, 1))
            .arg(at, length(f.amount), length(f.bound));
    case FindingKind::Graze:
        return tr("Balls %1 and %2 grazed within one step without colliding at t = %3 (closest approach %4)")
            .arg(ballOf(f, 0))
            .arg(ballOf(f, 1))
            .arg(at, length(f.amount));
    case FindingKind::Momentum:
        return tr("The momentum changed by %1% of the pair's speeds in a contact at t = %2").arg(figure(f.amount), at);
    case FindingKind::RepeatedSwap:
        return tr("The balls still overlap after a swap at t = %1, so the swap repeats").arg(at);
    case FindingKind::Stuck:
        return tr("Ball %1 lies on the floor with speed %2 at t = %3 but does not move")
            .arg(ballOf(f, 0))
            .arg(figure(f.amount), at);
    case FindingKind::AngularMomentum:
        return tr("The angular momentum of ball %1 about its contact point changed by %2% at the floor at t = %3 "
                  "(friction at the contact point cannot change it)")
            .arg(ballOf(f, 0))
            .arg(figure(f.amount), at);
    }
    return {};
}

QString HealthText::rule(ReportRule rule)
{
    switch (rule) {
    case ReportRule::None:
        return {};
    case ReportRule::ExplicitEulerGain:
        return tr("the report's own rule: eq 2.16 moves the position with the old velocity, so explicit Euler adds "
                  "g\u00b2 dt\u00b2/2 a step of flight, Appendix A");
    case ReportRule::FloorRuleGain:
        return tr("the report's own rule: the floor rule v' = -k v - g dt adds a step of gravity to each rebound, "
                  "Appendix B");
    case ReportRule::PushAndWallGravity:
        return tr(
            "the report's own rule: the push of one radius along the normal and the extra gravity at a side wall, "
            "Appendix D");
    case ReportRule::UnclampedPush:
        return tr("the report's own rule: a colliding ball is pushed one radius along the normal without being kept in "
                  "the box, and the next frame's wall check puts it back, Appendix D");
    case ReportRule::OneFacePerStep:
        return tr("the report's own rule: one face a step, the floor first, so a ball on the floor never meets a wall, "
                  "Appendix B");
    case ReportRule::SwapWithoutTest:
        return tr("the report's own rule: the velocities are swapped with no test that the balls approach, Appendix C");
    case ReportRule::SwapScaledByE:
        return tr("the report's own rule: both swapped velocities are scaled by e, Appendix C");
    case ReportRule::OnlyAboveFloor:
        return tr(
            "the report's own rule: only balls above the floor are updated, so a ball on the floor keeps its last "
            "velocity, Appendix D");
    }
    return {};
}

QString HealthText::remedy(const diagnostics::Finding& f, const SceneInfo& scene)
{
    switch (f.remedy) {
    case Remedy::None:
        return {};
    case Remedy::ReportSmallerDt:
        return tr("A smaller step shrinks it; the physical model avoids it.");
    case Remedy::ReportPhysical:
        return tr("The physical model avoids it.");
    case Remedy::ReportMomentum:
        return tr("The physical model conserves momentum.");
    case Remedy::ReportOnePerFrame:
        return tr("The report updates once per frame; the physical model avoids it.");
    case Remedy::ReportStepEnd:
        return tr("The report finds impacts only at the end of a step; a smaller step shrinks it.");
    case Remedy::SpringEuler:
        return tr("Explicit Euler gains energy at every step on a spring (dt \u03c9\u2080 = %1): choose symplectic "
                  "Euler, Verlet, RK4 or implicit Euler.")
            .arg(figure(f.dtOmega));
    case Remedy::SpringLimit:
        return tr("dt \u03c9\u2080 = %1, and %2 is stable only below %3: choose a step below %4 %5, or implicit "
                  "Euler.")
            .arg(figure(f.dtOmega), coreText(integratorTitle(f.integrator)), figure(f.limit), figure(f.dtLimit),
                 coreText(scene.timeUnit));
    case Remedy::EulerAddsEnergy:
        return tr("Explicit Euler adds energy at every step: choose symplectic Euler, Verlet or event-driven.");
    case Remedy::LocatedOrSmallerDt:
        return tr("Choose impacts located inside the step, or a smaller step.");
    case Remedy::SmallerDt:
        return tr("Choose a smaller step.");
    case Remedy::StreetContacts:
        return tr("The street's substeps follow its fastest ball, so a smaller step does not shorten them; this is "
                  "what its contact passes left where balls press on each other, most in a pile several balls "
                  "deep: fewer balls pile less deep.");
    }
    return {};
}

FindingText HealthText::describe(const diagnostics::HealthStatus& status, const SceneInfo& scene)
{
    if (status.level == diagnostics::Health::Ok)
        return {};
    return {what(status.finding, status.t, scene), rule(status.finding.rule), remedy(status.finding, scene)};
}

QString HealthText::halted(const SceneInfo& scene, const ParamValues& params, double t)
{
    const QString at = QStringLiteral("%1 %2").arg(QString::number(t, 'g', 6), coreText(scene.timeUnit));
    const auto limit = [&params](const char* key) {
        return params.indexOf(key) ? QString::number(static_cast<long long>(params.real(key))) : QStringLiteral("?");
    };
    switch (scene.id) {
    case SceneId::Bounce1d:
        return tr("The report's bounce limit put the ball at rest on the floor at t = %1: after more than %2 bounces "
                  "its position and velocity are set to zero (Appendix A)")
            .arg(at, limit("max_bounces"));
    case SceneId::Box3d:
        // Said in the headline: the charts' x and z fall to 0 there, and the ball stands in the
        // box's corner, not where its path ends.
        return tr("The report's bounce limit put the ball at rest at the origin, the box's corner, at t = %1: after "
                  "more than %2 floor and wall contacts its position and velocity are set to zero (Appendix B)")
            .arg(at, limit("max_bounces"));
    case SceneId::TwoBalls:
        return tr("The report's counter stopped both balls at t = %1: after more than %2 contacts and swaps both "
                  "velocities are set to zero, and the positions go on from them (Appendix C)")
            .arg(at, limit("max_events"));
    case SceneId::ManyBalls:
        return tr("The report's bounce limit stopped the motion at t = %1 (Appendix D)").arg(at);
    case SceneId::Street: // the physical model's stage: no report's counter stops it
        return {};
    }
    return {};
}

} // namespace ab::ui
