#!/usr/bin/env bash
# CI: the student's side builds and passes its tests with the compilers and standard
# libraries of the students' own machines, not only Debian's g++ (issue 39). For each
# target the exported handout is built (Release) and
#   a. with the untouched stubs, every lab's tests fail, each failure a stub's
#      "not implemented yet" (the progress report of `make test` says which);
#   b. with the reference labs copied in, every public test passes;
#   c. the classic scene renders the very PNG (and PFM) that the Linux (g++) build in
#      build/ renders, and so does the scene of the course's every feature (labs 7-10).
# Usage: bash instructor/scripts/test-platforms.sh [TARGET ...]   (default: every target)
# Targets:
#   libcxx   Debian's clang 14 with libc++: the compiler and standard library of macOS
#   aarch64  GCC for 64-bit ARM (Apple silicon's instruction set, no SSE), run under qemu-user
#   mingw    MinGW-w64's GCC for 64-bit Windows, run under Wine
# A target is a CMake toolchain file, instructor/scripts/platforms/TARGET.cmake (a cross
# target's also sets CMAKE_CROSSCOMPILING_EMULATOR, through which CTest and this script
# run its programs), and its lines in check_tools below. GoogleTest is built for each
# target from Debian's sources (/usr/src/googletest), once: PLATFORMS_BUILD_DIR/TARGET
# (build-platforms/ by default). The header-only libraries (GLM, CLI11, nlohmann-json,
# stb) are Debian's, seen by a cross target through a folder of their own (headers_prefix), with
# upstream's header-only cpp-httplib (httplib_header).
# JOBS compile jobs (2 by default).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
jobs=${JOBS:-2}
cache=${PLATFORMS_BUILD_DIR:-$root/build-platforms}
all_targets=(libcxx aarch64 mingw)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
fail() { echo "test-platforms: $*" >&2; exit 1; }
for target in "${targets[@]}"; do
    [ -f "instructor/scripts/platforms/$target.cmake" ] || fail "no target '$target' (the targets: ${all_targets[*]})"
done

work=$(mktemp -d)
# KEEP=1 keeps the builds and logs (their folder is printed) to look into a failure.
cleanup() { if [ -n "${KEEP:-}" ]; then echo "test-platforms: kept $work"; else rm -rf "$work"; fi; }
trap cleanup EXIT
times=()
# phase NAME COMMAND...: runs the command and records how long it took.
phase() {
    local name=$1 start=$SECONDS
    shift
    "$@"
    times+=("$(printf '%5d s  %s' $((SECONDS - start)) "$name")")
    echo "test-platforms: ${times[-1]}"
}
# quiet LOG COMMAND...: runs the command with its output in LOG, shown (its end) only if it fails.
quiet() {
    local log=$1
    shift
    "$@" > "$log" 2>&1 || { tail -40 "$log"; fail "failed: $*"; }
}

# What each target needs on this machine, with the command that installs it.
check_tools() {
    case $1 in
    libcxx)
        echo '#include <vector>' | clang++ -std=c++20 -stdlib=libc++ -x c++ -fsyntax-only - 2> /dev/null ||
            fail "libcxx needs clang++ and libc++: apt-get install clang libc++-14-dev libc++abi-14-dev"
        ;;
    aarch64)
        command -v aarch64-linux-gnu-g++ > /dev/null && command -v qemu-aarch64 > /dev/null ||
            fail "aarch64 needs the cross compiler and qemu-user: apt-get install g++-aarch64-linux-gnu qemu-user"
        ;;
    mingw)
        command -v x86_64-w64-mingw32-g++-posix > /dev/null && [ -x /usr/lib/wine/wine64 ] ||
            fail "mingw needs MinGW-w64 and Wine: apt-get install g++-mingw-w64-x86-64 wine64"
        ;;
    esac
    [ -f /usr/src/googletest/CMakeLists.txt ] || fail "$1 needs GoogleTest's sources: apt-get install googletest"
}

