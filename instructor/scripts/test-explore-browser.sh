#!/usr/bin/env bash
# `whitted explore` in headless Chromium, as a student uses it (instructor/scripts/lib/explore_check.py): in a
# copy of the handout with every lab done, the page of scenes/05_refraction.p3f shows the picture; a click on
# the glass shows the tree that `whitted trace --json` gives for that pixel; the normal pass and the difference
# from the goal show (and the difference passes); a lab file that no longer compiles shows its error with its
# line while the last picture stays; mended, the new picture comes.
#
#   test-explore-browser.sh [HANDOUT]
# HANDOUT: an exported handout with every lab done and `whitted` built in HANDOUT/build (test-handout.sh passes
# its own). Without it, the script exports one, copies the reference labs in and builds it.
# Needs chromium: bash scripts/install-deps.sh --browser.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    echo "test-explore-browser: chromium is not installed; run bash scripts/install-deps.sh --browser" >&2
    exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
handout=${1:-}
if [ -z "$handout" ]; then
    handout="$work/handout"
    bash instructor/scripts/export-handout.sh "$handout" > /dev/null
    cp solution/[0-9][0-9]_*.cpp "$handout/labs/"
    cmake -S "$handout" -B "$handout/build" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
    cmake --build "$handout/build" -j"$(nproc)" --target whitted > "$work/build.log"
fi
status=0
python3 "$root/instructor/scripts/lib/explore_check.py" check "$browser" "$handout" "$work" || status=$?
if [ "$status" -ne 0 ]; then
    echo "test-explore-browser: whitted explore's output:" >&2
    cat "$work/explore.log" >&2
    exit "$status"
fi
echo "test-explore-browser: passed"
