// SPDX-License-Identifier: MIT
// The report's own discrete rules, one file per stage (shared/report/README.md). Each
// reproduces its listing step for step; where a printed equation has a typo the intent
// is coded and the scene's notes say so.
#pragma once

#include "../simulation.h"

#include <memory>

namespace ab::report {

std::unique_ptr<Simulation> makeBounce1d(const RunSpec& spec, double dt);
std::unique_ptr<Simulation> makeBox3d(const RunSpec& spec, double dt);
std::unique_ptr<Simulation> makeTwoBalls(const RunSpec& spec, double dt);
std::unique_ptr<Simulation> makeManyBalls(const RunSpec& spec);

// The stage-2 rule for one ball and one step (Appendix C, `propagation`): one branch of
// floor, x = 0, x = L, z = 0, z = L, free flight, in that order. `p` is set to the
// clamped contact position the step starts from; returns true when a face was hit.
struct BoxStepRule {
    double g;  // magnitude, down is -y
    double k;  // restitution at floor and walls
    double box;
    double dt;
};
bool propagateInBox(const BoxStepRule& rule, Eigen::Vector3d& p, const Eigen::Vector3d& v, Eigen::Vector3d& pNew,
                    Eigen::Vector3d& vNew);

// The fixed tangent of eqs 2.24-2.25 for a unit normal n (or the zero vector), with the
// case n.z = 0 handled as the scene's notes explain. Always a unit vector.
Eigen::Vector3d fixedTangent(const Eigen::Vector3d& n);

// The report's stage-4 pair rule (eqs 2.23-2.31 as the code applies them): new
// velocities of ball 1 (at p1, moving v1) and ball 2. `e` is the secondary loss.
void resolveReportPair(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, Eigen::Vector3d& v1,
                       Eigen::Vector3d& v2, double e);

} // namespace ab::report
