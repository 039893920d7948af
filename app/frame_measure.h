// SPDX-License-Identifier: MIT
// --measure-frames: the window's frame times, printed after it has played a while.
#pragma once

namespace ab::ui {
class MainWindow;
}

namespace ab::app {

// Plays `window` for `seconds` with the turntable on (every frame drawn anew), then prints
// the frame times (medians, the slowest and when they came) and the steps it took, and
// quits; exits with 2 when there is no 3D view to measure.
void measureFrames(ab::ui::MainWindow& window, double seconds);

} // namespace ab::app
