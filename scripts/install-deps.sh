#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages the framework needs, if any are missing.
# As root it runs apt-get; with password-less sudo it uses sudo; otherwise it
# prints the exact command to run and stops with an error.
#
# With --bench it also installs what `make bench` compares against (POV-Ray and
# Embree 3). Those are optional: when they cannot be installed, it says so and
# succeeds, and the benchmark skips the comparisons. With --sandbox it also
# installs bubblewrap, the grader's optional sandbox; --fuzz, clang for the
# fuzzing build; --browser, chromium, which `make test-report` opens the
# grading report in; --proofs, GNU patch (the catalogued mistakes are patches
# of the reference); --ci, python3 (the grader checks read results.json with
# it; python3-yaml reads the handout's GitHub Classroom workflow), patch,
# qemu-user (to run the renderer on an emulated CPU without AVX2), bubblewrap,
# chromium, clang (the sanitizer build: faster than g++'s), and what
# instructor/scripts/test-platforms.sh builds the handout with: clang with libc++ (as on
# macOS), GCC for 64-bit ARM with qemu-user (Apple silicon's instruction set), MinGW-w64
# with Wine (Windows), and GoogleTest's sources; for CI on a bare machine.
set -euo pipefail

packages=(g++ make cmake libglm-dev libgtest-dev libstb-dev libcli11-dev nlohmann-json3-dev libcpp-httplib-dev)
optional=()
case "${1:-}" in
    "") ;;
    --bench) optional=(povray libembree-dev) ;;
    --sandbox) optional=(bubblewrap) ;;
    --fuzz) optional=(clang libclang-rt-14-dev) ;;
    --browser) optional=(chromium) ;;
    --proofs) packages+=(patch) ;;
    --ci) packages+=(python3 python3-yaml patch curl xz-utils qemu-user clang libc++-14-dev libc++abi-14-dev googletest g++-aarch64-linux-gnu g++-mingw-w64-x86-64 wine64)
          optional=(bubblewrap chromium libclang-rt-14-dev) ;;
    *) echo "usage: scripts/install-deps.sh [--bench|--sandbox|--fuzz|--browser|--proofs|--ci]" >&2; exit 2 ;;
esac
# The instructor tree's `make test` also builds a catalogued mistake (a patch of the reference: GNU patch)
# and the constant-answers proof (its lab files are written by a python3 script); its grader filters
# the student code's system calls with libseccomp, found by pkg-config.
if [ -d "$(dirname "$0")/../instructor" ]; then
    for package in patch python3 pkg-config libseccomp-dev; do
        [[ " ${packages[*]} " == *" $package "* ]] || packages+=("$package")
    done
fi

if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "install-deps: this is not a Debian/Ubuntu system; install by hand: ${packages[*]} (C++20 compiler, CMake >= 3.22, GLM, GoogleTest, stb, CLI11, nlohmann-json; the instructor tree: libseccomp)${optional[*]:+; optional: ${optional[*]}}" >&2
    exit 0
fi

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
required_missing=0
for package in "${packages[@]}"; do
    installed "$package" || { missing+=("$package"); required_missing=1; }
done
for package in ${optional[@]+"${optional[@]}"}; do
    installed "$package" || missing+=("$package")
done
[ ${#missing[@]} -eq 0 ] && exit 0

# Only optional packages missing: a failure to install them is a warning.
optional_only() {
    [ $required_missing -eq 0 ] || exit 1
    echo "install-deps: the optional ${missing[*]} could not be installed (make bench skips the comparisons, the grader the sandbox; make test-report needs chromium); to add them: sudo apt-get install -y ${missing[*]}" >&2
    exit 0
}

export DEBIAN_FRONTEND=noninteractive
if [ "$(id -u)" -eq 0 ]; then
    echo "install-deps: installing ${missing[*]}"
    { apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}"; } || optional_only
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    echo "install-deps: installing ${missing[*]} with sudo"
    { sudo -E apt-get update -qq && sudo -E apt-get install -y -qq --no-install-recommends "${missing[@]}"; } || optional_only
else
    [ $required_missing -eq 0 ] && optional_only
    echo "install-deps: missing packages. Run this, then try again:" >&2
    echo "    sudo apt-get install -y ${missing[*]}" >&2
    exit 1
fi
