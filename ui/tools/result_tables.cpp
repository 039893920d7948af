// SPDX-License-Identifier: MIT
#include "result_tables.h"

#include <QGuiApplication>
#include <QPalette>

#include <cmath>

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

// Three significant digits: the tables are read, the CSV keeps full precision.
QString figure(double x)
{
    return std::isfinite(x) ? QString::number(x, 'g', 3) : QString();
}

QString figure(const std::optional<double>& x)
{
    return x ? figure(*x) : QString();
}

QVariant sortable(const std::optional<double>& x)
{
    return x ? QVariant(*x) : QVariant(-1.0); // rows without the figure sort first
}

QColor mix(const QColor& a, const QColor& b, double t)
{
    return QColor::fromRgbF(static_cast<float>(a.redF() + (b.redF() - a.redF()) * t),
                            static_cast<float>(a.greenF() + (b.greenF() - a.greenF()) * t),
                            static_cast<float>(a.blueF() + (b.blueF() - a.blueF()) * t));
}

} // namespace

void StudyTableModel::setUnits(const QString& timeUnit, const QString& lengthUnit)
{
    timeUnit_ = timeUnit;
    lengthUnit_ = lengthUnit;
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

void StudyTableModel::clear()
{
    beginResetModel();
    rows_.clear();
    endResetModel();
}

void StudyTableModel::append(const study::Row& row)
{
    const int n = static_cast<int>(rows_.size());
    beginInsertRows({}, n, n);
    rows_.push_back(row);
    endInsertRows();
}

int StudyTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int StudyTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant StudyTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const study::Row& r = rows_[static_cast<std::size_t>(index.row())];
    if (role == Qt::TextAlignmentRole)
        return index.column() >= Dt ? QVariant(Qt::AlignRight | Qt::AlignVCenter) : QVariant();
    if (role != Qt::DisplayRole && role != Qt::UserRole)
        return {};
    const bool sort = role == Qt::UserRole;
    switch (index.column()) {
    case Integrator:
        return qs(std::string(integratorKey(r.method.integrator)));
    case Impacts:
        return qs(r.method.impactsKey());
    case Dt:
        return sort ? QVariant(r.dt) : QVariant(QString::number(r.dt, 'g', 4));
    case MaxError:
        return sort ? QVariant(r.maxError) : QVariant(figure(r.maxError));
    case RelativeError:
        return sort ? QVariant(r.relativeError) : QVariant(figure(r.relativeError));
    case CpuSeconds:
        return sort ? QVariant(r.cpuSeconds) : QVariant(figure(r.cpuSeconds));
    case Steps:
        return sort ? QVariant(r.steps) : QVariant(QString::number(r.steps));
    }
    return {};
}

QVariant StudyTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Integrator:
        return tr("integrator");
    case Impacts:
        return tr("impacts");
    case Dt:
        return tr("dt (%1)").arg(timeUnit_);
    case MaxError:
        return tr("max error (%1)").arg(lengthUnit_);
    case RelativeError:
        return tr("relative error");
    case CpuSeconds:
        return tr("CPU seconds");
    case Steps:
        return tr("steps");
    }
    return {};
}

Verdict verdictOf(const stability::RowResult& row)
{
    if (row.outcome == stability::RowOutcome::NotAvailable || row.outcome == stability::RowOutcome::Skipped)
        return Verdict::NotRun;
    if (row.verdict == "ok")
        return Verdict::Ok;
    return row.verdict == "degraded" ? Verdict::Degraded : Verdict::Failed;
}

QColor verdictBackground(Verdict verdict, const QColor& base)
{
    // Mixed into the base colour rather than painted over it, so the palette's text colour
    // keeps its contrast: pale on a light base, deep on a dark one.
    switch (verdict) {
    case Verdict::Failed:
        return mix(base, QColor(0xe0, 0x30, 0x30), 0.45);
    case Verdict::Degraded:
        return mix(base, QColor(0xf0, 0xa8, 0x00), 0.45);
    case Verdict::Ok:
    case Verdict::NotRun:
        break;
    }
    return {};
}

QString verdictText(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Failed:
        return StabilityTableModel::tr("\u2716 failed");
    case Verdict::Degraded:
        return StabilityTableModel::tr("\u25b2 degraded");
    case Verdict::Ok:
        return StabilityTableModel::tr("ok");
    case Verdict::NotRun:
        return StabilityTableModel::tr("\u2013 not run");
    }
    return {};
}

void StabilityTableModel::clear()
{
    beginResetModel();
    rows_.clear();
    endResetModel();
}

