// SPDX-License-Identifier: MIT
// The chart export's options: where the figure goes (a report's column, its full width,
// a slide, or a custom size in pixels or millimetres), the PNG's dpi, a caption saying
// how the run was made, and the time cursor (left out unless asked for).
#pragma once

#include "charts/figure_size.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace ab::ui {

struct ChartExportChoice {
    FigureOptions options;
    bool caption = false;
    bool cursor = false;
};

class ExportOptionsDialog : public QDialog {
    Q_OBJECT
public:
    // `png`: the dpi applies (SVG and PDF are vector, at their physical size). Without
    // `chartContents` (the report's figures) the caption and cursor are not offered.
    ExportOptionsDialog(const ChartExportChoice& initial, bool png, QWidget* parent = nullptr,
                        bool chartContents = true);
    // Throws InputError when the custom size or the dpi is refused.
    ChartExportChoice choice() const;

private:
    void updateSummary();

    QComboBox* preset_;
    QDoubleSpinBox* width_;
    QDoubleSpinBox* height_;
    QComboBox* unit_;
    QSpinBox* dpi_;
    QCheckBox* caption_;
    QCheckBox* cursor_;
    QLabel* summary_;
    bool png_;
};

} // namespace ab::ui
