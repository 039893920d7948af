// SPDX-License-Identifier: MIT
#include "export_options_dialog.h"

#include "ui/i18n/core_text.h"

#include "core/params.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace ab::ui {

namespace {

enum Preset { Column, Full, Slide, Custom };

} // namespace

ExportOptionsDialog::ExportOptionsDialog(const ChartExportChoice& initial, bool png, QWidget* parent,
                                         bool chartContents)
    : QDialog(parent), png_(png)
{
    setWindowTitle(tr("Figure size and contents"));
    auto* form = new QFormLayout;
    preset_ = new QComboBox;
    preset_->setObjectName("figurePreset");
    preset_->addItem(tr("Report column (85 mm wide)"));
    preset_->addItem(tr("Report full width (170 mm)"));
    preset_->addItem(tr("Slide (1920 x 1080 px, 16:9)"));
    preset_->addItem(tr("Custom size"));
    form->addRow(tr("For"), preset_);
    auto* custom = new QHBoxLayout;
    width_ = new QDoubleSpinBox;
    height_ = new QDoubleSpinBox;
    for (QDoubleSpinBox* box : {width_, height_}) {
        box->setDecimals(1);
        box->setRange(1.0, double(kMaxPixels));
    }
    unit_ = new QComboBox;
    unit_->addItem(tr("mm"));
    unit_->addItem(tr("px"));
    custom->addWidget(width_);
    custom->addWidget(new QLabel(QStringLiteral("\u00d7")));
    custom->addWidget(height_);
    custom->addWidget(unit_);
    form->addRow(tr("Size"), custom);
    dpi_ = new QSpinBox;
    dpi_->setObjectName("figureDpi");
    dpi_->setRange(kMinDpi, kMaxDpi);
    dpi_->setSuffix(tr(" dpi"));
    dpi_->setEnabled(png);
    dpi_->setToolTip(png ? tr("Pixels per inch of the PNG: 300 for print")
                         : tr("SVG and PDF are vector images: they have no dpi"));
    form->addRow(tr("Resolution"), dpi_);
    caption_ = new QCheckBox(tr("Caption: scene, model, integrator, impacts, dt and changed constants"));
    caption_->setObjectName("figureCaption");
    cursor_ = new QCheckBox(tr("Draw the time cursor"));
    cursor_->setObjectName("figureCursor");
    summary_ = new QLabel;
    summary_->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(caption_);
    layout->addWidget(cursor_);
    layout->addWidget(summary_);
    layout->addWidget(buttons);

    const FigureSize& s = initial.options.size;
    const int preset = s.name == "report-column" ? Column
                       : s.name == "report-full" ? Full
                       : s.name == "slide"       ? Slide
                                                 : Custom;
    preset_->setCurrentIndex(preset);
    unit_->setCurrentIndex(s.pixels ? 1 : 0);
    width_->setValue(s.pixels ? s.pixels->width() : s.widthMm);
    height_->setValue(s.pixels ? s.pixels->height() : s.heightMm);
    dpi_->setValue(initial.options.effectiveDpi());
    caption_->setChecked(initial.caption && chartContents);
    cursor_->setChecked(initial.cursor && chartContents);
    caption_->setVisible(chartContents);
    cursor_->setVisible(chartContents);
    auto presetChosen = [this] {
        const int p = preset_->currentIndex();
        const bool custom = p == Custom;
        for (QWidget* w : std::initializer_list<QWidget*>{width_, height_, unit_})
            w->setEnabled(custom);
        if (!custom) {
            const FigureSize f = p == Column ? FigureSize::reportColumn()
                                 : p == Full ? FigureSize::reportFull()
                                             : FigureSize::slideSize();
            unit_->setCurrentIndex(f.pixels ? 1 : 0);
            width_->setValue(f.pixels ? f.pixels->width() : f.widthMm);
            height_->setValue(f.pixels ? f.pixels->height() : f.heightMm);
            dpi_->setValue(defaultDpi(f));
        }
        updateSummary();
    };
    connect(preset_, &QComboBox::currentIndexChanged, this, presetChosen);
    for (QDoubleSpinBox* box : {width_, height_})
        connect(box, &QDoubleSpinBox::valueChanged, this, &ExportOptionsDialog::updateSummary);
    connect(unit_, &QComboBox::currentIndexChanged, this, &ExportOptionsDialog::updateSummary);
    connect(dpi_, &QSpinBox::valueChanged, this, &ExportOptionsDialog::updateSummary);
    for (QWidget* w : std::initializer_list<QWidget*>{width_, height_, unit_})
        w->setEnabled(preset == Custom);
    updateSummary();
}

ChartExportChoice ExportOptionsDialog::choice() const
{
    ChartExportChoice c;
    switch (preset_->currentIndex()) {
    case Column:
        c.options.size = FigureSize::reportColumn();
        break;
    case Full:
        c.options.size = FigureSize::reportFull();
        break;
    case Slide:
        c.options.size = FigureSize::slideSize();
        break;
    default: {
        const QString text = unit_->currentIndex() == 1
                                 ? QStringLiteral("%1x%2").arg(int(width_->value())).arg(int(height_->value()))
                                 : QStringLiteral("%1x%2mm").arg(width_->value()).arg(height_->value());
        c.options.size = parseFigureSize(text.toStdString(), tr("size").toStdString());
    }
    }
    c.options.dpi = dpi_->value();
    checkChartRoom(c.options, tr("size").toStdString());
    c.caption = caption_->isChecked();
    c.cursor = cursor_->isChecked();
    return c;
}

void ExportOptionsDialog::updateSummary()
{
    try {
        const ChartExportChoice c = choice();
        const QSizeF mm = c.options.millimetres();
        QString text = tr("%1 x %2 mm").arg(mm.width(), 0, 'f', 1).arg(mm.height(), 0, 'f', 1);
        if (png_) {
            const QSize px = c.options.pngPixels();
            text += tr(", %1 x %2 px at %3 dpi").arg(px.width()).arg(px.height()).arg(c.options.effectiveDpi());
        }
        summary_->setText(text);
        summary_->setStyleSheet(QString());
    } catch (const InputError& e) {
        summary_->setText(refusalText(e));
        summary_->setStyleSheet("color: #b00020;");
    }
}

} // namespace ab::ui
