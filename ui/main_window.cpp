// SPDX-License-Identifier: MIT
#include "main_window.h"

#include "about_box.h"
#include "charts/chart_export.h"
#include "export_files.h"
#include "figures/figure_actions.h"
#include "video/animation_actions.h"
#include "i18n/core_text.h"
#include "panels/parameter_panel.h"
#include "panels/stage_navigator.h"
#include "panels/status_readout.h"
#include "panels/transport_bar.h"
#include "presets/preset_actions.h"
#include "tools/background_job.h"
#include "tools/tools_menu.h"
#include "view/ball_view.h"

#include <QApplication>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

constexpr int maxTracePoints = 20000;

QString labelOf(const RunSpec& spec)
{
    return qs(variantLabel(RunVariant{spec.model, spec.integrator, spec.impacts, spec.dt}));
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setWindowTitle(tr("Amazeballs"));
    setWindowIcon(QIcon(":/icons/amazeballs.svg"));
    buildLayout();
    buildMenus();
    connect(&controller_, &RunController::runReplaced, this, &MainWindow::runReplaced);
    connect(&controller_, &RunController::advanced, this, &MainWindow::refresh);
    connect(&controller_, &RunController::playingChanged, transport_, &TransportBar::setPlaying);
    connect(&controller_, &RunController::speedChanged, transport_, &TransportBar::setSpeed);
    connect(&controller_, &RunController::selectionChanged, this, &MainWindow::ballSelected);
    fpsClock_.start();
    panelTimer_.setInterval(20); // a part a tick: about a frame apart under software OpenGL
    connect(&panelTimer_, &QTimer::timeout, this, &MainWindow::refreshPanelPart);
    turntable_.setInterval(16);
    connect(&turntable_, &QTimer::timeout, this, [this] {
        if (view_)
            view_->turn(0.16f); // 10 degrees a second
    });
    showScene(SceneId::Bounce1d);
}

MainWindow::~MainWindow() = default;

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
    splitter->setSizes({340, 640, 480});
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
    scroll->setWidget(settings);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
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
        return view_->container();
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

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    presets_ = new PresetActions(this);
    presets_->addFileActions(file);
    file->addAction(tr("Export current chart..."), QKeySequence(tr("Ctrl+E")), this,
                    [this] { exportInteractively(charts_->currentChart(), ExportFormat::Png); });
    QMenu* charts = file->addMenu(tr("Export chart"));
    for (ChartKind kind : allChartKinds())
        charts->addAction(tr("%1 chart...").arg(QString::fromLatin1(chartKey(kind).data())), this,
                          [this, kind] { exportInteractively(kind, ExportFormat::Png); });
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

MainWindow::Setup& MainWindow::setupFor(SceneId scene)
{
    auto it = setups_.find(scene);
    if (it == setups_.end()) {
        Setup s{RunSpec(scene), RunOptions{}};
        s.options.model = s.spec.model;
        s.options.integrator = s.spec.integrator;
        s.options.impacts = s.spec.impacts;
        s.options.steps = defaultSteps(scene, s.spec.model);
        it = setups_.emplace(scene, std::move(s)).first;
    }
    return it->second;
}

std::optional<QString> MainWindow::startRun(const Setup& setup)
{
    try {
        controller_.setRun(setup.spec, setup.options.steps, setup.options.compare);
    } catch (const InputError& e) {
        const QString message = QString::fromUtf8(e.what());
        showError(message);
        return message;
    }
    return std::nullopt;
}

void MainWindow::showScene(SceneId scene)
{
    const Setup& setup = setupFor(scene);
    if (const auto error = startRun(setup)) {
        navigator_->setCurrent(scene_); // stay on the stage that runs
        return;
    }
    showPanels(scene);
}

std::optional<QString> MainWindow::showSetup(const RunSpec& spec, const RunOptions& options)
{
    const Setup candidate{spec, options};
    if (auto error = startRun(candidate))
        return error;
    setups_.insert_or_assign(spec.scene, candidate);
    showPanels(spec.scene);
    return std::nullopt;
}

