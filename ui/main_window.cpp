// SPDX-License-Identifier: MIT
// The window's state: each stage's remembered setup, the run it starts, what follows a
// new run or selection. Its widgets are built in main_window_layout.cpp, it follows the
// run in main_window_refresh.cpp and exports in main_window_export.cpp.
#include "main_window.h"

#include "charts/run_description.h"
#include "i18n/core_text.h"
#include "panels/parameter_panel.h"
#include "panels/spin_equations.h"
#include "panels/stage_navigator.h"
#include "panels/status_readout.h"
#include "panels/street_equations.h"
#include "panels/transport_bar.h"
#include "sim/pacing.h"
#include "view/ball_view.h"
#include "view/street_camera_bar.h"

#include <QApplication>
#include <QStatusBar>

namespace ab::ui {

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
    connect(&controller_, &RunController::speedChanged, this,
            [this](double factor) { setupFor(scene_).speed = factor; });
    connect(&controller_, &RunController::selectionChanged, this, &MainWindow::ballSelected);
    // Enter in a field applies it and gives the keys back to the window's shortcuts (not
    // to the 3D view, whose focus takes the arrows for the camera).
    for (QObject* panel : {static_cast<QObject*>(parameters_), static_cast<QObject*>(runOptions_)})
        connect(panel, SIGNAL(editDone()), this, SLOT(handKeysBack()));
    connect(parameters_, &ParameterPanel::reportValuesRequested, runOptions_, &RunOptionsPanel::clearRefusals);
    fpsClock_.start();
    paceClock_.start();
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

MainWindow::Setup& MainWindow::setupFor(SceneId scene)
{
    auto it = setups_.find(scene);
    if (it == setups_.end()) {
        Setup s{RunSpec(scene), RunOptions{}, defaultSpeed(scene)};
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
        const QString message = refusalText(e);
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
    navigator_->setPreset(scene, {}, {}); // the lecturer chose the stage: no preset's text
    showPanels(scene);
}

std::optional<QString> MainWindow::showSetup(const RunSpec& spec, const RunOptions& options,
                                             std::optional<double> speed)
{
    const Setup candidate{spec, options, speed.value_or(defaultSpeed(spec.scene))};
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
    controller_.setSpeed(setup.speed);
    transport_->setSpeed(controller_.speed());
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
    for (QAction* shot : streetShots_) // the street's camera shots, greyed out in the other stages
        shot->setEnabled(view_ != nullptr && scene_ == SceneId::Street);
    const SceneInfo& info = sceneInfo(scene_);
    setWindowTitle(tr("Amazeballs - stage %1: %2").arg(info.stage).arg(coreText(info.title)));
    const RunSpec& spec = controller_.spec();
    const SceneLayout& layout = controller_.layout();
    const int ball = controller_.selectedBall();
    readout_->setRun(spec);
    // The comparison's lines are named after both runs; without one the names stay plain.
    const QString compareLabel = controller_.comparing()
                                     ? RunDescription::runLabel(controller_.comparisonEngine()->simulation().spec())
                                     : QString();
    charts_->setComparison(RunDescription::runLabel(spec), compareLabel);
    charts_->configure(info, layout.balls, ball, controller_.plannedEnd(), chartUnits());
    navigator_->setRunSection(SpinEquations::html(controller_.engine().simulation()) + StreetEquations::html(spec));
    showReference();
    if (view_) {
        view_->setScene(layout, coreText(info.lengthUnit), ballColours(spec, layout.balls), framedScene_ != scene_);
        framedScene_ = scene_;
        view_->setSelected(ball);
        streetCameras_->setVisible(layout.street != nullptr);
        view_->setGhosts({}, compareLabel.isEmpty()
                                 ? QString()
                                 : tr("solid: %1, ghost: %2").arg(RunDescription::runLabel(spec), compareLabel));
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
    return chartUnitsOf(meter, controller_.spec());
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
    // Drawn beside a comparison run too: the legend names each family of lines once.
    const std::optional<ReferenceMotion> motion = closedFormMotion();
    charts_->setReference(motion ? &*motion : nullptr);
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

void MainWindow::takeRunOf(MainWindow& old)
{
    setups_ = old.setups_;
    const std::optional<double> lookedAt = old.transport_->viewTime();
    framedScene_ = old.framedScene_; // the camera stays where it was, not framed anew
    controller_.takeOver(old.controller_);
    showPanels(scene_);
    for (ChartKind kind : allChartKinds())
        charts_->setChartShown(kind, old.charts_->chartShown(kind));
    navigator_->setPreset(scene_, old.navigator_->presetName(), old.navigator_->presetDescription());
    if (view_ && old.view_) {
        const OrbitCamera& c = old.view_->camera();
        view_->setCameraPose(c.target(), c.yaw(), c.pitch(), c.distance(), c.fovY());
        if (const std::optional<StreetShot> shot = old.view_->streetShot())
            view_->setStreetShot(*shot); // the flood shot goes on following the flood
    }
    if (lookedAt)
        transport_->lookAt(*lookedAt);
    refresh();
}

void MainWindow::setTurntable(bool on)
{
    if (on && view_)
        turntable_.start();
    else
        turntable_.stop();
}

void MainWindow::handKeysBack()
{
    if (QWidget* focus = QApplication::focusWidget(); focus && isAncestorOf(focus))
        focus->clearFocus();
    setFocus(Qt::OtherFocusReason);
}

void MainWindow::showError(const QString& message)
{
    statusBar()->showMessage(message, 10000);
}

} // namespace ab::ui
