// SPDX-License-Identifier: MIT
// The probes of the suite's bounce1d and box3d cases (cases.cpp): each compares a run with
// what is known of it in closed form.
#include "case_rows.h"

#include "../physical/spring_contact.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace ab::stability {

namespace {

// bounce1d: free flight against the parabola y = h0 + v0 t - g t^2 / 2 until the first
// contact (reference_error, in the scene's length unit).
class FlightProbe final : public Probe {
public:
    explicit FlightProbe(const RunSpec& spec)
        : h0_(spec.params.real("h0")), v0_(spec.params.real("v0")), g_(spec.params.real("g")),
          landing_(physical::timeToFloor(h0_, v0_, g_))
    {
    }

    void observe(const State& s) override
    {
        if (s.t >= landing_ || s.count > 0)
            return;
        error_ = std::max(error_, std::abs(s.p(1, 0) - (h0_ + v0_ * s.t - 0.5 * g_ * s.t * s.t)));
        checked_ = true;
    }
    std::optional<double> error() const override { return checked_ ? std::optional(error_) : std::nullopt; }
    std::string note() const override
    {
        return checked_ ? "flight error against the parabola " + num(error_) : std::string();
    }

private:
    double h0_, v0_, g_, landing_;
    double error_ = 0.0;
    bool checked_ = false;
};

// bounce1d: contacts against Zeno's sum. An impulse ball dropped with impact speed u
// bounces for 2 k u / g, 2 k^2 u / g, ...: it rests at t_fall + 2 k u / (g (1 - k)).
class ZenoProbe final : public Probe {
public:
    explicit ZenoProbe(const RunSpec& spec)
    {
        const double h0 = spec.params.real("h0"), v0 = spec.params.real("v0"), g = spec.params.real("g");
        const double k = spec.params.real("k");
        const double fall = physical::timeToFloor(h0, v0, g);
        rest_ = fall + 2.0 * k * std::abs(v0 - g * fall) / (g * (1.0 - k));
    }

    void observe(const State& s) override
    {
        if (s.count > contacts_) {
            contacts_ = s.count;
            last_ = s.t;
            if (s.t > rest_)
                ++late_;
        }
        if (s.halted && halt_ < 0.0)
            halt_ = s.t;
        end_ = s.t;
    }
    std::string note() const override
    {
        std::string n = "exact rest (impulse) at t = " + num(rest_) + "; " + std::to_string(contacts_) +
                        " contacts, the last at t = " + num(last_);
        if (halt_ >= 0.0)
            n += "; zeroed by the bounce limit at t = " + num(halt_);
        if (late_ > 0)
            n += "; " + std::to_string(late_) + " contacts after the exact rest (chatter)";
        return n;
    }

private:
    double rest_ = 0.0, last_ = 0.0, halt_ = -1.0, end_ = 0.0;
    long long contacts_ = 0, late_ = 0;
};

// bounce1d: the energy at the end against the start (drift over a long run).
class DriftProbe final : public Probe {
public:
    explicit DriftProbe(const RunSpec& spec) : g_(spec.params.real("g")), e0_(physical::startEnergy(spec))
    {
        if (spec.model == ModelKind::Physical && physical::contactLawOf(spec) != physical::ContactLaw::Impulse)
            floor_ = physical::springFloorFor(spec);
    }

    void observe(const State& s) override
    {
        const double y = s.p(1, 0);
        end_ = 0.5 * s.v(1, 0) * s.v(1, 0) + (floor_ ? floor_->potential(y) : g_ * y);
    }
    std::string note() const override { return "energy at the end " + num(end_ / e0_) + " x the start"; }

private:
    double g_, e0_;
    double end_ = 0.0;
    std::optional<physical::SpringFloor> floor_;
};

// The largest distance a ball's velocity carries it in one step, in box sides: above 1 a
// step can skip a wall entirely, whatever the state at the step's end shows (the report's
// box3d clamps that state back onto the wall it crossed).
class JumpProbe final : public Probe {
public:
    explicit JumpProbe(const RunSpec& spec)
        : box_(spec.params.real("box")), dt_(spec.dt.value_or(defaultDt(spec.scene, spec.model)))
    {
    }

    void observe(const State& s) override
    {
        if (s.size() > 0)
            jump_ = std::max(jump_, s.v.colwise().norm().maxCoeff() * dt_ / box_);
    }
    std::string note() const override { return "largest move in one step " + num(jump_) + " x the box side"; }

private:
    double box_, dt_;
    double jump_ = 0.0;
};

} // namespace

std::unique_ptr<Probe> flightProbe(const Simulation& sim)
{
    return std::make_unique<FlightProbe>(sim.spec());
}

std::unique_ptr<Probe> zenoProbe(const Simulation& sim)
{
    return std::make_unique<ZenoProbe>(sim.spec());
}

std::unique_ptr<Probe> driftProbe(const Simulation& sim)
{
    return std::make_unique<DriftProbe>(sim.spec());
}

std::unique_ptr<Probe> jumpProbe(const Simulation& sim)
{
    return std::make_unique<JumpProbe>(sim.spec());
}

} // namespace ab::stability