void MainWindow::showPanels(SceneId scene)
{
    scene_ = scene;
    const Setup& setup = setupFor(scene);
    const SceneInfo& info = sceneInfo(scene);
    navigator_->setCurrent(scene);
    parameters_->setScene(info, setup.spec.model, setup.spec.params);
    runOptions_->showOptions(info, setup.options);
}

bool MainWindow::applyValues(const ParamValues& values)
{
    Setup candidate = setupFor(scene_);
    candidate.spec.params = values;
    if (const auto error = startRun(candidate)) {
        parameters_->refuse({}, *error);
        return false;
    }
    setups_.at(scene_) = candidate;
    parameters_->showValues(values);
    return true;
}

bool MainWindow::applyOptions(const RunOptions& options)
{
    Setup candidate = setupFor(scene_);
    candidate.options = options;
    candidate.spec.model = options.model;
    candidate.spec.integrator = options.integrator;
    candidate.spec.impacts = options.impacts;
    candidate.spec.dt = options.dt;
    if (const auto error = startRun(candidate)) {
        runOptions_->refuse(*error);
        return false;
    }
    const bool modelChanged = candidate.spec.model != setupFor(scene_).spec.model;
    setups_.at(scene_) = candidate;
    const SceneInfo& info = sceneInfo(scene_);
    runOptions_->showOptions(info, options);
    if (modelChanged) // the panel shows only what the chosen model reads
        parameters_->setScene(info, options.model, candidate.spec.params);
    return true;
}

void MainWindow::runReplaced()
{
    scene_ = controller_.spec().scene;
    const SceneInfo& info = sceneInfo(scene_);
    setWindowTitle(tr("Amazeballs - stage %1: %2").arg(info.stage).arg(coreText(info.title)));
    const RunSpec& spec = controller_.spec();
    const SceneLayout& layout = controller_.layout();
    const int ball = controller_.selectedBall();
    readout_->setUnits(coreText(info.timeUnit), coreText(info.lengthUnit));
    // The comparison's lines are named after both runs; without one the names stay plain.
    const QString compareLabel =
        controller_.comparing() ? labelOf(controller_.comparisonEngine()->simulation().spec()) : QString();
    charts_->setComparison(labelOf(spec), compareLabel);
    charts_->configure(info, layout.balls, ball, controller_.plannedEnd(), chartUnits());
    showReference();
    if (view_) {
        view_->setScene(layout, coreText(info.lengthUnit), ballColours(spec, layout.balls), framedScene_ != scene_);
        framedScene_ = scene_;
        view_->setSelected(ball);
        view_->setGhosts({}, compareLabel.isEmpty() ? QString()
                                                    : tr("solid: %1, ghost: %2").arg(labelOf(spec), compareLabel));
    }
    transport_->goLive();
    panelClock_.invalidate();
    cancelPanelRefresh();
    panelsPlaying_ = false;
    refresh();
}

ChartUnits MainWindow::chartUnits() const
{
    const ConservationMeter meter(controller_.engine().simulation());
    return ChartUnits{meter.perUnitMass(), meter.hasSpring()};
}

void MainWindow::ballSelected(int ball)
{
    const SceneLayout& layout = controller_.layout();
    charts_->configure(sceneInfo(scene_), layout.balls, ball, controller_.plannedEnd(), chartUnits());
    showReference();
    if (view_)
        view_->setSelected(ball);
    panelClock_.invalidate();
    cancelPanelRefresh();
    refresh();
}

void MainWindow::showReference()
{
    // The textbook closed form of the same constants (core/reference/), also beside the
    // report's model: the gap between the two is the report's scheme at work. A run that
    // starts from a given state, or constants no closed form covers, get none.
    const RunSpec& spec = controller_.spec();
    reference_.reset();
    if (!spec.init) {
        try {
            reference_ = reference::makeReference(spec, controller_.plannedEnd());
        } catch (const InputError&) {
        }
    }
    const int ball = controller_.selectedBall();
    // Beside a comparison run the closed form would be a third line per axis, dashed like
    // the comparison's dotted one: the legend could no longer be read, so it gives way.
    if (!reference_ || ball >= reference_->balls() || controller_.comparing()) {
        charts_->setReference(nullptr);
        return;
    }
    const reference::Reference* ref = reference_.get();
    const ReferenceMotion motion{tr("closed form"), [ref, ball](double t) -> std::optional<Kinematics> {
                                     Kinematics k{ref->position(ball, t), ref->velocity(ball, t)};
                                     if (!k.p.allFinite() || !k.v.allFinite())
                                         return std::nullopt; // never drawn
                                     return k;
                                 }};
    charts_->setReference(&motion);
}

