#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer (the
# CMake preset "asan", in build-asan/) and runs every test there. Any report
# aborts the program that made it, so the test fails: zero reports is the bar.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc 2> /dev/null || echo 2)}
start=$(date +%s)
cmake --preset asan > /dev/null
cmake --build --preset asan -j"$jobs" > build-asan/build.log 2>&1 || { grep -m20 -E "error|Error" build-asan/build.log; exit 1; }
built=$(date +%s)
ctest --preset asan -j"$jobs"
echo "test-sanitizers: built in $((built - start)) s, tested in $(($(date +%s) - built)) s, no sanitizer reports"
