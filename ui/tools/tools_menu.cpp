// SPDX-License-Identifier: MIT
#include "tools_menu.h"

#include "stability_dialog.h"
#include "study_dialog.h"

#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>

namespace ab::ui {

namespace {

// One dialog of a kind per window: a running one is brought forward, an idle one is
// replaced so that it studies the scene as it is now.
template <class Dialog, class Make> void open(QMainWindow* window, Make make)
{
    if (auto* existing = window->findChild<Dialog*>()) {
        if (existing->running()) {
            existing->raise();
            existing->activateWindow();
            return;
        }
        existing->close();
        delete existing;
    }
    Dialog* dialog = make();
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
}

} // namespace

void addToolsMenu(QMainWindow* window, std::function<RunSpec()> current)
{
    QMenu* tools = window->menuBar()->addMenu(QMainWindow::tr("&Tools"));
    QAction* study = tools->addAction(QMainWindow::tr("&Accuracy study..."), window, [window, current] {
        open<StudyDialog>(window, [&] { return new StudyDialog(current(), window); });
    });
    study->setStatusTip(QMainWindow::tr("Error against run time of each integrator on the current scene"));
    QAction* suite = tools->addAction(QMainWindow::tr("&Stability suite..."), window, [window, current] {
        open<StabilityDialog>(window, [&] { return new StabilityDialog(current().scene, window); });
    });
    suite->setStatusTip(QMainWindow::tr("Stiff and extreme cases of both models, with a verdict for each"));
}

} // namespace ab::ui
