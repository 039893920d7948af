// SPDX-License-Identifier: MIT
#include "animation_actions.h"

#include "ui/main_window.h"
#include "ui/sim/playback_rate.h"
#include "ui/view/ball_view.h"

#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QStatusBar>

#include <algorithm>

namespace ab::ui {

namespace {

QString suffixOf(video::VideoFormat f)
{
    return QString::fromLatin1(video::videoFormatKey(f).data(), qsizetype(video::videoFormatKey(f).size()));
}

} // namespace

AnimationActions::AnimationActions(MainWindow* window) : QObject(window), window_(window) {}

void AnimationActions::addToFileMenu(QMenu* file)
{
    QAction* a = file->addAction(tr("Export animation..."), this, [this] { exportInteractively(); });
    a->setObjectName("exportAnimation");
}

AnimationRequest AnimationActions::requestFor(const AnimationChoice& c) const
{
    RunController& run = window_->controller();
    AnimationRequest r(run.spec());
    r.steps = run.plannedSteps();
    r.from = c.from;
    r.to = c.to;
    r.speed = c.speed;
    r.video = video::VideoSettings{c.format, c.size.width(), c.size.height(), c.fps};
    r.charts = c.charts;
    for (ChartKind k : allChartKinds())
        if (window_->charts()->chartShown(k))
            r.chartKinds.push_back(k);
    if (r.charts && r.chartKinds.empty())
        r.charts = false; // every chart is hidden: the 3D view alone
    r.ball = run.selectedBall();
    if (const BallView* view = window_->view(); view && view->width() > 0 && view->height() > 0) {
        // The window's camera. A clip narrower than the view moves back so that it sees as
        // much across as the view does (the width seen grows with distance times aspect).
        const OrbitCamera& cam = view->camera();
        const double viewAspect = double(view->width()) / double(view->height());
        const double clipAspect = (c.charts ? 0.6 : 1.0) * double(c.size.width()) / double(c.size.height());
        const double back = std::max(1.0, viewAspect / clipAspect);
        r.camera = CameraPose{cam.target(), cam.yaw(), cam.pitch(), float(cam.distance() * back)};
    }
    return r;
}

bool AnimationActions::exportTo(const QString& path, const AnimationChoice& choice)
{
    const AnimationRequest request = requestFor(choice);
    QProgressDialog progress(tr("Writing %1").arg(QFileInfo(path).fileName()), tr("Cancel"), 0, 1000, window_);
    progress.setObjectName("animationProgress");
    progress.setWindowTitle(tr("Export animation"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    progress.setAutoReset(false);
    progress.setAutoClose(false);
    const auto onProgress = [&](long long done, long long total) {
        progress.setValue(int(1000 * done / std::max(total, 1LL)));
        QCoreApplication::processEvents();
        return !progress.wasCanceled();
    };
    try {
        const AnimationStats stats = exportAnimation(request, path.toStdString(), onProgress);
        window_->statusBar()->showMessage(tr("Wrote %1: %2 frames").arg(QFileInfo(path).fileName()).arg(stats.frames),
                                          10000);
        return true;
    } catch (const AnimationCancelled&) {
        window_->statusBar()->showMessage(tr("Export cancelled; no file was written"), 10000);
        return false;
    }
}

void AnimationActions::exportInteractively()
{
    RunController& run = window_->controller();
    if (!run.hasRun())
        return;
    window_->controller().pause();
    const SceneInfo& scene = sceneInfo(run.spec().scene);
    const double start = run.spec().init ? run.spec().init->t : 0.0;
    const double end = run.plannedEnd();
    AnimationChoice initial = last_;
    initial.from = start;
    initial.to = end;
    initial.speed = run.speed();
    AnimationDialog dialog(start, end, playbackRate(scene), QString::fromStdString(scene.timeUnit), initial, window_);
    if (dialog.exec() != QDialog::Accepted)
        return;
    last_ = dialog.choice();
    const QString suffix = suffixOf(last_.format);
    const QString dir = lastDirectory_.isEmpty() ? QDir::homePath() : lastDirectory_;
    QString path = QFileDialog::getSaveFileName(window_, tr("Export animation"),
                                                dir + "/" + QString::fromStdString(scene.key) + "." + suffix,
                                                tr("%1 video (*.%2)").arg(suffix.toUpper(), suffix));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().toLower() != suffix)
        path += "." + suffix;
    lastDirectory_ = QFileInfo(path).absolutePath();
    try {
        exportTo(path, last_);
    } catch (const std::exception& e) {
        QMessageBox::warning(window_, tr("Export animation"),
                             tr("The animation was not written: %1").arg(QString::fromStdString(e.what())));
    }
}

} // namespace ab::ui
