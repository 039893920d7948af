// SPDX-License-Identifier: MIT
// Long work off the GUI thread: a BackgroundJob runs one function on a std::thread, passes
// its progress to the GUI thread as signals and lets the GUI cancel it. The work polls
// cancelled(); the job's destructor cancels and waits, so a dialog closed mid-run never
// leaves a thread writing into freed memory. runWithProgress wraps a job in a progress
// dialog for the window's exports.
#pragma once

#include <QObject>
#include <QString>

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>

class QWidget;

namespace ab::ui {

class BackgroundJob : public QObject {
    Q_OBJECT
public:
    using Work = std::function<void(BackgroundJob&)>;

    explicit BackgroundJob(QObject* parent = nullptr);
    ~BackgroundJob() override;

    // Runs `work` on a new thread; finished() follows on the GUI thread. An exception the
    // work throws is kept for error(). Refused (false) while a run is under way.
    bool start(Work work);
    void cancel() { cancel_ = true; }
    bool cancelled() const { return cancel_; }
    bool running() const { return running_; }
    // Blocks until the work has ended and finished() was emitted (for tests).
    void waitForFinished();
    std::exception_ptr error() const { return error_; }

    // From the work's thread: queues progress(done, total) to the GUI thread.
    void report(std::size_t done, std::size_t total);

signals:
    void progress(int done, int total);
    void finished();

private:
    void ended();

    std::thread thread_;
    std::atomic<bool> cancel_{false};
    bool running_ = false;
    std::exception_ptr error_;
};

// Reports progress; returns false once the user has cancelled.
using ProgressFn = std::function<bool(std::size_t done, std::size_t total)>;

// Runs `work` on a worker thread while the event loop turns; a progress dialog with
// Cancel appears when the work takes more than a moment. Returns when the work has ended
// and rethrows its exception here (a cancelled export throws what `work` threw).
void runWithProgress(QWidget* parent, const QString& label, const std::function<void(const ProgressFn&)>& work);

} // namespace ab::ui
