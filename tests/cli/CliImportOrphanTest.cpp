// Killing `rigmesh run` while its `rigmesh import` child reads a file (a CI
// timeout's SIGKILL, a SIGTERM, Ctrl+C) leaves no process and no temporary
// file behind: the child used to run on at 100% CPU, reparented to init,
// beside its rigmesh-XXXXXX folder.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "CliRunner.h"

extern char** environ;

namespace rigmesh::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A grid of n x n vertices as OBJ text: enough that reading it takes the
// import child a few seconds.
void writeLargeObj(const fs::path& path, int n) {
    std::ofstream out(path);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            out << "v " << i << ' ' << j << ' ' << ((i * 7 + j * 13) % 11) * 0.01 << '\n';
    for (int i = 0; i + 1 < n; ++i)
        for (int j = 0; j + 1 < n; ++j) {
            const int a = i * n + j + 1, b = a + 1, c = a + n, d = c + 1;
            out << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
        }
}

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The pids whose parent is `parent` and whose command line holds `word`.
std::vector<pid_t> childrenOf(pid_t parent, const std::string& word) {
    std::vector<pid_t> found;
    for (const fs::directory_entry& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos)
            continue;
        const std::string stat = fileText(entry.path() / "stat");
        const std::size_t close = stat.rfind(')');
        if (close == std::string::npos)
            continue;
        char state = 0;
        int ppid = 0;
        if (std::sscanf(stat.c_str() + close + 1, " %c %d", &state, &ppid) != 2 || ppid != parent)
            continue;
        std::string command = fileText(entry.path() / "cmdline");
        std::replace(command.begin(), command.end(), '\0', ' ');
        if (command.find(word) != std::string::npos)
            found.push_back(std::stoi(name));
    }
    return found;
}

// Running, not a zombie waiting for init to reap it.
bool running(pid_t pid) {
    const std::string stat = fileText("/proc/" + std::to_string(pid) + "/stat");
    const std::size_t close = stat.rfind(')');
    return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z';
}

pid_t startRun(const fs::path& recipe, const fs::path& temporary) {
    std::vector<std::string> environment;
    for (char** entry = environ; entry && *entry; ++entry)
        if (std::strncmp(*entry, "TMPDIR=", 7) != 0 &&
            std::strncmp(*entry, "RIGMESH_IMPORT_WORKER=", 22) != 0)
            environment.emplace_back(*entry);
    environment.push_back("TMPDIR=" + temporary.string());
    std::vector<char*> envp;
    for (std::string& entry : environment)
        envp.push_back(entry.data());
    envp.push_back(nullptr);
    std::string program = RIGMESH_CLI, run = "run", file = recipe.string();
    char* argv[] = {program.data(), run.data(), file.data(), nullptr};
    const pid_t pid = fork();
    if (pid == 0) {
        // As started from a terminal: the default action for every signal.
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        execve(argv[0], argv, envp.data());
        _exit(127);
    }
    return pid;
}

class ImportOrphans : public testing::TestWithParam<int> {
  protected:
    static void SetUpTestSuite() {
        folder() = scratch("orphans");
        fs::create_directories(folder());
        writeLargeObj(folder() / "grid.obj", 700);
        std::ofstream(folder() / "import.json")
            << R"({"format": "rigmesh-recipe", "version": 2, "steps": [)"
            << R"({"command": "import", "file": "grid.obj"}]})";
    }
    static void TearDownTestSuite() { fs::remove_all(folder()); }
    static fs::path& folder() {
        static fs::path path;
        return path;
    }
};

TEST_P(ImportOrphans, KillingTheParentMidImportLeavesNoChildAndNoTemporaryFile) {
    const int signal = GetParam();
    const fs::path temporary = folder() / ("tmp" + std::to_string(signal));
    fs::create_directories(temporary);
    const pid_t parent = startRun(folder() / "import.json", temporary);
    ASSERT_GT(parent, 0);
    std::vector<pid_t> children;
    for (const auto until = Clock::now() + std::chrono::seconds(20);
         children.empty() && Clock::now() < until;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        children = childrenOf(parent, " import ");
    }
    ASSERT_EQ(children.size(), 1u) << "the import child did not start";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // well into the read
    ASSERT_TRUE(running(children.front())) << "the import ended before the parent was killed";

    kill(parent, signal);
    int status = 0;
    waitpid(parent, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "the parent died of it";

    const auto deadline = Clock::now() + std::chrono::seconds(2);
    while (running(children.front()) && Clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const bool orphan = running(children.front());
    if (orphan)
        kill(children.front(), SIGKILL);  // leave the machine clean whatever the verdict
    EXPECT_FALSE(orphan) << "the import child outlived its parent by 2 s (" << strsignal(signal)
                         << ")";
    std::vector<std::string> left;
    for (const fs::directory_entry& entry : fs::directory_iterator(temporary))
        left.push_back(entry.path().filename().string());
    EXPECT_TRUE(left.empty()) << left.size() << " left in TMPDIR, e.g. " << left.front();
}

INSTANTIATE_TEST_SUITE_P(Signals, ImportOrphans, testing::Values(SIGKILL, SIGTERM, SIGINT),
                         [](const testing::TestParamInfo<int>& signal) {
                             return signal.param == SIGKILL   ? std::string("Kill")
                                    : signal.param == SIGTERM ? std::string("Term")
                                                              : std::string("Interrupt");
                         });

}  // namespace
}  // namespace rigmesh::test
