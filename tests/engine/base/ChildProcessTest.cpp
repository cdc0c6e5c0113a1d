// runChildProcess: how a child ended (exit code, crash, timeout, memory
// limit, missing program) and what it wrote to standard error.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "base/ChildProcess.h"

namespace rigmesh {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

ChildOutcome shell(const std::string& script, ChildLimits limits = {}) {
    return runChildProcess("/bin/sh", {"-c", script}, limits);
}

// The whole outcome, for a failure message.
std::string describe(const ChildOutcome& outcome) {
    static const char* const ends[] = {"exited", "signalled", "timed out", "failed to start"};
    std::ostringstream text;
    text << ends[static_cast<int>(outcome.end)] << " (exit code " << outcome.exitCode << ", signal "
         << outcome.signal << ") after " << outcome.seconds << " s, " << outcome.processorSeconds
         << " s of processor time; standard error: \"" << outcome.standardError << '"';
    return text.str();
}

TEST(ChildProcess, ExitCodeAndStandardErrorComeBack) {
    const ChildOutcome outcome = shell("echo 'noise' >&2; echo 'rigmesh: bad file' >&2; exit 3");
    ASSERT_EQ(outcome.end, ChildOutcome::End::Exited);
    EXPECT_EQ(outcome.exitCode, 3);
    EXPECT_EQ(lastLineStartingWith(outcome.standardError, "rigmesh: "), "bad file");
}

TEST(ChildProcess, StandardOutputIsDiscarded) {
    const ChildOutcome outcome = shell("echo 'only to stdout'");
    ASSERT_EQ(outcome.end, ChildOutcome::End::Exited);
    EXPECT_EQ(outcome.exitCode, 0);
    EXPECT_TRUE(outcome.standardError.empty());
}

TEST(ChildProcess, CrashIsReportedWithItsSignal) {
    const ChildOutcome outcome = shell("kill -SEGV $$");
    ASSERT_EQ(outcome.end, ChildOutcome::End::Signalled);
    EXPECT_EQ(outcome.signal, SIGSEGV);
}

TEST(ChildProcess, HangIsKilledAtTheTimeLimit) {
    ChildLimits limits;
    limits.seconds = 0.3;
    const ChildOutcome outcome = shell("sleep 30", limits);
    EXPECT_EQ(outcome.end, ChildOutcome::End::TimedOut);
    EXPECT_GE(outcome.seconds, 0.3);
    EXPECT_LT(outcome.seconds, 10.0);
}

// The kernel charges processor time a whole scheduler tick at a time (at most
// 10 ms, CONFIG_HZ >= 100), so RLIMIT_CPU can fire up to a tick before the
// child has run for the limit: CI once measured 0.998 s of wall clock.
constexpr double kSchedulerTick = 0.01;

// `script` busy for longer than a 1 s processor-time limit: a timeout, at
// least that long (less one tick) and well before the wall-clock bound a
// waiting child gets.
void expectStoppedByProcessorTime(const std::string& script) {
    ChildLimits limits;
    limits.seconds = 1.0;
    const ChildOutcome outcome = shell(script, limits);
    EXPECT_EQ(outcome.end, ChildOutcome::End::TimedOut) << describe(outcome);
    EXPECT_GE(outcome.seconds, limits.seconds - kSchedulerTick) << describe(outcome);
    EXPECT_LT(outcome.seconds, kWallClockFactor * limits.seconds + 1.0) << describe(outcome);
    // Never past the hard limit, a second after the soft one.
    EXPECT_LT(outcome.processorSeconds, limits.seconds + 1.5) << describe(outcome);
}

// The limit is the child's processor time: a busy loop is stopped once it
// has computed that long, however busy the machine is.
TEST(ChildProcess, BusyLoopIsStoppedByItsProcessorTime) {
    expectStoppedByProcessorTime("while :; do :; done");
}

// A child that ignores SIGXCPU is killed by the hard limit a second later:
// still a timeout, not a crash.
TEST(ChildProcess, BusyLoopIgnoringTheProcessorSignalStillTimesOut) {
    expectStoppedByProcessorTime("trap '' XCPU; while :; do :; done");
}

// A crashing child dumps no core: not to a file, nor to a program that a
// core_pattern pipes to, which would keep it from ending for seconds. The
// kernel takes a limit of 1 byte for that (0 is ignored by a pipe).
TEST(ChildProcess, ChildDumpsNoCoreEvenThroughAPipe) {
    ChildLimits limits;
    limits.maxResultBytes = 4096;
    const ChildOutcome outcome = shell("cat /proc/self/limits > /dev/fd/3", limits);
    ASSERT_EQ(outcome.end, ChildOutcome::End::Exited) << describe(outcome);
    std::istringstream lines(outcome.result);
    std::string line;
    while (std::getline(lines, line) && line.rfind("Max core file size", 0) != 0) {
    }
    std::istringstream values(line.substr(std::string("Max core file size").size()));
    std::string soft, hard;
    values >> soft >> hard;
    // 0 where our own hard limit is 0 already (it cannot be raised).
    rlimit ours{};
    getrlimit(RLIMIT_CORE, &ours);
    const std::string expected = ours.rlim_max == 0 ? "0" : "1";
    EXPECT_EQ(soft, expected) << line;
    EXPECT_EQ(hard, expected) << line;
}

// A program may be started with SIGCHLD ignored (which survives exec); the
// kernel would then reap the child itself and its exit status be lost.
TEST(ChildProcess, ExitCodeComesBackWhereChildSignalsWereIgnored) {
    struct sigaction before {};
    sigaction(SIGCHLD, nullptr, &before);
    std::signal(SIGCHLD, SIG_IGN);
    const ChildOutcome outcome = shell("exit 3");
    sigaction(SIGCHLD, &before, nullptr);
    ASSERT_EQ(outcome.end, ChildOutcome::End::Exited) << describe(outcome);
    EXPECT_EQ(outcome.exitCode, 3);
}

TEST(ChildProcess, MissingProgramFailsToStartWithTheReason) {
    const ChildOutcome outcome = runChildProcess("/nonexistent/rigmesh", {}, {});
    ASSERT_EQ(outcome.end, ChildOutcome::End::FailedToStart);
    EXPECT_NE(outcome.standardError.find("/nonexistent/rigmesh"), std::string::npos);
}

TEST(ChildProcess, AddressSpaceLimitStopsARunawayAllocation) {
    if (!addressSpaceLimitsSupported())
        GTEST_SKIP() << "address-space limits are off under AddressSanitizer";
    // dd's block buffer is allocated at once: 1 GiB does not fit in 256 MiB.
    ChildLimits limits;
    limits.addressSpaceBytes = 256u << 20;
    const ChildOutcome limited =
        runChildProcess("/bin/dd", {"if=/dev/zero", "of=/dev/null", "bs=1G", "count=1"}, limits);
    ASSERT_EQ(limited.end, ChildOutcome::End::Exited);
    EXPECT_NE(limited.exitCode, 0);
    EXPECT_NE(limited.standardError.find("memory"), std::string::npos) << limited.standardError;
    // Without the limit the same command succeeds.
    const ChildOutcome free =
        runChildProcess("/bin/dd", {"if=/dev/zero", "of=/dev/null", "bs=1G", "count=1"}, {});
    ASSERT_EQ(free.end, ChildOutcome::End::Exited);
    EXPECT_EQ(free.exitCode, 0) << free.standardError;
}

TEST(ChildProcess, ResultComesBackThroughDescriptorThree) {
    ChildLimits limits;
    limits.maxResultBytes = 64;
    const ChildOutcome outcome = shell("printf 'parts' > /dev/fd/3; echo 'to stdout'", limits);
    ASSERT_EQ(outcome.end, ChildOutcome::End::Exited);
    EXPECT_EQ(outcome.exitCode, 0) << outcome.standardError;
    EXPECT_EQ(outcome.result, "parts");
    EXPECT_FALSE(outcome.resultTooLarge);

    limits.maxResultBytes = 4;
    const ChildOutcome large = shell("printf 'too many' >&3", limits);
    EXPECT_TRUE(large.resultTooLarge);
    EXPECT_TRUE(large.result.empty());
}

TEST(ChildProcess, WithoutAResultDescriptorThreeIsClosed) {
    const ChildOutcome outcome = shell("printf 'x' >&3 && exit 0 || exit 7");
    ASSERT_EQ(outcome.end, ChildOutcome::End::Exited);
    EXPECT_EQ(outcome.exitCode, 7);
}

// A process of this test runs `script` through runChildProcess (with TMPDIR
// a fresh folder) and is then ended by `signal`. The script gets a file
// name as $0 and writes `pidCount` pids there, one per line; those still
// running 2 s later are survivors, and so is any file left in TMPDIR.
struct Stopped {
    std::vector<pid_t> survivors;
    std::vector<std::string> leftFiles;
};

bool running(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    const std::size_t close = text.rfind(')');
    // A zombie has ended; only its parent (init here) has not reaped it yet.
    return close != std::string::npos && close + 2 < text.size() && text[close + 2] != 'Z';
}

// Whether the process runs the program `sleep` (its name in /proc).
bool runsSleep(pid_t pid) {
    std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
    std::string name;
    return std::getline(comm, name) && name == "sleep";
}

Stopped stopParentDuring(const std::string& script, std::size_t pidCount, int signal) {
    const fs::path folder =
        fs::temp_directory_path() / ("rigmesh_child_test_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    const fs::path temporary = folder / "tmp";
    fs::create_directories(temporary);
    const fs::path pids = folder / "pids";
    const pid_t parent = fork();
    if (parent == 0) {
        setenv("TMPDIR", temporary.c_str(), 1);
        // As a program started from a terminal (a background job of a
        // script would ignore SIGINT; a test runner may block signals).
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
        ChildLimits limits;
        limits.seconds = 60;
        limits.maxResultBytes = 1024;
        runChildProcess("/bin/sh", {"-c", script, pids.string()}, limits);
        _exit(0);
    }
    // The script writes its pids once it runs.
    std::vector<pid_t> started;
    for (const auto until = Clock::now() + std::chrono::seconds(10);
         started.size() < pidCount && Clock::now() < until;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        started.clear();
        std::ifstream in(pids);
        for (pid_t pid; in >> pid;)
            started.push_back(pid);
    }
    EXPECT_EQ(started.size(), pidCount) << "the script did not start";
    // A pid is written as soon as its process is forked; wait until each one
    // runs `sleep`, so that `env --default-signal` has already restored the
    // default signal actions it is there for (under load it may not have).
    for (const auto until = Clock::now() + std::chrono::seconds(10);
         !std::all_of(started.begin(), started.end(), runsSleep) && Clock::now() < until;)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_TRUE(std::all_of(started.begin(), started.end(), runsSleep))
        << "a started process never ran sleep";
    kill(parent, signal);
    int status = 0;
    waitpid(parent, &status, 0);
    Stopped stopped;
    const auto deadline = Clock::now() + std::chrono::seconds(2);
    do {
        stopped.survivors.clear();
        for (pid_t pid : started)
            if (running(pid))
                stopped.survivors.push_back(pid);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    } while (!stopped.survivors.empty() && Clock::now() < deadline);
    for (pid_t pid : stopped.survivors)
        kill(pid, SIGKILL);  // leave the machine clean whatever the verdict
    for (const fs::directory_entry& entry : fs::directory_iterator(temporary))
        stopped.leftFiles.push_back(entry.path().filename().string());
    fs::remove_all(folder);
    return stopped;
}

TEST(ChildProcess, ChildDiesWhenItsParentIsKilled) {
    // SIGKILL cannot be forwarded: the child goes by PR_SET_PDEATHSIG.
    const Stopped stopped =
        stopParentDuring("echo $$ > \"$0.tmp\"; mv \"$0.tmp\" \"$0\"; exec sleep 60", 1, SIGKILL);
    EXPECT_TRUE(stopped.survivors.empty()) << stopped.survivors.size() << " still running";
    EXPECT_TRUE(stopped.leftFiles.empty()) << stopped.leftFiles.front();
}

TEST(ChildProcess, StopSignalsReachTheChildsWholeGroup) {
    // SIGTERM and SIGINT go on to the child's process group, so what the
    // child started goes too. (A shell starts its background commands with
    // SIGINT ignored; env --default-signal gives the grandchild the default
    // action back, as a program the child starts directly has.)
    for (int signal : {SIGTERM, SIGINT}) {
        const Stopped stopped = stopParentDuring(
            "env --default-signal sleep 60 & echo $! > \"$0.tmp\"; echo $$ >> \"$0.tmp\"; mv "
            "\"$0.tmp\" \"$0\"; "
            "exec sleep 60",
            2, signal);
        EXPECT_TRUE(stopped.survivors.empty())
            << strsignal(signal) << ": " << stopped.survivors.size() << " still running";
        EXPECT_TRUE(stopped.leftFiles.empty()) << stopped.leftFiles.front();
    }
}

TEST(ChildProcess, LastLineStartingWithFindsTheLastMatch) {
    EXPECT_EQ(lastLineStartingWith("a: 1\nb: 2\na: 3", "a: "), "3");
    EXPECT_EQ(lastLineStartingWith("nothing here\n", "a: "), "");
}

}  // namespace
}  // namespace rigmesh
