// SPDX-License-Identifier: MIT
#include "headless_app.h"

#include <QApplication>

#include <cstdlib>
#include <memory>

namespace ab::ui {

void ensureGuiApplication()
{
    if (QCoreApplication::instance())
        return;
    // The command line never needs a window; offscreen renders charts with fonts and
    // works without X. A caller that set QT_QPA_PLATFORM keeps its choice.
    if (!std::getenv("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "amazeballs-cli";
    static char* argv[] = {name, nullptr};
    static std::unique_ptr<QApplication> app = std::make_unique<QApplication>(argc, argv);
}

} // namespace ab::ui
