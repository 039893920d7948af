// SPDX-License-Identifier: MIT
// Time stepping with euler, symplectic-euler, verlet or rk4, and impacts found in one of
// two ways:
//  1. located: before a step is taken, the first contact inside it is solved on the
//     integrator's own step map (a polynomial root without drag, a bracketed root found
//     by re-integrating with drag); the step is split there, the impact resolved, and
//     the rest of the step taken the same way. Impacts then cost the integrator none of
//     its order.
//  2. step-end: the step is taken whole, and a ball found inside a wall or another ball
//     at its end is put back on the contact and bounced, as the report does. The impact
//     is late by up to one step, so the error is first order whatever the integrator.
// A ball resting on the floor moves under the contact constraint (world.h); on a rough
// floor friction spins a sliding ball up until it rolls (rolling.h): located steps end at
// that moment and put the ball on the rolling state there, step-end steps at the step's
// end. Spin follows the same integrator as the velocity; in flight it is constant.
// Located steps also end where the flight law itself has a kink (the drag -c |v| v of a
// ball thrown straight up, at its apex), so no step straddles it: across the kink the
// velocity's third derivative jumps, which would cost rk4 an order.
#include "impacts.h"
#include "integrators.h"
#include "physical_simulation.h"
#include "rolling.h"
#include "roots.h"

#include <algorithm>
#include <cmath>

namespace ab::physical {

namespace {

// Past this many impacts in one step (balls resting on each other, which needs a contact
// model this one does not have) the rest of the step uses step-end rules, so a step
// always ends.
constexpr int maxImpactsPerStep = 1000;
// A located rebound shorter than this fraction of a step is cut (rest rule): its height
// g (1e-9 dt)^2 / 8 is far below the error of any integrator here.
constexpr double locatedMinFlight = 1e-9;

class SteppedSimulation final : public PhysicalSimulation {
public:
    SteppedSimulation(const RunSpec& spec, double dt, World world, State initial)
        : PhysicalSimulation(spec, dt, std::move(world), std::move(initial)), integrator_(spec.integrator),
          located_(spec.impacts == ImpactMode::Located), alpha_(positionCurvature(spec.integrator)),
          support_(static_cast<std::size_t>(world_.balls()), nullptr)
    {
    }

    void step(State& s, State& next) override
    {
        next = s;
        withSpin(next);
        next.t = s.t + dt_;
        if (located_)
            stepLocated(next, s.t);
        else
            stepThenSettle(next, s.t + dt_, dt_, dt_);
    }

private:
    enum class Kind { None, Wall, Pair, Roll, Apex };
    struct Candidate {
        double h = never;
        Kind kind = Kind::None;
        int i = 0;
        int j = 0; // other ball or wall index
    };

    Kinematics ball(const State& s, int i) const { return {s.p.col(i), s.v.col(i), s.w.col(i)}; }
    const Wall* support(int i) const { return support_[static_cast<std::size_t>(i)]; }

    void classify(const State& s)
    {
        for (int i = 0; i < s.size(); ++i)
            support_[static_cast<std::size_t>(i)] = restingOn(world_, s.p.col(i), s.v.col(i));
    }

    Kinematics advanceBall(const State& s, int i, double h) const
    {
        return advance(integrator_, world_, i, support(i), ball(s, i), h);
    }

    // Moves every ball h on. Friction never reverses a slip: a ball that starts to roll
    // within h (located steps end there; step-end steps do not) rolls afterwards.
    void advanceAll(State& s, double h) const
    {
        for (int i = 0; i < s.size(); ++i) {
            const bool rollsBy = rollTimeOf(s, i) <= h;
            const Kinematics k = advanceBall(s, i, h);
            s.p.col(i) = k.p;
            s.v.col(i) = k.v;
            s.w.col(i) = k.w;
            if (rollsBy)
                rollOn(s, i);
        }
    }

    double rollTimeOf(const State& s, int i) const { return rollTime(world_, i, s.v.col(i), s.w.col(i), support(i)); }

    // Puts a sliding ball on the rolling state friction leads it to (rolling.h, S4).
    void rollOn(State& s, int i) const
    {
        Eigen::Vector3d v = s.v.col(i), w = s.w.col(i);
        roll(world_, *support(i), v, w);
        s.v.col(i) = v;
        s.w.col(i) = w;
    }

    void stepLocated(State& s, double t0)
    {
        double done = 0.0;
        for (int impacts = 0;; ++impacts) {
            const double left = dt_ - done;
            if (!(left > 0.0))
                break;
            classify(s);
            if (impacts == maxImpactsPerStep) {
                stepThenSettle(s, t0 + dt_, left, dt_);
                return;
            }
            const Candidate c = earliest(s, left);
            if (c.kind == Kind::None || c.h > left) {
                advanceAll(s, left);
                break;
            }
            advanceAll(s, c.h);
            done += c.h;
            const Vec3Array before = s.v, spinBefore = s.w;
            apply(s, c, t0 + done);
            if (c.h == 0.0 && s.v == before && s.w == spinBefore) {
                // A contact pressed shut that no impulse opens: a ball resting on another,
                // which needs a contact model this one does not have. Step-end rules finish
                // the step instead of finding the same contact again and again.
                stepThenSettle(s, t0 + dt_, dt_ - done, dt_);
                return;
            }
        }
        settle(s, t0 + dt_, locatedMinFlight * dt_); // round-off only: nothing is inside here
    }

