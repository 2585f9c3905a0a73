#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer (the
# CMake preset "asan", in build-asan/) and runs every test there. Any report
# aborts the program that made it, so the test fails: zero reports is the bar.
#   test-sanitizers.sh           build, then test
#   test-sanitizers.sh --build   build only (CI builds beside its other steps)
#   test-sanitizers.sh --test    test what --build built
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-all}
case $what in all | --build | --test) ;; *) echo "usage: scripts/test-sanitizers.sh [--build|--test]" >&2; exit 2 ;; esac
jobs=${JOBS:-$(nproc 2> /dev/null || echo 2)}
start=$(date +%s)
if [ "$what" != --test ]; then
    # clang where it can build a sanitized program (clang and its runtime, libclang-rt-14-dev on Debian 12): on the
    # project's 2-core machine it built and ran this in 911 s against g++'s 1099 s (its tests 180 s against 339 s).
    # CXX chooses the compiler of a new build-asan/ only.
    if [ -z "${CXX:-}" ] && command -v clang++ > /dev/null &&
        echo 'int main() { return 0; }' | clang++ -fsanitize=address,undefined -x c++ - -o /tmp/whitted-asan-probe.$$ 2> /dev/null; then
        export CXX=clang++ CC=clang
    fi
    rm -f /tmp/whitted-asan-probe.$$
    cmake --preset asan > /dev/null
    cmake --build --preset asan -j"$jobs" > build-asan/build.log 2>&1 || { grep -m20 -E "error|Error" build-asan/build.log; exit 1; }
    echo "test-sanitizers: built in $(($(date +%s) - start)) s"
fi
if [ "$what" != --build ]; then
    [ -f build-asan/CTestTestfile.cmake ] || { echo "test-sanitizers: nothing built in build-asan/: run it with --build first" >&2; exit 1; }
    tested=$(date +%s)
    ctest --preset asan -j"$jobs"
    echo "test-sanitizers: tested in $(($(date +%s) - tested)) s, no sanitizer reports"
fi
