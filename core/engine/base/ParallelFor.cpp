#include "base/ParallelFor.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace rigmesh {

int parallelWorkers(int count, int threads) {
    return std::max(1, std::min(threads, count));
}

void parallelFor(int count, int threads,
                 const std::function<void(int begin, int end, int worker)>& task) {
    if (threads < 1)
        throw std::logic_error("Parallel work needs at least one thread, not " +
                               std::to_string(threads) + ".");
    if (count <= 0)
        return;
    const int workers = parallelWorkers(count, threads);
    std::vector<std::exception_ptr> errors(workers);
    const auto run = [&](int worker) {
        const int begin = static_cast<int>(static_cast<long long>(count) * worker / workers);
        const int end = static_cast<int>(static_cast<long long>(count) * (worker + 1) / workers);
        try {
            task(begin, end, worker);
        } catch (...) {
            errors[worker] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (int worker = 1; worker < workers; ++worker) {
        try {
            pool.emplace_back(run, worker);
        } catch (const std::system_error&) {
            run(worker);  // no thread available: the caller does this range itself
        }
    }
    run(0);
    for (std::thread& thread : pool)
        thread.join();
    for (const std::exception_ptr& error : errors)
        if (error)
            std::rethrow_exception(error);
}

}  // namespace rigmesh
