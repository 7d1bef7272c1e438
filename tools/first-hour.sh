#!/usr/bin/env bash
# The first hour, checked: the README's two commands, run on a clean clone of this repository, print
# only lines a newcomer should read (docs/running.md, "What the two commands print"):
#
#  1. `./gradlew test`: at most 60 lines, each one of the test summary's forms (a run's counts, a
#     skip reason, its slowest tests). On a failure of the tests themselves, after their summary,
#     the full log of each failing run.
#  2. `./gradlew -q :desktop:run` without a display: exactly one line, starting "skinlab: ", and
#     exit status 4 (unavailable; docs/cli.md, "Exit statuses").
#
# Any other line fails the check, printed with its number. The clone is made from the committed
# HEAD (what a newcomer gets); build outputs and untracked files of this checkout play no part. It
# lies beside this checkout, so that the tests find ../shared as they do here.
#
# Usage: tools/first-hour.sh [CLONE_DIR]    (default: a new folder beside this checkout, removed afterwards)
set -uo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
max_lines=60
if [ $# -gt 0 ]; then
    clone=$1
    keep=1
else
    clone=$(mktemp -d "$(dirname "$repo")/first-hour.XXXXXX") || exit 1
    keep=0
fi
cleanup() { [ "$keep" = 1 ] || rm -rf "$clone"; }
trap cleanup EXIT

rm -rf "$clone"
git clone --quiet "$repo" "$clone" || { echo "first-hour: cannot clone $repo"; exit 1; }
# The tests read ../shared beside the repository, as on a developer's machine.
[ -e "$clone/../shared" ] || [ ! -d "$repo/../shared" ] || {
    echo "first-hour: the clone $clone has no ../shared beside it; give a CLONE_DIR next to $repo"
    exit 1
}
cd "$clone" || exit 1

failed=0
check_lines() { # NAME FILE PATTERN...: every line of FILE matches one of the patterns
    local name=$1 file=$2
    shift 2
    local n=0 line pattern ok
    while IFS= read -r line || [ -n "$line" ]; do
        n=$((n + 1))
        ok=0
        for pattern in "$@"; do
            if [[ $line =~ $pattern ]]; then
                ok=1
                break
            fi
        done
        if [ "$ok" = 0 ]; then
            echo "first-hour: $name printed a line outside the allowed forms (line $n): $line"
            failed=1
        fi
    done < "$file"
}

# The full log of every test run that failed, or that ended without its summary (the modules'
# build/test-output folders, gradle/test-summary's among them).
show_failing_logs() {
    local log
    while IFS= read -r log; do
        if [ ! -e "${log%.log}-counts.properties" ]; then
            echo "=== the full log of a run that ended without its summary: $log"
            cat "$log"
        elif ! grep -qx 'failed=0' "${log%.log}-counts.properties"; then
            echo "=== the full log of the failing run: $log"
            cat "$log"
        fi
    done < <(find . -path '*/build/test-output/*.log' -not -path './integrations/*' -not -path './examples/*' | sort)
}

echo "=== ./gradlew test (on a clean clone: $clone)"
test_out=$(mktemp)
./gradlew test > "$test_out" 2>&1
test_status=$?
cat "$test_out"
if [ "$test_status" != 0 ]; then
    show_failing_logs
    echo "first-hour: ./gradlew test failed (status $test_status)"
    exit 1
fi
lines=$(wc -l < "$test_out")
if [ "$lines" -gt "$max_lines" ]; then
    echo "first-hour: ./gradlew test printed $lines lines, more than $max_lines"
    failed=1
fi
check_lines "./gradlew test" "$test_out" \
    '^[^ ].*: [0-9]+ tests, [0-9]+ passed, [0-9]+ skipped, 0 failed in [0-9][^()]* \(full log: [^ ]+\)$' \
    '^  skipped [0-9]+: .+$' \
    '^  slowest: .+$'

echo "=== ./gradlew -q :desktop:run, without a display"
run_out=$(mktemp)
env -u DISPLAY -u WAYLAND_DISPLAY ./gradlew -q :desktop:run > "$run_out" 2>&1
run_status=$?
cat "$run_out"
echo "(exit status $run_status)"
if [ "$run_status" != 4 ]; then
    echo "first-hour: ./gradlew -q :desktop:run without a display exited with $run_status, not 4"
    failed=1
fi
if [ "$(wc -l < "$run_out")" != 1 ]; then
    echo "first-hour: ./gradlew -q :desktop:run without a display printed $(wc -l < "$run_out") lines, not one"
    failed=1
fi
check_lines "./gradlew -q :desktop:run" "$run_out" '^skinlab: .+ xvfb-run.*$'

rm -f "$test_out" "$run_out"
if [ "$failed" = 0 ]; then
    echo "first-hour: both README commands printed only the allowed lines ($lines lines for the tests)"
fi
exit "$failed"
