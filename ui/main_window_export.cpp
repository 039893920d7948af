// SPDX-License-Identifier: MIT
// The window's exports: a chart as PNG or SVG, the charts' data as CSV, the 3D view as PNG.
#include "main_window.h"

#include "charts/chart_export.h"
#include "export_files.h"
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

void MainWindow::exportChartTo(ChartKind kind, const QString& path)
{
    exportChart(charts_->chart(kind), path, QSize(1200, 800));
}

void MainWindow::exportDataTo(const QString& path)
{
    const int axes = controller_.layout().axes;
    const int ball = controller_.selectedBall();
    MotionTrack copy;
    std::optional<MotionTrack> compare;
    controller_.engine().read([&](const Recording& rec, const Frame&) { copy = rec.track(); });
    if (const RunEngine* other = controller_.comparisonEngine())
        other->read([&](const Recording& rec, const Frame&) { compare = rec.track(); });
    // A long run's CSV takes seconds: written on a worker, with progress and Cancel.
    runWithProgress(this, tr("Writing %1").arg(QFileInfo(path).fileName()), [&](const ProgressFn& progress) {
        saveMotionCsv(copy, axes, ball, path, progress, compare ? &*compare : nullptr);
    });
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
        filter = format == ExportFormat::Svg ? tr("SVG image (*.svg);;PNG image (*.png)")
                                             : tr("PNG image (*.png);;SVG image (*.svg)");
        suggested = base + (format == ExportFormat::Svg ? ".svg" : ".png");
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
        path += chosenFilter.contains("*.svg") ? ".svg" : chosenFilter.contains("*.csv") ? ".csv" : ".png";
    lastDirectory_ = QFileInfo(path).absolutePath();
    try {
        if (format == ExportFormat::Csv)
            exportDataTo(path);
        else
            exportChartTo(kind, path);
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
