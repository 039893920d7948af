// SPDX-License-Identifier: MIT
// The window's widgets and menus: built once, in the constructor.
#include "main_window.h"

#include "about_box.h"
#include "figures/figure_actions.h"
#include "i18n/core_text.h"
#include "keys_dialog.h"
#include "panels/parameter_panel.h"
#include "panels/stage_navigator.h"
#include "panels/status_readout.h"
#include "panels/transport_bar.h"
#include "presets/preset_actions.h"
#include "tools/tools_menu.h"
#include "video/animation_actions.h"
#include "view/ball_view.h"
#include "view/street_camera_bar.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QLabel>
#include <QMenuBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace ab::ui {

namespace {

// Keeps the settings' combo boxes as wide as their longest item and the settings at least
// as wide as their layout's minimum, as fonts and items change (a combo box's own minimum
// is a dozen characters, whatever its size policy); none while their scroll area is
// folded away (lecture mode), so that they do not widen the column.
class KeepLayoutMinimum : public QObject {
public:
    KeepLayoutMinimum(QWidget* settings, QWidget* scroll) : QObject(settings), settings_(settings), scroll_(scroll)
    {
        settings->installEventFilter(this);
        scroll->installEventFilter(this);
    }
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        const QEvent::Type t = event->type();
        if (t == QEvent::LayoutRequest || t == QEvent::Show || (watched == scroll_ && t == QEvent::Resize)) {
            for (QComboBox* combo : settings_->findChildren<QComboBox*>())
                combo->setMinimumWidth(combo->sizeHint().width());
            const bool open = scroll_->height() > 0 && settings_->layout();
            settings_->setMinimumWidth(open ? settings_->layout()->minimumSize().width() : 0);
        }
        return QObject::eventFilter(watched, event);
    }

private:
    QWidget* settings_;
    QWidget* scroll_;
};

// A wheel turned over a choice in the scrolling settings column scrolls the column and never
// turns the choice, focused or not: on the way down the column it would change the model, the
// integrator or the impacts, and with them start the run again. A choice is made with a click
// or the keys.
class WheelScrollsTheColumn : public QObject {
public:
    WheelScrollsTheColumn(QWidget* widget, QAbstractScrollArea* column) : QObject(widget), column_(column)
    {
        widget->setFocusPolicy(Qt::StrongFocus); // the wheel gives it no focus either
        widget->installEventFilter(this);
    }
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::Wheel)
            return QObject::eventFilter(watched, event);
        QCoreApplication::sendEvent(column_->viewport(), event); // the column's own wheel
        return true;
    }

private:
    QAbstractScrollArea* column_;
};

// Gives the settings column, whenever the window has room for it, the width its choices
// need (up to 30 % of the window), taken from the 3D view while that keeps 400 px, then
// from the charts: a window opened small and then maximised would otherwise keep a column
// that scrolls sideways, its choices and buttons cut at its edge. It only widens, so a
// column the user dragged narrower stays so until the window grows again.
class WidenSettingsColumn : public QObject {
public:
    WidenSettingsColumn(QSplitter* columns, QScrollArea* settings)
        : QObject(columns), columns_(columns), settings_(settings)
    {
        columns->installEventFilter(this);
    }
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Resize || event->type() == QEvent::Show)
            QMetaObject::invokeMethod(
                this, [this] { widen(); }, Qt::QueuedConnection);
        return QObject::eventFilter(watched, event);
    }

private:
    void widen()
    {
        QList<int> sizes = columns_->sizes();
        if (!settings_ || sizes.size() != 3 || !settings_->widget() || settings_->height() == 0)
            return;
        const int need = settings_->widget()->minimumWidth() + settings_->verticalScrollBar()->sizeHint().width() +
                         2 * settings_->frameWidth();
        const int target = std::min(need, int(0.3 * columns_->width()));
        int missing = target - sizes[0];
        if (missing <= 0)
            return;
        const int fromView = std::clamp(sizes[1] - 400, 0, missing);
        const int fromCharts = std::clamp(sizes[2] - 300, 0, missing - fromView);
        if (fromView + fromCharts == 0)
            return;
        sizes[0] += fromView + fromCharts;
        sizes[1] -= fromView;
        sizes[2] -= fromCharts;
        columns_->setSizes(sizes);
    }

    QSplitter* columns_;
    QScrollArea* settings_;
};

} // namespace

