// SPDX-License-Identifier: MIT
// Stage 4 as Appendix D codes it: one update per frame, each ball in index order moves,
// checks the walls, then collides with the first other ball within c r, repeatedly.
// The search for that ball is the report's scan of every other ball (`all-pairs`) or a
// linked-cell grid (`grid`) that finds the same lowest index: the frame's result does
// not depend on the broadphase.
#include "report_models.h"

#include "../interrupt.h"

#include "../broadphase/cell_list.h"
#include "../random.h"

#include <algorithm>
#include <cmath>

namespace ab::report {

namespace {

// three.js's Vector3.normalize(): divides by the length, and leaves a zero vector zero.
Eigen::Vector3d normalizeOrZero(const Eigen::Vector3d& v)
{
    const double len = v.norm();
    return len > 0.0 ? Eigen::Vector3d(v / len) : v;
}

} // namespace

Eigen::Vector3d fixedTangent(const Eigen::Vector3d& n)
{
    // Eqs 2.24-2.25: t = (0.3, 0.3, tz), tz = -(0.3 n.x + 0.3 n.y) / n.z, normalised.
    const Eigen::Vector3d literal(0.3, 0.3, (-(n.x() * 0.3) - (n.y() * 0.3)) / n.z());
    const double length = literal.norm();
    if (std::isfinite(length) && length > 0.0)
        return literal / length;
    // n.z = 0 (or so small that tz overflows): the same direction times n.z,
    // (0.3 n.z, 0.3 n.z, -0.3 (n.x + n.y)), which stays finite and tends to (0, 0, 1).
    const Eigen::Vector3d scaled(0.3 * n.z(), 0.3 * n.z(), -0.3 * (n.x() + n.y()));
    if (scaled.norm() > 0.0)
        return scaled.normalized();
    // n.x + n.y = 0 as well: eq 2.24 holds for every tz; take tz = 0.
    return Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
}

void resolveReportPair(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, Eigen::Vector3d& v1, Eigen::Vector3d& v2,
                       double e)
{
    // Speeds are kept, swapped and damped: ball 1 leaves with e |v2|, ball 2 with e |v1|.
    const double l1 = e * v1.norm();
    const double l2 = e * v2.norm();
    const Eigen::Vector3d u1 = normalizeOrZero(v1);
    const Eigen::Vector3d u2 = normalizeOrZero(v2);
    const Eigen::Vector3d n = normalizeOrZero(p1 - p2); // eq 2.23
    const Eigen::Vector3d t = fixedTangent(n);          // eqs 2.24-2.25
    // Projections of the normalised velocities on n and t.
    const Eigen::Vector3d u1n = u1.dot(n) * n;
    const Eigen::Vector3d u1t = u1.dot(t) * t; // kept (eq 2.26)
    const Eigen::Vector3d u2n = u2.dot(n) * n;
    const Eigen::Vector3d u2t = u2.dot(t) * t;                            // kept (eq 2.27)
    const Eigen::Vector3d u2nAfter = (e * (u1n - u2n) + u1n + u2n) / 2.0; // eq 2.30 with its /2 (as 2.6)
    const Eigen::Vector3d u1nAfter = u1n + u2n - u2nAfter;                // eq 2.31 as intended
    // three.js's setLength: normalise (zero stays zero), then scale.
    v1 = normalizeOrZero(u1nAfter + u1t) * l2;
    v2 = normalizeOrZero(u2nAfter + u2t) * l1;
}

namespace {

class ManyBalls final : public Simulation {
public:
    explicit ManyBalls(const RunSpec& spec)
        : Simulation(spec, 1.0), n_(static_cast<int>(spec.params.integer("n"))), r_(spec.params.real("r")),
          limit_(spec.params.real("box") / 2.0 - r_), g_(spec.params.real("g")),
          primary_(spec.params.real("primary_loss")), secondary_(spec.params.real("secondary_loss")),
          maxBounces_(spec.params.integer("max_bounces")), contact_(spec.params.real("contact_factor") * r_),
          broadphase_(spec.broadphase)
    {
        if (broadphase_ == Broadphase::Grid) {
            // Centres live within +-limit; balls pushed or flying beyond it fall in the
            // border cells. Up to 8 cells a ball keeps a sparse box from costing memory.
            const double side = std::max(2.0 * limit_, contact_);
            cells_ = broadphase::GridGeometry(-side / 2.0, side, contact_,
                                              std::max<std::size_t>(8 * static_cast<std::size_t>(n_), 64));
        }
    }

