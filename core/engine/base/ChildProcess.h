// Runs a program in a child process with a time limit and an address-space
// limit, and says how it ended. For work we cannot trust not to crash, loop
// or allocate without end: reading untrusted files through Assimp. POSIX only (fork, execv,
// setrlimit, waitpid); no Qt.
//
// The child's standard output is discarded and its standard error kept (up
// to `maxErrorBytes`), so a `rigmesh: <message>` line can be passed on. A
// result can come back through descriptor 3 (`maxResultBytes`), a temporary
// file that has no name, so nothing is left on disk whichever way the child
// or the parent ends.
//
// The child never outlives the thread that started it: it gets SIGKILL when
// that thread ends (PR_SET_PDEATHSIG, which also covers the parent being
// killed with SIGKILL), and SIGINT, SIGTERM and SIGHUP sent to the parent
// while it waits are passed on to the child's process group
// (base/ForwardedSignals). runChildProcess waits on the calling thread, so
// that thread outlives the child.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rigmesh {

inline constexpr double kWallClockFactor = 4.0;

struct ChildLimits {
    // The child's own processor time (RLIMIT_CPU, whole seconds), so that a
    // machine busy with other work does not cut a reading short; a child
    // that waits instead of computing is killed after kWallClockFactor times
    // as long on the wall clock.
    double seconds = 60.0;
    std::size_t addressSpaceBytes = 0;  // RLIMIT_AS; 0 = no limit
    std::size_t maxErrorBytes = 64 * 1024;
    // > 0: the child's descriptor 3 is an unnamed temporary file (the child
    // may write to it, e.g. as /dev/fd/3), and what it holds when the child
    // ends comes back in ChildOutcome::result, up to this many bytes.
    std::size_t maxResultBytes = 0;
};

struct ChildOutcome {
    enum class End {
        Exited,         // exitCode is valid
        Signalled,      // crashed or was killed by a signal other than ours
        TimedOut,       // over ChildLimits::seconds of processor time, or of its wall-clock bound
        FailedToStart,  // fork or exec failed (errorText says why)
    };
    End end = End::FailedToStart;
    int exitCode = -1;
    int signal = 0;
    double seconds = 0.0;           // on the wall clock, from start to end
    double processorSeconds = 0.0;  // the child's own user and system time
    std::string standardError;      // what the child wrote there, or why it did not start
    std::string result;             // what it wrote to descriptor 3 (maxResultBytes > 0)
    bool resultTooLarge = false;    // it wrote more than maxResultBytes there
};

// `program` is a path (no PATH search); `arguments` exclude argv[0].
ChildOutcome runChildProcess(const std::string& program, const std::vector<std::string>& arguments,
                             const ChildLimits& limits);

// The last line of `text` that starts with `prefix`, without the prefix;
// empty if none. E.g. the "rigmesh: " message of a failed child.
std::string lastLineStartingWith(const std::string& text, const std::string& prefix);

// Whether address-space limits can be used in this build (not under
// AddressSanitizer, whose shadow memory needs terabytes of address space).
bool addressSpaceLimitsSupported();

}  // namespace rigmesh
