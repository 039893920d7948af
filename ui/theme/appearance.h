// SPDX-License-Identifier: MIT
// Applies a theme, the colour-blind-safe palette and a font and line scale to the
// application and to every chart of a window. Charts keep their own pens and fonts as
// the base: each application starts again from that base, so switching back and forth
// never compounds.
#pragma once

#include "theme.h"

class QChart;
class QWidget;

namespace ab::ui {

struct Appearance {
    Theme theme = Theme::Light;
    bool colourBlindSafe = false;
    double scale = 1.0; // fonts and chart lines; lecture mode enlarges both
};

// Chart text grows less than the window's: a chart's plot area shrinks as its labels
// grow, and at the full scale the small charts would be all labels.
double chartFontScale(const Appearance& appearance);

// The palette of every widget, and the application font scaled from the size it had
// the first time this ran.
void applyToApplication(const Appearance& appearance);
// Background, text, grid, line colours and widths, fonts of one chart.
void applyToChart(QChart* chart, const Appearance& appearance);
// Every chart shown inside `root`.
void applyToCharts(QWidget* root, const Appearance& appearance);

} // namespace ab::ui
