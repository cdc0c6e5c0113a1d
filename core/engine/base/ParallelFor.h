// The engine's one way to run work on several threads: [0, count) is split
// into `threads` contiguous ranges (fixed by count and threads alone, never by
// timing), each run on its own std::thread (the caller's thread takes the
// first), all are joined, and the first exception any range threw (in range
// order) is rethrown in the caller. No worker ever terminates the program.
#pragma once

#include <functional>

namespace rigmesh {

// task(begin, end, worker) handles [begin, end); worker is in [0, workers) and
// identifies per-thread scratch space. Uses min(threads, count) workers (at
// least one); count <= 0 runs nothing. Throws std::logic_error if threads < 1.
void parallelFor(int count, int threads,
                 const std::function<void(int begin, int end, int worker)>& task);

// The number of workers parallelFor(count, threads, ...) uses.
int parallelWorkers(int count, int threads);

}  // namespace rigmesh
