#include "FuzzHarness.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace rigmesh::fuzz {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double environmentNumber(const char* name, double fallback) {
    const char* text = std::getenv(name);
    if (!text || !*text)
        return fallback;
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    return end != text && *end == '\0' && value >= 0 ? value : fallback;
}

double inputBoundSeconds(double targetSeconds) {
#ifdef RIGMESH_FUZZ_SANITIZED
    constexpr double kSlowdown = 10;  // Debug + ASan/UBSan
#else
    constexpr double kSlowdown = 1;
#endif
    return kSlowdown * (targetSeconds > 0.0 ? targetSeconds
                                            : environmentNumber("RIGMESH_FUZZ_INPUT_SECONDS", 5));
}

fs::path outputFolder() {
    const char* folder = std::getenv("RIGMESH_FUZZ_OUTPUT");
    return folder && *folder ? fs::path(folder) : fs::path(RIGMESH_FUZZ_DEFAULT_OUTPUT);
}

void writeFile(const fs::path& path, const std::string& bytes) {
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The input, printable: C escapes for other bytes, cut after 4 kB.
std::string printable(const std::string& input) {
    std::ostringstream out;
    const std::size_t shown = std::min<std::size_t>(input.size(), 4096);
    for (std::size_t i = 0; i < shown; ++i) {
        const auto c = static_cast<unsigned char>(input[i]);
        if (c == '\\')
            out << "\\\\";
        else if (c >= 32 && c < 127)
            out << input[i];
        else if (c == '\n')
            out << "\\n";
        else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            out << escaped;
        }
    }
    if (shown < input.size())
        out << "... (" << input.size() << " bytes in all)";
    return out.str();
}

// The path of the input being run, for the crash handler (async-signal-safe:
// a fixed buffer written before each input).
char gCurrentInputPath[4096];

#ifndef RIGMESH_FUZZ_SANITIZED  // the sanitizers report crashes themselves
void reportCrash(int signal) {
    const char message[] = "\nfuzz: crashed on the input saved at ";
    [[maybe_unused]] auto a = ::write(2, message, sizeof message - 1);
    [[maybe_unused]] auto b = ::write(2, gCurrentInputPath, std::strlen(gCurrentInputPath));
    [[maybe_unused]] auto c = ::write(2, "\n", 1);
    std::raise(signal);  // SA_RESETHAND restored the default action
}
#endif

// Ends the process if one input runs far past its bound (a hang): the input
// is already on disk as <target>-current.
class Watchdog {
  public:
    explicit Watchdog(double limitSeconds) : limit_(limitSeconds), thread_([this] { watch(); }) {}
    ~Watchdog() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    void started() { start_ = Clock::now().time_since_epoch().count(); }
    void finished() { start_ = 0; }

  private:
    void watch() {
        std::unique_lock lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stop_; })) {
            const auto start = start_.load();
            if (start == 0)
                continue;
            const double seconds = std::chrono::duration<double>(Clock::now().time_since_epoch() -
                                                                 Clock::duration(start))
                                       .count();
            if (seconds > limit_) {
                std::fprintf(stderr,
                             "\nfuzz: an input ran %.0f s (limit %.0f s); it is saved at %s\n",
                             seconds, limit_, gCurrentInputPath);
                std::fflush(stderr);
                std::_Exit(1);
            }
        }
    }

    double limit_;
    std::atomic<Clock::rep> start_{0};
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> filesIn(const std::string& folder, const std::string& extension) {
    std::vector<std::string> out;
    if (!fs::is_directory(folder))
        return out;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().extension() == "." + extension)
            out.push_back(entry.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

FuzzSummary runFuzzTarget(const FuzzTarget& target, double inputSeconds) {
    FuzzSummary summary;
    const double budget = environmentNumber("RIGMESH_FUZZ_SECONDS", 15);
    const auto seed = static_cast<std::uint64_t>(environmentNumber("RIGMESH_FUZZ_SEED", 20261123));
    const double bound = inputBoundSeconds(inputSeconds);
    const fs::path output = outputFolder();
    const fs::path current = output / (target.name + "-current." + target.extension);
    std::snprintf(gCurrentInputPath, sizeof gCurrentInputPath, "%s", current.c_str());
    fs::create_directories(output);
#ifndef RIGMESH_FUZZ_SANITIZED  // the sanitizers report crashes themselves
    // On an alternate stack, so that a stack overflow is reported too.
    static std::vector<char> alternateStack(1 << 16);
    stack_t stack{};
    stack.ss_sp = alternateStack.data();
    stack.ss_size = alternateStack.size();
    ::sigaltstack(&stack, nullptr);
    struct sigaction action {};
    action.sa_handler = reportCrash;
    action.sa_flags = SA_ONSTACK | SA_RESETHAND;
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
        ::sigaction(signal, &action, nullptr);
#endif
    Watchdog watchdog(4 * bound);

    const auto fail = [&](const std::string& input, const std::string& problem) {
        const std::size_t hash = std::hash<std::string>{}(input);
        const fs::path saved = output / (target.name + "-" + std::to_string(hash % 100000000) +
                                         "." + target.extension);
        writeFile(saved, input);
        summary.failures.push_back(saved.string());
        ADD_FAILURE() << target.name << ": " << problem << "\n  input saved at " << saved.string()
                      << "\n  input: " << printable(input);
    };
    const auto runOne = [&](const std::string& input) {
        writeFile(current, input);
        watchdog.started();
        const auto start = Clock::now();
        FuzzVerdict verdict;
        try {
            verdict = target.check(input);
        } catch (const std::exception& e) {
            verdict.problem = std::string("unexpected exception: ") + e.what();
        } catch (...) {
            verdict.problem = "unexpected exception of an unknown type";
        }
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        watchdog.finished();
        if (verdict.problem.empty() && seconds > bound)
            verdict.problem =
                "took " + std::to_string(seconds) + " s (bound " + std::to_string(bound) + " s)";
        summary.rejected += verdict.rejected ? 1 : 0;
        if (verdict.problem.empty())
            return;
        fail(input, verdict.problem);
    };

    for (const std::string& path :
         filesIn(std::string(RIGMESH_TEST_DATA) + "/fuzz/" + target.name, target.extension)) {
        runOne(readFile(path));
        ++summary.regressionInputs;
    }
    for (const std::string& input : target.seeds)
        runOne(input);

    Mutator mutator(target.kind, target.seeds, seed);
    const auto end = Clock::now() + std::chrono::duration<double>(budget);
    // Stop after 20 failures: they are usually one defect.
    while (Clock::now() < end && summary.failures.size() < 20) {
        runOne(mutator.next());
        ++summary.mutatedInputs;
    }
    fs::remove(current);
    std::printf(
        "fuzz %s: %d regression inputs, %d seeds, %d mutated inputs (%d rejected with a "
        "message), %zu failures; seed %llu, %.0f s\n",
        target.name.c_str(), summary.regressionInputs, static_cast<int>(target.seeds.size()),
        summary.mutatedInputs, summary.rejected, summary.failures.size(),
        static_cast<unsigned long long>(seed), budget);
    return summary;
}

}  // namespace rigmesh::fuzz
