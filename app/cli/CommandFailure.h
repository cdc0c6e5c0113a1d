// The one place where the rigmesh command line turns an exception into its
// message on standard error and its exit status (docs/ARCHITECTURE.md,
// "Errors"; packaging/man/rigmesh.1, EXIT STATUS).
#pragma once

#include <cstdio>
#include <exception>

namespace rigmesh::cli {

// The exit statuses of rigmesh.
enum ExitStatus : int {
    kExitSuccess = 0,
    // Bad input (a rigmesh::Error: a stroke that crosses itself, a corrupt
    // file, a failed step) or too little memory for it.
    kExitBadInput = 1,
    // No command, an unknown one.
    kExitUsage = 2,
    // A programming error or a library's failure (std::logic_error and any
    // other exception): a bug to report, not the user's input.
    kExitInternalError = 3,
};

// Writes "rigmesh: <reason>" for `thrown` to `out` and returns the exit
// status: an Error's message and kExitBadInput; "out of memory" and
// kExitBadInput for std::bad_alloc; "internal error: <what>" and
// kExitInternalError for anything else.
int reportFailure(const std::exception_ptr& thrown, std::FILE* out = stderr);

}  // namespace rigmesh::cli
