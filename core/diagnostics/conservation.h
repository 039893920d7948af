// SPDX-License-Identifier: MIT
// What a run conserves, or fails to: the energy of a state split into kinetic, potential
// and spring parts, the total momentum per axis, and how many balls move. One function
// for any simulation, so the window's charts, `amazeballs-cli chart` and the tests read
// the same numbers.
//
//  1. Masses: the physical model's own (`m`, or `m1`, `m2`: its World); energies are then
//     in mass length^2/time^2 and momenta in mass length/time. The report model and
//     many-balls have equal masses: unit mass, so the values are per unit mass.
//     A turning ball's rotational energy I |w|^2 / 2 counts as kinetic (stages 1-3 and
//     many-balls, physical model).
//  2. Potential energy is m g (y - floor): the floor is y = 0 (stages 1-3, and the street's
//     foot) or the box's bottom face y = -L/2 (stage 4), as the 3D view draws it.
//  3. Impacts are counted by the models: in State::impacts (many-balls, both models, and the
//     street), in the scene's one counter State::count in stages 1-3 (the report's contacts,
//     which its bounce limit counts, and the physical model's impacts).
#pragma once

#include "../physical/spring_contact.h"
#include "../physical/world.h"
#include "../simulation.h"

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <vector>

namespace ab {

struct EnergyParts {
    double kinetic = 0.0;   // sum of 1/2 m |v|^2, and of 1/2 I |w|^2 where the balls turn
    double potential = 0.0; // sum of m g (y - floor)
    double spring = 0.0;    // stored in the spring floor (bounce1d, physical, contact 1 or 2); else 0
    double rotation = 0.0;  // the rotational part of `kinetic`, sum of 1/2 I |w|^2 (0 without spin)
    double left = 0.0;      // taken out of the run by the balls that left it (State::energyLeft); else 0
    double total() const { return kinetic + potential + spring + left; }
    double translation() const { return kinetic - rotation; } // sum of 1/2 m |v|^2
};

struct ConservationSample {
    EnergyParts energy;
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero(); // sum of m v, per axis
    long long moving = 0;                               // balls faster than movingSpeed()
    long long impacts = 0;                              // impacts since the start (note 3)
};

class ConservationMeter {
public:
    explicit ConservationMeter(const Simulation& sim);

    // One pass over the balls (O(N), no allocation): energy, momentum, moving balls.
    ConservationSample measure(const State& s) const;

    bool perUnitMass() const { return mass_.empty(); }
    bool hasSpring() const { return spring_.has_value(); }
    // Whether the run's balls turn (ballsTurn): its energy then has a rotational part.
    bool turns() const { return turns_; }
    double floor() const { return floor_; }
    // A ball slower than this counts as at rest (see the .cpp for why this value).
    double movingSpeed() const { return movingSpeed_; }

private:
    ConservationSample measureWorld(const State& s) const;
    ConservationSample measureEqualMasses(const State& s) const;
    // The street: the balls on it as measureEqualMasses does, those that left as State::energyLeft.
    ConservationSample measureStreet(const State& s) const;

    std::vector<double> mass_; // empty: unit masses
    double g_ = 0.0;
    double floor_ = 0.0;
    double movingSpeed_ = 0.0;
    // A centre at or below this height never moves (the report's stage 4); -inf elsewhere.
    double frozenAtOrBelow_ = -std::numeric_limits<double>::infinity();
    std::optional<physical::SpringFloor> spring_;
    const physical::World* world_ = nullptr; // the physical model's, when the simulation has one (not owned)
    double spinInertia_ = 0.0;               // q r^2 of many-balls' turning balls (docs/spin.md); 0 elsewhere
    std::optional<double> footX_;            // the street's open foot (street::hasLeft); none elsewhere
    bool turns_ = false;
    bool oneCounter_ = false; // stages 1-3: impacts are State::count (note 3)
};

// Whether the balls of a run can turn (docs/spin.md): the physical model with rough
// contacts (mu > 0 and beta > -1, where the scene has them) or a start spin (`w0`, `w1`,
// `w2`, many-balls' `spin`, or an `--init` state with spins). The report model's balls
// never turn: it has no rotation.
bool ballsTurn(const RunSpec& spec);
// Whether the contacts of a scene's parameters have friction (mu > 0 and beta > -1,
// where the scene has both): Walton's impulse and rolling friction act.
bool roughContacts(const ParamValues& params);

// The meter built for `sim`, applied to `s` (convenient for one state; a run builds the
// meter once).
ConservationSample measureConservation(const Simulation& sim, const State& s);

} // namespace ab
