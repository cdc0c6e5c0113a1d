// Runs one fuzz target under GoogleTest: first every saved regression input
// (tests/data/fuzz/<target>/), then mutated seeds until the time budget is
// spent. `check` gets each input and says whether it was accepted with a
// valid result or rejected with the project's error type and a message, or
// what is wrong. Any other exception, a check
// problem or an input running past the per-input bound fails the test,
// printing the input and writing it to RIGMESH_FUZZ_OUTPUT (default: the
// build's tests/fuzz/failures) so it can become a regression input. A crash
// leaves the input in that folder as <target>-current.<ext>.
//
// Environment: RIGMESH_FUZZ_SECONDS (budget per target, default 15),
// RIGMESH_FUZZ_SEED (default 20261123), RIGMESH_FUZZ_INPUT_SECONDS (bound per
// input, default 5; times 10 in sanitizer builds).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "Mutator.h"

namespace rigmesh::fuzz {

// What one input did: accepted (problem empty, rejected false), rejected with
// the project's error and a message (rejected true), or went wrong (problem).
struct FuzzVerdict {
    bool rejected = false;
    std::string problem;
};

struct FuzzTarget {
    std::string name;       // also the folder of its regression inputs
    std::string extension;  // of saved inputs: "json", "svg", "rigmesh"
    InputKind kind;
    std::vector<std::string> seeds;
    std::function<FuzzVerdict(const std::string& input)> check;
};

struct FuzzSummary {
    int regressionInputs = 0;
    int mutatedInputs = 0;
    int rejected = 0;                   // inputs that threw the project's error
    std::vector<std::string> failures;  // saved paths
};

// Runs the target; adds GoogleTest failures. Returns the counts.
// `inputSeconds` > 0 is this target's per-input bound instead of the
// default above (a whole modelling session is one input of some targets).
FuzzSummary runFuzzTarget(const FuzzTarget& target, double inputSeconds = 0.0);

// Reads a whole file (throws std::runtime_error if it cannot).
std::string readFile(const std::string& path);
// Every regular file under `folder` with `extension`, sorted.
std::vector<std::string> filesIn(const std::string& folder, const std::string& extension);

}  // namespace rigmesh::fuzz
