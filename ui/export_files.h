// SPDX-License-Identifier: MIT
// The window's exports, each written whole or not at all (a temporary file renamed into
// place): an image (the 3D view) and the charts' data as CSV. Chart images go through
// ui/charts/chart_export.h, the same code the command line uses.
#pragma once

#include <QImage>
#include <QString>

namespace ab::ui {

class MotionTrack;

// Saves `image` as PNG; throws InputError naming the path and the reason.
void saveImageAtomically(const QImage& image, const QString& path);

// Writes the track as CSV (writeMotionCsv); throws InputError.
void saveMotionCsv(const MotionTrack& track, int axes, int ball, const QString& path);

} // namespace ab::ui