# The header-only libraries, as a prefix of their own: a cross compiler must not see this machine's
# /usr/include (its C library's headers are x86-64 Linux's), only these folders and their CMake files.
headers_prefix() {
    local prefix=$cache/headers package
    rm -rf "$prefix"
    mkdir -p "$prefix/include" "$prefix/share/cmake"
    for package in glm CLI nlohmann stb; do ln -s "/usr/include/$package" "$prefix/include/$package"; done
    # The packages' CMake files find their headers relative to themselves: copies, not links.
    for package in glm CLI11 nlohmann_json; do cp -r "/usr/share/cmake/$package" "$prefix/share/cmake/"; done
    httplib_header "$prefix/include"
}

# cpp-httplib for `whitted explore`'s server: Debian's package is a library compiled for this machine, which no
# target can link, so the targets compile upstream's header-only httplib.h, from the source Debian packages (the
# same version, 0.11.4), fetched once into $cache and checked against its SHA-256. Without it (no network), the
# targets build without cpp-httplib, and this says so: `whitted explore` then only says what to install.
httplib_options=(-DCMAKE_DISABLE_FIND_PACKAGE_httplib=ON)
httplib_header() {
    local include=$1 archive=$cache/downloads/cpp-httplib_0.11.4+ds.orig.tar.xz
    local url=http://deb.debian.org/debian/pool/main/c/cpp-httplib/cpp-httplib_0.11.4+ds.orig.tar.xz
    local sha256=8b1a5df569003b6a4f24c68489bbda5c64aec94697bdc9ebba5d79408b2ae7eb
    mkdir -p "$cache/downloads"
    if ! echo "$sha256  $archive" | sha256sum -c --quiet > /dev/null 2>&1; then
        rm -f "$archive"
        if ! curl -fsS --max-time 60 -o "$archive.part" "$url" || ! echo "$sha256  $archive.part" | sha256sum -c --quiet; then
            rm -f "$archive.part"
            echo "test-platforms: NOTE cannot fetch $url: the targets build without cpp-httplib (whitted explore's server unproven)"
            return 0
        fi
        mv "$archive.part" "$archive"
    fi
    tar -xJf "$archive" -O --wildcards '*/httplib.h' > "$include/httplib.h"
    httplib_options=(-DWHITTED_HTTPLIB_HEADER_ONLY=ON "-Dhttplib_INCLUDE_DIR=$include")
}

# Wine's own Windows folder, made once (its first start takes seconds), and a Wine server kept
# running for the whole run (each of the hundreds of test programs would otherwise start one).
start_wine() {
    export WINEPREFIX=$cache/wine WINEDEBUG=-all
    mkdir -p "$WINEPREFIX" # the server needs the folder; the first program fills it
    /usr/lib/wine/wineserver -k 2> /dev/null || true # a server left by an earlier run
    /usr/lib/wine/wineserver -p
    /usr/lib/wine/wine64 cmd /c exit > /dev/null 2>&1 || true
    trap 'cleanup; /usr/lib/wine/wineserver -k 2> /dev/null || true' EXIT
}

# The renders compared: the classic scene as the README renders it, as a PNG and as a PFM (its float
# pixels, before they are rounded to bytes), and the scene of the course's every feature (labs 7-10).
# render_all FOLDER COMMAND...: those renders into FOLDER, by `COMMAND render` run where scenes/ is.
renders=(whitted_1980.png whitted_1980.pfm course_features.pfm)
render_all() {
    local out=$1
    shift
    mkdir -p "$out"
    "$@" render scenes/whitted_1980.p3f --width 512 --height 512 -q -o "$out/whitted_1980.png"
    "$@" render scenes/whitted_1980.p3f --width 512 --height 512 -q -o "$out/whitted_1980.pfm"
    "$@" render scenes/course_features.p3f -q -o "$out/course_features.pfm"
}

# The Linux renders to compare with: build/whitted (g++, the instructor's tree), built if missing.
linux_renders() {
    if [ ! -f build/CMakeCache.txt ]; then
        quiet "$work/linux-configure.log" cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
    fi
    quiet "$work/linux-build.log" cmake --build build -j"$jobs" --target whitted
    render_all "$work/linux" build/whitted
}

