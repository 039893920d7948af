// SPDX-License-Identifier: MIT
// The work-precision chart of an accuracy study: largest position error (relative to the
// scene's length scale) against CPU time, both on log axes, one line per integrator and
// impact mode in order of the step. Lower-left is better; a line's slope is minus its
// order divided by the cost's growth. The window and `study --chart` draw the same chart.
#pragma once

#include "core/study/study.h"

#include <memory>

class QChart;

namespace ab::ui {

std::unique_ptr<QChart> makeWorkPrecisionChart(const study::Result& result);

} // namespace ab::ui
