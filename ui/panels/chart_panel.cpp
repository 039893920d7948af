// SPDX-License-Identifier: MIT
#include "chart_panel.h"

#include <QChartView>
#include <QContextMenuEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QVBoxLayout>

namespace ab::ui {

namespace {

std::size_t slot(ChartKind kind)
{
    return static_cast<std::size_t>(kind);
}

} // namespace

ChartPanel::ChartPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("chartPanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Charts of ball")));
    ball_ = new QSpinBox;
    ball_->setObjectName("ballSpin");
    ball_->setToolTip(tr("The ball the charts and the trace follow (or click a ball in the 3D view)"));
    row->addWidget(ball_);
    ballCount_ = new QLabel;
    row->addWidget(ballCount_);
    row->addStretch(1);
    auto* hint = new QLabel(tr("Right-click a chart to export it"));
    hint->setStyleSheet("color: #666;");
    row->addWidget(hint);
    layout->addLayout(row);

    auto* splitter = new QSplitter(Qt::Vertical);
    for (ChartKind kind : allChartKinds()) {
        auto* chart = new MotionChart(kind);
        auto* view = new QChartView(chart);
        view->setObjectName(QStringLiteral("chart-%1").arg(QString::fromLatin1(chartKey(kind).data())));
        view->setRenderHint(QPainter::Antialiasing);
        view->setMinimumHeight(200); // title, legend and a readable plot (five charts need the scroll area)
        view->installEventFilter(this);
        view->viewport()->installEventFilter(this);
        charts_[slot(kind)] = chart;
        views_[slot(kind)] = view;
        splitter->addWidget(view);
    }
    applies_.fill(true);
    wanted_.fill(true);
    available_.fill(true);
    splitter->setSizes({300, 300, 260, 220, 220, 220});
    // Up to five charts: when the window is too short for all of them at a readable
    // height they scroll, rather than shrink until their labels are cut.
    auto* scroll = new QScrollArea;
    scroll->setObjectName("chartScroll");
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(splitter);
    layout->addWidget(scroll, 1);

    connect(ball_, &QSpinBox::valueChanged, this, [this](int v) {
        if (!updating_)
            emit ballRequested(v - 1);
    });
}

void ChartPanel::configure(const SceneInfo& scene, int balls, int ball, double tEnd, const ChartUnits& units)
{
    updating_ = true;
    ball_->setRange(1, std::max(balls, 1));
    ball_->setValue(ball + 1);
    ball_->setEnabled(balls > 1);
    updating_ = false;
    ballCount_->setText(tr("of %1").arg(balls));
    for (ChartKind kind : allChartKinds()) {
        const std::size_t i = slot(kind);
        if (available_[i])
            wanted_[i] = !views_[i]->isHidden(); // the wish, as the View menu or a preset left it
        applies_[i] = chartApplies(kind, scene.id);
        charts_[i]->configure(scene, ball, units);
        charts_[i]->setTimeSpan(tEnd);
    }
    applyVisibility();
}

bool ChartPanel::available(std::size_t i) const
{
    return applies_[i] && (i != slot(ChartKind::Difference) || differenceDrawable(comparing_, closedForm_));
}

void ChartPanel::applyVisibility()
{
    for (std::size_t i = 0; i < kinds; ++i) {
        if (available_[i])
            wanted_[i] = !views_[i]->isHidden();
        available_[i] = available(i);
        views_[i]->setHidden(!(wanted_[i] && available_[i]));
    }
}

void ChartPanel::setChartShown(ChartKind kind, bool on)
{
    const std::size_t i = slot(kind);
    wanted_[i] = on;
    views_[i]->setHidden(!(on && available_[i]));
}

bool ChartPanel::chartShown(ChartKind kind) const
{
    const std::size_t i = slot(kind);
    return available_[i] ? !views_[i]->isHidden() : wanted_[i];
}

void ChartPanel::showTrack(const MotionTrack& track)
{
    for (std::size_t i = 0; i < charts_.size(); ++i)
        charts_[i]->showTrack(track, columns(i));
}

void ChartPanel::setCursorTime(std::optional<double> t)
{
    for (MotionChart* c : charts_)
        c->setCursorTime(t);
}

void ChartPanel::setReference(const ReferenceMotion* reference)
{
    for (MotionChart* c : charts_)
        c->setReference(reference);
    closedForm_ = reference != nullptr;
    applyVisibility();
}

void ChartPanel::setComparison(const QString& mainName, const QString& compareName)
{
    for (MotionChart* c : charts_)
        c->setComparison(mainName, compareName);
    comparing_ = !compareName.isEmpty();
    applyVisibility();
}

void ChartPanel::showComparisonTrack(const MotionTrack& track)
{
    for (std::size_t i = 0; i < charts_.size(); ++i)
        charts_[i]->showComparisonTrack(track, columns(i));
}

int ChartPanel::columns(std::size_t slot) const
{
    return std::max(views_[slot]->width(), 200); // a point a pixel column, 200 at least
}

bool ChartPanel::refreshSlot(std::size_t slot, const MotionTrack& track, const MotionTrack* comparison,
                             std::optional<double> cursor)
{
    if (slot >= kinds || !views_[slot] || views_[slot]->isHidden())
        return false;
    const int width = columns(slot);
    charts_[slot]->showTrack(track, width);
    if (comparison)
        charts_[slot]->showComparisonTrack(*comparison, width);
    charts_[slot]->setCursorTime(cursor);
    return true;
}

MotionChart* ChartPanel::chart(ChartKind kind) const
{
    return charts_[slot(kind)];
}

QChartView* ChartPanel::chartView(ChartKind kind) const
{
    return views_[slot(kind)];
}

bool ChartPanel::eventFilter(QObject* watched, QEvent* event)
{
    for (ChartKind kind : allChartKinds()) {
        QChartView* view = views_[slot(kind)];
        if (!view || (watched != view && watched != view->viewport()))
            continue;
        if (event->type() == QEvent::Enter || event->type() == QEvent::MouseButtonPress)
            current_ = kind;
        if (event->type() == QEvent::ContextMenu) {
            current_ = kind;
            QMenu menu;
            menu.addAction(tr("Export this chart as PNG..."), this,
                           [this, kind] { emit exportRequested(kind, ExportFormat::Png); });
            menu.addAction(tr("Export this chart as SVG..."), this,
                           [this, kind] { emit exportRequested(kind, ExportFormat::Svg); });
            menu.addSeparator();
            menu.addAction(tr("Export the chart data as CSV..."), this,
                           [this, kind] { emit exportRequested(kind, ExportFormat::Csv); });
            menu.exec(static_cast<QContextMenuEvent*>(event)->globalPos());
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace ab::ui