# GoogleTest built with the target's toolchain into PREFIX, unless the one there was built with this toolchain file
# and these options.
# At -O1: its one large file compiles in half the time of -O3 (12 s against 21 s), and the tests' time is their own.
googletest() {
    local target=$1 prefix=$2 toolchain=$root/instructor/scripts/platforms/$1.cmake stamp
    local options=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" -DBUILD_GMOCK=OFF)
    stamp=$( (cat "$toolchain" /usr/src/googletest/CMakeLists.txt; echo "${options[*]}") | sha256sum)
    [ "$(cat "$prefix/toolchain.sha256" 2> /dev/null)" != "$stamp" ] || return 0
    rm -rf "$prefix" "$prefix-build"
    quiet "$work/$target-googletest-configure.log" cmake -S /usr/src/googletest -B "$prefix-build" \
        --toolchain "$toolchain" "${options[@]}" -DCMAKE_INSTALL_PREFIX="$prefix"
    quiet "$work/$target-googletest-build.log" cmake --build "$prefix-build" -j"$jobs"
    quiet "$work/$target-googletest-install.log" cmake --install "$prefix-build"
    rm -rf "$prefix-build"
    echo "$stamp" > "$prefix/toolchain.sha256"
}

# The handout built for the target; a warning counts as a failure (each is a portability problem).
build_handout() {
    local target=$1 build=$2 log=$3
    quiet "$log" cmake --build "$build" -j"$jobs"
    if grep -q "warning:" "$log"; then
        grep -B12 -A3 "warning:" "$log" | head -60
        fail "$target: the build printed $(grep -c "warning:" "$log") warnings"
    fi
}

# The progress report of `make test` (cmake -P scripts/lab.cmake: every test, then each lab's progress) on the target's build, in LOG; its exit status in LOG.status.
progress() {
    local handout=$1 build=$2 log=$3 status=0
    (cd "$handout" && cmake -DBUILD_DIR="$build" -DJOBS="$jobs" -P scripts/lab.cmake) > "$log" 2>&1 || status=$?
    echo "$status" > "$log.status"
}

# failed_tests BUILD: the names of the tests that failed (or did not run) in the progress report's CTest run in BUILD.
failed_tests() {
    grep -E "\*\*\*(Failed|Exception|Timeout)|Not Run" "$1/Testing/progress.log" | sed -nE 's/.*Test +#[0-9]+: ([^ ]+) .*/\1/p'
}

# test_outputs BUILD NAMES: what each of the tests NAMES printed in the last CTest run in BUILD (its first 40 lines).
test_outputs() {
    local name
    for name in $2; do
        echo "test-platforms: the output of $name:"
        awk -v name="$name" '$2 == "Test:" && $3 == name { on = 1 } on { print; if (++n == 40 || /^<end of output>/) exit }' \
            "$1/Testing/Temporary/LastTest.log"
    done
}

# With the stubs: every lab's tests fail, and every failing test failed on a stub's "not implemented yet".
check_stubs() {
    local target=$1 handout=$2 build=$3 log=$work/$1-stubs.log labs failed waiting others
    progress "$handout" "$build" "$log"
    [ "$(cat "$log.status")" -ne 0 ] || fail "$target: make test's report passed with the stubs"
    grep -E "tests pass" "$log"
    labs=$(grep -c . "$work/$target-labs.tsv")
    [ "$(grep -cE "^   lab [0-9]+ \(.*\): 0/[0-9]+ tests pass" "$log")" -eq "$labs" ] ||
        fail "$target: not every one of the $labs labs has a progress line with 0 tests passed"
    # Every failed test's output names a stub (read from the CTest log as the progress report reads it).
    failed=$(failed_tests "$build" | sort)
    waiting=$(awk '/^[0-9]+\/[0-9]+ Test: / { name = $3 } /is not implemented yet/ && name != "" { print name; name = "" }' \
        "$build/Testing/Temporary/LastTest.log" | sort -u)
    others=$(comm -23 <(printf '%s\n' "$failed") <(printf '%s\n' "$waiting"))
    if [ -n "$others" ]; then
        test_outputs "$build" "$others"
        fail "$target: with the stubs, these tests failed without a stub's message: $others"
    fi
    echo "$target stubs: $(grep -c . <<< "$failed") tests fail, each on a stub;" \
        "$(grep -c ' Passed ' "$build/Testing/progress.log") pass (they need no lab)"
}

