// SPDX-License-Identifier: MIT
// The stability suite's cases for rough balls (docs/spin.md): the physical model only (the
// report's balls do not turn). A superball (k = e = 1, beta = 1, friction that sticks)
// keeps its energy exactly at every impact, so over a million steps any drift is the
// method's; mu = 10 makes every contact stick; a fast ball with back-spin against a wall
// turns its spin into motion along the wall at each impact.
#include "case_rows.h"

#include "../physical/physical_simulation.h"

namespace ab::stability {

namespace {

// The energy at the end against the start, rotation counted: the World's energy (stages
// 1-3, with the balls' masses), or per unit mass for many-balls' equal balls,
// sum |v|^2/2 + q r^2 |w|^2/2 + g (y - floor).
class SpinDriftProbe final : public Probe {
public:
    explicit SpinDriftProbe(const Simulation& sim) : world_(physical::worldOf(sim))
    {
        const ParamValues& p = sim.spec().params;
        if (!world_) {
            g_ = p.real("g");
            q_ = p.real("inertia");
            r_ = p.real("r");
            floor_ = -p.real("box") / 2.0 + r_;
        }
    }

    void observe(const State& s) override { track_.add(energy(s)); }
    std::optional<double> error() const override { return track_.error(); }
    std::string note() const override
    {
        return "energy at the end (rotation counted) " + num(track_.ratio()) + " x the start";
    }

private:
    double energy(const State& s) const
    {
        if (world_)
            return physical::energy(*world_, s);
        double e = 0.0;
        for (int i = 0; i < s.size(); ++i)
            e += 0.5 * s.v.col(i).squaredNorm() + 0.5 * q_ * r_ * r_ * s.spin(i).squaredNorm() +
                 g_ * (s.p(1, i) - floor_);
        return e;
    }

    const physical::World* world_;
    double g_ = 0.0, q_ = 0.0, r_ = 0.0, floor_ = 0.0;
    EnergyTrack track_;
};

std::unique_ptr<Probe> spinDrift(const Simulation& sim)
{
    return std::make_unique<SpinDriftProbe>(sim);
}

// A physical row of a spin case (the rows take their integrators from physicalRows).
CaseRow spinRow(const std::string& name, const std::string& setting, SceneId scene,
                std::vector<std::string> assignments, long long steps)
{
    CaseRow r = reportRow(name, setting, scene, std::move(assignments), std::nullopt, steps);
    r.model = ModelKind::Physical;
    return r;
}

State oneBall(const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& w)
{
    State s;
    s.resize(1);
    s.p.col(0) = p;
    s.v.col(0) = v;
    s.w = w;
    return s;
}

} // namespace

std::vector<CaseRow> spinEnergyDrift()
{
    // Impacts that keep the energy exactly: a superball bouncing on the floor of box3d from
    // 100 m with r w_z = u/q, so that every bounce reverses its tangential speed u (the slip
    // u + r w_z reverses, and r n x v + q r^2 w is kept: u' = -u, w_z' = w_z - 2u/(q r)) and it
    // swings back and forth clear of the walls, its friction always sticking (the slip is
    // at most 3.5 u here, mu allows 10 x 2 x 44 m/s); two superballs that meet. Any drift
    // is the method's. In many-balls' box a spinning ball meets a wall or the floor now and
    // then so slowly that even mu = 10 cannot stop its slip (sliding, S10): that row shows
    // the dissipation, and that the energy never rises (max_energy_gain); 1e5 steps keep
    // it cheap.
    const std::string name = "spin-energy-drift";
    std::vector<CaseRow> rows;
    CaseRow box = spinRow(name, "box3d superball on the floor, k = 1, beta = 1, mu = 10, 1e6 steps", SceneId::Box3d,
                          {"k=1", "beta=1", "mu=10", "p0=150,100,150", "v0=2,0,0", "w0=0,1,5"}, 1'000'000);
    box.probe = spinDrift;
    append(rows, physicalRows(box, impulseIntegrators));
    CaseRow two = spinRow(name, "two-balls, k = e = 1, beta = 1, mu = 10, 1e6 steps", SceneId::TwoBalls,
                          {"k=1", "e=1", "beta=1", "mu=10", "v1=10,5,15", "w1=0,3,1", "w2=2,0,-1"}, 1'000'000);
    two.probe = spinDrift;
    append(rows, physicalRows(two, {Integrator::Verlet, Integrator::Event}));
    CaseRow many = spinRow(
        name, "many-balls n 20, k = e = 1, beta = 1, mu = 10, 1e5 steps (slow wall impacts slide)", SceneId::ManyBalls,
        {"n=20", "primary_loss=1", "secondary_loss=1", "beta=1", "mu=10", "spin=0.05", "rest_height=0"}, 100'000);
    many.probe = spinDrift;
    append(rows, physicalRows(many, {Integrator::Verlet}));
    return rows;
}

std::vector<CaseRow> spinLargeMu()
{
    const std::string name = "spin-large-mu";
    std::vector<CaseRow> rows;
    CaseRow box = spinRow(name, "box3d, mu = 10, beta = 0, thrown spinning", SceneId::Box3d,
                          {"mu=10", "beta=0", "p0=100,50,150", "v0=40,0,-25", "w0=0,30,5"}, 3000);
    box.probe = spinDrift;
    append(rows, physicalRows(box, impulseIntegrators));
    CaseRow two = spinRow(name, "two-balls, mu = 10, beta = 0.5", SceneId::TwoBalls,
                          {"mu=10", "beta=0.5", "w1=0,0,20", "w2=5,0,0"}, 2000);
    two.probe = spinDrift;
    append(rows, physicalRows(two, impulseIntegrators));
    CaseRow pile = spinRow(name, "many-balls n 1000 in a box of 24, mu = 10, beta = 0.5, settling", SceneId::ManyBalls,
                           {"n=1000", "box=24", "mu=10", "beta=0.5", "spin=0.5"}, 200);
    pile.probe = spinDrift;
    append(rows, physicalRows(pile, {Integrator::SymplecticEuler, Integrator::Verlet}));
    return rows;
}

std::vector<CaseRow> spinBackspinWall()
{
    // Moving +x, a ball rolls with w_z = -v/r; back-spin is w_z > 0, here r w_z 10 times the
    // speed. At the x wall the contact point moves up at r w_z: friction throws the ball down.
    const std::string name = "spin-backspin-wall";
    std::vector<CaseRow> rows;
    for (double speed : {300.0, 3000.0}) {
        CaseRow box = spinRow(
            name,
            "box3d, vx " + num(speed) + " m/s at the x wall, r w_z = +" + num(10.0 * speed) + ", mu = 0.5, beta = 0.5",
            SceneId::Box3d,
            {"mu=0.5", "beta=0.5", "p0=150,20,150", "v0=" + num(speed) + ",0,0", "w0=0,0," + num(10.0 * speed)}, 400);
        box.probe = spinDrift;
        append(rows, physicalRows(box, impulseIntegrators));
    }
    CaseRow many = spinRow(name, "many-balls, one ball at 30 per frame, r w_z = +300, mu = 0.5, beta = 0.5",
                           SceneId::ManyBalls, {"n=1", "mu=0.5", "beta=0.5"}, 300);
    many.init = oneBall({20, 0, 0}, {30, 0, 0}, {0, 0, 300});
    many.probe = spinDrift;
    append(rows,
           physicalRows(many, {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4}));
    return rows;
}

} // namespace ab::stability
