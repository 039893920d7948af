// SPDX-License-Identifier: MIT
// The window's exports: a chart as PNG, SVG or PDF at a size for where it goes, the
// charts' data as CSV, the 3D view as PNG. A chart is built for export from the same
// recipe `amazeballs-cli chart` uses (ui/charts/chart_recipe.h).
#include "main_window.h"

#include "charts/chart_data_csv.h"
#include "charts/chart_recipe.h"
#include "charts/run_description.h"
#include "export_files.h"
#include "panels/transport_bar.h"
#include "tools/background_job.h"
#include "view/ball_view.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QStatusBar>

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

} // namespace

std::optional<ReferenceMotion> MainWindow::closedFormMotion() const
{
    const int ball = controller_.selectedBall();
    if (!reference_ || ball >= reference_->balls())
        return std::nullopt;
    const reference::Reference* ref = reference_.get();
    return ReferenceMotion{tr("closed form"), [ref, ball](double t) -> std::optional<Kinematics> {
                               Kinematics k{ref->position(ball, t), ref->velocity(ball, t)};
                               if (!k.p.allFinite() || !k.v.allFinite())
                                   return std::nullopt; // never drawn
                               return k;
                           }};
}

void MainWindow::exportChartTo(ChartKind kind, const QString& path, const ChartExportChoice& how)
{
    checkFigurePath(path);
    const Simulation& sim = controller_.engine().simulation();
    const RunEngine* other = controller_.comparisonEngine();
    ChartRecipe recipe;
    recipe.kind = kind;
    recipe.scene = &sceneInfo(scene_);
    recipe.ball = controller_.selectedBall();
    recipe.units = chartUnits();
    recipe.tEnd = controller_.plannedEnd();
    recipe.runName = RunDescription::runLabel(sim.spec());
    if (other)
        recipe.comparisonName = RunDescription::runLabel(other->simulation().spec());
    recipe.closedForm = closedFormMotion();
    if (kind == ChartKind::Difference && !differenceDrawable(other != nullptr, recipe.closedForm.has_value()))
        throw InputError(path.toStdString() + ": the difference chart needs a comparison run or a closed form");
    if (how.caption) {
        const RunFacts facts{&sim.spec(), sim.dt()};
        const RunFacts compareFacts{other ? &other->simulation().spec() : nullptr,
                                    other ? other->simulation().dt() : 0.0};
        recipe.caption = RunDescription::caption(facts, other ? &compareFacts : nullptr, recipe.closedForm.has_value());
    }
    if (how.cursor) {
        const std::optional<double> viewT = transport_->viewTime();
        recipe.cursor = viewT ? viewT : std::optional<double>(controller_.status().t);
    }
    // Built while the recordings are held (the lines are thinned copies), drawn after.
    std::unique_ptr<MotionChart> chart;
    controller_.engine().read([&](const Recording& rec, const Frame&) {
        recipe.run = &rec.track();
        if (!other) {
            chart = buildFigureChart(recipe, how.options);
            return;
        }
        other->read([&](const Recording& compare, const Frame&) {
            recipe.comparison = &compare.track();
            chart = buildFigureChart(recipe, how.options);
        });
    });
    exportChart(chart.get(), path, how.options);
}

void MainWindow::exportDataTo(const QString& path)
{
    const Simulation& sim = controller_.engine().simulation();
    const RunEngine* other = controller_.comparisonEngine();
    MotionTrack copy;
    std::optional<MotionTrack> compare;
    controller_.engine().read([&](const Recording& rec, const Frame&) { copy = rec.track(); });
    if (other)
        other->read([&](const Recording& rec, const Frame&) { compare = rec.track(); });
    const std::optional<ReferenceMotion> closedForm = closedFormMotion();
    ChartData data;
    data.run = &copy;
    data.axes = controller_.layout().axes;
    data.ball = controller_.selectedBall();
    data.comparison = compare ? &*compare : nullptr;
    data.closedForm = closedForm ? &*closedForm : nullptr;
    data.timeUnit = sceneInfo(scene_).timeUnit;
    data.lengthUnit = sceneInfo(scene_).lengthUnit;
    const ChartUnits units = chartUnits();
    data.perUnitMass = units.perUnitMass;
    data.spins = units.spins;
    data.streetBlocks = units.streetBlocks;
    const RunFacts facts{&sim.spec(), sim.dt()};
    const RunFacts compareFacts{other ? &other->simulation().spec() : nullptr, other ? other->simulation().dt() : 0.0};
    data.comments = RunDescription::comments(facts, other ? &compareFacts : nullptr, closedForm.has_value(), data.ball,
                                             controller_.layout().balls);
    // A long run's CSV takes seconds: written on a worker, with progress and Cancel.
    runWithProgress(this, tr("Writing %1").arg(QFileInfo(path).fileName()),
                    [&](const ProgressFn& progress) { saveChartCsv(data, path, progress); });
}

