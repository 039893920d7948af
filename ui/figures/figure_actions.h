// SPDX-License-Identifier: MIT
// The Figures menu: each of the report's figures (ui/figures/report_figures.h) in a
// dialog of its own that redraws at any size and exports PNG, SVG or PDF at a size for
// where it goes (a report's column or full width, a slide, a custom size).
#pragma once

#include "report_figures.h"

#include <QDialog>
#include <QObject>

class QMenuBar;

namespace ab::ui {

class FigureDialog : public QDialog {
    Q_OBJECT
public:
    FigureDialog(FigureData data, QWidget* parent = nullptr);

    const FigureData& data() const { return data_; }
    // Throws InputError naming the path and the reason. Without options: 1200 x 900 px.
    void exportTo(const QString& path) const;
    void exportTo(const QString& path, const FigureOptions& options) const;

private:
    void exportInteractively(const QString& suffix);

    FigureData data_;
    QWidget* canvas_;
};

class FigureActions : public QObject {
    Q_OBJECT
public:
    explicit FigureActions(QWidget* window);

    void addFiguresMenu(QMenuBar* bar);
    // Opens (or raises) the figure's dialog.
    FigureDialog* show(ReportFigure figure);

private:
    QWidget* window_;
};

} // namespace ab::ui
