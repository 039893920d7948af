// SPDX-License-Identifier: MIT
// Stage 1 as Appendix A codes it: explicit Euler with the position moved by the OLD
// velocity, a bounce step without gravity, and a bounce counter against Zeno behaviour.
#include "report_models.h"

namespace ab::report {

namespace {

class Bounce1d final : public Simulation {
public:
    Bounce1d(const RunSpec& spec, double dt)
        : Simulation(spec, dt), g_(spec.params.real("g")), k_(spec.params.real("k")),
          maxBounces_(spec.params.integer("max_bounces"))
    {
    }

    State initialState() const override
    {
        State s;
        s.resize(1);
        s.p(1, 0) = spec_.params.real("h0");
        s.v(1, 0) = spec_.params.real("v0");
        return s;
    }

    void step(State& s, State& next) override
    {
        next = s;
        next.t = s.t + dt_;
        if (s.halted)
            return; // the listing has stopped: every later state stays zero
        double& p = s.p(1, 0);
        double& v = s.v(1, 0);
        double pNew = 0.0;
        double vNew = 0.0;
        if (p <= 0.0 && v <= 0.0) {
            // Floor hit (eqs 2.13-2.14): the contact state is put on the floor, the
            // velocity reverses with restitution k, and this step has no gravity.
            p = 0.0;
            vNew = -k_ * v;
            pNew = vNew * dt_;
            ++next.count;
        } else {
            // Free fall (eqs 2.15-2.16, 2.16 read as p + v dt): gravity is -g, and the
            // position moves with the velocity the step started with.
            vNew = v - g_ * dt_;
            pNew = p + v * dt_;
        }
        if (next.count > maxBounces_) {
            // Zeno guard: the contact state and every later one are zero.
            p = v = pNew = vNew = 0.0;
            next.halted = s.halted = true;
        }
        next.p(1, 0) = pNew;
        next.v(1, 0) = vNew;
    }

private:
    double g_, k_;
    long long maxBounces_;
};

} // namespace

std::unique_ptr<Simulation> makeBounce1d(const RunSpec& spec, double dt)
{
    return std::make_unique<Bounce1d>(spec, dt);
}

} // namespace ab::report
