// What the small programs that write the tests' expectations (expected_pose,
// expected_clips, posed_vertices) share: writing their JSON and reporting a
// failure as "program: reason" with exit status 1.
#pragma once

#include <cstdio>
#include <exception>
#include <fstream>
#include <nlohmann/json.hpp>

namespace rigmesh::test {

// `out` as indented JSON in `path`; false, said on stderr, when it cannot be written.
inline bool writeJson(const nlohmann::json& out, const char* path, const char* program) {
    std::ofstream file(path);
    file << out.dump(1) << "\n";
    if (!file.flush()) {
        std::fprintf(stderr, "%s: cannot write %s\n", program, path);
        return false;
    }
    return true;
}

// main() of such a program: `run`'s exit status, or 1 after printing an
// exception's reason.
inline int runProgram(const char* program, int (*run)(int, char**), int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: %s\n", program, error.what());
        return 1;
    }
}

}  // namespace rigmesh::test
