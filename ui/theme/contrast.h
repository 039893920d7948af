// SPDX-License-Identifier: MIT
// Contrast of colours by WCAG 2.1: what the themes, the charts and the 3D view's labels are
// held to.
#pragma once

#include <QColor>

namespace ab::ui {

// WCAG 2.1 relative luminance of an sRGB colour, and the contrast ratio of two colours
// (1 to 21). AA asks 4.5:1 for text, 3:1 for lines, icons and field borders.
double relativeLuminance(const QColor& colour);
double contrastRatio(const QColor& a, const QColor& b);
// `colour`, its lightness moved away from `background` until their ratio is `ratio`.
QColor withContrast(const QColor& colour, const QColor& background, double ratio);

} // namespace ab::ui
