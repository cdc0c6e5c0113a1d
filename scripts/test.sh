#!/usr/bin/env bash
# README command 2: set up, build, and run the whole test suite through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh dev
status=0
ctest --preset dev "$@" || status=$?
if [ "$status" -ne 0 ]; then
    # The failures' own output again, last: with two tests at a time it is
    # spread through the log, and a report that keeps only its end (as CI's
    # does) would otherwise say which tests failed but not why.
    scripts/print-failed-tests.sh build/dev || true
fi
exit "$status"
