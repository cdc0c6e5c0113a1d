#!/usr/bin/env bash
# Builds the Google Benchmark programs in a Release configuration
# (build/release-bench) and runs them, printing the console tables and writing
# JSON results to build/release-bench/results/.
#
# Usage: scripts/run-benchmarks.sh [extra Google Benchmark flags...]
#   e.g. scripts/run-benchmarks.sh --benchmark_filter=Pipeline
# Environment: REPETITIONS (default 3), JOBS (default: nproc).
set -euo pipefail

cd "$(dirname "$0")/.."
build=build/release-bench
results="$build/results"
repetitions="${REPETITIONS:-3}"
jobs="${JOBS:-$(nproc)}"

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DRIGMESH_BUILD_TESTS=ON -DRIGMESH_BUILD_BENCHMARKS=ON
programs="${PROGRAMS:-sketch_to_surface rigged_part bone_heat pose merge weight_paint}"
cmake --build "$build" $(printf -- "--target bench_%s " $programs) -j "$jobs"

mkdir -p "$results"
echo "uptime: $(uptime)"
echo "The timings are wall-clock; other processes on this machine slow them down."

for program in $programs; do
    echo
    echo "=== bench_$program ==="
    "$build/tests/benchmarks/bench_$program" \
        --benchmark_repetitions="$repetitions" \
        --benchmark_report_aggregates_only=true \
        --benchmark_out="$results/$program.json" \
        --benchmark_out_format=json \
        "$@"
done

echo
echo "uptime: $(uptime)"
echo "JSON results: $results/sketch_to_surface.json $results/bone_heat.json"
