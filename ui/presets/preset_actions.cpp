// SPDX-License-Identifier: MIT
#include "preset_actions.h"

#include "ui/i18n/core_text.h"
#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/panels/stage_navigator.h"
#include "ui/view/ball_view.h"

#include <QChartView>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

std::string presetName(const Preset& p)
{
    return "preset '" + p.name + "'";
}

// The preset's charts as kinds; an unknown key is refused, naming it.
std::vector<ChartKind> chartsOf(const Preset& p)
{
    std::vector<ChartKind> kinds;
    for (std::size_t i = 0; i < p.view.charts.size(); ++i) {
        const auto kind = parseChartKind(p.view.charts[i]);
        if (!kind) {
            std::string known;
            for (ChartKind k : allChartKinds())
                known += (known.empty() ? "" : ", ") + std::string(chartKey(k));
            throw InputError(presetName(p) + ": view.charts[" + std::to_string(i) + "]: unknown chart '" +
                             p.view.charts[i] + "' (this window shows " + known + ")");
        }
        kinds.push_back(*kind);
    }
    return kinds;
}

void showCharts(ChartPanel& panel, const std::vector<ChartKind>& shown)
{
    for (ChartKind kind : allChartKinds()) {
        const bool on = shown.empty() || std::find(shown.begin(), shown.end(), kind) != shown.end();
        panel.setChartShown(kind, on); // a preset without charts shows them all
    }
}

// The camera of the preset, completed from the current one where it leaves parts out.
void placeCamera(BallView& view, const PresetView& v)
{
    if (!v.cameraYaw && !v.cameraPitch && !v.cameraDistance && !v.cameraTarget) {
        view.resetView(); // framed for the stage, as when the stage is first shown
        return;
    }
    const OrbitCamera& c = view.camera();
    const Eigen::Vector3d t = v.cameraTarget.value_or(Eigen::Vector3d(c.target().x(), c.target().y(), c.target().z()));
    view.setCameraPose(QVector3D(float(t.x()), float(t.y()), float(t.z())), float(v.cameraYaw.value_or(c.yaw())),
                       float(v.cameraPitch.value_or(c.pitch())), float(v.cameraDistance.value_or(c.distance())));
}

QString chartName(ChartKind kind)
{
    switch (kind) {
    case ChartKind::Position:
        return PresetActions::tr("Position");
    case ChartKind::Velocity:
        return PresetActions::tr("Velocity");
    case ChartKind::Energy:
        return PresetActions::tr("Energy");
    case ChartKind::Momentum:
        return PresetActions::tr("Momentum (two or more balls)");
    case ChartKind::Activity:
        return PresetActions::tr("Moving balls and impacts (many balls)");
    case ChartKind::Difference:
        return PresetActions::tr("Difference between the runs (with a comparison or a closed form)");
    case ChartKind::Spin:
        return PresetActions::tr("Spin (balls that turn, physical model)");
    case ChartKind::FootRate:
        return PresetActions::tr("Balls passing the foot of each block (street)");
    case ChartKind::Speeds:
        return PresetActions::tr("Speeds of the balls on the street (street)");
    }
    return QString::fromLatin1(chartKey(kind).data()); // a chart added later, by its key
}

QString describe(const RunSpec& spec, long long steps)
{
    const SceneInfo& info = sceneInfo(spec.scene);
    QString text = PresetActions::tr("Stage %1 (%2), %3 model")
                       .arg(info.stage)
                       .arg(coreText(info.title), qs(std::string(modelKey(spec.model))));
    if (spec.model == ModelKind::Physical)
        text += PresetActions::tr(", %1 integrator, impacts %2")
                    .arg(qs(std::string(integratorKey(spec.integrator))), qs(std::string(impactModeKey(spec.impacts))));
    if (spec.dt)
        text += PresetActions::tr(", step %1 %2").arg(*spec.dt).arg(coreText(info.timeUnit));
    return text + PresetActions::tr(", %1 steps.").arg(steps);
}

} // namespace

