// runChildProcess: how a child ended (exit code, crash, timeout, memory
// limit, missing program) and what it wrote to standard error.
#include <gtest/gtest.h>

#include <csignal>

#include "base/ChildProcess.h"

namespace rigmesh {
namespace {

ChildOutcome shell(const std::string& script, ChildLimits limits = {}) {
    return runChildProcess("/bin/sh", {"-c", script}, limits);
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

TEST(ChildProcess, LastLineStartingWithFindsTheLastMatch) {
    EXPECT_EQ(lastLineStartingWith("a: 1\nb: 2\na: 3", "a: "), "3");
    EXPECT_EQ(lastLineStartingWith("nothing here\n", "a: "), "");
}

}  // namespace
}  // namespace rigmesh
