#include "base/ChildProcess.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <thread>

#include "base/ForwardedSignals.h"

namespace rigmesh {
namespace {

// Descriptors the parent hands over are moved to 10 and above first, so
// that placing them at 0-3 in the child never overwrites one another (a
// parent started with its standard input closed gets new files at 0).
constexpr int kFirstHighDescriptor = 10;

int highDescriptor(int fd) {
    if (fd < 0 || fd >= kFirstHighDescriptor)
        return fd;
    const int high = fcntl(fd, F_DUPFD_CLOEXEC, kFirstHighDescriptor);
    close(fd);
    return high;
}

// A temporary file without a name (O_TMPFILE; where the file system cannot,
// one unlinked at once): it disappears with its last descriptor, so no
// error path and no signal can leave it behind.
int anonymousTemporaryFile() {
    std::error_code error;
    std::filesystem::path folder = std::filesystem::temp_directory_path(error);
    if (error)
        folder = "/tmp";  // TMPDIR names a missing folder
    // Close-on-exec: no other child of this process inherits it (dup2 onto
    // the child's own descriptors clears the flag there).
    int fd = open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (fd < 0) {
        std::string pattern = (folder / "rigmesh-child-XXXXXX").string();
        fd = mkostemp(pattern.data(), O_CLOEXEC);
        if (fd >= 0)
            unlink(pattern.c_str());
    }
    return highDescriptor(fd);
}

// The last `maxBytes` of what the child wrote (its final message matters
// most), or with `fromStart` the first.
std::string readBack(int fd, std::size_t maxBytes, bool fromStart = false) {
    std::string text;
    const off_t size = lseek(fd, 0, SEEK_END);
    if (size < 0)
        return text;
    const off_t start =
        size > static_cast<off_t>(maxBytes) && !fromStart ? size - static_cast<off_t>(maxBytes) : 0;
    if (lseek(fd, start, SEEK_SET) != start)
        return text;
    const std::size_t wanted = std::min(maxBytes, static_cast<std::size_t>(size - start));
    text.resize(wanted);
    std::size_t got = 0;
    while (got < wanted) {
        const ssize_t n = read(fd, text.data() + got, wanted - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        got += static_cast<std::size_t>(n);
    }
    text.resize(got);
    return text;
}

int waitInterrupted(pid_t pid, int* status, int options, rusage* usage = nullptr) {
    int result;
    do {
        result = wait4(pid, status, options, usage);
    } while (result < 0 && errno == EINTR);
    return result;
}

double processorSeconds(const rusage& usage) {
    const auto seconds = [](const timeval& time) {
        return static_cast<double>(time.tv_sec) + 1e-6 * static_cast<double>(time.tv_usec);
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The child's environment: ours, and under AddressSanitizer (where RLIMIT_AS
// cannot be used) a resident-memory limit that ASan itself enforces.
std::vector<std::string> childEnvironment(const ChildLimits& limits) {
    std::vector<std::string> environment;
    std::string asanOptions;
    for (char** entry = environ; entry && *entry; ++entry) {
        if (std::strncmp(*entry, "ASAN_OPTIONS=", 13) == 0)
            asanOptions = *entry + 13;
        else
            environment.emplace_back(*entry);
    }
    if (limits.addressSpaceBytes > 0 && !addressSpaceLimitsSupported()) {
        if (!asanOptions.empty())
            asanOptions += ':';
        asanOptions += "allocator_may_return_null=1:hard_rss_limit_mb=" +
                       std::to_string(limits.addressSpaceBytes >> 20);
    }
    if (!asanOptions.empty())
        environment.push_back("ASAN_OPTIONS=" + asanOptions);
    return environment;
}

}  // namespace

bool addressSpaceLimitsSupported() {
#if defined(__SANITIZE_ADDRESS__)
    return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return false;
#else
    return true;
#endif
#else
    return true;
#endif
}

ChildOutcome runChildProcess(const std::string& program, const std::vector<std::string>& arguments,
                             const ChildLimits& limits) {
    ChildOutcome outcome;
    // Everything the child needs is prepared before fork: between fork and
    // exec only async-signal-safe calls are allowed (the caller may have threads).
    std::vector<std::string> storage;
    storage.reserve(arguments.size() + 1);
    storage.push_back(program);
    storage.insert(storage.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& argument : storage)
        argv.push_back(argument.data());
    argv.push_back(nullptr);
    std::vector<std::string> environmentStorage = childEnvironment(limits);
    std::vector<char*> envp;
    for (std::string& entry : environmentStorage)
        envp.push_back(entry.data());
    envp.push_back(nullptr);

    const int errorFd = anonymousTemporaryFile();
    const int resultFd = limits.maxResultBytes > 0 ? anonymousTemporaryFile() : -1;
    if (errorFd < 0 || (limits.maxResultBytes > 0 && resultFd < 0)) {
        outcome.standardError =
            "cannot create a temporary file: " + std::string(std::strerror(errno));
        if (errorFd >= 0)
            close(errorFd);
        if (resultFd >= 0)
            close(resultFd);
        return outcome;
    }
    auto closeFiles = [&] {
        close(errorFd);
        if (resultFd >= 0)
            close(resultFd);
    };
    // exec failure is reported through a close-on-exec pipe: it closes
    // unread on success and carries errno on failure.
    int execPipe[2];
    if (pipe2(execPipe, O_CLOEXEC) != 0) {
        outcome.standardError = "cannot create a pipe: " + std::string(std::strerror(errno));
        closeFiles();
        return outcome;
    }
    execPipe[0] = highDescriptor(execPipe[0]);
    execPipe[1] = highDescriptor(execPipe[1]);
    const int nullFd = highDescriptor(open("/dev/null", O_RDWR | O_CLOEXEC));
    const bool limitAddressSpace = limits.addressSpaceBytes > 0 && addressSpaceLimitsSupported();
    // With SIGCHLD ignored (a program can be started so; it survives exec)
    // the kernel reaps the child itself and its exit status is lost.
    struct sigaction childSignal {};
    sigaction(SIGCHLD, nullptr, &childSignal);
    if (childSignal.sa_handler == SIG_IGN)
        std::signal(SIGCHLD, SIG_DFL);
    const pid_t parent = getpid();
    const auto start = std::chrono::steady_clock::now();

    const pid_t pid = fork();
    if (pid == 0) {
        setpgid(0, 0);  // its own group: a timeout kills whatever it started too
        // Dies with the thread that started it, even when that is killed
        // with SIGKILL; if the parent is already gone, stop here.
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent)
            _exit(127);
        if (nullFd >= 0) {
            dup2(nullFd, STDIN_FILENO);
            dup2(nullFd, STDOUT_FILENO);
        }
        dup2(errorFd, STDERR_FILENO);
        // Descriptor 3 is the result file or nothing: not whatever the
        // parent happened to inherit there (ctest's own, a shell's).
        if (resultFd >= 0)
            dup2(resultFd, 3);
        else
            close(3);
        // No core dump: 1 byte, not 0, because a core_pattern that pipes
        // to a program (apport, systemd-coredump) ignores a limit of 0 and
        // keeps a dying child waiting on that program for seconds; the
        // kernel takes 1 as "no dump" there, and less than a page stops a
        // dump to a file too. 0 where the hard limit is 0 already.
        const rlimit oneByteCore{1, 1};
        const rlimit noCore{0, 0};
        if (setrlimit(RLIMIT_CORE, &oneByteCore) != 0)
            setrlimit(RLIMIT_CORE, &noCore);
        // A clean signal state: blocked signals and ignored ones survive
        // exec, and a parent may have been started with some (a CI runner
        // was). The signals the parent forwards (base/ForwardedSignals) and
        // the processor limit's SIGXCPU must end the child.
        for (const int stop : {SIGINT, SIGTERM, SIGHUP, SIGXCPU})
            signal(stop, SIG_DFL);
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
        if (limits.seconds > 0) {
            // The soft limit's SIGXCPU ends the child; the hard one a second
            // later kills a child that catches or ignores it all the same.
            const rlim_t cpu = static_cast<rlim_t>(std::ceil(std::min(limits.seconds, 1e7)));
            const rlimit processor{cpu, cpu + 1};
            setrlimit(RLIMIT_CPU, &processor);
        }
        if (limitAddressSpace) {
            const rlimit space{limits.addressSpaceBytes, limits.addressSpaceBytes};
            setrlimit(RLIMIT_AS, &space);
        }
        execve(argv[0], argv.data(), envp.data());
        const int failure = errno;
        [[maybe_unused]] const ssize_t written = write(execPipe[1], &failure, sizeof failure);
        _exit(127);
    }
    close(execPipe[1]);
    if (nullFd >= 0)
        close(nullFd);
    if (pid < 0) {
        outcome.standardError = "cannot start a process: " + std::string(std::strerror(errno));
        close(execPipe[0]);
        closeFiles();
        return outcome;
    }
    // The group exists before anything is forwarded to it, whichever of
    // parent and child runs first (one of the two calls fails harmlessly).
    setpgid(pid, pid);
    std::optional<ForwardedSignals> forwarding;
    forwarding.emplace(pid);

    int status = 0;
    rusage usage{};
    bool ended = false;
    auto pause = std::chrono::microseconds(500);
    const auto deadline =
        start +
        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(
                limits.seconds > 0 ? kWallClockFactor * std::min(limits.seconds, 1e7) : 0.0));
    while (!ended) {
        const int result = waitInterrupted(pid, &status, WNOHANG, &usage);
        if (result == pid) {
            ended = true;
        } else if (result < 0) {
            break;  // not our child any more (cannot happen unless SIGCHLD is ignored)
        } else if (std::chrono::steady_clock::now() >= deadline) {
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);  // in case it had not made its group yet
            waitInterrupted(pid, &status, 0, &usage);
            outcome.end = ChildOutcome::End::TimedOut;
            break;
        } else {
            std::this_thread::sleep_for(pause);
            pause = std::min(pause * 2, std::chrono::microseconds(20000));
        }
    }
    forwarding.reset();  // reaped: its group id may be anyone's now
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.processorSeconds = processorSeconds(usage);

