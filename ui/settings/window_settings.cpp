// SPDX-License-Identifier: MIT
#include "window_settings.h"

#include "ui/main_window.h"
#include "ui/presets/preset_actions.h"

#include <QSettings>

#include <algorithm>

namespace ab::ui {

namespace {

QString sceneSetting(const SceneInfo& info)
{
    return QStringLiteral("scenes/%1").arg(QString::fromStdString(info.key));
}

} // namespace

WindowSettings::WindowSettings(MainWindow& window, QSettings& store) : QObject(&window), window_(window), store_(store)
{
    connect(&window_.controller(), &RunController::runReplaced, this, [this] {
        if (!restoring_)
            rememberCurrentScene();
    });
}

bool WindowSettings::restore()
{
    restoring_ = true;
    const SceneInfo* last = findScene(store_.value("window/scene").toString().toStdString());
    // The last stage goes last, so that it is the one shown, with its camera.
    std::vector<const SceneInfo*> order;
    for (const SceneInfo* s : allScenes())
        if (s != last)
            order.push_back(s);
    if (last)
        order.push_back(last);
    for (const SceneInfo* s : order) {
        const QString json = store_.value(sceneSetting(*s)).toString();
        if (json.isEmpty())
            continue;
        try {
            applyPresetToWindow(window_, parsePreset(json.toStdString(), "remembered " + s->key + " setup"));
        } catch (const InputError& e) {
            skipped_ << QString::fromUtf8(e.what());
        }
    }
    if (last && window_.scene() != last->id)
        window_.showScene(last->id);
    restoring_ = false;
    const bool placed = window_.restoreGeometry(store_.value("window/geometry").toByteArray());
    window_.restoreState(store_.value("window/state").toByteArray());
    return placed;
}

void WindowSettings::save()
{
    store_.setValue("window/geometry", window_.saveGeometry());
    store_.setValue("window/state", window_.saveState());
    store_.setValue("window/scene", QString::fromStdString(sceneInfo(window_.scene()).key));
    rememberCurrentScene();
    store_.sync();
}

void WindowSettings::rememberCurrentScene()
{
    const SceneInfo& info = sceneInfo(window_.controller().spec().scene);
    try {
        const Preset p = capturePreset(window_, info.key, "The setup last used for " + info.key + ".");
        store_.setValue(sceneSetting(info), QString::fromStdString(presetToJson(p)));
    } catch (const InputError&) {
        // A setup that cannot be written as a preset is not remembered; the last good one stays.
    }
}

QRect WindowSettings::firstStartGeometry(const QRect& available)
{
    const QSize wanted(1400, 900), frame(0, 30); // a title bar's height for the window manager
    const QSize room = available.size() - frame;
    const QSize size = wanted.boundedTo(room).expandedTo(QSize(640, 480));
    // Centred in the free area, its frame inside it.
    const QPoint at(available.x() + std::max(0, (available.width() - size.width()) / 2),
                    available.y() + std::max(frame.height(), (available.height() - size.height()) / 2));
    return QRect(at, size);
}

} // namespace ab::ui
