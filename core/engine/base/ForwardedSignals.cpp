#include "base/ForwardedSignals.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <mutex>

namespace rigmesh {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kSignalCount = sizeof kSignals / sizeof kSignals[0];
// Children waited for at once: one per thread that imports.
constexpr int kSlots = 64;

// The handler reads these without a lock: only lock-free atomics and
// dispositions written before it was installed.
std::atomic<pid_t> groups[kSlots];
struct sigaction previous[kSignalCount];
bool installed[kSignalCount];

std::mutex registryMutex;
int registered = 0;

int indexOf(int signal) {
    for (int k = 0; k < kSignalCount; ++k)
        if (kSignals[k] == signal)
            return k;
    return -1;
}

// Async-signal-safe: kill, sigaction and raise only.
void forwardSignal(int signal, siginfo_t* info, void* context) {
    const int savedErrno = errno;
    for (std::atomic<pid_t>& group : groups) {
        const pid_t id = group.load(std::memory_order_relaxed);
        if (id > 0)
            kill(-id, signal);
    }
    const int k = indexOf(signal);
    if (k >= 0) {
        const struct sigaction& before = previous[k];
        if (before.sa_flags & SA_SIGINFO) {
            if (before.sa_sigaction)
                before.sa_sigaction(signal, info, context);
        } else if (before.sa_handler == SIG_DFL) {
            // The default action: put it back and raise again; the signal is
            // blocked in here, so it arrives (and ends us) as we return.
            sigaction(signal, &before, nullptr);
            raise(signal);
        } else if (before.sa_handler != SIG_IGN) {
            before.sa_handler(signal);
        }
    }
    errno = savedErrno;
}

bool isOurs(const struct sigaction& action) {
    return (action.sa_flags & SA_SIGINFO) && action.sa_sigaction == &forwardSignal;
}

void install() {
    struct sigaction ours {};
    ours.sa_sigaction = &forwardSignal;
    ours.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&ours.sa_mask);
    for (int signal : kSignals)
        sigaddset(&ours.sa_mask, signal);
    for (int k = 0; k < kSignalCount; ++k) {
        struct sigaction current {};
        installed[k] = false;
        if (sigaction(kSignals[k], nullptr, &current) != 0 || isOurs(current))
            continue;
        // A program that ignores the signal (nohup) keeps ignoring it, and
        // so do its children.
        if (!(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_IGN)
            continue;
        previous[k] = current;
        installed[k] = sigaction(kSignals[k], &ours, nullptr) == 0;
    }
}

void uninstall() {
    for (int k = 0; k < kSignalCount; ++k) {
        if (!installed[k])
            continue;
        struct sigaction current {};
        // Someone who installed a handler after us keeps it.
        if (sigaction(kSignals[k], nullptr, &current) == 0 && isOurs(current))
            sigaction(kSignals[k], &previous[k], nullptr);
        installed[k] = false;
    }
}

}  // namespace

ForwardedSignals::ForwardedSignals(pid_t group) {
    const std::lock_guard lock(registryMutex);
    for (int s = 0; s < kSlots && group > 0; ++s) {
        pid_t free = 0;
        if (groups[s].compare_exchange_strong(free, group)) {
            slot_ = s;
            break;
        }
    }
    if (slot_ >= 0 && registered++ == 0)
        install();
}

ForwardedSignals::~ForwardedSignals() {
    if (slot_ < 0)
        return;
    const std::lock_guard lock(registryMutex);
    groups[slot_].store(0);
    if (--registered == 0)
        uninstall();
}

}  // namespace rigmesh
