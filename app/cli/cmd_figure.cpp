// SPDX-License-Identifier: MIT
// `figure`: one of the report's figures (2.5, 2.6, 2.7, 3.1), redrawn from the report model
// with the report's constants, as PNG, SVG or PDF, headless (QPainter, no OpenGL), at a
// size preset (--size, --dpi) or in pixels (--width, --height).
#include "commands.h"
#include "suggest.h"

#include "../../core/io/atomic_file.h"
#include "../../ui/charts/chart_export.h"
#include "../../ui/charts/headless_app.h"
#include "../../ui/figures/report_figures.h"

#include <QFileInfo>

#include <limits>

namespace ab::cli {

namespace {

std::string figureNumbers()
{
    std::string out;
    for (ui::ReportFigure f : ui::allReportFigures())
        out += (out.empty() ? "" : ", ") + std::string(ui::figureNumber(f));
    return out;
}

} // namespace

int figureCommand(Parsed& args, std::ostream&, std::ostream&)
{
    const std::string number = args.positional("figure number (" + figureNumbers() + ")");
    const auto figure = ui::parseReportFigure(number);
    if (!figure)
        throw InputError("figure: unknown figure '" + printableInput(number) + "'" +
                         nearOrChoices(number, valueWords(Values::Figure)));
    const auto path = args.option("out");
    if (!path)
        throw InputError("figure: missing --out FILE.png, FILE.svg or FILE.pdf");
    ui::checkFigurePath(QString::fromStdString(*path), "--out");
    const auto size = args.option("size");
    const auto width = args.integer("width", 200, 8000);
    const auto height = args.integer("height", 150, 8000);
    if (size && (width || height))
        throw InputError("--size: give either --size or --width/--height, not both");
    const auto dpi = args.integer("dpi", std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max());
    if (dpi)
        ui::checkDpi(*dpi);
    std::optional<ui::FigureOptions> options;
    if (size || dpi) {
        options = ui::FigureOptions{size ? ui::parseFigureSize(*size) : ui::FigureSize::reportFull(),
                                    dpi ? std::optional<int>(int(*dpi)) : std::nullopt};
        if (QFileInfo(QString::fromStdString(*path)).suffix().toLower() == "png")
            (void)options->pngPixels();
        ui::checkChartRoom(*options, size ? "--size" : "--dpi");
    }
    checkWritable(*path);

    ui::ensureGuiApplication();
    const ui::FigureData data = ui::computeFigure(*figure);
    if (options)
        ui::exportFigure(data, QString::fromStdString(*path), *options);
    else
        ui::exportFigure(data, QString::fromStdString(*path),
                         QSize(int(width.value_or(1200)), int(height.value_or(900))));
    return 0;
}

} // namespace ab::cli
