// SPDX-License-Identifier: MIT
// The health check's angular momentum (health.h, check 5). A ball touching the floor feels
// forces at its contact point (the impact's impulse, Walton's tangential impulse, Coulomb
// friction while it slides) and gravity along the normal n = +y, so its angular momentum
// about the contact point, per unit mass
//     L = r n x v + q r^2 w                                           (docs/spin.md S13, S4)
// does not change: not at a floor impact, not while it slides or rolls, not in flight. A
// side wall, another ball or drag would change it; a step near any of them is not checked.
#include "health_parts.h"

#include "../physical/physical_simulation.h"

#include <Eigen/Geometry> // cross products

#include <cmath>

namespace ab::diagnostics {

namespace {

constexpr int kAllPairsMost = 256; // more balls: no ball is taken as clear of the others

// The largest distance ball i moves in the step from b to a, with one step of gravity.
double travelOf(const State& b, const State& a, int i, double dt, double g)
{
    return dt * std::max(b.v.col(i).norm(), a.v.col(i).norm()) + g * dt * dt;
}

} // namespace

void HealthCheck::Impl::setUpAngularMomentum()
{
    const physical::World* world = physical::worldOf(sim);
    // The street's faces are not the floor this check is about (health_street.cpp checks it).
    angularChecked = !report && !spring && spinInertia > 0.0 && lever > 0.0 && !(world && world->hasDrag()) &&
                     spec.scene != SceneId::Street;
    sideLo = walls.lo;
    sideHi = walls.hi;
    sideLo.y() = -infinity; // the floor is the contact this check is about
    if (spec.scene == SceneId::ManyBalls)
        sideHi.y() = walls.hi.x(); // the closed box's ceiling, as far from the centre as the walls
}

bool HealthCheck::Impl::clearOfSides(const State& b, const State& a, int i) const
{
    const double travel = travelOf(b, a, i, dt, g) + tolerance;
    for (const State* s : {&b, &a})
        for (int axis = 0; axis < 3; ++axis)
            if (s->p(axis, i) - sideLo[axis] <= travel || sideHi[axis] - s->p(axis, i) <= travel)
                return false;
    return true;
}

void HealthCheck::Impl::markNearBalls(const State& b, const State& a)
{
    const int n = a.size();
    nearBall.assign(static_cast<std::size_t>(n), n > kAllPairsMost ? 1 : 0);
    if (n > kAllPairsMost)
        return;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            // Within reach of each other in either state: a contact may have acted.
            const double reach = 2.0 * r + travelOf(b, a, i, dt, g) + travelOf(b, a, j, dt, g) + tolerance;
            if ((b.p.col(i) - b.p.col(j)).norm() < reach || (a.p.col(i) - a.p.col(j)).norm() < reach)
                nearBall[static_cast<std::size_t>(i)] = nearBall[static_cast<std::size_t>(j)] = 1;
        }
}

void HealthCheck::Impl::checkAngularMomentum(const State& b, const State& a, int i)
{
    if (!b.spins() || !a.spins() || nearBall[static_cast<std::size_t>(i)])
        return;
    const double floor = walls.lo.y();
    if (std::min(b.p(1, i), a.p(1, i)) - floor > travelOf(b, a, i, dt, g) + tolerance)
        return; // not at the floor in this step
    if (!clearOfSides(b, a, i))
        return;
    // The many-balls engine stops a ball slower than its rest speed outright (spin and all):
    // a rule of rest, not a contact.
    if (spec.scene == SceneId::ManyBalls && a.v.col(i).isZero(0.0))
        return;
    const Eigen::Vector3d n = Eigen::Vector3d::UnitY();
    const auto about = [&](const State& s) {
        return Eigen::Vector3d(lever * n.cross(Eigen::Vector3d(s.v.col(i))) + spinInertia * s.w.col(i));
    };
    const double scale = lever * std::max(b.v.col(i).norm(), a.v.col(i).norm()) +
                         spinInertia * std::max(b.w.col(i).norm(), a.w.col(i).norm());
    if (!(scale > 0.0))
        return;
    const double error = (about(a) - about(b)).norm() / scale;
    fig.maxAngularMomentumError = std::max(fig.maxAngularMomentumError.value_or(0.0), error);
    if (error <= 1e-9)
        return;
    raise(Kind::AngularMomentum, Health::Warning, [&](std::string& what, std::string& advice, Finding& f) {
        f.kind = FindingKind::AngularMomentum;
        f.balls = {i};
        f.amount = 100.0 * error;
        what = "angular momentum of ball " + std::to_string(i) + " about its contact point changed by " +
               num(f.amount) + "% at the floor" + at() + " (friction at the contact point cannot change it)";
        advice = advise(f, Remedy::SmallerDt);
    });
}

} // namespace ab::diagnostics
