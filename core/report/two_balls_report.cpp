// SPDX-License-Identifier: MIT
// Stage 3 as Appendix C codes it: each ball moves with the stage-2 rule, then a pair
// closer than 2r swaps velocities scaled by e (0.95), with one shared counter.
#include "report_models.h"

namespace ab::report {

namespace {

class TwoBalls final : public Simulation {
public:
    TwoBalls(const RunSpec& spec, double dt)
        : Simulation(spec, dt),
          rule_{spec.params.real("g"), spec.params.real("k"), spec.params.real("box"), dt},
          e_(spec.params.real("e")), r_(spec.params.real("r")), maxEvents_(spec.params.integer("max_events"))
    {
    }

    State initialState() const override
    {
        State s;
        s.resize(2);
        s.p.col(0) = spec_.params.vector("p1");
        s.v.col(0) = spec_.params.vector("v1");
        s.p.col(1) = spec_.params.vector("p2");
        s.v.col(1) = spec_.params.vector("v2");
        return s;
    }

    void step(State& s, State& next) override
    {
        next = s;
        next.t = s.t + dt_;
        for (int i = 0; i < 2; ++i) {
            // `propagation` works on a copy: the stored start state keeps its coordinate.
            Eigen::Vector3d p = s.p.col(i);
            Eigen::Vector3d pNew, vNew;
            if (propagateInBox(rule_, p, s.v.col(i), pNew, vNew))
                ++next.count;
            next.p.col(i) = pNew;
            next.v.col(i) = vNew;
        }
        // Contact test on the new centres, Euclidean as the code intends (it has a typo).
        if ((next.p.col(0) - next.p.col(1)).norm() < 2.0 * r_) {
            const Eigen::Vector3d v0 = next.v.col(0);
            next.v.col(0) = e_ * next.v.col(1);
            next.v.col(1) = e_ * v0;
            ++next.count;
        }
        if (next.count > maxEvents_) {
            // Both velocities are zero from the step's start state on; positions go on.
            s.v.setZero();
            next.v.setZero();
            next.halted = s.halted = true;
        }
    }

private:
    BoxStepRule rule_;
    double e_, r_;
    long long maxEvents_;
};

} // namespace

std::unique_ptr<Simulation> makeTwoBalls(const RunSpec& spec, double dt)
{
    return std::make_unique<TwoBalls>(spec, dt);
}

} // namespace ab::report
