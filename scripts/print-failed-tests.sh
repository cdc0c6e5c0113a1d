#!/usr/bin/env bash
# Prints the end of each failed test's output from CTest's log of the last
# run in the build folder $1 (Testing/Temporary/LastTestsFailed.log names
# them, LastTest.log holds what they printed).
set -uo pipefail
build="${1:?usage: print-failed-tests.sh BUILD_FOLDER}"
failed="$build/Testing/Temporary/LastTestsFailed.log"
log="$build/Testing/Temporary/LastTest.log"
[ -f "$failed" ] && [ -f "$log" ] || exit 0
# A test's section runs from "Test: NAME" to the "<end of output>" after it.
output_of() {
    awk -v name="$1" '
        index($0, "Test: " name) && substr($0, index($0, "Test: ") + 6) == name { inside = 1; next }
        inside && /^<end of output>$/ { exit }
        inside { print }
    ' "$log"
}
while IFS= read -r entry; do
    name="${entry#*:}"
    echo "---- $name: the end of its output"
    output_of "$name" | tail -n 40
done < "$failed"
# Last, and short, since a report may keep only the end: each failed
# GoogleTest assertion ("file:line: Failure" and the lines after it).
echo "---- the failed assertions"
while IFS= read -r entry; do
    name="${entry#*:}"
    output_of "$name" | awk -v name="$name" '
        / Failure$/ { inside = 1; print name ": " $0; next }
        inside && (/^\[/ || /^$/) { inside = 0 }
        inside { print "    " $0 }
    ' | head -n 12
done < "$failed"
