// SPDX-License-Identifier: MIT
#include "chart_recipe.h"

#include <QGraphicsLayout>

#include <cmath>

namespace ab::ui {

ChartLook figureLook(const FigureOptions& options)
{
    const double pxPerPt = kSceneDpi / 72.0;
    return options.size.slide ? ChartLook::slide(pxPerPt) : ChartLook::print(pxPerPt);
}

std::unique_ptr<MotionChart> buildFigureChart(const ChartRecipe& recipe, const FigureOptions& options)
{
    if (!recipe.scene || !recipe.run)
        throw std::logic_error("a chart recipe without a scene or a run");
    const int columns = std::max(200, int(std::lround(options.sceneSize().width())));
    auto chart = std::make_unique<MotionChart>(recipe.kind, figureLook(options));
    chart->resize(options.sceneSize());
    chart->setCaption(recipe.caption);
    chart->setComparison(recipe.comparison ? recipe.runName : QString(),
                         recipe.comparison ? recipe.comparisonName : QString());
    chart->configure(*recipe.scene, recipe.ball, recipe.units);
    chart->setTimeSpan(recipe.tEnd);
    chart->setReference(recipe.closedForm ? &*recipe.closedForm : nullptr, columns);
    // Laid out at its size with its legend and caption before the lines are drawn: the
    // ticks follow the plot's size.
    if (chart->layout()) {
        chart->layout()->invalidate();
        chart->layout()->activate();
    }
    chart->setReference(recipe.closedForm ? &*recipe.closedForm : nullptr, columns);
    chart->showTrack(*recipe.run, columns);
    if (recipe.comparison)
        chart->showComparisonTrack(*recipe.comparison, columns);
    chart->setCursorTime(recipe.cursor);
    return chart;
}

void exportChartFigure(const ChartRecipe& recipe, const QString& path, const FigureOptions& options)
{
    checkFigurePath(path);
    const std::unique_ptr<MotionChart> chart = buildFigureChart(recipe, options);
    exportChart(chart.get(), path, options);
}

} // namespace ab::ui
