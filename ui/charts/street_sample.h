// SPDX-License-Identifier: MIT
// What the street's own charts (stage 5) draw, measured once per recorded step: how many
// balls are past the foot of each charted block (the foot-rate chart turns these counts
// into balls per second), and the distribution of the speeds of the balls still on the
// street, as its 10th, 50th and 90th percentiles and its largest value.
#pragma once

#include "core/state.h"
#include "core/street/street_layout.h"

#include <array>
#include <vector>

namespace ab::ui {

// The blocks whose feet the foot-rate chart draws, at most this many lines.
inline constexpr int kFootLines = 5;
// The speed chart's lines: 10th percentile, median, 90th percentile, fastest.
inline constexpr int kSpeedLines = 4;

struct StreetSample {
    std::array<double, kFootLines> pastFoot{}; // balls whose centres are beyond the foot of footBlocks()[i]
    std::array<double, kSpeedLines> speed{};   // of the balls on the street (0 when none is)
    double onStreet = 0.0;                     // balls on the street (the speeds' sample size)
};

// The blocks (0-based) the foot-rate chart follows: every block up to kFootLines, else the
// first kFootLines - 1 and the last (whose foot is the street's).
std::vector<int> footBlocks(int blocks);

// The sample of state `s` on `street`.
StreetSample measureStreet(const street::Layout& street, const State& s);

// Balls per unit of time passing the foot of charted block `line`, at every sample of the
// counts `past` at times `t`: (N_i - N_j) / (t_i - t_j), with j the latest sample at or
// before t_i - window (the first while the run is younger than the window). A difference of
// counts, so it is exact for any stride of the samples.
std::vector<double> passingRate(const std::vector<double>& t, const std::vector<double>& past, double window);

} // namespace ab::ui