    // `stepFlight`: rebounds shorter than this are cut (the rest rule), besides those too
    // short for double precision (impacts.h).
    void stepThenSettle(State& s, double tEnd, double h, double stepFlight)
    {
        classify(s);
        advanceAll(s, h);
        settle(s, tEnd, stepFlight);
    }

    // --- finding the first contact inside a step of length `left` ---

    Candidate earliest(const State& s, double left) const
    {
        Candidate best;
        auto consider = [&](double h, Kind kind, int i, int j) {
            if (h < best.h)
                best = {h, kind, i, j};
        };
        for (int i = 0; i < s.size(); ++i) {
            for (std::size_t w = 0; w < world_.walls.size(); ++w)
                if (&world_.walls[w] != support(i))
                    consider(wallCrossing(s, i, world_.walls[w], left), Kind::Wall, i, static_cast<int>(w));
            consider(rollTimeOf(s, i), Kind::Roll, i, 0);
            consider(apexTime(s, i, left), Kind::Apex, i, 0);
            for (int j = i + 1; j < s.size(); ++j)
                consider(pairCrossing(s, i, j, left), Kind::Pair, i, j);
        }
        return best;
    }

    double wallCrossing(const State& s, int i, const Wall& wall, double left) const
    {
        const Kinematics k = ball(s, i);
        if (!world_.hasDrag()) {
            // Constant acceleration: the step map is p + v h + alpha a h^2 (integrators.h).
            const Eigen::Vector3d a = rates(world_, i, k.v, k.w, support(i)).a;
            return firstInwardCrossing({wall.gap(k.p), wall.normalSpeed(k.v), alpha_ * wall.side * a[wall.axis], 0, 0},
                                       left);
        }
        const double g0 = wall.gap(k.p);
        if (g0 < 0.0)
            return wall.normalSpeed(k.v) < 0.0 ? 0.0 : never;
        const auto gapAfter = [&](double h) { return wall.gap(advanceBall(s, i, h).p); };
        const double gEnd = gapAfter(left);
        return gEnd < 0.0 ? bracketedRoot(gapAfter, 0.0, g0, left, gEnd) : never;
    }

    // rollTime (rolling.h): where the slip's rate of change, taken as it is at the start,
    // brings it to zero. Exact without drag; with drag first order, as it changes the
    // slip's rate while it slides. (Solving on the step map instead fails: past the
    // moment the friction force flips, and velocity Verlet's average of the two cancels.)

    // When a ball moving straight up under quadratic drag stops rising: there |v| v is
    // not twice differentiable. (With any sideways motion |v| never reaches zero.)
    double apexTime(const State& s, int i, double left) const
    {
        const Eigen::Vector3d v = s.v.col(i);
        if (!(world_.dragQuadratic > 0.0) || support(i) || v.x() != 0.0 || v.z() != 0.0 || !(v.y() > 0.0))
            return never;
        const auto rising = [&](double h) { return advanceBall(s, i, h).v.y(); };
        const double end = rising(left);
        return end < 0.0 ? bracketedRoot(rising, 0.0, v.y(), left, end) : never;
    }

    double pairCrossing(const State& s, int i, int j, double left) const
    {
        const double reach = 2.0 * world_.radius;
        const Eigen::Vector3d d0 = s.p.col(i) - s.p.col(j);
        const Eigen::Vector3d d1 = s.v.col(i) - s.v.col(j);
        if (!world_.hasDrag()) {
            // Same gravity on both: their separation moves on the polynomial
            // d(h) = d0 + d1 h + d2 h^2 (d2 = 0 unless one of them rests), and
            // |d(h)|^2 - (2r)^2 is a polynomial of degree 2 (or 4).
            const Eigen::Vector3d d2 = alpha_ * (rates(world_, i, s.v.col(i), s.w.col(i), support(i)).a -
                                                 rates(world_, j, s.v.col(j), s.w.col(j), support(j)).a);
            return firstInwardCrossing({d0.squaredNorm() - reach * reach, 2.0 * d0.dot(d1),
                                        d1.squaredNorm() + 2.0 * d0.dot(d2), 2.0 * d1.dot(d2), d2.squaredNorm()},
                                       left);
        }
        const double g0 = d0.norm() - reach;
        if (g0 < 0.0)
            return d0.dot(d1) < 0.0 ? 0.0 : never;
        const auto gapAfter = [&](double h) {
            return (advanceBall(s, i, h).p - advanceBall(s, j, h).p).norm() - reach;
        };
        // A sign change at the step's end, or at the closest approach of the straight-line
        // relative motion (two balls can meet and part again inside one step).
        double end = left;
        if (d1.squaredNorm() > 0.0)
            end = std::clamp(-d0.dot(d1) / d1.squaredNorm(), 0.0, left);
        double gEnd = end > 0.0 ? gapAfter(end) : g0;
        if (!(gEnd < 0.0)) {
            end = left;
            gEnd = gapAfter(left);
        }
        return gEnd < 0.0 ? bracketedRoot(gapAfter, 0.0, g0, end, gEnd) : never;
    }

