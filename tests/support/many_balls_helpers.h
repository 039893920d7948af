// SPDX-License-Identifier: MIT
// Helpers of the many-balls physical tests: a run from --set style assignments with a
// step, and a start state from (position, velocity) pairs.
#pragma once

#include "sim_helpers.h"

#include <Eigen/Core>

#include <initializer_list>
#include <string>
#include <utility>

namespace testing {

// The physical model of many-balls with --set style assignments and step dt.
inline ab::RunSpec manyBallsPhysical(std::initializer_list<std::string> assignments, double dt)
{
    ab::RunSpec s = spec(ab::SceneId::ManyBalls, assignments, ab::ModelKind::Physical);
    s.dt = dt;
    return s;
}

// Balls at the given centres with the given velocities, without spin.
inline ab::State ballsAt(std::initializer_list<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pv)
{
    ab::State s;
    s.resize(static_cast<int>(pv.size()));
    int i = 0;
    for (const auto& [p, v] : pv) {
        s.p.col(i) = p;
        s.v.col(i) = v;
        ++i;
    }
    return s;
}

} // namespace testing