void StabilityTableModel::append(const stability::RowResult& row)
{
    const int n = static_cast<int>(rows_.size());
    beginInsertRows({}, n, n);
    rows_.push_back(row);
    endInsertRows();
}

int StabilityTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int StabilityTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant StabilityTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const stability::RowResult& r = rows_[static_cast<std::size_t>(index.row())];
    switch (role) {
    case Qt::DisplayRole:
        return display(r, index.column());
    case Qt::UserRole:
        return sortKey(r, index.column());
    case Qt::BackgroundRole: {
        const QColor c = verdictBackground(verdictOf(r), QGuiApplication::palette().color(QPalette::Base));
        return c.isValid() ? QVariant(c) : QVariant();
    }
    case Qt::ForegroundRole:
        // Rows that did not run are greyed; the others keep the palette's text colour.
        return verdictOf(r) == Verdict::NotRun
                   ? QVariant(QGuiApplication::palette().color(QPalette::Disabled, QPalette::Text))
                   : QVariant();
    case Qt::ToolTipRole:
        return r.note.empty() ? QVariant() : QVariant(qs(r.note));
    case Qt::TextAlignmentRole:
        return index.column() >= EnergyGain && index.column() <= CpuSeconds
                   ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                   : QVariant();
    }
    return {};
}

QVariant StabilityTableModel::display(const stability::RowResult& r, int column) const
{
    const bool ran = r.outcome == stability::RowOutcome::Ran;
    switch (column) {
    case Case:
        return qs(r.caseName);
    case Model:
        return qs(r.model);
    case Integrator:
        return qs(r.integrator);
    case Setting:
        return qs(r.setting);
    case VerdictColumn:
        return verdictText(verdictOf(r));
    case EnergyGain:
        return ran ? figure(r.figures.maxEnergyGain) : QString();
    case Penetration:
        return ran ? figure(r.figures.maxPenetration) : QString();
    case Escaped:
        return ran ? QString::number(r.figures.escaped) : QString();
    case Nonfinite:
        return ran ? (r.figures.nonfinite ? tr("yes") : tr("no")) : QString();
    case ReferenceError:
        return figure(r.referenceError);
    case Dt:
        return figure(r.dt);
    case CpuSeconds:
        return ran ? figure(r.cpuSeconds) : QString();
    case Note:
        return qs(r.note);
    }
    return {};
}

QVariant StabilityTableModel::sortKey(const stability::RowResult& r, int column) const
{
    switch (column) {
    case VerdictColumn:
        return static_cast<int>(verdictOf(r));
    case EnergyGain:
        return r.figures.maxEnergyGain;
    case Penetration:
        return r.figures.maxPenetration;
    case Escaped:
        return r.figures.escaped;
    case Nonfinite:
        return r.figures.nonfinite ? 1 : 0;
    case ReferenceError:
        return sortable(r.referenceError);
    case Dt:
        return r.dt;
    case CpuSeconds:
        return r.cpuSeconds;
    default:
        return display(r, column);
    }
}

QVariant StabilityTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Case:
        return tr("case");
    case Model:
        return tr("model");
    case Integrator:
        return tr("integrator");
    case Setting:
        return tr("setting");
    case VerdictColumn:
        return tr("verdict");
    case EnergyGain:
        return tr("max energy gain");
    case Penetration:
        return tr("max penetration");
    case Escaped:
        return tr("escaped");
    case Nonfinite:
        return tr("non-finite");
    case ReferenceError:
        return tr("reference error");
    case Dt:
        return tr("dt");
    case CpuSeconds:
        return tr("CPU seconds");
    case Note:
        return tr("note");
    }
    return {};
}

StabilityFilter::StabilityFilter(QObject* parent) : QSortFilterProxyModel(parent)
{
    setSortRole(Qt::UserRole);
}

void StabilityFilter::setText(const QString& text)
{
    text_ = text.trimmed();
    invalidateFilter();
}

void StabilityFilter::setVerdict(std::optional<Verdict> verdict)
{
    verdict_ = verdict;
    invalidateFilter();
}

bool StabilityFilter::filterAcceptsRow(int sourceRow, const QModelIndex&) const
{
    const auto* model = static_cast<const StabilityTableModel*>(sourceModel());
    const stability::RowResult& r = model->rows()[static_cast<std::size_t>(sourceRow)];
    if (verdict_ && verdictOf(r) != *verdict_)
        return false;
    if (text_.isEmpty())
        return true;
    for (const std::string* field : {&r.caseName, &r.model, &r.integrator, &r.setting})
        if (qs(*field).contains(text_, Qt::CaseInsensitive))
            return true;
    return false;
}

} // namespace ab::ui
