#!/usr/bin/env bash
# CI check of the student handout, as a student meets it:
#   1. export it; `make test` fails and names the unfinished stubs;
#   2. `make render` explains that lab 1 is missing;
#   3. with labs 1-3 done, `make render` renders stage 3 and says which labs are missing;
#   4. with every lab done (the reference files copied in), `make test` passes;
#   5. `whitted explore` works in headless Chromium, with its live rebuild (test-explore-browser.sh, on this build).
# The GitHub Classroom workflow's graded steps give 0 points after 1 and every public point after 4
# (instructor/scripts/test-classroom.sh runs the workflow's build step too, and times it).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
handout="$work/handout"
fail() { echo "test-handout: $*" >&2; exit 1; }

bash instructor/scripts/export-handout.sh "$handout" > /dev/null
for private in solution instructor .ci; do
    [ ! -e "$handout/$private" ] || fail "the handout contains $private"
done
grep -q '^set(WHITTED_DEFAULT_MODE handout)$' "$handout/cmake/WhittedMode.cmake" || fail "the handout is not in handout mode"
# The handout shares shared/ with the instructor tree, for the SPD scenes.
[ -d "$root/../shared" ] && ln -s "$root/../shared" "$work/shared"
cd "$handout"
# The Makefile's header speaks of what the handout has: no instructor commands, no documents it lacks.
if sed '/^[^#]/,$d' Makefile | grep -nE "make (handout|proofs|references|test-grader|test-hostile|test-report|fuzz|bench)|docs/"; then
    fail "the handout's Makefile names instructor commands or documents the handout does not have"
fi

echo "test-handout: 1. make test with the untouched stubs"
if make test > "$work/test1.log" 2>&1; then fail "make test passed with stubs"; fi
grep -q "lab 1 (ray casting): 0/" "$work/test1.log" || fail "no progress line for lab 1"
grep -q "primary_ray() is not implemented yet" "$work/test1.log" || fail "the stub message is not shown"
grep -A40 "^Lab progress" "$work/test1.log" | grep -E "tests pass"
# Tests of the whole renderer fail with stubs because labs are not done, not because something is broken: say so.
grep -qE "integration: 0/[0-9]+ tests pass.* wait for a lab that is not done yet" "$work/test1.log" ||
    fail "the integration line does not say its tests wait for unfinished labs"
# The GitHub Classroom workflow: valid, and its graded steps (read from it, run as GitHub runs them) give no point.
python3 "$root/instructor/scripts/lib/classroom_steps.py" check . "$root/instructor/rubric.json"
python3 "$root/instructor/scripts/lib/classroom_steps.py" grade . none > "$work/classroom1.log" 2>&1 ||
    { cat "$work/classroom1.log"; fail "the classroom workflow's graded steps did not all fail on the stubs"; }
tail -1 "$work/classroom1.log"

echo "test-handout: 2. make render with the untouched stubs"
if make render > "$work/render1.log" 2>&1; then fail "make render succeeded with stubs"; fi
grep -q "nothing can be rendered before lab 1 is done" "$work/render1.log" || { cat "$work/render1.log"; fail "make render did not explain"; }

echo "test-handout: 3. labs 1-3 done"
cp "$root"/solution/0[123]_*.cpp labs/
make render > "$work/render2.log" 2>&1 || { cat "$work/render2.log"; fail "make render failed with labs 1-3"; }
grep -q "rendering stage 3" "$work/render2.log" || fail "make render did not say it renders stage 3"
[ -s whitted_1980.png ] || fail "no whitted_1980.png"
grep -E "^note|lab [456]" "$work/render2.log"
# One lab's tests alone: lab 3's pass now, lab 4's (still a stub) do not; a lab that is no number is refused.
make test LAB=3 > "$work/lab3.log" 2>&1 || { tail -30 "$work/lab3.log"; fail "make test LAB=3 failed with labs 1-3 done"; }
grep -q "100% tests passed" "$work/lab3.log" || fail "make test LAB=3 did not run lab 3's tests"
if make test LAB=4 > "$work/lab4.log" 2>&1; then fail "make test LAB=4 passed with lab 4's stub"; fi
grep -q "mirror_direction() is not implemented yet" "$work/lab4.log" || fail "make test LAB=4 did not show the stub's message"
if make test LAB=three > /dev/null 2>&1; then fail "make test LAB=three was accepted"; fi

echo "test-handout: 4. every lab done"
cp "$root"/solution/[0-9][0-9]_*.cpp labs/ # every lab, whatever their number
make test > "$work/test2.log" 2>&1 || { tail -40 "$work/test2.log"; fail "make test failed with every lab done"; }
grep -A12 "^Lab progress" "$work/test2.log"
# Every progress line says ok: a skipped test (one that cannot run here) is no failure.
not_ok=$(grep -E "tests pass" "$work/test2.log" | grep -v "^ok " || true)
[ -z "$not_ok" ] || fail "progress lines without ok once every lab is done: $not_ok"
python3 "$root/instructor/scripts/lib/classroom_steps.py" grade . all > "$work/classroom2.log" 2>&1 ||
    { cat "$work/classroom2.log"; fail "the classroom workflow's graded steps did not all pass once every lab is done"; }
tail -1 "$work/classroom2.log"

echo "test-handout: 5. whitted explore in a browser: a click on the glass, a pass, the goal, a save that breaks a lab, one that mends it"
bash "$root/instructor/scripts/test-explore-browser.sh" "$handout"
echo "test-handout: passed"