void MainWindow::buildLayout()
{
    transport_ = new TransportBar;
    auto* bar = addToolBar(tr("Transport"));
    bar->setObjectName("transportToolBar");
    bar->setMovable(false);
    bar->addWidget(transport_);

    charts_ = new ChartPanel;
    auto* splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(buildLeftPanel());
    splitter->addWidget(buildViewArea());
    splitter->addWidget(charts_);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 3);
    splitter->setStretchFactor(2, 2);
    splitter->setSizes({400, 600, 480}); // the settings column as wide as its widest choice at 1400
    new WidenSettingsColumn(splitter, splitter->findChild<QScrollArea*>("settingsScroll"));
    setCentralWidget(splitter);
    readout_ = new StatusReadout(statusBar());
    readout_->setFrameRate(view_ ? 0.0 : -1.0);

    // Play or Step while looking back forks the run at the moment shown (issue: step
    // back); Pause keeps the moment in view.
    connect(transport_, &TransportBar::playToggled, this, [this] {
        if (controller_.playing()) {
            controller_.pause();
            return;
        }
        resumeFromLookedBackMoment();
        controller_.play();
    });
    connect(transport_, &TransportBar::stepRequested, this, [this] {
        resumeFromLookedBackMoment();
        controller_.stepOnce();
    });
    connect(transport_, &TransportBar::resetRequested, &controller_, &RunController::reset);
    connect(transport_, &TransportBar::speedRequested, &controller_, &RunController::setSpeed);
    connect(transport_, &TransportBar::viewTimeChanged, this, &MainWindow::refresh);
    connect(charts_, &ChartPanel::ballRequested, &controller_, &RunController::selectBall);
    connect(charts_, &ChartPanel::exportRequested, this, &MainWindow::exportInteractively);
    // Queued: a page can change inside a relayout, and a relayout can come while the run's
    // recording is locked (a reading or chart being refreshed), which refreshPanels locks.
    connect(
        charts_, &ChartPanel::pageChanged, this,
        [this] {
            if (controller_.hasRun())
                refreshPanels(); // the charts of the new page were not drawn while off it
        },
        Qt::QueuedConnection);
}

QWidget* MainWindow::buildLeftPanel()
{
    navigator_ = new StageNavigator;
    connect(navigator_, &StageNavigator::sceneRequested, this, &MainWindow::showScene);

    auto* settings = new QWidget;
    auto* layout = new QVBoxLayout(settings);
    auto* runTitle = new QLabel(tr("<b>Run</b>"));
    runOptions_ = new RunOptionsPanel;
    auto* paramTitle = new QLabel(tr("<b>Constants</b> (hover for the equation)"));
    parameters_ = new ParameterPanel;
    layout->addWidget(runTitle);
    layout->addWidget(runOptions_);
    layout->addSpacing(6);
    layout->addWidget(paramTitle);
    layout->addWidget(parameters_);
    layout->addStretch(1);
    auto* scroll = new QScrollArea;
    scroll->setObjectName("settingsScroll");
    scroll->setWidget(settings);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    // A choice is never cut to fit the column: each combo box is as wide as its longest
    // item, and the settings scroll sideways where the column is narrower. (A layout with
    // wrapped labels has a height for its width, and QScrollArea then sets the width to
    // the viewport's, below the layout's minimum, unless the widget's own minimum says no.)
    for (QComboBox* combo : settings->findChildren<QComboBox*>()) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
        new WheelScrollsTheColumn(combo, scroll);
    }
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    new KeepLayoutMinimum(settings, scroll);
    connect(parameters_, &ParameterPanel::valuesProposed, this, &MainWindow::applyValues);
    connect(runOptions_, &RunOptionsPanel::optionsProposed, this, &MainWindow::applyOptions);

    auto* left = new QSplitter(Qt::Vertical);
    left->addWidget(navigator_);
    left->addWidget(scroll);
    left->setStretchFactor(0, 1);
    left->setStretchFactor(1, 1);
    left->setMinimumWidth(300);
    return left;
}

QWidget* MainWindow::buildViewArea()
{
    if (BallView::available()) {
        view_ = new BallView; // owned by its container
        connect(view_, &BallView::ballPicked, &controller_, &RunController::selectBall);
        connect(view_, &BallView::keysReleased, this, [this] {
            activateWindow();
            transport_->setFocus();
        });
        connect(view_, &BallView::framePainted, this, [this](double, double) { ++framesSinceFps_; });
        // The street's camera shots above the view, shown in stage 5 only (runReplaced).
        auto* area = new QWidget;
        area->setObjectName("viewArea");
        auto* column = new QVBoxLayout(area);
        column->setContentsMargins(0, 0, 0, 0);
        column->setSpacing(0);
        streetCameras_ = new StreetCameraBar(view_);
        streetCameras_->hide();
        column->addWidget(streetCameras_);
        column->addWidget(view_->container(), 1);
        return area;
    }
    // No OpenGL windows on this platform (offscreen, minimal): say so where the view would be.
    placeholder_ = new QLabel(tr("The 3D view needs OpenGL, which the '%1' platform does not offer.\n"
                                 "Charts, constants and the run work as usual.")
                                  .arg(QGuiApplication::platformName()));
    placeholder_->setObjectName("viewPlaceholder");
    placeholder_->setAlignment(Qt::AlignCenter);
    placeholder_->setWordWrap(true);
    placeholder_->setMinimumSize(320, 240);
    return placeholder_;
}

