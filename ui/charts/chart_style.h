// SPDX-License-Identifier: MIT
// How the charts are drawn: the window's look (fonts in points for the screen) or a
// figure's (fonts and lines in points of the printed or projected size), and the colour
// and line style of every line, chosen so that a chart reads in greyscale and for
// colour-blind readers: the run's lines differ in style as well as colour, the closed
// form is dashed, a comparison run dotted in a darker, violet-tinted family of its own.
#pragma once

#include <QColor>
#include <QFont>
#include <QPen>

namespace ab::ui {

enum class ChartKind;

struct ChartLook {
    bool figure = false;          // false: the window (fonts by point size, the screen's dpi)
    double pxPerPt = 96.0 / 72.0; // scene units per typographic point
    double textPt = 9.5;          // axis labels, axis titles, legend
    double titlePt = 11.0;
    double captionPt = 9.0;
    double linePt = 1.5; // the run's lines; the others are drawn relative to it

    static ChartLook window();
    // A figure for print: 8 pt labels, 9.5 pt title, 1 pt lines.
    static ChartLook print(double pxPerPt);
    // A figure for a projected slide: lecture sizes, 16 pt labels, 20 pt title, 2.5 pt lines.
    static ChartLook slide(double pxPerPt);

    double px(double pt) const { return pt * pxPerPt; }
    QFont font(const QFont& base, double pt, bool bold = false) const;
};

enum class LineFamily { Run, ClosedForm, Comparison };

// The colour of line `line` of a chart of `kind` (x, y, z; kinetic, potential, total,
// spring; moving balls, impacts) in `family`.
QColor lineColour(ChartKind kind, int line, LineFamily family = LineFamily::Run);
// The comparison's colour for a run line of colour `run` on a dark plot, where the
// darkened family of lineColour() would sink into the background: the run's hue turned
// up to 60 degrees towards violet (a violet one 90 on, to red), saturated and light:
// magenta beside red, cyan beside green, violet beside blue.
QColor comparisonOnDark(const QColor& run);
// The property a comparison series carries: the colour of the run line it shadows.
inline constexpr char comparisonOfProperty[] = "ab_comparisonOf";
// Line `line`, the `order`-th line the chart shows (0-based), of `family`.
QPen linePen(ChartKind kind, int line, int order, LineFamily family, const ChartLook& look);
QPen cursorPen(const ChartLook& look);

} // namespace ab::ui
