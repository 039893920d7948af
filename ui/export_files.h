// SPDX-License-Identifier: MIT
// The window's exports, each written whole or not at all (a temporary file renamed into
// place): an image (the 3D view) and the charts' data as CSV. Chart images go through
// ui/charts/chart_export.h, the same code the command line uses.
#pragma once

#include <QImage>
#include <QString>

#include <cstddef>
#include <functional>
#include <stdexcept>

namespace ab::ui {

struct ChartData;

// Saves `image` as PNG; throws InputError naming the path and the reason.
void saveImageAtomically(const QImage& image, const QString& path);

// Thrown when an export is cancelled; the target is then untouched.
struct ExportCancelled : std::runtime_error {
    ExportCancelled() : std::runtime_error("export cancelled") {}
};

// Told (rows written, rows in all) every few thousand rows; returns false to cancel.
using ExportProgress = std::function<bool(std::size_t done, std::size_t total)>;

// Writes the charts' data as CSV (writeChartCsv: the run, its closed form and a
// comparison run, with comment lines saying how it was made); throws InputError, or
// ExportCancelled when `progress` says stop (nothing is written).
void saveChartCsv(const ChartData& data, const QString& path, const ExportProgress& progress = {});

} // namespace ab::ui