    int execErrno = 0;
    const bool execFailed = read(execPipe[0], &execErrno, sizeof execErrno) == sizeof execErrno;
    close(execPipe[0]);
    outcome.standardError = readBack(errorFd, limits.maxErrorBytes);
    if (resultFd >= 0) {
        const off_t size = lseek(resultFd, 0, SEEK_END);
        outcome.resultTooLarge = size > static_cast<off_t>(limits.maxResultBytes);
        if (!outcome.resultTooLarge)
            outcome.result = readBack(resultFd, limits.maxResultBytes, true);
    }
    closeFiles();

    if (execFailed) {
        outcome.end = ChildOutcome::End::FailedToStart;
        outcome.standardError = "cannot run " + program + ": " + std::strerror(execErrno);
    } else if (outcome.end == ChildOutcome::End::TimedOut) {
        // set above
    } else if (ended && WIFEXITED(status)) {
        outcome.end = ChildOutcome::End::Exited;
        outcome.exitCode = WEXITSTATUS(status);
    } else if (ended && WIFSIGNALED(status) &&
               (WTERMSIG(status) == SIGXCPU ||
                (WTERMSIG(status) == SIGKILL && limits.seconds > 0 &&
                 processorSeconds(usage) >= std::ceil(std::min(limits.seconds, 1e7))))) {
        // Its processor time ran out: the soft limit's SIGXCPU, or the hard
        // limit's SIGKILL for a child that ignored that.
        outcome.end = ChildOutcome::End::TimedOut;
    } else if (ended && WIFSIGNALED(status)) {
        outcome.end = ChildOutcome::End::Signalled;
        outcome.signal = WTERMSIG(status);
    } else {
        outcome.end = ChildOutcome::End::FailedToStart;
        outcome.standardError = "lost track of the process running " + program;
    }
    return outcome;
}

std::string lastLineStartingWith(const std::string& text, const std::string& prefix) {
    std::string found;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos)
            end = text.size();
        if (text.compare(begin, prefix.size(), prefix) == 0)
            found = text.substr(begin + prefix.size(), end - begin - prefix.size());
        begin = end + 1;
    }
    return found;
}

}  // namespace rigmesh
