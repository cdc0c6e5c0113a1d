// Long work off the GUI thread: a job computes on a worker
// thread and hands back what to apply; the GUI thread applies it as one
// command when the work is done, or drops it when the user cancelled. The
// window stays responsive the whole time (it repaints, orbits, shows the
// progress and takes Cancel), and the document changes only at the end.
//
// The contract for `work`: it reads the document but never changes it
// (commands' create() functions do just that: they run the engine on the
// immutable parts), touches no widget, and returns the step to apply on the
// GUI thread. While a job runs the studio is read-only (jobs/JobStatus)
// so nothing else changes the document under it. An exception thrown by
// the work, or by the apply step on the GUI thread, becomes the failure
// message (widgets/UserAction.h: an Error's own text, anything else an
// internal error); the apply step pushes its command through
// model/GuardedUndo, so the document is untouched.
//
// Cancel gives the studio back at once. Work started with runWithProgress
// sees it through its JobProgress and may stop early; other work (the
// engine's solves have no cancellation points) finishes on its own. Either
// way its result is thrown away: a cancelled job leaves nothing behind.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <functional>
#include <memory>

#include "jobs/JobProgress.h"

namespace rigmesh::widgets {

class JobRunner : public QObject {
    Q_OBJECT
  public:
    // What a finished job applies on the GUI thread.
    using Apply = std::function<void()>;
    // The work: runs on a worker thread, returns what to apply.
    using Work = std::function<Apply()>;
    // Work that reports its progress and looks for a cancel on the way.
    using ProgressWork = std::function<Apply(JobProgress&)>;
    // Called on the GUI thread with the reason when the work threw.
    using Failed = std::function<void(const QString& reason)>;
    // Called on the GUI thread when the user cancelled.
    using Cancelled = std::function<void()>;

    explicit JobRunner(QObject* parent = nullptr);
    ~JobRunner() override;

    // Starts a job. Returns false (and starts nothing) while another runs.
    // What a cancelled job made outside the document goes with its dropped
    // Apply (a staged export removes its files when destroyed).
    bool run(const QString& title, Work work, Failed failed, Cancelled cancelled = {});
    // The same for work that reports progress (shown as a filling bar).
    bool runWithProgress(const QString& title, ProgressWork work, Failed failed,
                         Cancelled cancelled = {});
    // run() on `runner`, or all at once on this thread when it is null (a
    // view without a window: tests, tools). False if the runner is busy.
    static bool runOn(JobRunner* runner, const QString& title, Work work, Failed failed,
                      Cancelled cancelled = {});
    bool busy() const { return running_ != nullptr; }
    QString title() const { return title_; }
    qint64 elapsedMilliseconds() const { return busy() ? clock_.elapsed() : 0; }
    // The running job's fraction done (0..1), or negative when unknown.
    double fraction() const;
    // True while any runner of the application has a job (tests wait on it).
    static bool anyBusy();

  public slots:
    // Gives the studio back now and drops the job's result when it comes.
    void cancel();

  signals:
    // A job started (busy) or ended, was cancelled or failed (not busy).
    void busyChanged(bool busy);

  private:
    struct Job;
    void finish(const std::shared_ptr<Job>& job);
    void end();

    std::shared_ptr<Job> running_;
    QString title_;
    QElapsedTimer clock_;
};

}  // namespace rigmesh::widgets
