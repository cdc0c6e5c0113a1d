// Runs the rigmesh executable and captures its exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rigmesh::test {

struct CliResult {
    int exitCode = -1;
    std::string out, err;
};

inline std::string readWholeFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// `arguments` are appended to the CLI path as given (quote them yourself).
inline CliResult runCli(const std::string& arguments) {
    const auto folder = std::filesystem::temp_directory_path();
    const auto outPath = folder / ("rigmesh_cli_out_" + std::to_string(::getpid()));
    const auto errPath = folder / ("rigmesh_cli_err_" + std::to_string(::getpid()));
    const std::string command = std::string("'") + RIGMESH_CLI + "' " + arguments + " >'" +
                                outPath.string() + "' 2>'" + errPath.string() + "'";
    int status = std::system(command.c_str());
    CliResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readWholeFile(outPath);
    result.err = readWholeFile(errPath);
    std::filesystem::remove(outPath);
    std::filesystem::remove(errPath);
    return result;
}

// A path in this test process's scratch folder (created on first use): one
// folder per process, since CTest runs tests in parallel processes.
inline std::filesystem::path scratch(const std::string& name) {
    std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("rigmesh_cli_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    return folder / name;
}

// A path quoted for the shell runCli goes through.
inline std::string quoted(const std::filesystem::path& path) {
    return "'" + path.string() + "'";
}

}  // namespace rigmesh::test
