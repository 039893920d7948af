// SPDX-License-Identifier: MIT
// The health check's places (health.h, check 2): a centre beyond the floor or a wall, found
// late or escaped, the floor spring's depth, and the report's stage-4 ball stuck on the floor.
#include "health_parts.h"

#include <cmath>

namespace ab::diagnostics {

namespace health_parts {

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
    case SceneId::Street: // its foot is y = 0, the lowest the road goes; its boxes are checkStreet's
        return {{-infinity, 0.0, -infinity}, {infinity, infinity, infinity}};
    }
    throw std::logic_error("scene without walls");
}

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

} // namespace health_parts

std::string HealthCheck::Impl::wallName(const Beyond& b, Finding& f) const
{
    f.wallAxis = b.axis;
    f.wallFace = b.low ? walls.lo[b.axis] : walls.hi[b.axis];
    if (b.axis == 1)
        return "the floor";
    const double face = b.low ? walls.lo[b.axis] : walls.hi[b.axis];
    return std::string("the ") + "xyz"[b.axis] + " = " + num(face) + " wall";
}

void HealthCheck::Impl::checkPlace(const State& b, const State& a, int i)
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
            return "ball " + std::to_string(i) + " is " + length(where.depth) + " beyond " + wallName(where, f) + at() +
                   " (left the box)" + escapeCause(b, i, where, f);
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

std::string HealthCheck::Impl::pushCause(Finding& f) const
{
    if (!(report && spec.scene == SceneId::ManyBalls))
        return {};
    f.rule = ReportRule::UnclampedPush;
    return " (Appendix D pushes a colliding ball one radius along the normal without clamping it into the "
           "box; the next frame's wall check puts it back)";
}

std::string HealthCheck::Impl::escapeCause(const State& b, int i, const Beyond& where, Finding& f) const
{
    if (!(report && where.axis != 1 && (spec.scene == SceneId::Box3d || spec.scene == SceneId::TwoBalls) &&
          b.p(1, i) <= 0.0))
        return {};
    f.rule = ReportRule::OneFacePerStep;
    return ": the report handles one face per step, the floor first (Appendix B), so a ball on the floor "
           "never meets a wall";
}

void HealthCheck::Impl::checkStuck(const State& b, const State& a, int i)
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

} // namespace ab::diagnostics
