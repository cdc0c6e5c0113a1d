#include "jobs/JobRunner.h"

#include <QCoreApplication>
#include <QPointer>
#include <atomic>
#include <exception>
#include <new>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "UserAction.h"
#include "base/Error.h"
#include "model/ErrorText.h"

namespace rigmesh::widgets {

namespace {

std::atomic<int> busyRunners{0};

// The text for the user of the exception `thrown`: an engine Error in the
// user's language; a programming error (std::logic_error and the like) as
// an internal error, so that a job reports it instead of ending the program.
// No action name: every Failed callback says what failed.
QString failureText(const std::exception_ptr& thrown) {
    return UserAction::failureText({}, thrown);
}

// Runs a finished job's apply step (it pushes the job's command) on the
// GUI thread; what it throws goes to `failed`, never into the event loop.
// Without a `failed` the exception goes on to the caller.
void applyGuarded(const JobRunner::Apply& apply, const JobRunner::Failed& failed) {
    if (!apply)
        return;
    try {
        apply();
    } catch (...) {
        if (!failed)
            throw;
        failed(failureText(std::current_exception()));
    }
}

}  // namespace

// What the worker and the GUI thread share: the work's outcome, written by
// the worker before it posts the job back, read on the GUI thread after.
struct JobRunner::Job {
    Work work;
    Failed failed;
    Cancelled cancelled;
    Apply apply;
    QString error;
    std::shared_ptr<JobProgress> progress = std::make_shared<JobProgress>();
};

JobRunner::JobRunner(QObject* parent) : QObject(parent) {}

JobRunner::~JobRunner() {
    if (running_)
        --busyRunners;
}

bool JobRunner::anyBusy() {
    return busyRunners.load() > 0;
}

bool JobRunner::runOn(JobRunner* runner, const QString& title, Work work, Failed failed,
                      Cancelled cancelled) {
    if (runner)
        return runner->run(title, std::move(work), std::move(failed), std::move(cancelled));
    Apply apply;
    try {
        apply = work();
    } catch (const Error& error) {
        if (failed)
            failed(model::errorText(error));
        return true;
    } catch (...) {
        if (!failed)
            throw;
        failed(failureText(std::current_exception()));
        return true;
    }
    applyGuarded(apply, failed);
    return true;
}

double JobRunner::fraction() const {
    return running_ ? running_->progress->fraction() : -1.0;
}

bool JobRunner::runWithProgress(const QString& title, ProgressWork work, Failed failed,
                                Cancelled cancelled) {
    // The progress lives as long as the work that writes it.
    auto progress = std::make_shared<JobProgress>();
    progress->setFraction(0.0);
    const bool started = run(
        title, [work = std::move(work), progress] { return work(*progress); }, std::move(failed),
        std::move(cancelled));
    if (started)
        running_->progress = progress;
    return started;
}

bool JobRunner::run(const QString& title, Work work, Failed failed, Cancelled cancelled) {
    if (running_)
        return false;
    auto job = std::make_shared<Job>();
    job->work = std::move(work);
    job->failed = std::move(failed);
    job->cancelled = std::move(cancelled);
    running_ = job;
    title_ = title;
    clock_.start();
    ++busyRunners;
    emit busyChanged(true);
    QPointer<JobRunner> self(this);
    // Detached: if the window goes first, the worker still finishes and its
    // result is dropped (the QPointer is null by then).
    std::thread([job, self] {
        // Below the GUI thread's priority (Linux nice is per thread, and the
        // engine's own threads inherit it): the window keeps its time slices
        // on a busy machine.
        setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 5);
        try {
            job->apply = job->work();
        } catch (...) {
            job->error = failureText(std::current_exception());
        }
        // Back on the GUI thread (qApp outlives every window).
        QMetaObject::invokeMethod(
            qApp,
            [job, self] {
                if (self)
                    self->finish(job);
            },
            Qt::QueuedConnection);
    }).detach();
    return true;
}

void JobRunner::finish(const std::shared_ptr<Job>& job) {
    if (job != running_)
        return;  // cancelled: the result is dropped with the job
    end();
    if (!job->error.isEmpty()) {
        if (job->failed)
            job->failed(job->error);
        return;
    }
    try {
        applyGuarded(job->apply, job->failed);
    } catch (...) {
        // No one to tell (a job without a Failed): not into the event loop.
        qWarning("%s", qPrintable(failureText(std::current_exception())));
    }
}

void JobRunner::cancel() {
    if (!running_)
        return;
    const std::shared_ptr<Job> job = running_;
    job->progress->cancel();
    end();
    if (job->cancelled)
        job->cancelled();
}

void JobRunner::end() {
    running_.reset();
    title_.clear();
    --busyRunners;
    emit busyChanged(false);
}

}  // namespace rigmesh::widgets
