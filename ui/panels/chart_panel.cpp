// SPDX-License-Identifier: MIT
#include "chart_panel.h"

#include <QChartView>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QMenu>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QStringList>
#include <QTabBar>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>

namespace ab::ui {

namespace {

std::size_t slot(ChartKind kind)
{
    return static_cast<std::size_t>(kind);
}

// A legend above the plot while its entries fit in one row there (Qt Charts cuts them to
// "..." rather than wrap), beside it, one entry a line, when they do not.
void placeLegend(MotionChart* chart, int width)
{
    const QFontMetrics fm(chart->legend()->font());
    int row = 0;
    for (QLegendMarker* m : chart->legend()->markers())
        if (m->isVisible() && m->series()->isVisible())
            row += fm.horizontalAdvance(m->label()) + 2 * fm.height();
    const Qt::Alignment side = row + 24 <= width ? Qt::AlignTop : Qt::AlignRight;
    if (chart->legend()->alignment() != side)
        chart->legend()->setAlignment(side);
}

} // namespace

ChartPanel::ChartPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("chartPanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 6, 0); // the hint and the last tab clear the window's edge
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
    hint->setObjectName("chartHint");
    hint->setForegroundRole(QPalette::PlaceholderText); // the theme's quiet text, 4.5:1 in every theme
    hint_ = hint;
    row->addWidget(hint, 1);
    layout->addLayout(row);

    addPages(layout);

    auto* splitter = new QSplitter(Qt::Vertical);
    for (ChartKind kind : allChartKinds()) {
        auto* chart = new MotionChart(kind);
        auto* view = new QChartView(chart);
        view->setObjectName(QStringLiteral("chart-%1").arg(QString::fromLatin1(chartKey(kind).data())));
        view->setRenderHint(QPainter::Antialiasing);
        view->setMinimumHeight(200); // title, legend and a readable plot (five charts need the scroll area)
        view->installEventFilter(this);
        view->viewport()->installEventFilter(this);
        auto* holder = new QWidget;
        auto* box = new QVBoxLayout(holder);
        box->setContentsMargins(0, 0, 0, 0);
        box->addWidget(view);
        // A chart's plot moved (its value labels grew, a page or a size changed): the column's
        // plots are lined up again once the layout has settled.
        connect(chart, &QChart::plotAreaChanged, this, &ChartPanel::scheduleAlignment);
        charts_[slot(kind)] = chart;
        views_[slot(kind)] = view;
        holders_[slot(kind)] = holder;
        splitter->addWidget(holder);
    }
    applies_.fill(true);
    wanted_.fill(true);
    available_.fill(true);
    QList<int> sizes = {300, 300, 260};
    while (sizes.size() < qsizetype(allChartKinds().size()))
        sizes << 220; // every chart a size: one left out would start collapsed to nothing
    splitter->setSizes(sizes);
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

void ChartPanel::scheduleAlignment()
{
    if (alignmentPending_)
        return;
    alignmentPending_ = true;
    QTimer::singleShot(0, this, [this] {
        alignmentPending_ = false;
        std::vector<MotionChart*> column;
        for (std::size_t s = 0; s < kinds; ++s)
            if (holders_[s]->isVisible())
                column.push_back(charts_[s]);
        alignPlotAreas(column);
    });
}

void ChartPanel::addPages(QVBoxLayout* layout)
{
    pages_ = new QTabBar;
    pages_->setObjectName("chartPages");
    pages_->setExpanding(false);
    pages_->setElideMode(Qt::ElideNone);
    pages_->setUsesScrollButtons(false);
    // Whole tabs are as wide as their names: as the panel's minimum they would hold the window
    // wider than the screen once the tabs were shown (a font grown by lecture mode, a resize),
    // and the list below would never get its turn. The panel's width decides (paginate).
    pages_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    pages_->hide();
    layout->addWidget(pages_);
    // Where the tabs do not fit the panel whole (the street's six charts, one a page in lecture
    // mode at 1280x720), a list names the page shown instead: scroll arrows would hide part of
    // a tab's name from the back of the hall.
    pagesMenu_ = new QComboBox;
    pagesMenu_->setObjectName("chartPagesMenu");
    pagesMenu_->setAccessibleName(tr("Chart page"));
    pagesMenu_->setToolTip(tr("The charts shown: one page of the stage's charts"));
    pagesMenu_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    pagesMenu_->hide();
    layout->addWidget(pagesMenu_, 0, Qt::AlignLeft);
    connect(pages_, &QTabBar::currentChanged, this, [this](int page) {
        if (page >= 0 && page < pagesMenu_->count()) {
            const QSignalBlocker quiet(pagesMenu_);
            pagesMenu_->setCurrentIndex(page);
        }
        if (!updating_ && page >= 0)
            showPage(page);
    });
    connect(pagesMenu_, &QComboBox::currentIndexChanged, this, [this](int page) {
        if (page >= 0)
            pages_->setCurrentIndex(page);
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
        applies_[i] = chartApplies(kind, scene.id, units);
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
    paginate();
}

void ChartPanel::setChartShown(ChartKind kind, bool on)
{
    const std::size_t i = slot(kind);
    wanted_[i] = on;
    views_[i]->setHidden(!(on && available_[i]));
    paginate();
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
        return false; // a chart on another page is kept up too: it may be exported
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

std::vector<ChartKind> ChartPanel::shownCharts() const
{
    std::vector<ChartKind> out;
    for (ChartKind kind : allChartKinds())
        if (!views_[slot(kind)]->isHidden())
            out.push_back(kind);
    return out;
}

ChartKind ChartPanel::currentChart() const
{
    if (onCurrentPage(current_))
        return current_;
    for (ChartKind kind : shownCharts())
        if (onCurrentPage(kind))
            return kind;
    return current_;
}

bool ChartPanel::onCurrentPage(ChartKind kind) const
{
    return views_[slot(kind)]->isVisibleTo(this);
}

int ChartPanel::readableChartHeight() const
{
    int tallest = 200;
    for (ChartKind kind : shownCharts())
        tallest = std::max(tallest, readableHeight(*charts_[slot(kind)], views_[slot(kind)]->width()));
    return tallest;
}

void ChartPanel::paginate()
{
    for (ChartKind kind : shownCharts())
        placeLegend(charts_[slot(kind)], views_[slot(kind)]->width());
    const std::vector<ChartKind> kinds = shownCharts();
    const int need = readableChartHeight();
    const int header = layout()->itemAt(0) ? layout()->itemAt(0)->sizeHint().height() : 0;
    const int room = height() - header - layout()->spacing();
    std::size_t perPage = std::max<std::size_t>(1, std::size_t(std::max(room, 0) / need));
    if (perPage < kinds.size()) { // the tabs, or the list of pages, take a row of their own
        const int row = std::max(pages_->sizeHint().height(), pagesMenu_->sizeHint().height());
        perPage = std::max<std::size_t>(1, std::size_t(std::max(room - row, 0) / need));
    }
    const int count = kinds.empty() ? 0 : int((kinds.size() + perPage - 1) / perPage);
    const int current = pages_->currentIndex();
    updating_ = true;
    while (pages_->count() > count)
        pages_->removeTab(pages_->count() - 1);
    for (int p = 0; p < count; ++p) {
        QStringList names;
        for (std::size_t i = std::size_t(p) * perPage; i < std::min(kinds.size(), std::size_t(p + 1) * perPage); ++i) {
            page_[slot(kinds[i])] = p;
            names << chartName(kinds[i]);
        }
        const QString label = names.join(QStringLiteral(" + "));
        if (p < pages_->count())
            pages_->setTabText(p, label);
        else
            pages_->addTab(label);
    }
    {
        const QSignalBlocker quiet(pagesMenu_);
        pagesMenu_->clear();
        for (int p = 0; p < count; ++p)
            pagesMenu_->addItem(pages_->tabText(p));
    }
    // Tabs wider than the panel give way to the list of pages (see the constructor).
    const QMargins margins = layout()->contentsMargins();
    const bool tabsFit = pages_->sizeHint().width() <= width() - margins.left() - margins.right();
    pages_->setVisible(count > 1 && tabsFit);
    pagesMenu_->setVisible(count > 1 && !tabsFit);
    pages_->setCurrentIndex(std::clamp(current, 0, std::max(count - 1, 0)));
    {
        const QSignalBlocker quiet(pagesMenu_);
        pagesMenu_->setCurrentIndex(pages_->currentIndex());
    }
    updating_ = false;
    showPage(pages_->currentIndex());
}

void ChartPanel::showPage(int page)
{
    for (ChartKind kind : allChartKinds()) {
        const std::size_t i = slot(kind);
        // A chart wanted but not drawable now (the difference chart without a comparison or a
        // closed form) has a hidden view and no page: its holder must not keep an empty place.
        holders_[i]->setVisible(shown(i) && !views_[i]->isHidden() && (pages_->count() <= 1 || page_[i] == page));
    }
    emit pageChanged();
}

QString ChartPanel::chartName(ChartKind kind)
{
    switch (kind) {
    case ChartKind::Position:
        return tr("Position");
    case ChartKind::Velocity:
        return tr("Velocity");
    case ChartKind::Energy:
        return tr("Energy");
    case ChartKind::Momentum:
        return tr("Momentum");
    case ChartKind::Activity:
        return tr("Activity");
    case ChartKind::Difference:
        return tr("Difference");
    case ChartKind::Spin:
        return tr("Spin");
    case ChartKind::FootRate:
        return tr("Foot rate");
    case ChartKind::Speeds:
        return tr("Speeds");
    }
    return {};
}

void ChartPanel::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    // The export hint is a tip (the context menu says it too): shown where it fits whole.
    const int used = ball_->sizeHint().width() + ballCount_->sizeHint().width() +
                     ballCount_->fontMetrics().horizontalAdvance(tr("Charts of ball")) + 48;
    hint_->setVisible(used + hint_->sizeHint().width() <= width());
    paginate();
}

void ChartPanel::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) // lecture mode: larger charts need more room each
        QMetaObject::invokeMethod(
            this, [this] { paginate(); }, Qt::QueuedConnection); // after the charts' fonts
}

bool ChartPanel::eventFilter(QObject* watched, QEvent* event)
{
    for (ChartKind kind : allChartKinds()) {
        QChartView* view = views_[slot(kind)];
        if (!view || (watched != view && watched != view->viewport()))
            continue;
        if (event->type() == QEvent::MouseButtonPress) // chosen with a click, not a pointer passing over
            current_ = kind;
        if (event->type() == QEvent::ContextMenu) {
            current_ = kind;
            QMenu menu;
            menu.addAction(tr("Export this chart as PNG..."), this,
                           [this, kind] { emit exportRequested(kind, ExportFormat::Png); });
            menu.addAction(tr("Export this chart as SVG..."), this,
                           [this, kind] { emit exportRequested(kind, ExportFormat::Svg); });
            // A lab report's figure: vector, with its fonts, at the size the options choose.
            menu.addAction(tr("Export this chart as PDF..."), this,
                           [this, kind] { emit exportRequested(kind, ExportFormat::Pdf); });
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
