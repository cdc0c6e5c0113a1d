// A full disk without root tricks: in a forked child, RLIMIT_FSIZE caps every
// file at `bytes` and SIGXFSZ is ignored, so a write past the cap fails with
// EFBIG exactly as a write on a full disk fails with ENOSPC.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <functional>

#include "base/Error.h"

namespace rigmesh::fulldisk {

enum class FullDiskOutcome { RefusedWithError, Succeeded, Crashed };

// Runs `write` in a child whose files cannot grow past `bytes`.
inline FullDiskOutcome runOnFullDisk(long bytes, const std::function<void()>& write) {
    const pid_t child = ::fork();
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{static_cast<rlim_t>(bytes), static_cast<rlim_t>(bytes)};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            write();
        } catch (const Error&) {
            ::_exit(0);
        } catch (...) {
            ::_exit(3);
        }
        ::_exit(1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) == 3)
        return FullDiskOutcome::Crashed;
    return WEXITSTATUS(status) == 0 ? FullDiskOutcome::RefusedWithError
                                    : FullDiskOutcome::Succeeded;
}

}  // namespace rigmesh::fulldisk
