// SPDX-License-Identifier: MIT
#include "conservation.h"

#include "../physical/physical_simulation.h"
#include "../street/street_census.h"

#include <cmath>

namespace ab {

namespace {

// The length a ball is measured against: its radius where the scene has one (stages 3
// and 4), else one length unit (stages 1 and 2 treat the ball as a point).
double ballRadius(const RunSpec& spec)
{
    const bool hasRadius =
        spec.scene == SceneId::TwoBalls || spec.scene == SceneId::ManyBalls || spec.scene == SceneId::Street;
    return hasRadius ? spec.params.real("r") : 1.0;
}

bool nonZeroVector(const ParamValues& v, const char* key)
{
    return v.indexOf(key) && !v.vector(key).isZero(0.0);
}

} // namespace

bool roughContacts(const ParamValues& v)
{
    return v.indexOf("mu") && v.indexOf("beta") && v.real("mu") > 0.0 && v.real("beta") > -1.0;
}

bool ballsTurn(const RunSpec& spec)
{
    if (spec.model != ModelKind::Physical)
        return false;
    const ParamValues& v = spec.params;
    if (spec.init && spec.init->spins() && !spec.init->w.isZero(0.0))
        return true;
    switch (spec.scene) {
    case SceneId::Bounce1d: // its ball spins only about the vertical, which the floor never changes
        return v.indexOf("w0") && v.real("w0") != 0.0;
    case SceneId::Box3d:
        return roughContacts(v) || nonZeroVector(v, "w0");
    case SceneId::TwoBalls:
        return roughContacts(v) || nonZeroVector(v, "w1") || nonZeroVector(v, "w2");
    case SceneId::ManyBalls:
        return roughContacts(v) || v.real("spin") > 0.0;
    case SceneId::Street:
        return roughContacts(v);
    }
    return false;
}

ConservationMeter::ConservationMeter(const Simulation& sim)
{
    const RunSpec& spec = sim.spec();
    g_ = spec.params.real("g");
    // Stage 4's box is centred at the origin (Appendix D): its floor is y = -L/2. The
    // street's foot is y = 0 (street_layout.h).
    floor_ = spec.scene == SceneId::ManyBalls ? -spec.params.real("box") / 2.0 : 0.0;
    world_ = physical::worldOf(sim);
    turns_ = ballsTurn(spec);
    oneCounter_ = spec.scene == SceneId::Bounce1d || spec.scene == SceneId::Box3d || spec.scene == SceneId::TwoBalls;
    if (world_) {
        mass_ = world_->mass;
    } else if (spec.model == ModelKind::Physical && spec.scene == SceneId::Bounce1d &&
               physical::contactLawOf(spec) != physical::ContactLaw::Impulse) {
        spring_ = physical::springFloorFor(spec);
        mass_ = {spec.params.real("m")};
    } else if (spec.model == ModelKind::Physical &&
               (spec.scene == SceneId::ManyBalls || spec.scene == SceneId::Street)) {
        spinInertia_ = spec.params.real("inertia") * spec.params.real("r") * spec.params.real("r"); // I/m = q r^2
    }
    if (spec.scene == SceneId::Street)
        footX_ = street::Layout::fromParams(spec.params).xFoot;
    // "Moving": faster than the speed that would lift the ball by h = r/100 against
    // gravity (1/2 v^2 = g h, so v = sqrt(2 g h)), a rise no one sees. It lies below the
    // physical model's rest speed sqrt(2 g h_rest) at the default h_rest = 0.02 r, so a
    // ball the rest rule keeps bouncing counts as moving, and above the report model's
    // one-frame jitter on the floor (about g per frame: 0.0098 against 0.014 at the
    // report's g = 0.00982 and r = 1). Without gravity: r/100 per unit of time.
    const double still = ballRadius(spec) / 100.0;
    movingSpeed_ = g_ > 0.0 ? std::sqrt(2.0 * g_ * still) : still;
    // Appendix D moves only balls whose centre is above -(L/2 - r): one on the floor keeps
    // whatever velocity a collision gave it but never moves again, so it is not counted
    // as moving, whatever its speed (its kinetic energy still counts: the state holds it).
    if (spec.model == ModelKind::Report && spec.scene == SceneId::ManyBalls)
        frozenAtOrBelow_ = floor_ + ballRadius(spec);
}

ConservationSample ConservationMeter::measure(const State& s) const
{
    ConservationSample out = world_ ? measureWorld(s) : footX_ ? measureStreet(s) : measureEqualMasses(s);
    out.impacts = oneCounter_ ? s.count : s.impacts;
    return out;
}

ConservationSample ConservationMeter::measureWorld(const State& s) const
{
    // Few balls (one or two): the World's own energy, then momentum p = sum m v.
    ConservationSample out;
    const physical::KineticPotential e = physical::energyParts(*world_, s);
    out.energy.kinetic = e.kinetic + e.rotational; // a turning ball's energy is kinetic too
    out.energy.rotation = e.rotational;
    out.energy.potential = e.potential;
    const double moving2 = movingSpeed_ * movingSpeed_;
    for (int i = 0; i < s.size(); ++i) {
        out.momentum += mass_[static_cast<std::size_t>(i)] * s.v.col(i);
        out.moving += s.v.col(i).squaredNorm() > moving2 && s.p(1, i) > frozenAtOrBelow_ ? 1 : 0;
    }
    return out;
}

ConservationSample ConservationMeter::measureEqualMasses(const State& s) const
{
    // Every ball has mass m (1 for the report and many-balls, `m` for the spring floor):
    // E_k = m sum |v|^2 / 2, E_p = m g sum (y - floor), p = m sum v. One pass over the
    // structure-of-arrays state, each axis a contiguous row, so a million balls cost one
    // streaming read of p.y and v.
    const double m = mass_.empty() ? 1.0 : mass_.front();
    const double moving2 = movingSpeed_ * movingSpeed_;
    const int n = s.size();
    const double* vx = s.v.row(0).data();
    const double* vy = s.v.row(1).data();
    const double* vz = s.v.row(2).data();
    const double* y = s.p.row(1).data();
    double v2sum = 0.0, heights = 0.0, px = 0.0, py = 0.0, pz = 0.0;
    long long moving = 0;
    for (int i = 0; i < n; ++i) {
        const double v2 = vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i];
        v2sum += v2;
        heights += y[i] - floor_;
        px += vx[i], py += vy[i], pz += vz[i];
        moving += v2 > moving2 && y[i] > frozenAtOrBelow_ ? 1 : 0;
    }
    ConservationSample out;
    out.energy.kinetic = 0.5 * m * v2sum;
    if (spinInertia_ > 0.0 && s.spins()) { // a turning ball's energy I |w|^2 / 2 is kinetic too
        out.energy.rotation = 0.5 * m * spinInertia_ * s.w.squaredNorm();
        out.energy.kinetic += out.energy.rotation;
    }
    out.energy.potential = m * g_ * heights;
    out.momentum = m * Eigen::Vector3d(px, py, pz);
    out.moving = moving;
    if (spring_ && n > 0) {
        // SpringFloor::potential(y) is g y + (spring energy per unit mass) below the floor:
        // the spring's share is what is left after gravity's g y.
        out.energy.spring = m * (spring_->potential(y[0]) - spring_->g * y[0]);
    }
    return out;
}

