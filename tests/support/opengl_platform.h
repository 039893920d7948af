// SPDX-License-Identifier: MIT
// Whether the test's platform gives OpenGL windows: the GL tests run under xvfb-run with
// QT_QPA_PLATFORM=xcb, and skip on the offscreen and minimal platforms, which have none.
#pragma once

#include <QGuiApplication>
#include <QString>

namespace testing {

inline constexpr const char* kNeedsOpenGl = "needs OpenGL; run under xvfb-run with QT_QPA_PLATFORM=xcb";

inline bool platformHasOpenGl()
{
    const QString platform = QGuiApplication::platformName();
    return platform != "offscreen" && platform != "minimal";
}

} // namespace testing