Preset capturePreset(MainWindow& window, const std::string& name, const std::string& description)
{
    RunController& run = window.controller();
    const RunSpec& spec = run.spec();
    Preset p;
    p.name = name;
    p.description = description;
    p.scene = spec.scene;
    p.model = spec.model;
    p.integrator = spec.integrator;
    p.impacts = spec.impacts;
    p.dt = spec.dt;
    p.steps = run.plannedSteps();
    for (std::size_t i = 0; i < spec.params.table().size(); ++i)
        if (!spec.params.isDefault(i)) // a preset lists only what differs from the report
            p.params.emplace_back(spec.params.table()[i].key, spec.params.raw(i));
    // Only the charts the preset format names (presetChartKeys): a preset must read back.
    const std::vector<std::string>& known = presetChartKeys();
    for (ChartKind kind : allChartKinds())
        if (window.charts()->chartShown(kind) && std::find(known.begin(), known.end(), chartKey(kind)) != known.end())
            p.view.charts.emplace_back(chartKey(kind));
    p.view.selectedBall = run.selectedBall();
    p.view.compare = run.comparison();
    if (const BallView* view = window.view()) {
        const OrbitCamera& c = view->camera();
        p.view.cameraYaw = c.yaw();
        p.view.cameraPitch = c.pitch();
        p.view.cameraDistance = c.distance();
        p.view.cameraTarget = Eigen::Vector3d(c.target().x(), c.target().y(), c.target().z());
    }
    return p;
}

void applyPresetToWindow(MainWindow& window, const Preset& preset)
{
    // Everything that can be refused is checked first; then the run is replaced in one go.
    RunSpec spec(preset.scene);
    applyPreset(preset, spec);
    const std::vector<ChartKind> charts = chartsOf(preset);
    const RunOptions options{spec.model,
                             spec.integrator,
                             spec.impacts,
                             spec.dt,
                             preset.steps.value_or(defaultSteps(spec.scene, spec.model)),
                             preset.view.compare};
    if (const auto error = window.showSetup(spec, options, preset.view.speed))
        throw InputError(presetName(preset) + ": " + error->toStdString());
    showCharts(*window.charts(), charts);
    // What the preset is about, in the navigator beside the stage it opens.
    // In the preset's own words: the navigator translates them each time it shows them, so a
    // language chosen later applies to them too.
    window.navigator()->setPreset(preset.scene, QString::fromStdString(preset.name),
                                  QString::fromStdString(preset.description));
    window.controller().selectBall(preset.view.selectedBall.value_or(0));
    if (BallView* view = window.view())
        placeCamera(*view, preset.view);
}

PresetActions::PresetActions(MainWindow* window) : QObject(window), window_(window)
{
    window_->setAcceptDrops(true);
    window_->installEventFilter(this);
}

void PresetActions::addFileActions(QMenu* file)
{
    file->addAction(tr("Open preset..."), QKeySequence::Open, this, &PresetActions::openInteractively);
    file->addAction(tr("Save preset..."), QKeySequence::Save, this, &PresetActions::saveInteractively);
    file->addSeparator();
}

void PresetActions::addPresetsMenu(QMenuBar* bar)
{
    QMenu* menu = bar->addMenu(tr("&Presets"));
    menu->setObjectName("presetsMenu");
    menu->setToolTipsVisible(true);
    const SceneInfo* section = nullptr;
    for (const BuiltinPreset& b : builtinPresets()) {
        const SceneInfo& info = sceneInfo(b.preset.scene);
        if (section != &info) {
            menu->addSection(tr("Stage %1: %2").arg(info.stage).arg(coreText(info.title)));
            section = &info;
        }
        const QString key = qs(b.key);
        QAction* action = menu->addAction(coreText(b.preset.name), this, [this, key] { open(key); });
        action->setToolTip(coreText(b.preset.description));
        action->setData(key);
    }
}

