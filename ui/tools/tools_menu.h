// SPDX-License-Identifier: MIT
// The window's Tools menu: the accuracy study and the stability suite of the current
// scene, each in its own dialog beside the window.
#pragma once

#include "core/simulation.h"

#include <functional>

class QMainWindow;

namespace ab::ui {

// Adds Tools > Accuracy study... and Stability suite... to the window's menu bar.
// `current` gives the run of the scene on screen (its constants, model and options).
void addToolsMenu(QMainWindow* window, std::function<RunSpec()> current);

} // namespace ab::ui
