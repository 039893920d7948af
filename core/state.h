// SPDX-License-Identifier: MIT
// The changing state of a run: time, ball positions, velocities and spins, and the little memory
// the report's rules keep (bounce counters). The fixed description lives in the scene's
// parameters; this is all a step reads and writes.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace ab {

// 3 x N, row-major: x of every ball, then y of every ball, then z (structure of arrays,
// so one axis of many balls is contiguous). A single ball is `p.col(i)`.
using Vec3Array = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;

struct State {
    double t = 0.0;
    Vec3Array p; // centres
    Vec3Array v; // velocities
    // Angular velocities (rad per time unit, right-hand rule), 3 x N where the balls turn
    // (the physical model of stages 1-3); empty (3 x 0) everywhere else, which reads as no
    // spin and costs the N-ball scenes nothing.
    Vec3Array w;
    // Per-ball contact counters (the report's stage 4 counts bounces per ball).
    std::vector<int> bounces;
    // One counter for the whole scene (the report's stages 1-3 share one `count`).
    long long count = 0;
    // Impacts since the start, ball-wall and ball-ball, each pair contact once (filled by
    // the many-balls models, report and physical; the charts' impacts per unit of time).
    long long impacts = 0;
    // Energy per unit mass that balls took with them out of the run (the street's open foot):
    // each one's kinetic, rotational and potential energy at the end of the step it passed
    // the foot in, summed since the start. The balls that left stay past the foot at rest and
    // count for nothing else. 0 in every other scene.
    double energyLeft = 0.0;
    // The report's bounce limit was reached: from here on the report zeroes the state.
    bool halted = false;

    int size() const { return static_cast<int>(p.cols()); }
    bool spins() const { return w.cols() == p.cols() && w.cols() > 0; }
    // Ball i's angular velocity; zero where the state has none.
    Eigen::Vector3d spin(int i) const { return spins() ? Eigen::Vector3d(w.col(i)) : Eigen::Vector3d::Zero(); }
    void resize(int n)
    {
        p.setZero(3, n);
        v.setZero(3, n);
        w.resize(3, 0);
        bounces.assign(static_cast<std::size_t>(n), 0);
    }
};

} // namespace ab