    State initialState() const override
    {
        // Appendix D: positions uniform in [-9, 9]^3, each velocity component uniform in
        // [0, 1) with a random sign, drawn per ball in that order.
        State s;
        s.resize(n_);
        SplitMix64 rng(static_cast<std::uint64_t>(spec_.params.integer("seed")));
        for (int i = 0; i < n_; ++i) {
            for (int a = 0; a < 3; ++a)
                s.p(a, i) = 18.0 * rng.uniform() - 9.0;
            for (int a = 0; a < 3; ++a)
                s.v(a, i) = rng.uniform();
            for (int a = 0; a < 3; ++a)
                if (rng.uniform() < 0.5)
                    s.v(a, i) = -s.v(a, i);
        }
        return s;
    }

    void step(State& s, State& next) override
    {
        next = s;
        next.t = s.t + 1.0;
        State& b = next;
        if (broadphase_ == Broadphase::Grid)
            grid_.build(cells_, b.p);
        int repeats = 0; // shared by all balls of one frame, as `counter` in update_pos
        for (int i = 0; i < n_; ++i) {
            // One frame of millions of balls in contact is quadratic (the report's ball
            // check): an interrupt is honoured within the frame.
            if ((i & 15) == 0)
                throwIfInterruptRequested();
            if (b.bounces[i] > maxBounces_ && b.p(1, i) < -limit_ + r_) {
                b.p(1, i) = -limit_; // rest on the floor
                b.v.col(i).setZero();
            }
            if (b.p(1, i) > -limit_) {
                b.v(1, i) -= g_; // one frame of gravity, then move by the velocity
                b.p.col(i) += b.v.col(i);
                wallCheck(b, i);
                while (ballCheck(b, i) && repeats < 100)
                    ++repeats;
            }
            if (broadphase_ == Broadphase::Grid)
                grid_.move(i, b.p(0, i), b.p(1, i), b.p(2, i));
        }
    }

private:
    void clampAxis(State& b, int axis, int i) const { b.p(axis, i) = std::clamp(b.p(axis, i), -limit_, limit_); }

    void wallCheck(State& b, int i) const
    {
        double& x = b.p(0, i);
        double& y = b.p(1, i);
        double& z = b.p(2, i);
        if (y <= -limit_) {
            // Floor: reverse y with the primary loss, damp x and z with the secondary.
            b.v(1, i) *= -primary_;
            b.v(0, i) *= secondary_;
            b.v(2, i) *= secondary_;
            y = -limit_;
            clampAxis(b, 0, i);
            clampAxis(b, 2, i);
        } else if (x < -limit_ || x > limit_) {
            b.v(1, i) *= secondary_;
            b.v(0, i) *= -primary_;
            b.v(2, i) *= secondary_;
            b.v(1, i) -= g_;
            x = x < -limit_ ? -limit_ : limit_;
            clampAxis(b, 2, i);
        } else if (z < -limit_ || z > limit_) {
            b.v(1, i) *= secondary_;
            b.v(0, i) *= secondary_;
            b.v(2, i) *= -primary_;
            b.v(1, i) -= g_;
            z = z < -limit_ ? -limit_ : limit_;
        } else {
            return;
        }
        ++b.bounces[i];
        ++b.impacts;
    }

    // The lowest index j != i within c r of centre q, or -1.
    int firstInContact(const State& b, int i, const Eigen::Vector3d& q) const
    {
        if (broadphase_ == Broadphase::Grid)
            return grid_.lowestWithin(i, q, contact_, b.p);
        for (int j = 0; j < n_; ++j)
            if (j != i && broadphase::withinReach(q, b.p, j, contact_))
                return j;
        return -1;
    }

    // The first other ball (lowest index) closer than c r is resolved; true if one was.
    bool ballCheck(State& b, int i) const
    {
        const Eigen::Vector3d pi = b.p.col(i);
        const int j = firstInContact(b, i, pi);
        if (j < 0)
            return false;
        Eigen::Vector3d vi = b.v.col(i);
        Eigen::Vector3d vj = b.v.col(j);
        resolveReportPair(pi, b.p.col(j), vi, vj, secondary_);
        b.v.col(i) = vi;
        b.v.col(j) = vj;
        ++b.impacts; // one impact per pair resolved
        const int cap = static_cast<int>(maxBounces_ - 3);
        b.bounces[i] = std::min(b.bounces[i], cap);
        b.bounces[j] = std::min(b.bounces[j], cap);
        // Ball 1 is pushed one radius (the code's 1 unit) along the normal, unclamped.
        b.p.col(i) += r_ * normalizeOrZero(pi - b.p.col(j));
        return true;
    }

    int n_;
    double r_, limit_, g_, primary_, secondary_;
    long long maxBounces_;
    double contact_;
    Broadphase broadphase_;
    broadphase::GridGeometry cells_;
    broadphase::CellList grid_;
};

} // namespace

std::unique_ptr<Simulation> makeManyBalls(const RunSpec& spec)
{
    return std::make_unique<ManyBalls>(spec);
}

} // namespace ab::report
