// SPDX-License-Identifier: MIT
// Streets for the window's street tests: a run of the street with n balls and cars, the
// default street's layout, and hand-made states of balls rolling on its road.
#pragma once

#include "core/simulation.h"
#include "core/street/street_layout.h"

#include <string>
#include <vector>

namespace testing {

inline ab::RunSpec streetSpec(int balls = 10, int cars = 0)
{
    ab::RunSpec spec(ab::SceneId::Street);
    spec.params.parse("n", std::to_string(balls));
    spec.params.parse("cars", std::to_string(cars));
    return spec;
}

inline ab::street::Layout defaultStreet()
{
    return ab::street::Layout::fromParams(ab::RunSpec(ab::SceneId::Street).params);
}

// Ball i at (x, the road's height + r, 0) moving at `speed` along x.
inline ab::State stateAt(const ab::street::Layout& s, const std::vector<double>& xs, const std::vector<double>& speeds,
                         double t)
{
    ab::State st;
    st.resize(int(xs.size()));
    st.t = t;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        st.p.col(Eigen::Index(i)) = Eigen::Vector3d(xs[i], s.roadY(xs[i]) + s.radius, 0.0);
        st.v.col(Eigen::Index(i)) = Eigen::Vector3d(speeds[i], 0.0, 0.0);
    }
    return st;
}

} // namespace testing
