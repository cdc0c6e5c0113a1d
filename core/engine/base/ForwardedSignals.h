// Passes the signals that ask a program to stop (SIGINT, SIGTERM, SIGHUP)
// on to the process groups of the children it is waiting for, so that
// stopping a parent (Ctrl+C, a CI timeout's SIGTERM) also stops whatever
// those children started. The children themselves also die with their
// parent through PR_SET_PDEATHSIG (base/ChildProcess.cpp), which covers
// SIGKILL, where nothing can be forwarded.
//
// While at least one group is registered, our handler is installed for
// each of these signals the program does not ignore; it signals every
// registered group, then does what the program's own disposition says: the
// previous handler is called, or the default action (ending the program)
// is taken by re-raising the signal. With no group registered the previous
// dispositions are back in place.
#pragma once

#include <sys/types.h>

namespace rigmesh {

// Registers `group` (a process group id) for as long as it lives.
class ForwardedSignals {
  public:
    explicit ForwardedSignals(pid_t group);
    ~ForwardedSignals();
    ForwardedSignals(const ForwardedSignals&) = delete;
    ForwardedSignals& operator=(const ForwardedSignals&) = delete;

  private:
    int slot_ = -1;  // -1: every slot was taken (the child still dies with us)
};

}  // namespace rigmesh
