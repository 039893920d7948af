// SPDX-License-Identifier: MIT
// What the window remembers between sessions (QSettings): its geometry and toolbar
// state, the last stage, and each stage's setup (model, integrator, step, constants,
// charts, camera), stored as preset JSON so that it is read back with the presets'
// checks. A remembered setup this program no longer accepts is skipped, not half-applied.
#pragma once

#include <QObject>
#include <QRect>
#include <QStringList>

class QSettings;

namespace ab::ui {

class MainWindow;

class WindowSettings : public QObject {
    Q_OBJECT
public:
    // Remembers each stage's setup from now on, whenever its run is replaced.
    WindowSettings(MainWindow& window, QSettings& store);

    // Restores the geometry, the remembered stage setups and the last stage. Returns
    // false when there was no geometry to restore (a first start). What was skipped is
    // listed by skipped().
    bool restore();
    // Stores the geometry, the last stage and its setup (the camera included).
    void save();
    const QStringList& skipped() const { return skipped_; }

    // A first start's window on a screen whose free area is `available`: 1400 x 900 where
    // that fits with room for a window frame, else the free area less that room (a 1280 x
    // 720 screen: 1280 x 690), never more.
    static QRect firstStartGeometry(const QRect& available);

private:
    void rememberCurrentScene();

    MainWindow& window_;
    QSettings& store_;
    QStringList skipped_;
    bool restoring_ = false;
};

} // namespace ab::ui
