// What a background job's work and the window share while it runs: how far the work got, written by
// the worker, shown by JobStatus; and whether the user cancelled, set by the GUI thread, so work
// that checks it (the auto-rig's flow steps) stops early instead of running
// to the end for nothing. Lock-free: both sides only read and write atomics.
#pragma once

#include <atomic>

namespace rigmesh::widgets {

class JobProgress {
  public:
    // 0..1; negative = not known (the bar just shows activity).
    void setFraction(double fraction) { fraction_.store(fraction); }
    double fraction() const { return fraction_.load(); }
    void cancel() { cancelled_.store(true); }
    bool cancelled() const { return cancelled_.load(); }

  private:
    std::atomic<double> fraction_{-1.0};
    std::atomic<bool> cancelled_{false};
};

}  // namespace rigmesh::widgets
