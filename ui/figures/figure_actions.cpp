// SPDX-License-Identifier: MIT
#include "figure_actions.h"

#include "ui/export_options_dialog.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

namespace ab::ui {

namespace {

QString numberOf(ReportFigure figure)
{
    return QString::fromLatin1(figureNumber(figure).data(), qsizetype(figureNumber(figure).size()));
}

// Draws the dialog's figure at the widget's size.
class FigureCanvas : public QWidget {
public:
    explicit FigureCanvas(const FigureData* data) : data_(data)
    {
        setMinimumSize(480, 360);
        setAttribute(Qt::WA_OpaquePaintEvent);
    }

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter painter(this);
        paintFigure(painter, QRectF(rect()), *data_);
    }

private:
    const FigureData* data_;
};

} // namespace

FigureDialog::FigureDialog(FigureData data, QWidget* parent) : QDialog(parent), data_(std::move(data))
{
    setObjectName(QStringLiteral("figure-%1").arg(numberOf(data_.figure)));
    setWindowTitle(figureCaption(data_.figure));
    canvas_ = new FigureCanvas(&data_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    QPushButton* png = buttons->addButton(tr("Export PNG..."), QDialogButtonBox::ActionRole);
    QPushButton* svg = buttons->addButton(tr("Export SVG..."), QDialogButtonBox::ActionRole);
    QPushButton* pdf = buttons->addButton(tr("Export PDF..."), QDialogButtonBox::ActionRole);
    connect(png, &QPushButton::clicked, this, [this] { exportInteractively("png"); });
    connect(svg, &QPushButton::clicked, this, [this] { exportInteractively("svg"); });
    connect(pdf, &QPushButton::clicked, this, [this] { exportInteractively("pdf"); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(canvas_, 1);
    layout->addWidget(buttons);
    resize(1000, 760);
}

void FigureDialog::exportTo(const QString& path) const
{
    exportFigure(data_, path, QSize(1200, 900));
}

void FigureDialog::exportTo(const QString& path, const FigureOptions& options) const
{
    exportFigure(data_, path, options);
}

void FigureDialog::exportInteractively(const QString& suffix)
{
    const QString name = QStringLiteral("figure-%1.%2").arg(numberOf(data_.figure), suffix);
    const QString filter = suffix == "svg"   ? tr("SVG image (*.svg)")
                           : suffix == "pdf" ? tr("PDF document (*.pdf)")
                                             : tr("PNG image (*.png)");
    QString path = QFileDialog::getSaveFileName(this, tr("Export figure"), QDir::currentPath() + "/" + name, filter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += "." + suffix;
    ExportOptionsDialog options(ChartExportChoice{FigureOptions{FigureSize::reportFull(), std::nullopt}},
                                QFileInfo(path).suffix().toLower() == "png", this, false);
    if (options.exec() != QDialog::Accepted)
        return;
    try {
        exportTo(path, options.choice().options);
    } catch (const InputError& e) {
        QMessageBox::warning(this, tr("Export failed"), QString::fromUtf8(e.what()));
    }
}

FigureActions::FigureActions(QWidget* window) : QObject(window), window_(window) {}

void FigureActions::addFiguresMenu(QMenuBar* bar)
{
    QMenu* menu = bar->addMenu(tr("F&igures"));
    menu->setObjectName("figuresMenu");
    for (ReportFigure figure : allReportFigures())
        menu->addAction(figureCaption(figure), this, [this, figure] { show(figure); });
}

FigureDialog* FigureActions::show(ReportFigure figure)
{
    const QString name = QStringLiteral("figure-%1").arg(numberOf(figure));
    auto* dialog = window_->findChild<FigureDialog*>(name, Qt::FindDirectChildrenOnly);
    if (!dialog) {
        dialog = new FigureDialog(computeFigure(figure), window_);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    dialog->show();
    dialog->raise();
    return dialog;
}

} // namespace ab::ui
