#!/usr/bin/env bash
# The handout's GitHub Classroom workflow, run here step by step as GitHub runs it:
#   1. export the handout and validate .github/workflows/classroom.yml (YAML, steps, points = the rubric's public ones);
#   2. its build step on the stubs, then its graded steps: every one fails, 0 points;
#   3. the reference labs (solution/) copied into labs/, the build step again (only the lab
#      files compile), then the graded steps: every one passes, every public point.
# The commands are read from the workflow file, never copied (instructor/scripts/lib/classroom_steps.py).
# With --fresh-checkout, step 3 builds a new export in the same folder instead (new files, no
# build/, the compiler cache of step 2), as a push does on GitHub: only the lab files miss the cache.
# With --keep, the work folder stays. The timings are printed at the end.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
fresh=0 keep=0
for arg in "$@"; do
    case "$arg" in
        --fresh-checkout) fresh=1 ;;
        --keep) keep=1 ;;
        *) echo "usage: instructor/scripts/test-classroom.sh [--fresh-checkout] [--keep]" >&2; exit 2 ;;
    esac
done
fail() { echo "test-classroom: $*" >&2; exit 1; }
steps() { python3 "$root/instructor/scripts/lib/classroom_steps.py" "$@"; }
work=$(mktemp -d)
if [ $keep -eq 1 ]; then echo "test-classroom: work folder $work"; else trap 'rm -rf "$work"' EXIT; fi
# ${{ runner.temp }}: the compiler cache lives in $work/runner/ccache, outside the checkout.
mkdir -p "$work/runner"
labs=$(ls "$root"/solution/[0-9][0-9]_*.cpp | wc -l)

echo "test-classroom: 1. export the handout, validate its workflow"
bash instructor/scripts/export-handout.sh "$work/handout" > /dev/null
steps check "$work/handout" instructor/rubric.json

echo "test-classroom: 2. the stubs: build step, then every graded step fails"
start=$SECONDS
steps build "$work/handout" "$work/runner"
first_build=$((SECONDS - start))
start=$SECONDS
steps grade "$work/handout" none
grade_stubs=$((SECONDS - start))

echo "test-classroom: 3. the reference labs: build step, then every graded step passes"
checkout="$work/handout"
if [ $fresh -eq 1 ]; then
    # The same folder, as on GitHub (the runner checks out to the same path every run): the
    # tests' compile flags name the source folder, so another path would miss the cache.
    rm -rf "$checkout"
    bash instructor/scripts/export-handout.sh "$checkout" > /dev/null
fi
cp "$root"/solution/[0-9][0-9]_*.cpp "$checkout/labs/"
start=$SECONDS
steps build "$checkout" "$work/runner"
rebuild=$((SECONDS - start))
log="$work/runner/build-step.log"
if [ $fresh -eq 1 ]; then
    # A fresh checkout compiles every file again for make; ccache has all but the labs.
    if command -v ccache > /dev/null; then
        misses=$(sed -nE 's/^[[:space:]]*Misses:[[:space:]]+([0-9]+).*/\1/p' "$log" | head -1)
        [ "${misses:-x}" = "$labs" ] || fail "the fresh checkout missed the compiler cache ${misses:-?} times; only the $labs lab files should (see $log)"
    fi
else
    # Make's own bookkeeping: only the lab files compile again.
    compiled=$(grep -oE "Building CXX object \S+" "$log" | awk '{print $4}')
    others=$(printf '%s\n' "$compiled" | grep -vE "/labs/[0-9][0-9]_[a-z0-9_]+\.cpp\.o$" || true)
    [ -z "$others" ] || fail "replacing labs/ recompiled more than the lab files: $others"
    [ "$(printf '%s\n' "$compiled" | grep -c .)" -eq "$labs" ] || fail "replacing labs/ did not recompile the $labs lab files"
fi
start=$SECONDS
steps grade "$checkout" all
grade_reference=$((SECONDS - start))

echo "test-classroom: timings: first build ${first_build} s; rebuild after replacing labs/ ${rebuild} s$([ $fresh -eq 1 ] && echo ' (a fresh checkout with the compiler cache)'); graded steps ${grade_stubs} s on the stubs, ${grade_reference} s on the reference"
echo "test-classroom: passed"
