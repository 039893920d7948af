// SPDX-License-Identifier: MIT
// Command-line chart rendering needs a QApplication (Qt Charts items are widgets) but no
// window: this makes one on demand, on the offscreen platform unless a display is set.
#pragma once

namespace ab::ui {

// Creates the process's QApplication if there is none; safe to call again.
void ensureGuiApplication();

} // namespace ab::ui
