// SPDX-License-Identifier: MIT
// The window: stage navigator, parameters and run options on the left, the 3D view in
// the middle, the charts on the right, the transport bar on top and the readings in the
// status bar. Each stage keeps its own constants and options while the window is open.
// Anything the core refuses is shown and not applied; the previous run stays.
#pragma once

#include "charts/motion_chart.h"
#include "export_options_dialog.h"
#include "panels/chart_panel.h"
#include "panels/run_options_panel.h"
#include "sim/run_controller.h"

#include "core/reference/reference.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QTimer>

#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QLabel;

namespace ab::ui {

class BallView;
class ParameterPanel;
class StageNavigator;
class StatusReadout;
class StreetCameraBar;
class TransportBar;
class PresetActions;
class FigureActions;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Switches to a stage with its remembered constants and options.
    void showScene(SceneId scene);
    // Apply new constants or options to the current stage; false (and shown) when the
    // core refuses them, and then nothing changes.
    bool applyValues(const ParamValues& values);
    bool applyOptions(const RunOptions& options);
    // The current stage's applied options (a comparison included).
    RunOptions options() { return setupFor(scene_).options; }
    // Shows `spec`'s stage with these options as its remembered setup (a preset). Returns
    // the core's refusal (also shown), and then nothing changes.
    std::optional<QString> showSetup(const RunSpec& spec, const RunOptions& options,
                                     std::optional<double> speed = std::nullopt);

    // Exports; each throws InputError naming the path and the reason. A chart is drawn
    // for its size (a report's column by default), with the caption and the time cursor
    // only when asked for.
    void exportChartTo(ChartKind kind, const QString& path, const ChartExportChoice& how = {});
    void exportDataTo(const QString& path);
    void exportViewTo(const QString& path);

    RunController& controller() { return controller_; }
    StageNavigator* navigator() const { return navigator_; }
    ParameterPanel* parameters() const { return parameters_; }
    RunOptionsPanel* runOptions() const { return runOptions_; }
    TransportBar* transport() const { return transport_; }
    ChartPanel* charts() const { return charts_; }
    StatusReadout* readout() const { return readout_; }
    BallView* view() const { return view_; } // nullptr without OpenGL (offscreen tests)
    SceneId scene() const { return scene_; }

    void setTurntable(bool on);
    // Lecture mode takes Space and the arrows for its walk: Help > Keys and mouse says so.
    void setLectureKeys(bool on) { lectureKeys_ = on; }

    // Goes on with `old`'s run as it stands (a language switch builds the window anew):
    // every stage's setup, the run with its recording, time, comparison, speed and
    // selection, the moment looked back at, the camera, the charts shown and the preset's
    // text. `old` is left without a run.
    void takeRunOf(MainWindow& old);

private slots:
    // The keyboard back to the window's shortcuts after Enter in a field.
    void handKeysBack();

private:
    struct Setup {
        RunSpec spec;
        RunOptions options;
        double speed = 1.0; // the stage's own (defaultSpeed), kept while the window is open
    };

    void buildLayout();
    // When the time slider looks back, forks the run at the frame shown and goes live
    // there; false when it shows the live state.
    bool resumeFromLookedBackMoment();
    void buildMenus();
    // The street's camera shots in the View menu (F, S, G), active in stage 5.
    void addStreetShots(QMenu* view);
    QWidget* buildLeftPanel();
    QWidget* buildViewArea();
    // Starts the run; on refusal shows the core's message and returns it.
    std::optional<QString> startRun(const Setup& setup);
    Setup& setupFor(SceneId scene);
    // The stage's panels show its remembered setup, which runs.
    void showPanels(SceneId scene);
    void runReplaced();
    void ballSelected(int ball);
    // The scene's closed form, drawn dashed beside the run where the core has one.
    void showReference();
    // The closed form of the selected ball, if the run has one (reference_).
    std::optional<ReferenceMotion> closedFormMotion() const;
    void refresh();
    // `pathEnd`: where the selected ball's drawn path ends (SceneLayout::pathEndsAtHalt).
    void refreshView(const Recording& rec, const Frame& current, std::optional<double> viewT,
                     std::optional<double> pathEnd);
    ChartUnits chartUnits() const; // of the current run's model
    void exportInteractively(ChartKind kind, ExportFormat format);
    void exportViewInteractively();
    void showError(const QString& message);
    void showKeys();
    void showAbout();

    RunController controller_;
    std::map<SceneId, Setup> setups_;
    SceneId scene_ = SceneId::Bounce1d;
    std::vector<QAction*> streetShots_; // View > Street: from the foot, from the side, follow the flood
    StageNavigator* navigator_ = nullptr;
    ParameterPanel* parameters_ = nullptr;
    RunOptionsPanel* runOptions_ = nullptr;
    TransportBar* transport_ = nullptr;
    ChartPanel* charts_ = nullptr;
    BallView* view_ = nullptr;
    QLabel* placeholder_ = nullptr;
    StreetCameraBar* streetCameras_ = nullptr; // over the view, in stage 5
    StatusReadout* readout_ = nullptr;
    // While playing, the panels (charts, slider, readings) are refreshed four times a
    // second, one part a tick of panelTimer_ (refreshPanelPart), so that no frame of the
    // 3D view pays for all of them; panelPart_ is the next part, -1 when none is due.
    void refreshPanels();
    void refreshPanelPart();
    void refreshReadings(const EngineStatus& status);
    void cancelPanelRefresh();
    QElapsedTimer panelClock_;
    QTimer panelTimer_;
    int panelPart_ = -1;
    bool panelsPlaying_ = false;
    bool lectureKeys_ = false;
    QElapsedTimer fpsClock_;
    int framesSinceFps_ = 0;
    // The run's time against the wall clock over the last two seconds of play: the speed it
    // keeps (followKeptSpeed), as (wall seconds, run time) samples.
    void followKeptSpeed(const EngineStatus& status);
    QElapsedTimer paceClock_;
    std::deque<std::pair<double, double>> pace_;
    QTimer turntable_;
    std::optional<SceneId> framedScene_;
    QString lastDirectory_;
    ChartExportChoice lastChartExport_; // the export dialog's last choice
    std::unique_ptr<reference::Reference> reference_;
    PresetActions* presets_ = nullptr;
    FigureActions* figures_ = nullptr;
};

} // namespace ab::ui