bool MainWindow::resumeFromLookedBackMoment()
{
    const std::optional<double> viewT = transport_->viewTime();
    if (!viewT || !controller_.hasRun())
        return false;
    struct Moment {
        long long step;
        double t;
    };
    std::optional<Moment> shown;
    controller_.engine().read([&](const Recording& rec, const Frame&) {
        if (const Frame* f = rec.frameAt(*viewT))
            shown = Moment{f->step, f->t};
    });
    transport_->goLive();
    if (!shown || shown->step >= controller_.status().steps)
        return false;
    controller_.resumeFrom(shown->step);
    statusBar()->showMessage(tr("Went back to t = %1 %2: the run goes on from there, and what came after is dropped")
                                 .arg(QString::number(shown->t, 'g', 6), coreText(sceneInfo(scene_).timeUnit)),
                             8000);
    return true;
}

void MainWindow::refresh()
{
    if (!controller_.hasRun())
        return;
    const EngineStatus status = controller_.status();
    const std::optional<double> viewT = transport_->viewTime();
    controller_.engine().read([&](const Recording& rec, const Frame& current) { refreshView(rec, current, viewT); });
    if (const RunEngine* compare = controller_.comparisonEngine()) {
        compare->read([&](const Recording& rec, const Frame& current) {
            if (view_) { // the comparison at the moment shown: it never runs ahead of the main run
                const Frame* shown = viewT ? rec.frameAt(*viewT) : &current;
                view_->setGhosts((shown ? shown : &current)->p, view_->ghostLegend());
            }
        });
    }
    // The 3D view follows every new state. The panels redraw four times a second while
    // playing: with a GL view in the window every widget redraw recomposes the whole
    // window, which software OpenGL pays for in the frame it lands in, so their refresh
    // is spread over the next frames, a chart at a time. The moment play stops is spread
    // too (it is still part of playback: the run ending under a lecturer's eyes); any
    // other change of a stopped run (a scrub, a new selection) redraws them at once.
    const bool stopping = panelsPlaying_ && !status.playing;
    const bool spread = status.playing || stopping;
    panelsPlaying_ = status.playing;
    if (!spread) {
        cancelPanelRefresh();
        refreshPanels();
        return;
    }
    const bool due = stopping || !panelClock_.isValid() || panelClock_.elapsed() >= 250;
    if (!due || (panelPart_ >= 0 && !stopping))
        return;
    panelClock_.restart();
    panelPart_ = 0; // from the first chart again, with what is recorded now
    panelTimer_.start();
}

void MainWindow::cancelPanelRefresh()
{
    panelTimer_.stop();
    panelPart_ = -1;
}

void MainWindow::refreshPanels()
{
    const EngineStatus status = controller_.status();
    const std::optional<double> viewT = transport_->viewTime();
    controller_.engine().read([&](const Recording& rec, const Frame&) { charts_->showTrack(rec.track()); });
    if (const RunEngine* compare = controller_.comparisonEngine())
        compare->read([&](const Recording& rec, const Frame&) { charts_->showComparisonTrack(rec.track()); });
    panelClock_.restart();
    charts_->setCursorTime(viewT ? viewT : std::optional<double>(status.t));
    refreshReadings(status);
}

