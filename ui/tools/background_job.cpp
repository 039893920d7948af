// SPDX-License-Identifier: MIT
#include "background_job.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QProgressDialog>

namespace ab::ui {

BackgroundJob::BackgroundJob(QObject* parent) : QObject(parent) {}

BackgroundJob::~BackgroundJob()
{
    cancel();
    if (thread_.joinable())
        thread_.join();
}

bool BackgroundJob::start(Work work)
{
    if (running_)
        return false;
    if (thread_.joinable())
        thread_.join();
    cancel_ = false;
    error_ = nullptr;
    running_ = true;
    thread_ = std::thread([this, work = std::move(work)] {
        try {
            work(*this);
        } catch (...) {
            error_ = std::current_exception(); // read on the GUI thread after ended()
        }
        // Queued to this object: dropped if the job is destroyed first (its destructor joins).
        QMetaObject::invokeMethod(this, &BackgroundJob::ended, Qt::QueuedConnection);
    });
    return true;
}

void BackgroundJob::ended()
{
    if (thread_.joinable())
        thread_.join();
    running_ = false;
    emit finished();
}

void BackgroundJob::waitForFinished()
{
    while (running_)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
}

void BackgroundJob::report(std::size_t done, std::size_t total)
{
    const int d = static_cast<int>(done), t = static_cast<int>(total);
    QMetaObject::invokeMethod(
        this, [this, d, t] { emit progress(d, t); }, Qt::QueuedConnection);
}

void runWithProgress(QWidget* parent, const QString& label, const std::function<void(const ProgressFn&)>& work)
{
    BackgroundJob job;
    QProgressDialog dialog(label, QObject::tr("Cancel"), 0, 100, parent);
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(400); // shown only for work that takes more than a moment
    dialog.setAutoReset(false);
    dialog.setAutoClose(false);
    dialog.setValue(0);
    QEventLoop loop;
    QObject::connect(&job, &BackgroundJob::progress, &dialog, [&dialog](int done, int total) {
        dialog.setMaximum(total);
        dialog.setValue(done);
    });
    QObject::connect(&dialog, &QProgressDialog::canceled, &job, &BackgroundJob::cancel);
    QObject::connect(&job, &BackgroundJob::finished, &loop, &QEventLoop::quit);
    job.start([&work](BackgroundJob& j) {
        work([&j](std::size_t done, std::size_t total) {
            j.report(done, total);
            return !j.cancelled();
        });
    });
    if (job.running())
        loop.exec();
    if (job.error())
        std::rethrow_exception(job.error());
}

} // namespace ab::ui
