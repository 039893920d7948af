// SPDX-License-Identifier: MIT
// Chart export shared by the window and the command line: PNG or SVG (chosen by the
// file's extension), written whole or not at all. Works for charts that were never shown
// and on the offscreen platform (no OpenGL series: they vanish from images).
#pragma once

#include <QImage>
#include <QSize>
#include <QString>

class QChart;

namespace ab::ui {

// The chart drawn at `size` pixels (device pixel ratio 1).
QImage renderChart(QChart* chart, QSize size);

// Writes `chart` to `path` (.png or .svg); throws ab::InputError naming the path and the
// reason (unknown extension, folder missing or not writable, write failed).
void exportChart(QChart* chart, const QString& path, QSize size = QSize(1200, 800));

} // namespace ab::ui
