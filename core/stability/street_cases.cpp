// SPDX-License-Identifier: MIT
// The stability suite's cases for the street (docs/street.md): the physical model's `event`
// flight only (the street has no report model). An elastic smooth ball on a 45 deg street
// keeps its energy to round-off (exact flight, exact face impacts); balls thrown at a kerb or
// down into the road far faster than one step's worth of kerb must not pass; the advert's
// 250,000 balls stay healthy.
#include "case_rows.h"

#include "../diagnostics/conservation.h"
#include "../street/street_census.h"

namespace ab::stability {

namespace {

// Total energy (translation, rotation, potential above the foot) at the last state before a
// ball left at the foot (a ball that leaves takes its energy with it), against the start.
class StreetEnergyProbe final : public Probe {
public:
    explicit StreetEnergyProbe(const Simulation& sim)
        : meter_(sim), layout_(street::Layout::fromParams(sim.spec().params))
    {
    }

    void observe(const State& s) override
    {
        if (!left_)
            left_ = street::census(layout_, s).left > 0;
        if (!left_)
            track_.add(meter_.measure(s).energy.total());
    }
    std::optional<double> error() const override { return track_.error(); }
    std::string note() const override
    {
        return "energy " + num(track_.ratio()) + " x the start " + (left_ ? "when the first ball left" : "at the end");
    }

private:
    ConservationMeter meter_;
    street::Layout layout_;
    EnergyTrack track_;
    bool left_ = false;
};

std::unique_ptr<Probe> streetEnergy(const Simulation& sim)
{
    return std::make_unique<StreetEnergyProbe>(sim);
}

CaseRow streetRow(const std::string& name, const std::string& setting, std::vector<std::string> assignments,
                  long long steps)
{
    CaseRow r = reportRow(name, setting, SceneId::Street, std::move(assignments), std::nullopt, steps);
    r.model = ModelKind::Physical;
    r.integrator = Integrator::Event;
    r.probe = streetEnergy;
    return r;
}

State thrown(const Eigen::Vector3d& p, const Eigen::Vector3d& v)
{
    State s;
    s.resize(1);
    s.w.setZero(3, 1);
    s.p.col(0) = p;
    s.v.col(0) = v;
    return s;
}

} // namespace

std::vector<CaseRow> streetElastic()
{
    // mu = 0, e = 1 (beta = 1): every impact with the road, the crossings, the kerbs and the
    // houses is a mirror, and the flight between them exact: the energy stays to round-off
    // until the ball leaves at the foot.
    return {streetRow("street-elastic", "street at 45 deg, one ball, mu = 0, e = beta = 1, 1200 steps",
                      {"n=1", "slope=45", "mu=0", "e=1", "beta=1", "rest_height=0", "speed=3", "block_length=60"},
                      1200)};
}

std::vector<CaseRow> streetKerbCrossing()
{
    // At 2000 m/s a ball crosses the 3 m sidewalk 11 times in one 1/60 s step, and at
    // 5000 m/s down it would pass 80 m of road in a step: the faces' roots find every impact.
    std::vector<CaseRow> rows;
    CaseRow kerb =
        streetRow("street-kerb-crossing", "one ball across the street at 2000 m/s, e = 0.9", {"n=1", "e=0.9"}, 300);
    kerb.init = thrown({20.0, 70.0, 0.0}, {0.0, 0.0, 2000.0});
    rows.push_back(kerb);
    CaseRow road =
        streetRow("street-kerb-crossing", "one ball down into the road at 5000 m/s, e = 0.9", {"n=1", "e=0.9"}, 300);
    road.init = thrown({30.0, 80.0, 2.0}, {100.0, -5000.0, 0.0});
    rows.push_back(road);
    return rows;
}

std::vector<CaseRow> streetAdvert()
{
    return {streetRow("street-advert", "250,000 balls from the hopper, mu = 0.6, beta = 0.4, e = 0.85, 10 steps",
                      {"n=250000", "mu=0.6", "beta=0.4", "e=0.85", "cars=12"}, 10)};
}

} // namespace ab::stability