ConservationSample ConservationMeter::measureStreet(const State& s) const
{
    // Per unit mass, the balls on the street only: E_k = sum (|v|^2 + q r^2 |w|^2) / 2,
    // E_p = g sum y (the foot at y = 0), p = sum v. A ball past the foot has left the run
    // (street::hasLeft): what it took is State::energyLeft, counted once, as it left.
    const double moving2 = movingSpeed_ * movingSpeed_;
    const bool turning = spinInertia_ > 0.0 && s.spins();
    double v2sum = 0.0, w2sum = 0.0, heights = 0.0;
    ConservationSample out;
    for (int i = 0; i < s.size(); ++i) {
        if (s.p(0, i) > *footX_)
            continue;
        const double v2 = s.v.col(i).squaredNorm();
        v2sum += v2;
        w2sum += turning ? s.w.col(i).squaredNorm() : 0.0;
        heights += s.p(1, i) - floor_;
        out.momentum += s.v.col(i);
        out.moving += v2 > moving2 ? 1 : 0;
    }
    out.energy.rotation = 0.5 * spinInertia_ * w2sum;
    out.energy.kinetic = 0.5 * v2sum + out.energy.rotation;
    out.energy.potential = g_ * heights;
    out.energy.left = s.energyLeft;
    return out;
}

ConservationSample measureConservation(const Simulation& sim, const State& s)
{
    return ConservationMeter(sim).measure(s);
}

} // namespace ab