void PresetActions::addChartToggles(QMenu* view)
{
    chartToggles_ = view->addMenu(tr("Charts shown"));
    for (ChartKind kind : allChartKinds()) {
        QAction* action = chartToggles_->addAction(chartName(kind));
        action->setCheckable(true);
        action->setChecked(true);
        connect(action, &QAction::toggled, this, [this, kind](bool on) { window_->charts()->setChartShown(kind, on); });
    }
}

void PresetActions::syncChartToggles()
{
    if (!chartToggles_)
        return;
    const auto actions = chartToggles_->actions();
    for (std::size_t i = 0; i < allChartKinds().size() && i < std::size_t(actions.size()); ++i) {
        const QSignalBlocker block(actions[qsizetype(i)]);
        actions[qsizetype(i)]->setChecked(window_->charts()->chartShown(allChartKinds()[i]));
    }
}

std::optional<QString> PresetActions::open(const QString& nameOrPath)
{
    try {
        const Preset preset = loadPreset(nameOrPath.toStdString());
        applyPresetToWindow(*window_, preset);
        syncChartToggles();
        window_->statusBar()->showMessage(tr("Opened preset: %1").arg(coreText(preset.name)), 8000);
        emit presetOpened(coreText(preset.name));
        return std::nullopt;
    } catch (const InputError& e) {
        const QString message = refusalText(e);
        window_->statusBar()->showMessage(message, 15000);
        // Window-modal and not waited for: the window stays as it was, the message says why.
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Preset not opened"), message, QMessageBox::Ok, window_);
        box->setObjectName("presetError");
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        return message;
    }
}

void PresetActions::saveTo(const QString& path)
{
    const std::string name = QFileInfo(path).completeBaseName().toStdString();
    const Preset preset = capturePreset(
        *window_, name, describe(window_->controller().spec(), window_->controller().plannedSteps()).toStdString());
    try {
        savePreset(path.toStdString(), preset);
    } catch (const std::logic_error& e) { // text that would not read back: said, not written
        throw InputError(e.what());
    }
}

void PresetActions::openInteractively()
{
    const QString path = QFileDialog::getOpenFileName(window_, tr("Open preset"),
                                                      lastDirectory_.isEmpty() ? QDir::currentPath() : lastDirectory_,
                                                      tr("Amazeballs preset (*.json)"));
    if (path.isEmpty())
        return;
    lastDirectory_ = QFileInfo(path).absolutePath();
    open(path);
}

void PresetActions::saveInteractively()
{
    const QString dir = lastDirectory_.isEmpty() ? QDir::currentPath() : lastDirectory_;
    const QString suggested = dir + "/" + qs(sceneInfo(window_->scene()).key) + "-preset.json";
    QString path =
        QFileDialog::getSaveFileName(window_, tr("Save preset"), suggested, tr("Amazeballs preset (*.json)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += ".json";
    lastDirectory_ = QFileInfo(path).absolutePath();
    try {
        saveTo(path);
        window_->statusBar()->showMessage(tr("Wrote %1").arg(path), 5000);
    } catch (const InputError& e) {
        QMessageBox::warning(window_, tr("Preset not saved"), QString::fromUtf8(e.what()));
    }
}

// A single .json file dragged onto the window opens as a preset.
bool PresetActions::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type type = event->type();
    if (watched != window_ || (type != QEvent::DragEnter && type != QEvent::DragMove && type != QEvent::Drop))
        return QObject::eventFilter(watched, event);
    auto* drop = static_cast<QDropEvent*>(event); // drag enter and move events are drop events
    const QList<QUrl> urls = drop->mimeData() ? drop->mimeData()->urls() : QList<QUrl>();
    if (urls.size() != 1 || !urls.front().isLocalFile() ||
        !urls.front().toLocalFile().endsWith(".json", Qt::CaseInsensitive))
        return false;
    drop->acceptProposedAction();
    if (type == QEvent::Drop)
        open(urls.front().toLocalFile());
    return true;
}

} // namespace ab::ui