# With the reference labs: every public test passes.
check_reference() {
    local target=$1 handout=$2 build=$3 log=$work/$1-reference.log not_ok
    cp "$root"/solution/[0-9][0-9]_*.cpp "$handout/labs/"
    build_handout "$target" "$build" "$work/$target-build-reference.log"
    progress "$handout" "$build" "$log"
    grep -E "tests pass" "$log"
    if [ "$(cat "$log.status")" -ne 0 ]; then
        test_outputs "$build" "$(failed_tests "$build")"
        fail "$target: make test's report failed with the reference labs"
    fi
    not_ok=$(grep -E "tests pass" "$log" | grep -v "^ok " || true)
    [ -z "$not_ok" ] || fail "$target: progress lines without ok with the reference labs: $not_ok"
    echo "$target reference labs: $(grep -E "tests passed, [0-9]+ tests failed out of" "$build/Testing/progress.log")," \
        "$(grep -c '\*\*\*Skipped' "$build/Testing/progress.log") skipped"
}

# The target's renders, compared byte for byte with the Linux renders.
check_renders() {
    local target=$1 handout=$2 file
    # Into a folder whose name has a space, as a student's folders often do.
    local out="$work/$target/renders of $target"
    (cd "$handout" && render_all "$out" "${run[@]}" "$bin") || fail "$target: whitted render failed"
    for file in "${renders[@]}"; do
        if cmp -s "$work/linux/$file" "$out/$file"; then
            echo "$target render: $file identical to the Linux render"
        else
            echo "$target render: $file differs from the Linux render:"
            build/whitted diff "$work/linux/$file" "$out/$file" || true
            fail "$target: $file differs from the Linux render"
        fi
    done
}

phase "Linux renders (build/whitted)" linux_renders
headers_prefix
for target in "${targets[@]}"; do
    echo "test-platforms: $target"
    check_tools "$target"
    [ "$target" != mingw ] || start_wine
    prefix=$cache/$target/googletest
    phase "$target: GoogleTest (built once into $prefix)" googletest "$target" "$prefix"
    # The handout where a student keeps it: in a folder whose name has a space and, but under Wine, a letter
    # beyond ASCII (Wine decodes a program's arguments in this machine's locale, C in CI, which has no such letter).
    home="$work/$target/Zoë Student"
    [ "$target" != mingw ] || home="$work/$target/Zoe Student"
    handout=$home/labs
    build=$handout/build
    quiet "$work/$target-export.log" bash instructor/scripts/export-handout.sh "$handout"
    # The SPD scenes, beside the handout as beside this tree (their tests skip without them).
    [ ! -d "$root/../shared" ] || ln -s "$root/../shared" "$home/shared"
    quiet "$work/$target-configure.log" cmake -S "$handout" -B "$build" \
        --toolchain "$root/instructor/scripts/platforms/$target.cmake" \
        -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix;$cache/headers" -DCMAKE_FIND_ROOT_PATH="$prefix;$cache/headers" \
        "${httplib_options[@]}"
    # How to run the target's programs: directly, or through its emulator (qemu-user, wine).
    emulator=$(sed -n 's/^CMAKE_CROSSCOMPILING_EMULATOR:[A-Z]*=//p' "$build/CMakeCache.txt" | tr ';' ' ')
    read -r -a run <<< "$emulator"
    phase "$target: build the handout with the stubs" build_handout "$target" "$build" "$work/$target-build.log"
    bin=$build/whitted
    [ -f "$bin" ] || bin=$bin.exe # Windows
    "${run[@]}" "$bin" labs --tsv > "$work/$target-labs.tsv"
    phase "$target: a. the stubs' tests" check_stubs "$target" "$handout" "$build"
    phase "$target: b. the reference labs: build and tests" check_reference "$target" "$handout" "$build"
    phase "$target: c. renders" check_renders "$target" "$handout"
done
printf '%s\n' "test-platforms: phase times" "${times[@]}"
echo "test-platforms: passed (${targets[*]})"
