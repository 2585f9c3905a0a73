#!/usr/bin/env bash
# The same grade whatever the machine's load (CI, after `make test`). Grades the
# reference and the reference with one catalogued lab 8 mistake
# (one_point_too_few: a light sample short) under the Gradescope set-up's
# default limits (--timeout 20 --budget 600), two ways:
#   one-cpu  on one CPU (taskset -c 0): the checker and the worker share it;
#   busy-8   on every CPU, with 8 busy loops beside the grading (4 loops, the
#            step between, was dropped to keep CI inside its time: it never
#            failed where these two passed).
# The reference must get 100/100 each time, and the mistake the same points and
# statuses, test by test, each time. Then the grader is killed (SIGTERM, SIGKILL)
# in the middle of a lab: no checker or worker may be left 2 s later. Prints how
# long each grading took.
set -euo pipefail
cd "$(dirname "$0")/../.."
command -v taskset > /dev/null || { echo "test-grading-stability: needs taskset (util-linux)" >&2; exit 1; }
# shellcheck source=lib/grading-checks.sh
source instructor/scripts/lib/grading-checks.sh test-grading-stability
loops=()
stop_loops() {
    [ "${#loops[@]}" -eq 0 ] || kill "${loops[@]}" 2> /dev/null || true
    loops=()
}
trap 'stop_loops; cleanup' EXIT
# busy N: N loops that use a CPU each until stop_loops.
busy() {
    for ((i = 0; i < $1; i++)); do
        bash -c 'while :; do :; done' &
        loops+=($!)
    done
}
limits=(--timeout 20 --budget 600)

mkdir -p "$work/reference/labs" "$work/mistake"
cp solution/*.cpp "$work/reference/labs/"
cp -r solution "$work/mistake/solution"
patch -s -d "$work/mistake" -p1 < instructor/tests/mistakes/08_soft_shadows/one_point_too_few.patch

for condition in one-cpu busy-8; do
    prefix=()
    case $condition in
    one-cpu) prefix=(taskset -c 0) ;;
    busy-8) busy 8 ;;
    esac
    timed "reference-$condition" 0 "$work/reference-$condition.log" "$work/reference-$condition.log" \
        "${prefix[@]}" "$whitted" grade "$work/reference/labs" --out "$work/reference-$condition" --jobs "$jobs" -q \
        "${fence_options[@]}" "${limits[@]}"
    timed "mistake-$condition" 1 "$work/mistake-$condition.log" "$work/mistake-$condition.log" \
        "${prefix[@]}" "$whitted" grade "$work/mistake/solution" --out "$work/mistake-$condition" --jobs "$jobs" -q \
        "${fence_options[@]}" "${limits[@]}"
    stop_loops
    check "reference-$condition" 'ok(results["score"] == 100, "score " + str(results["score"]) + ", expected 100")
for t in results["tests"]:
    ok(t["status"] == "passed", t["name"] + ": " + t["extra_data"]["status"] + ": " + t["output"][:200])'
    check "mistake-$condition" 'ok(0 < results["score"] < 100, "score " + str(results["score"]))
ok(lab_score("08_soft_shadows") < lab_max("08_soft_shadows"), "lab 8 has full marks")
for lab in by_lab:
    if lab not in ("08_soft_shadows", "integration"): ok(lab_score(lab) == lab_max(lab), lab + ": " + str(lab_score(lab)))'
done

# The mistake's grade, test by test, is the same under every load.
if python3 - "$work" <<'PY'; then
import json, sys
def grade(condition):
    results = json.load(open(f"{sys.argv[1]}/mistake-{condition}/results.json"))
    return [(t["name"], t["extra_data"]["status"], t["score"]) for t in results["tests"]], results["score"]
one, score = grade("one-cpu")
problems = [f"{condition}: {a} instead of {b}" for condition in ("busy-8",)
            for a, b in zip(grade(condition)[0], one) if a != b]
for problem in problems[:20]: print("  " + problem)
print(f"  the mistake scored {score} each time" if not problems else f"  {len(problems)} tests differ")
sys.exit(1 if problems else 0)
PY
    echo "ok   the mistake's grade is the same on one CPU and with 8 busy loops"
else
    echo "FAIL the mistake's grade depends on the load"
    failures=$((failures + 1))
fi

# Nothing outlives a grading, however it ends: the grader killed with SIGTERM (as `timeout` does in the Gradescope
# set-up's run_autograder) and with SIGKILL while a lab's tests run leaves no checker and no worker 2 s later.
for signal in TERM KILL; do
    # The grading's own folders (TMPDIR: its workers) under $work, so that its programs are told from any other's.
    mkdir -m 1777 "$work/tmp-$signal"
    TMPDIR="$work/tmp-$signal" "$whitted" grade "$work/reference/labs" --out "$work/killed-$signal" --jobs "$jobs" -q \
        "${fence_options[@]}" > "$work/killed-$signal.log" 2>&1 &
    grader=$!
    # Until lab 8's image test runs (its checker's report goes to this grading's folder): it takes a second or two.
    running="gtest_filter=Lab8Image\.StageSceneMatchesTheReference .*$work/killed-$signal/"
    for ((i = 0; i < 1200; i++)); do
        pgrep -f "$running" > /dev/null && break
        sleep 0.05
    done
    before=$(pgrep -f "$work/(killed|tmp)-$signal/" | wc -l)
    if [ "$before" -lt 2 ]; then
        echo "FAIL killed-$signal: lab 8's image test was not seen running within 60 s"
        failures=$((failures + 1))
        kill -KILL "$grader" 2> /dev/null || true
        continue
    fi
    kill -"$signal" "$grader"
    wait "$grader" 2> /dev/null || true
    sleep 2
    left=$(pgrep -af "$work/(killed|tmp)-$signal/" || true)
    if [ -z "$left" ]; then
        echo "ok   killed-$signal: $before of its programs ran; none 2 s after SIG$signal of the grader"
    else
        echo "FAIL killed-$signal: left running 2 s after SIG$signal of the grader:"
        printf '  %s\n' "$left"
        pkill -KILL -f "$work/(killed|tmp)-$signal/" || true
        failures=$((failures + 1))
    fi
done

echo "test-grading-stability: seconds per grading (--timeout 20 --budget 600, --jobs $jobs):"
printf '  %s\n' "${summary[@]}"
if [ "$failures" -ne 0 ]; then
    echo "test-grading-stability: $failures failures"
    exit 1
fi
echo "test-grading-stability: all passed"
