// SPDX-License-Identifier: MIT
// Presets in the window: the current stage's setup captured as a Preset (model,
// integrator, impacts, step, run length, the constants that differ from the report's,
// camera, charts shown, selected ball) and a preset applied all or nothing. The File
// menu's Open/Save, the Presets menu of built-ins grouped by stage, and .json files
// dropped on the window all go through open(). A refused preset shows one message naming
// the field and changes nothing: everything is checked before the window is touched.
#pragma once

#include "core/io/preset.h"

#include <QObject>
#include <QString>

#include <optional>
#include <string>

class QMenu;
class QMenuBar;

namespace ab::ui {

class MainWindow;

// The window's current stage as a preset called `name`.
Preset capturePreset(MainWindow& window, const std::string& name, const std::string& description);
// Applies `preset` to the window; throws InputError naming the field (the window is
// then as before).
void applyPresetToWindow(MainWindow& window, const Preset& preset);

class PresetActions : public QObject {
    Q_OBJECT
public:
    explicit PresetActions(MainWindow* window);

    void addFileActions(QMenu* file);
    void addPresetsMenu(QMenuBar* bar);
    // Checkable "Charts shown" entries, which presets set too.
    void addChartToggles(QMenu* view);

    // Opens a built-in preset by name or a .json file. Returns the refusal, which is also
    // shown in a message box (not blocking) and the status bar.
    std::optional<QString> open(const QString& nameOrPath);
    // Writes the current stage as a preset; throws InputError naming the path.
    void saveTo(const QString& path);

signals:
    void presetOpened(const QString& name);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void openInteractively();
    void saveInteractively();
    void syncChartToggles();

    MainWindow* window_;
    QMenu* chartToggles_ = nullptr;
    QString lastDirectory_;
};

} // namespace ab::ui
