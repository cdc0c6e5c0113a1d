// The rigmesh command line's one path from an exception to a message and an
// exit status (app/cli/CommandFailure.h): bad input exits 1 with its
// message, a programming error exits 3 as an internal error.
#include <gtest/gtest.h>

#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>

#include "CommandFailure.h"
#include "base/Error.h"

namespace {

struct Reported {
    int status = -1;
    std::string text;
};

template <typename Exception>
Reported reportOf(const Exception& thrown) {
    std::FILE* out = std::tmpfile();
    Reported reported;
    reported.status = rigmesh::cli::reportFailure(std::make_exception_ptr(thrown), out);
    std::rewind(out);
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, out))
        reported.text += buffer;
    std::fclose(out);
    return reported;
}

TEST(CliCommandFailure, BadInputPrintsItsMessageAndExitsOne) {
    const rigmesh::Error error("the stroke crosses itself");
    const Reported reported = reportOf(error);
    EXPECT_EQ(reported.status, 1);
    EXPECT_EQ(reported.status, rigmesh::cli::kExitBadInput);
    EXPECT_EQ(reported.text, std::string("rigmesh: ") + error.what() + "\n");
}

TEST(CliCommandFailure, LogicErrorIsAnInternalErrorWithExitStatusThree) {
    const Reported reported = reportOf(std::logic_error("triangles are not adjacent"));
    EXPECT_EQ(reported.status, 3);
    EXPECT_EQ(reported.status, rigmesh::cli::kExitInternalError);
    EXPECT_EQ(reported.text, "rigmesh: internal error: triangles are not adjacent\n");
}

TEST(CliCommandFailure, LibraryExceptionIsAnInternalError) {
    const Reported reported = reportOf(std::runtime_error("a library gave up"));
    EXPECT_EQ(reported.status, rigmesh::cli::kExitInternalError);
    EXPECT_EQ(reported.text, "rigmesh: internal error: a library gave up\n");
}

TEST(CliCommandFailure, OutOfMemoryIsSaidAndExitsOne) {
    const Reported reported = reportOf(std::bad_alloc());
    EXPECT_EQ(reported.status, rigmesh::cli::kExitBadInput);
    EXPECT_EQ(reported.text, "rigmesh: out of memory\n");
}

TEST(CliCommandFailure, ExceptionOfUnknownTypeIsAnInternalError) {
    const Reported reported = reportOf(42);
    EXPECT_EQ(reported.status, rigmesh::cli::kExitInternalError);
    EXPECT_EQ(reported.text, "rigmesh: internal error: an exception of unknown type\n");
}

TEST(CliCommandFailure, ExitStatusesAreDistinct) {
    using namespace rigmesh::cli;
    EXPECT_EQ(kExitSuccess, 0);
    EXPECT_EQ(kExitUsage, 2);  // what `rigmesh frobnicate` exits with (CliBuild)
    EXPECT_NE(kExitInternalError, kExitBadInput);
    EXPECT_NE(kExitInternalError, kExitUsage);
}

}  // namespace