void MainWindow::refreshPanelPart()
{
    if (!controller_.hasRun() || panelPart_ < 0) {
        cancelPanelRefresh();
        return;
    }
    const EngineStatus status = controller_.status();
    const std::optional<double> viewT = transport_->viewTime();
    const std::optional<double> cursor = viewT ? viewT : std::optional<double>(status.t);
    // The next shown chart; hidden ones take no tick.
    while (static_cast<std::size_t>(panelPart_) < ChartPanel::kSlots) {
        const auto slot = static_cast<std::size_t>(panelPart_++);
        bool drawn = false;
        controller_.engine().read([&](const Recording& rec, const Frame&) {
            if (const RunEngine* compare = controller_.comparisonEngine())
                compare->read([&](const Recording& other, const Frame&) {
                    drawn = charts_->refreshSlot(slot, rec.track(), &other.track(), cursor);
                });
            else
                drawn = charts_->refreshSlot(slot, rec.track(), nullptr, cursor);
        });
        if (drawn)
            return;
    }
    refreshReadings(status); // the last part: slider and readings
    cancelPanelRefresh();
}

void MainWindow::refreshReadings(const EngineStatus& status)
{
    double start = status.t;
    controller_.engine().read([&](const Recording& rec, const Frame& current) {
        start = rec.frames().empty() ? current.t : rec.frames().front().t;
    });
    transport_->setRecorded(start, status.t, coreText(sceneInfo(scene_).timeUnit));
    readout_->show(status);
    if (view_ && fpsClock_.elapsed() >= 1000) {
        readout_->setFrameRate(1000.0 * framesSinceFps_ / double(fpsClock_.restart()));
        framesSinceFps_ = 0;
    }
}

void MainWindow::refreshView(const Recording& rec, const Frame& current, std::optional<double> viewT)
{
    if (!view_)
        return;
    const Frame* shown = viewT ? rec.frameAt(*viewT) : &current;
    if (!shown)
        shown = &current;
    view_->setBalls(shown->p);
    if (controller_.layout().axes == 1) {
        view_->setTrace({}); // the vertical scene's trace would hide the ball's own line
        return;
    }
    // The selected ball's path so far (Figure 2.6), thinned to a drawable number of points.
    const MotionTrack& track = rec.track();
    const double until = viewT.value_or(current.t);
    const auto end = std::upper_bound(track.t().begin(), track.t().end(), until) - track.t().begin();
    const std::size_t n = static_cast<std::size_t>(end);
    const std::size_t stride = std::max<std::size_t>(1, n / maxTracePoints);
    std::vector<QVector3D> trace;
    trace.reserve(n / stride + 2);
    for (std::size_t i = 0; i < n; i += stride)
        trace.emplace_back(float(track.p(0)[i]), float(track.p(1)[i]), float(track.p(2)[i]));
    if (n > 0 && (n - 1) % stride != 0)
        trace.emplace_back(float(track.p(0)[n - 1]), float(track.p(1)[n - 1]), float(track.p(2)[n - 1]));
    view_->setTrace(std::move(trace));
}

void MainWindow::setTurntable(bool on)
{
    if (on && view_)
        turntable_.start();
    else
        turntable_.stop();
}

void MainWindow::showError(const QString& message)
{
    statusBar()->showMessage(message, 10000);
}

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

void MainWindow::showKeys()
{
    QMessageBox::information(
        this, tr("Keys and mouse"),
        tr("<table>"
           "<tr><td><b>Space</b></td><td>play / pause</td></tr>"
           "<tr><td><b>Right</b></td><td>one step</td></tr>"
           "<tr><td><b>R</b></td><td>reset the run</td></tr>"
           "<tr><td><b>[ ]</b></td><td>slower / faster</td></tr>"
           "<tr><td><b>1 - 4</b></td><td>the report's stages; PgUp / PgDn: previous / next</td></tr>"
           "<tr><td><b>Ctrl+E</b></td><td>export the current chart (Ctrl+Shift+E: its data as CSV)</td></tr>"
           "<tr><td><b>Home</b></td><td>reset the 3D view; T: turntable</td></tr>"
           "<tr><td colspan=2><br><b>3D view</b>: left drag orbits, right or middle drag (or Shift+left) pans, "
           "the wheel zooms, a click selects a ball, a double click on empty space resets the view. "
           "After a click in the view the arrow keys move the camera as in the report's WebGL program; "
           "Esc gives them back to the transport.</td></tr></table>"));
}

void MainWindow::showAbout()
{
    showAboutBox(this);
}

} // namespace ab::ui
