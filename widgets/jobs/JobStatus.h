// What a window shows and blocks while a background job runs: after 100 ms, the job's title,
// elapsed time, a busy bar (jobs/BusyBar) and Cancel (also Esc) in the status bar; from the first
// moment, every key, click and shortcut that could edit the document is swallowed, so the document
// cannot change under the job. The view still repaints and navigates (middle button, wheel), and
// nothing greys out for a quick job.
#pragma once

#include <QObject>
#include <QPointer>
#include <QTimer>

class QLabel;
class QMainWindow;
class QPushButton;

namespace rigmesh::widgets {

class BusyBar;
class JobRunner;

class JobStatus : public QObject {
    Q_OBJECT
  public:
    // Adds its widgets to the window's status bar.
    JobStatus(QMainWindow* window, JobRunner* runner);

    QPushButton* cancelButton() const { return cancel_; }
    // Shown: the job has run for over 100 ms.
    bool progressShown() const;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void busyChanged(bool busy);
    void showProgress();
    bool allowed(QObject* watched, QEvent* event) const;

    QMainWindow* window_;
    JobRunner* runner_;
    QLabel* label_;
    BusyBar* bar_;
    QPushButton* cancel_;
    QTimer delay_, tick_;
    bool filtering_ = false;
};

}  // namespace rigmesh::widgets
