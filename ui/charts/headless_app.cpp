// SPDX-License-Identifier: MIT
#include "headless_app.h"

#include <QApplication>
#include <QDir>
#include <QFile>

#include <cstdlib>
#include <memory>
#include <unistd.h>

namespace ab::ui {

void ensureGuiApplication()
{
    if (QCoreApplication::instance())
        return;
    // The command line never needs a window; offscreen renders charts with fonts and
    // works without X. A caller that set QT_QPA_PLATFORM keeps its choice.
    if (!std::getenv("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // Qt warns on stderr when there is no runtime folder (CI, cron, ssh): give it a private
    // one, as a login session would.
    if (!std::getenv("XDG_RUNTIME_DIR")) {
        const QByteArray dir = QDir::tempPath().toLocal8Bit() + "/runtime-" + QByteArray::number(getuid());
        if (QDir().mkpath(QString::fromLocal8Bit(dir)) &&
            QFile::setPermissions(QString::fromLocal8Bit(dir),
                                  QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner))
            qputenv("XDG_RUNTIME_DIR", dir);
    }
    static int argc = 1;
    static char name[] = "amazeballs-cli";
    static char* argv[] = {name, nullptr};
    static std::unique_ptr<QApplication> app = std::make_unique<QApplication>(argc, argv);
}

} // namespace ab::ui
