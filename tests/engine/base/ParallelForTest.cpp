// parallelFor: every index once, ranges fixed by count and threads, and a
// worker's exception reaching the caller instead of terminating the program.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "base/Error.h"
#include "base/ParallelFor.h"

namespace rigmesh {
namespace {

TEST(ParallelFor, VisitsEveryIndexExactlyOnce) {
    for (const int threads : {1, 2, 3, 8}) {
        for (const int count : {0, 1, 2, 7, 1000}) {
            std::vector<std::atomic<int>> visits(count);
            parallelFor(count, threads, [&](int begin, int end, int) {
                for (int i = begin; i < end; ++i)
                    ++visits[i];
            });
            for (int i = 0; i < count; ++i)
                EXPECT_EQ(visits[i].load(), 1) << "index " << i << ", " << threads << " threads";
        }
    }
}

TEST(ParallelFor, RangesAreContiguousAndOneWorkerEach) {
    const int count = 10, threads = 3;
    std::vector<int> owner(count, -1);
    parallelFor(count, threads, [&](int begin, int end, int worker) {
        for (int i = begin; i < end; ++i)
            owner[i] = worker;
    });
    EXPECT_EQ(owner, (std::vector<int>{0, 0, 0, 1, 1, 1, 2, 2, 2, 2}));
    EXPECT_EQ(parallelWorkers(count, threads), 3);
    EXPECT_EQ(parallelWorkers(2, 8), 2);
    EXPECT_EQ(parallelWorkers(0, 8), 1);
}

TEST(ParallelFor, ResultDoesNotDependOnTheThreadCount) {
    const int count = 5000;
    const auto squares = [&](int threads) {
        std::vector<double> out(count);
        parallelFor(count, threads, [&](int begin, int end, int) {
            for (int i = begin; i < end; ++i)
                out[i] = 0.5 * i * i;
        });
        return out;
    };
    const std::vector<double> single = squares(1);
    for (const int threads : {2, 3, 7})
        EXPECT_EQ(squares(threads), single) << threads << " threads";
}

TEST(ParallelFor, WorkerExceptionReachesTheCaller) {
    std::atomic<int> finished{0};
    try {
        parallelFor(100, 4, [&](int begin, int end, int worker) {
            if (worker == 2)
                throw Error("range " + std::to_string(begin) + "-" + std::to_string(end));
            ++finished;
        });
        ADD_FAILURE() << "the worker's exception was lost";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "range 50-75");
    }
    EXPECT_EQ(finished.load(), 3);  // the other workers still ran and were joined
}

TEST(ParallelFor, FirstFailingRangeWinsWhenSeveralThrow) {
    EXPECT_THROW(parallelFor(40, 4,
                             [](int, int, int worker) {
                                 if (worker == 1)
                                     throw std::logic_error("first");
                                 if (worker == 3)
                                     throw std::runtime_error("later");
                             }),
                 std::logic_error);
}

TEST(ParallelFor, CallerThreadExceptionIsRethrownAfterJoining) {
    std::atomic<int> finished{0};
    EXPECT_THROW(parallelFor(10, 2,
                             [&](int, int, int worker) {
                                 if (worker == 0)
                                     throw Error("caller");
                                 ++finished;
                             }),
                 Error);
    EXPECT_EQ(finished.load(), 1);
}

TEST(ParallelFor, RejectsFewerThanOneThread) {
    EXPECT_THROW(parallelFor(10, 0, [](int, int, int) {}), std::logic_error);
}

}  // namespace
}  // namespace rigmesh
