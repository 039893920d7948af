// SPDX-License-Identifier: MIT
// One chart, two front ends: everything a chart draws (the run, its closed form, a
// comparison run, the caption, the cursor when asked for), from which the window's
// export and `amazeballs-cli chart` build the same figure, laid out for its size
// (figure_size.h) with fonts and lines in points of that size.
#pragma once

#include "chart_export.h"
#include "motion_chart.h"

#include <memory>
#include <optional>

namespace ab::ui {

struct ChartRecipe {
    ChartKind kind = ChartKind::Position;
    const SceneInfo* scene = nullptr;
    int ball = 0; // 0-based
    ChartUnits units;
    double tEnd = 1.0; // the planned run
    const MotionTrack* run = nullptr;
    QString runName; // shown beside a comparison
    const MotionTrack* comparison = nullptr;
    QString comparisonName;
    std::optional<ReferenceMotion> closedForm;
    QString caption;              // empty: none
    std::optional<double> cursor; // the time cursor, only when asked for
};

// The look for a figure of these options: print sizes, or lecture sizes on a slide.
ChartLook figureLook(const FigureOptions& options);
// The chart of `recipe`, laid out for `options` (its lines thinned to the scene's width
// in columns, the same for every front end).
std::unique_ptr<MotionChart> buildFigureChart(const ChartRecipe& recipe, const FigureOptions& options);
// Writes it to `path` (.png, .svg or .pdf); throws InputError.
void exportChartFigure(const ChartRecipe& recipe, const QString& path, const FigureOptions& options);

} // namespace ab::ui
