// SPDX-License-Identifier: MIT
// The report's figures redrawn from the report model run with the report's constants:
//   2.5  stage 1, position and velocity of the ball against time (two panels);
//   2.6  stage 2, the ball's trajectory in the 300 x 300 x 300 box (3D, projected);
//   2.7  stage 2, velocity along x, y and z against time (three panels);
//   3.1  stage 4, the WebGL box with 200 balls (shaded circles seen in perspective).
// Everything is painted with QPainter (no Qt Charts, no OpenGL), so the window, the
// command line and the tests draw the same picture on any platform, as PNG, SVG or PDF.
#pragma once

#include "core/simulation.h"
#include "ui/charts/figure_size.h"

#include <QImage>
#include <QRectF>
#include <QSize>
#include <QString>

#include <optional>
#include <string_view>
#include <vector>

class QPainter;

namespace ab::ui {

enum class ReportFigure { Bounce1d, BoxTrajectory, BoxVelocity, ManyBalls };

const std::vector<ReportFigure>& allReportFigures();
std::string_view figureNumber(ReportFigure figure); // "2.5", "2.6", "2.7", "3.1"
std::optional<ReportFigure> parseReportFigure(std::string_view number);
// The report's caption, in the program's language.
QString figureCaption(ReportFigure figure);

// What a figure draws: ball 0's recorded states for 2.5-2.7, the last state for 3.1.
struct FigureData {
    ReportFigure figure = ReportFigure::Bounce1d;
    RunSpec spec{SceneId::Bounce1d};
    long long steps = 0;
    std::vector<double> t;
    std::vector<Eigen::Vector3d> p, v;
    // The first state the report's bounce counter zeroed (the ball stops there), if any.
    std::optional<std::size_t> halt;
    State last;
};

// Runs the report model with the report's constants (Figure 3.1: with its 200 balls).
FigureData computeFigure(ReportFigure figure);

// Text `textPx` scene units high (0: scaled to the area, for the window's dialog).
void paintFigure(QPainter& painter, const QRectF& area, const FigureData& data, int textPx = 0);
QImage renderFigure(const FigureData& data, QSize size);
// Writes the figure to `path` (.png or .svg) whole or not at all; throws InputError
// naming the path and the reason.
void exportFigure(const FigureData& data, const QString& path, QSize size = QSize(1200, 900));
// At a size for where the figure goes, as PNG, SVG or PDF (ui/charts/figure_size.h).
void exportFigure(const FigureData& data, const QString& path, const FigureOptions& options);

} // namespace ab::ui
