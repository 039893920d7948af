// SPDX-License-Identifier: MIT
// Table models of the accuracy study and the stability suite, for QTableView. Display
// text is formatted; Qt::UserRole gives the value to sort by (numbers as numbers, the
// verdict by severity). The stability model marks each verdict twice: a text marker in
// the verdict column and a row background blended from the palette's base colour, so the
// highlight reads in light and dark themes alike.
#pragma once

#include "core/stability/suite.h"
#include "core/study/study.h"

#include <QAbstractTableModel>
#include <QColor>
#include <QSortFilterProxyModel>

namespace ab::ui {

class StudyTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Integrator, Impacts, Dt, MaxError, RelativeError, CpuSeconds, Steps, ColumnCount };

    using QAbstractTableModel::QAbstractTableModel;

    void setUnits(const QString& timeUnit, const QString& lengthUnit);
    void clear();
    void append(const study::Row& row);
    const std::vector<study::Row>& rows() const { return rows_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    std::vector<study::Row> rows_;
    QString timeUnit_, lengthUnit_;
};

// How a row of the suite came out, worst last.
enum class Verdict { NotRun, Ok, Degraded, Failed };
Verdict verdictOf(const stability::RowResult& row);
// The row background for a verdict: red (failed) or amber (degraded) mixed into `base`
// (the palette's), invalid for the others.
QColor verdictBackground(Verdict verdict, const QColor& base);
// The verdict column's text, with a marker that tells the verdict without colour.
QString verdictText(Verdict verdict);

class StabilityTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Case,
        Model,
        Integrator,
        Setting,
        VerdictColumn,
        EnergyGain,
        Penetration,
        Escaped,
        Nonfinite,
        ReferenceError,
        Dt,
        CpuSeconds,
        Note,
        ColumnCount
    };

    using QAbstractTableModel::QAbstractTableModel;

    void clear();
    void append(const stability::RowResult& row);
    const std::vector<stability::RowResult>& rows() const { return rows_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    QVariant display(const stability::RowResult& row, int column) const;
    QVariant sortKey(const stability::RowResult& row, int column) const;

    std::vector<stability::RowResult> rows_;
};

// Filters the suite's rows by a text (found in case, model, integrator or setting) and a
// verdict; sorts by Qt::UserRole.
class StabilityFilter : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit StabilityFilter(QObject* parent = nullptr);
    void setText(const QString& text);
    // Only rows of this verdict; nothing for all rows.
    void setVerdict(std::optional<Verdict> verdict);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString text_;
    std::optional<Verdict> verdict_;
};

} // namespace ab::ui
