// SPDX-License-Identifier: MIT
// File > Export animation...: the dialog (ui/video/animation_dialog.h), a file name, and
// the clip made from the window's run (its spec, planned steps, followed ball, camera
// and shown charts) by the same code as `amazeballs-cli video`, with a progress dialog
// whose Cancel leaves no file. Frames are drawn and encoded in turn on the GUI thread
// (Qt Charts and the offscreen view need it), the event loop turning between frames.
#pragma once

#include "animation_dialog.h"
#include "animation_export.h"

#include <QObject>

class QMenu;

namespace ab::ui {

class MainWindow;

class AnimationActions : public QObject {
    Q_OBJECT
public:
    explicit AnimationActions(MainWindow* window);

    // Adds "Export animation..." to the File menu.
    void addToFileMenu(QMenu* file);

    // The clip of the window's current run as `choice` asks for.
    AnimationRequest requestFor(const AnimationChoice& choice) const;
    // Writes the clip with a progress dialog; false when cancelled (no file is left).
    // Throws InputError or std::runtime_error naming what failed (and leaves no file).
    bool exportTo(const QString& path, const AnimationChoice& choice);

private:
    void exportInteractively();

    MainWindow* window_;
    AnimationChoice last_;
    QString lastDirectory_;
};

} // namespace ab::ui
