// SPDX-License-Identifier: MIT
// Figure export shared by the window and the command line: PNG, SVG or PDF (chosen by the
// file's extension), at a size for where the figure goes (figure_size.h), written whole
// or not at all. SVG and PDF carry the physical size; PNG the dpi. Works for charts that
// were never shown and on the offscreen platform (no OpenGL series: they vanish from
// images).
#pragma once

#include "figure_size.h"

#include <QImage>
#include <QRectF>
#include <QSize>
#include <QString>

#include <functional>

class QChart;
class QPainter;

namespace ab::ui {

// The chart drawn at `size` pixels (device pixel ratio 1).
QImage renderChart(QChart* chart, QSize size);

// Throws InputError unless `path` ends in .png, .svg or .pdf (`what` names the option).
void checkFigurePath(const QString& path, const std::string& what = "");

// Paints a figure laid out in scene units (`options.sceneSize()`) into `path`: PNG at
// the options' pixels and dpi, SVG and PDF at their physical size. Throws InputError
// naming the path and the reason (unknown extension, folder missing or not writable,
// a size too large, the write failed).
using ScenePainter = std::function<void(QPainter& painter, const QRectF& scene)>;
void writeFigureFile(const QString& path, const FigureOptions& options, const QString& title,
                     const ScenePainter& paint);

// Writes `chart` laid out at the options' scene size.
void exportChart(QChart* chart, const QString& path, const FigureOptions& options);
// The chart at `size` pixels (144 dpi), with the fonts it has.
void exportChart(QChart* chart, const QString& path, QSize size = QSize(1200, 800));

} // namespace ab::ui