void MainWindow::addStreetShots(QMenu* view)
{
    const std::pair<StreetShot, QString> shots[] = {{StreetShot::Foot, tr("Street: from the foot")},
                                                    {StreetShot::Side, tr("Street: from the side")},
                                                    {StreetShot::Flood, tr("Street: follow the flood")}};
    const char* keys[] = {"F", "S", "G"};
    view->addSeparator();
    for (std::size_t i = 0; i < std::size(shots); ++i) {
        const StreetShot shot = shots[i].first;
        QAction* a = view->addAction(shots[i].second, QKeySequence(QString::fromLatin1(keys[i])), this, [this, shot] {
            if (view_ && scene_ == SceneId::Street)
                view_->setStreetShot(shot);
        });
        a->setEnabled(view_ != nullptr && scene_ == SceneId::Street);
        streetShots_.push_back(a);
    }
}

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    presets_ = new PresetActions(this);
    presets_->addFileActions(file);
    file->addAction(tr("Export current chart..."), QKeySequence(tr("Ctrl+E")), this,
                    [this] { exportInteractively(charts_->currentChart(), ExportFormat::Png); });
    // Only the charts the stage shows: the menu is filled each time it opens.
    QMenu* charts = file->addMenu(tr("Export chart"));
    charts->setObjectName("exportChartMenu");
    auto fill = [this, charts] {
        charts->clear();
        for (ChartKind kind : charts_->shownCharts()) {
            QAction* a = charts->addAction(tr("%1 chart...").arg(ChartPanel::chartName(kind)), this,
                                           [this, kind] { exportInteractively(kind, ExportFormat::Png); });
            a->setObjectName(QStringLiteral("export-%1").arg(QString::fromLatin1(chartKey(kind).data())));
        }
    };
    connect(charts, &QMenu::aboutToShow, this, fill);
    fill();
    file->addAction(tr("Export chart data as CSV..."), QKeySequence(tr("Ctrl+Shift+E")), this,
                    [this] { exportInteractively(charts_->currentChart(), ExportFormat::Csv); });
    QAction* viewPng = file->addAction(tr("Export 3D view as PNG..."), this, [this] { exportViewInteractively(); });
    viewPng->setEnabled(view_ != nullptr);
    (new AnimationActions(this))->addToFileMenu(file);
    file->addSeparator();
    file->addAction(tr("Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* run = menuBar()->addMenu(tr("&Run"));
    run->addAction(tr("Play / pause"), QKeySequence(Qt::Key_Space), transport_, &TransportBar::playToggled);
    run->addAction(tr("One step"), QKeySequence(Qt::Key_Right), transport_, &TransportBar::stepRequested);
    run->addAction(tr("Reset"), QKeySequence(Qt::Key_R), &controller_, &RunController::reset);
    run->addAction(tr("Slower"), QKeySequence(Qt::Key_BracketLeft), this,
                   [this] { controller_.setSpeed(controller_.speed() / 1.5); });
    run->addAction(tr("Faster"), QKeySequence(Qt::Key_BracketRight), this,
                   [this] { controller_.setSpeed(controller_.speed() * 1.5); });

    QMenu* stage = menuBar()->addMenu(tr("&Stage"));
    for (const SceneInfo* s : allScenes()) {
        const SceneId id = s->id;
        stage->addAction(tr("%1  %2").arg(s->stage).arg(coreText(s->title)), QKeySequence(Qt::Key_0 + s->stage), this,
                         [this, id] { showScene(id); });
    }
    stage->addSeparator();
    stage->addAction(tr("Previous stage"), QKeySequence(Qt::Key_PageUp), navigator_, &StageNavigator::previous);
    stage->addAction(tr("Next stage"), QKeySequence(Qt::Key_PageDown), navigator_, &StageNavigator::next);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->setObjectName("viewMenu"); // the lecture and theme items join it (ui/shell/)
    QAction* reset = view->addAction(tr("Reset view"), QKeySequence(Qt::Key_Home), this, [this] {
        if (view_)
            view_->resetView();
    });
    QAction* turn =
        view->addAction(tr("Turntable"), QKeySequence(Qt::Key_T), this, [this](bool on) { setTurntable(on); });
    turn->setCheckable(true);
    reset->setEnabled(view_ != nullptr);
    addStreetShots(view);
    turn->setEnabled(view_ != nullptr);
    presets_->addChartToggles(view);

    presets_->addPresetsMenu(menuBar());
    figures_ = new FigureActions(this);
    figures_->addFiguresMenu(menuBar());

    addToolsMenu(this, [this] { return controller_.spec(); });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->setObjectName("helpMenu");
    help->addAction(tr("Keys and mouse"), QKeySequence::HelpContents, this, &MainWindow::showKeys);
    help->addAction(tr("About Amazeballs"), this, &MainWindow::showAbout);
}

void MainWindow::showKeys()
{
    QDialog* keys = makeKeysDialog(this, lectureKeys_);
    keys->setAttribute(Qt::WA_DeleteOnClose);
    keys->open();
}

void MainWindow::showAbout()
{
    showAboutBox(this);
}

} // namespace ab::ui