    // --- resolving ---

    void apply(State& s, const Candidate& c, double t)
    {
        switch (c.kind) {
        case Kind::Wall: {
            const Wall& wall = world_.walls[static_cast<std::size_t>(c.j)];
            s.p(wall.axis, c.i) = wall.position; // on the contact exactly
            hitWall(s, c.i, c.j, t, locatedMinFlight * dt_);
            return;
        }
        case Kind::Pair:
            hitPair(s, c.i, c.j, t);
            return;
        case Kind::Roll:
            rollOn(s, c.i);
            return;
        case Kind::Apex:
            s.v(1, c.i) = 0.0; // the root leaves it within round-off of zero
            return;
        case Kind::None:
            break;
        }
        throw std::logic_error("impact without a rule");
    }

    void hitWall(State& s, int i, int w, double t, double stepFlight)
    {
        Eigen::Vector3d v = s.v.col(i), spin = s.w.col(i);
        const Wall& wall = world_.walls[static_cast<std::size_t>(w)];
        const double speed =
            resolveWallImpact(world_, wall, v, spin, std::max(stepFlight, shortestFlight(world_, wall, t)));
        s.v.col(i) = v;
        s.w.col(i) = spin;
        if (speed > 0.0)
            count(s, {t, i, -1, w, speed});
    }

    void hitPair(State& s, int i, int j, double t)
    {
        Eigen::Vector3d pi = s.p.col(i), pj = s.p.col(j), vi = s.v.col(i), vj = s.v.col(j);
        Eigen::Vector3d wi = s.w.col(i), wj = s.w.col(j);
        separatePair(world_, i, j, pi, pj, true);
        const double speed = resolvePairImpact(world_, i, j, pi, pj, vi, vj, {wi, wj});
        s.p.col(i) = pi;
        s.p.col(j) = pj;
        s.v.col(i) = vi;
        s.v.col(j) = vj;
        s.w.col(i) = wi;
        s.w.col(j) = wj;
        if (speed > 0.0) {
            ++s.bounces[static_cast<std::size_t>(j)];
            count(s, {t, i, j, -1, speed});
        }
    }

    void count(State& s, const Impact& impact)
    {
        ++s.count;
        ++s.bounces[static_cast<std::size_t>(impact.ball)];
        logImpact(impact);
    }

    // Step-end rules: every centre found inside a wall or another ball is put back on the
    // contact and, if it was approaching, bounced. Separating a pair can push a ball into
    // a wall and the reverse, so the passes repeat until nothing overlaps (a ball wedged between a wall and the
    // other converges geometrically; a jam that cannot be resolved stops after 64 passes).
    void settle(State& s, double t, double stepFlight)
    {
        for (int pass = 0; pass < 64; ++pass) {
            bool moved = false;
            for (int i = 0; i < s.size(); ++i) {
                for (int j = i + 1; j < s.size(); ++j) {
                    if ((s.p.col(i) - s.p.col(j)).norm() < 2.0 * world_.radius) {
                        hitPair(s, i, j, t);
                        moved = true;
                    }
                }
            }
            for (int i = 0; i < s.size(); ++i) {
                for (std::size_t w = 0; w < world_.walls.size(); ++w) {
                    if (world_.walls[w].gap(s.p.col(i)) < 0.0) {
                        putBackOnWall(s, i, world_.walls[w]);
                        hitWall(s, i, static_cast<int>(w), t, stepFlight);
                        moved = true;
                    }
                }
            }
            if (!moved)
                return;
        }
    }

    // Moves a centre found `depth` inside a wall back onto it. Gravity pressing into the
    // wall would have given the ball 2 g depth of squared speed on the way in, so that much
    // is taken back: lifting it out must not create energy (for the floor; the side walls
    // have no potential), or the step-end rule would pump a ball that should settle.
    void putBackOnWall(State& s, int i, const Wall& wall) const
    {
        const double depth = -wall.gap(s.p.col(i));
        s.p(wall.axis, i) = wall.position;
        const double approach = -wall.normalSpeed(s.v.col(i));
        const double pressing = -wall.side * world_.gravity()[wall.axis];
        if (approach > 0.0 && pressing > 0.0)
            s.v(wall.axis, i) = -wall.side * std::sqrt(std::max(0.0, approach * approach - 2.0 * pressing * depth));
    }

    Integrator integrator_;
    bool located_;
    double alpha_;
    std::vector<const Wall*> support_;
};

} // namespace

std::unique_ptr<Simulation> makeSteppedSimulation(const RunSpec& spec, double dt, World world, State initial)
{
    return std::make_unique<SteppedSimulation>(spec, dt, std::move(world), std::move(initial));
}

} // namespace ab::physical
