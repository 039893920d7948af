// SPDX-License-Identifier: MIT
// `figure`: one of the report's figures (2.5, 2.6, 2.7, 3.1), redrawn from the report model
// with the report's constants, as PNG or SVG, headless (QPainter, no OpenGL).
#include "commands.h"

#include "../../core/io/atomic_file.h"
#include "../../ui/charts/headless_app.h"
#include "../../ui/figures/report_figures.h"

#include <QFileInfo>

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

int figureCommand(Args& args, std::ostream&, std::ostream&)
{
    const std::string number = args.positional("figure number (" + figureNumbers() + ")");
    const auto figure = ui::parseReportFigure(number);
    if (!figure)
        throw InputError("figure: unknown figure '" + printableInput(number) + "' (choose " + figureNumbers() + ")");
    const auto path = args.option("out");
    if (!path)
        throw InputError("figure: missing --out FILE.png or FILE.svg");
    const QString suffix = QFileInfo(QString::fromStdString(*path)).suffix().toLower();
    if (suffix != "png" && suffix != "svg")
        throw InputError("--out: " + printableInput(*path) + " must end in .png or .svg");
    const long long width = args.integer("width", 200, 8000).value_or(1200);
    const long long height = args.integer("height", 150, 8000).value_or(900);
    args.finish();
    checkWritable(*path);

    ui::ensureGuiApplication();
    const ui::FigureData data = ui::computeFigure(*figure);
    ui::exportFigure(data, QString::fromStdString(*path), QSize(int(width), int(height)));
    return 0;
}

} // namespace ab::cli
