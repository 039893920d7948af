// SPDX-License-Identifier: MIT
// The charts' data as CSV, the same from the window and `amazeballs-cli chart --data`:
// `#` comment lines saying how the run was made (run_description.h), then a header with
// the unit of every column in brackets, then every kept sample of the run at full
// precision (shortest round-trip form, locale-independent):
//   t [T], ball (1-based, as the window numbers the balls), the position and velocity of
//   the axes shown (1: y alone; 3: x, y, z), energy_total, energy_kinetic,
//   energy_potential, energy_spring (of all balls, per unit mass or with the physical
//   model's masses), momentum_x, _y, _z, moving (balls), impacts (since the start), and
//   where the balls turn wx, wy, wz (the ball's angular velocity, rad/T) and
//   energy_translation, energy_rotation (the kinetic energy's parts); on the street
//   past_foot_<k> (balls past the foot of each charted block k, 1-based), speed_p10,
//   speed_median, speed_p90, speed_max (of the balls on the street; empty once none is) and
//   energy_left (what the balls that left at the foot took with them); the ball's own cells
//   (position, velocity, spin) are empty once it has left at the street's foot;
//   with a closed form: x_closed_form ... vz_closed_form at the row's time (empty where it
//   does not apply); with a comparison run: compare_t and the same columns prefixed
//   `compare_`, from the comparison's last sample at or before the row's time (the same
//   time when both runs share their step; empty before its first sample).
#pragma once

#include "motion_chart.h"
#include "motion_track.h"

#include <ostream>
#include <string>
#include <vector>

namespace ab::ui {

struct ChartData {
    const MotionTrack* run = nullptr;
    int axes = 3;
    int ball = 0; // 0-based; written 1-based
    const MotionTrack* comparison = nullptr;
    const ReferenceMotion* closedForm = nullptr;
    std::string timeUnit = "s", lengthUnit = "m";
    bool perUnitMass = true;
    bool spins = false;                // the balls turn: wx, wy, wz, energy_translation, energy_rotation after the rest
    int streetBlocks = 0;              // the street's blocks: its counts and speeds after those
    std::vector<std::string> comments; // without the "# "
};

void writeChartCsv(std::ostream& out, const ChartData& data);

} // namespace ab::ui