void MainWindow::exportViewTo(const QString& path)
{
    if (!view_)
        throw InputError(path.toStdString() + ": there is no 3D view on this platform");
    saveImageAtomically(view_->grabFramebuffer(), path);
}

void MainWindow::exportInteractively(ChartKind kind, ExportFormat format)
{
    const QString key = QString::fromLatin1(chartKey(kind).data());
    const QString base = QStringLiteral("%1-%2").arg(qs(sceneInfo(scene_).key), key);
    QString filter;
    QString suggested;
    switch (format) {
    case ExportFormat::Png:
    case ExportFormat::Svg:
    case ExportFormat::Pdf:
        filter = format == ExportFormat::Svg   ? tr("SVG image (*.svg);;PDF document (*.pdf);;PNG image (*.png)")
                 : format == ExportFormat::Pdf ? tr("PDF document (*.pdf);;SVG image (*.svg);;PNG image (*.png)")
                                               : tr("PNG image (*.png);;PDF document (*.pdf);;SVG image (*.svg)");
        suggested = base + (format == ExportFormat::Svg ? ".svg" : format == ExportFormat::Pdf ? ".pdf" : ".png");
        break;
    case ExportFormat::Csv:
        filter = tr("CSV table (*.csv)");
        suggested = qs(sceneInfo(scene_).key) + "-charts.csv";
        break;
    }
    const QString dir = lastDirectory_.isEmpty() ? QDir::currentPath() : lastDirectory_;
    QString chosenFilter;
    QString path = QFileDialog::getSaveFileName(this, tr("Export"), dir + "/" + suggested, filter, &chosenFilter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty()) // a name typed without its type: take the filter's
        path += chosenFilter.contains("*.svg")   ? ".svg"
                : chosenFilter.contains("*.pdf") ? ".pdf"
                : chosenFilter.contains("*.csv") ? ".csv"
                                                 : ".png";
    lastDirectory_ = QFileInfo(path).absolutePath();
    try {
        if (format == ExportFormat::Csv) {
            exportDataTo(path);
        } else {
            ExportOptionsDialog options(lastChartExport_, QFileInfo(path).suffix().toLower() == "png", this);
            if (options.exec() != QDialog::Accepted)
                return;
            lastChartExport_ = options.choice();
            exportChartTo(kind, path, lastChartExport_);
        }
        statusBar()->showMessage(tr("Wrote %1").arg(path), 5000);
    } catch (const ExportCancelled&) {
        statusBar()->showMessage(tr("Export cancelled: nothing written"), 5000);
    } catch (const InputError& e) {
        QMessageBox::warning(this, tr("Export failed"), QString::fromUtf8(e.what()));
    }
}

void MainWindow::exportViewInteractively()
{
    const QString dir = lastDirectory_.isEmpty() ? QDir::currentPath() : lastDirectory_;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export 3D view"), dir + "/" + qs(sceneInfo(scene_).key) + "-view.png", tr("PNG image (*.png)"));
    if (path.isEmpty())
        return;
    lastDirectory_ = QFileInfo(path).absolutePath();
    try {
        exportViewTo(path);
        statusBar()->showMessage(tr("Wrote %1").arg(path), 5000);
    } catch (const InputError& e) {
        QMessageBox::warning(this, tr("Export failed"), QString::fromUtf8(e.what()));
    }
}

} // namespace ab::ui
