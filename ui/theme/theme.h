// SPDX-License-Identifier: MIT
// The window's looks: four themes (light, dark and their high-contrast versions for a
// projector), each a QPalette for the widgets plus colours for the charts and the 3D
// view, and the Okabe-Ito palette (Okabe & Ito 2008, "Color Universal Design"), whose
// eight colours stay apart under the common colour-vision deficiencies.
#pragma once

#include "contrast.h"

#include <QColor>
#include <QPalette>
#include <QString>

#include <array>
#include <optional>
#include <vector>

namespace ab::ui {

enum class Theme { Light, Dark, HighContrastLight, HighContrastDark };

const std::vector<Theme>& allThemes();
QString themeTitle(Theme theme); // translated
QString themeKey(Theme theme);   // "light", "dark", "high-contrast-light", "high-contrast-dark"
std::optional<Theme> parseTheme(const QString& key);
bool isDark(Theme theme);
bool isHighContrast(Theme theme);

QPalette themePalette(Theme theme);
// The frame of an editable field (line edit, spin box, combo box): 3:1 against the
// window and the field's base, so that a field never reads as a label.
QColor fieldBorder(Theme theme);

// The colours a chart or the 3D view draws its frame with.
struct SurfaceColours {
    QColor background; // chart background, the 3D view's clear colour
    QColor plotArea;
    QColor text;
    QColor grid;
    QColor axisLine;
};
SurfaceColours surfaceColours(Theme theme);

// Black, orange, sky blue, bluish green, yellow, blue, vermillion, reddish purple.
const std::array<QColor, 8>& okabeIto();
// The Okabe-Ito colour nearest in hue to `colour` (greys stay as they are), so that a
// chart's x, y, z (red, green, blue) become vermillion, bluish green and blue.
QColor colourBlindSafe(const QColor& colour);
// `balls` ball colours (0xRRGGBB) cycling through the Okabe-Ito colours that show on
// the theme's background (no black on dark, no yellow on light).
std::vector<unsigned> okabeItoBallColours(int balls, Theme theme);

} // namespace ab::ui
