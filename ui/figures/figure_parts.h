// SPDX-License-Identifier: MIT
// What the report figures' two files share: report_figures.cpp draws the line plots (2.5,
// 2.7) and puts a figure together with its title and caption; figure_projection.cpp draws
// the projected 3D figures (2.6, 3.1). Both translate in one context and draw in one ink.
#pragma once

#include "report_figures.h"

#include <QColor>
#include <QCoreApplication>
#include <QString>

#include <string>
#include <vector>

class QPainter;
class QRectF;

namespace ab::ui::figure_parts {

// The context the figures' strings are translated in.
struct ReportFigures {
    Q_DECLARE_TR_FUNCTIONS(ReportFigures)
};

inline QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

inline const QColor ink(0x22, 0x22, 0x22);
inline const QColor grid(0xdd, 0xdd, 0xdd);
inline const QColor line(0x00, 0x72, 0xbd); // MATLAB's first line colour, as in the report's plots

// Ticks at whole multiples of a nice step within [lo, hi], about `count` of them.
std::vector<double> ticks(double lo, double hi, int count);

// Figure 2.6: the ball's path in the box, seen from the front right and above, with the
// box's edges and MATLAB-style tick labels.
void paintTrajectory(QPainter& p, const QRectF& area, const FigureData& d);

// Figure 3.1: the balls at the end of the run in the box, in perspective from the side the
// report's WebGL camera stands on, shaded and drawn far to near.
void paintBalls(QPainter& p, const QRectF& area, const FigureData& d);

} // namespace ab::ui::figure_parts
