// Wall-clock milliseconds for the timings results report (StageTimings,
// merge, cut and bone edit statistics).
#pragma once

#include <chrono>

namespace rigmesh {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace rigmesh
