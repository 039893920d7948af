// SPDX-License-Identifier: MIT
// Stage 2 as Appendix B codes it, with the position moved by the NEW velocity as eqs
// 2.18-2.22 and `propagation` (Appendix C) have it.
#include "report_models.h"

namespace ab::report {

bool propagateInBox(const BoxStepRule& r, Eigen::Vector3d& p, const Eigen::Vector3d& v, Eigen::Vector3d& pNew,
                    Eigen::Vector3d& vNew)
{
    // Free flight of the axes a branch does not bounce: semi-implicit Euler,
    // v' = v + g dt (eq 2.19), p' = p + v' dt (eqs 2.20, 2.22); x and z keep v (eq 2.21).
    vNew = Eigen::Vector3d(v.x(), v.y() - r.g * r.dt, v.z());
    auto bounce = [&](int axis, double face) {
        // Wall on `axis` (eqs 2.17-2.18): start from the face, reverse with k.
        p[axis] = face;
        vNew[axis] = -r.k * v[axis];
    };
    bool contact = true;
    if (p.y() <= 0.0) {
        // Floor: restitution plus one step of gravity, v' = -k v - g dt, and the
        // position restarts from the floor, p' = v' dt (Appendix B).
        bounce(1, 0.0);
        vNew.y() = -r.k * v.y() - r.g * r.dt;
    } else if (p.x() <= 0.0) {
        bounce(0, 0.0);
    } else if (p.x() >= r.box) {
        bounce(0, r.box);
    } else if (p.z() <= 0.0) {
        bounce(2, 0.0);
    } else if (p.z() >= r.box) {
        bounce(2, r.box);
    } else {
        contact = false;
    }
    pNew = p + vNew * r.dt;
    return contact;
}

namespace {

class Box3d final : public Simulation {
public:
    Box3d(const RunSpec& spec, double dt)
        : Simulation(spec, dt),
          rule_{spec.params.real("g"), spec.params.real("k"), spec.params.real("box"), dt},
          maxBounces_(spec.params.integer("max_bounces"))
    {
    }

    State initialState() const override
    {
        State s;
        s.resize(1);
        s.p.col(0) = spec_.params.vector("p0");
        s.v.col(0) = spec_.params.vector("v0");
        return s;
    }

    void step(State& s, State& next) override
    {
        next = s;
        next.t = s.t + dt_;
        if (s.halted)
            return; // zero from the limit on; the listing's further zero steps change nothing
        Eigen::Vector3d p = s.p.col(0);
        Eigen::Vector3d pNew, vNew;
        if (propagateInBox(rule_, p, s.v.col(0), pNew, vNew))
            ++next.count;
        // Appendix B writes the clamp into the stored contact state (p_matrix(:, index_old)).
        s.p.col(0) = p;
        next.p.col(0) = pNew;
        next.v.col(0) = vNew;
        if (next.count > maxBounces_) {
            // The report's bounce limit: this step's start state and every later one are zero.
            s.p.setZero();
            s.v.setZero();
            next.p.setZero();
            next.v.setZero();
            next.halted = s.halted = true;
        }
    }

private:
    BoxStepRule rule_;
    long long maxBounces_;
};

} // namespace

std::unique_ptr<Simulation> makeBox3d(const RunSpec& spec, double dt)
{
    return std::make_unique<Box3d>(spec, dt);
}

} // namespace ab::report
