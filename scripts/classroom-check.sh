#!/usr/bin/env bash
# One step of the GitHub Classroom workflow (.github/workflows/classroom.yml),
# the same on your machine as on GitHub:
#   bash scripts/classroom-check.sh build         configure (Release) and build everything
#   bash scripts/classroom-check.sh 3 unit        lab 3's public tests, except its image test
#   bash scripts/classroom-check.sh 3 image       lab 3's image test; it counts only once lab 3's unit tests pass
#   bash scripts/classroom-check.sh integration   the whole renderer's tests; they count only once every lab's unit tests pass
# It exits 0 when the step passes (the workflow then gives the step's points),
# 1 when it fails, 2 when it is asked wrongly, and builds only what the step
# needs, in build/ (BUILD_DIR), the folder make uses.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
usage="usage: bash scripts/classroom-check.sh build | LAB unit | LAB image | integration   (LAB: a lab number, as in ./$build/whitted labs)"

grep -q '^set(WHITTED_DEFAULT_MODE handout)$' cmake/WhittedMode.cmake ||
    { echo "classroom-check: this is not a student handout (cmake/WhittedMode.cmake); export one with make handout OUT=folder" >&2; exit 2; }

configure() {
    [ -f "$build/CMakeCache.txt" ] && return
    # CMAKE_CXX_COMPILER_LAUNCHER=ccache in the environment (the workflow's build step) makes CMake compile through ccache.
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null ||
        { echo "classroom-check: cmake could not configure $build (its messages are above)" >&2; exit 1; }
}

# build [TARGET]: quiet when nothing fails; the compiler's messages when something does.
build() {
    configure
    local log
    log=$(mktemp)
    if ! cmake --build "$build" -j"$jobs" ${1:+--target "$1"} > "$log" 2>&1; then
        grep -E "error|Error" "$log" | sed -n '1,40p' # sed reads to the end: head would stop grep with SIGPIPE (exit 141)
        rm -f "$log"
        echo "classroom-check: the build${1:+ of $1} failed (the first errors are above; make shows them all)" >&2
        exit 1
    fi
    rm -f "$log"
}

# unit_tests LAB_REGEX: a lab's public tests but its image test (tests named labN.LabNImage.*).
unit_tests() { ctest --test-dir "$build" -L "^lab$1\$" -E "^lab[0-9]+\.Lab[0-9]+Image\." --no-tests=error -j"$jobs" "${@:2}"; }

case "${1:-}" in
    build)
        [ $# -eq 1 ] || { echo "$usage" >&2; exit 2; }
        configure
        # Through ccache (the workflow's build step): its statistics say how much came from the cache.
        launcher=$(sed -n 's/^CMAKE_CXX_COMPILER_LAUNCHER:[A-Z]*=//p' "$build/CMakeCache.txt")
        if [ "$launcher" = ccache ]; then ccache --zero-stats > /dev/null; fi
        cmake --build "$build" -j"$jobs"
        if [ "$launcher" = ccache ]; then ccache --show-stats; fi
        ;;
    integration)
        [ $# -eq 1 ] || { echo "$usage" >&2; exit 2; }
        build
        if ! units=$(unit_tests "[0-9]+" 2>&1); then
            echo "classroom-check: the integration tests count only once every lab's unit tests pass; these fail:" >&2
            printf '%s\n' "$units" | sed -n 's/^[[:space:]]*[0-9]* - \(lab[0-9]*\.[^ ]*\).*/  \1/p' | sed -n '1,20p' >&2
            exit 1
        fi
        ctest --test-dir "$build" -L '^integration$' --no-tests=error --output-on-failure -j"$jobs" || exit 1
        ;;
    *)
        [ $# -eq 2 ] && [[ "$1" =~ ^[0-9]+$ ]] && [[ "$2" =~ ^(unit|image)$ ]] || { echo "$usage" >&2; exit 2; }
        lab=$((10#$1))
        grep -qE "^ *LabInfo\{$lab, " framework/include/whitted/lab_table.hpp ||
            { echo "classroom-check: there is no lab $lab (framework/include/whitted/lab_table.hpp lists the labs)" >&2; exit 2; }
        build "lab$lab"
        case "$2" in
            unit) unit_tests "$lab" --output-on-failure || exit 1 ;;
            image)
                if ! unit_tests "$lab" > /dev/null 2>&1; then
                    echo "classroom-check: lab $lab's image test counts only once its unit tests pass (bash scripts/classroom-check.sh $lab unit shows which fail)" >&2
                    exit 1
                fi
                ctest --test-dir "$build" -R "^lab$lab\.Lab${lab}Image\." --no-tests=error --output-on-failure -j"$jobs" || exit 1
                ;;
        esac
        ;;
esac
