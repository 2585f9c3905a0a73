# Shared by instructor/scripts/test-grader.sh and instructor/scripts/test-hostile.sh: grading a
# submission and checking its results.json and report.html. Sourced from the
# tree's root as `source instructor/scripts/lib/grading-checks.sh NAME`: builds whitted,
# makes the work folder $work (removed at exit unless KEEP_WORK is set), counts
# problems in $failures and timings in $summary.
tree=$(pwd)
build=${BUILD_DIR:-build}
jobs=${JOBS:-2}
whitted="$tree/$build/whitted"

test -f "$build/CMakeCache.txt" || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j"$jobs" --target whitted > /dev/null

work=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX")
chmod 755 "$work"
tree_mode=$(stat -c %a "$tree")
cleanup() {
    chmod "$tree_mode" "$tree"
    [ -n "${KEEP_WORK:-}" ] || rm -rf "$work"
}
trap cleanup EXIT

# Where bubblewrap cannot run, the grader refuses to grade unless the student's
# code cannot read the answers: as root, make the tree unreadable to other users
# (restored at exit); as another user, nothing protects them, so say so.
fence_options=()
if ! bwrap --dev-bind / / true 2> /dev/null; then
    if [ "$(id -u)" -eq 0 ]; then
        chmod o-rwx "$tree"
        echo "note: bubblewrap does not work here: the tree is made unreadable to other users while grading"
    else
        fence_options=(--allow-exposed-answers)
        echo "note: bubblewrap does not work here and the grader is not root: grading with --allow-exposed-answers"
    fi
fi
failures=0
summary=()

# timed NAME EXPECTED_EXIT STDOUT STDERR COMMAND...: runs the command, its output in the two files (one file when they
# are the same), records how long it took in $seconds and $summary, and counts a failure when it exits otherwise.
timed() {
    local name=$1 expected=$2 out=$3 err=$4 start status=0
    shift 4
    start=$(date +%s.%N)
    if [ "$out" = "$err" ]; then "$@" > "$out" 2>&1 || status=$?; else "$@" > "$out" 2> "$err" || status=$?; fi
    seconds=$(python3 -c "print(f'{$(date +%s.%N) - $start:.1f}')")
    summary+=("$(printf '%-16s %6s s  exit %d' "$name" "$seconds" "$status")")
    if [ "$status" -ne "$expected" ]; then
        echo "FAIL $name: exit code $status, expected $expected"
        cat "$err"
        failures=$((failures + 1))
    fi
}

# grade NAME SUBMISSION EXPECTED_EXIT [options...]: grades into $work/NAME, records the time.
grade() {
    local name=$1 submission=$2 expected=$3
    shift 3
    timed "$name" "$expected" "$work/$name.log" "$work/$name.log" \
        "$whitted" grade "$submission" --out "$work/$name" --jobs "$jobs" -q "${fence_options[@]}" "$@"
}

# check NAME PYTHON_CONDITIONS: validates results.json and report.html, then the case's own conditions.
check() {
    local name=$1 conditions=$2
    if ! python3 -m json.tool "$work/$name/results.json" > /dev/null; then
        echo "FAIL $name: results.json is not valid JSON"
        failures=$((failures + 1))
        return
    fi
    if ! python3 - "$work/$name" "$conditions" <<'EOF'; then
import json, re, sys
folder, conditions = sys.argv[1], sys.argv[2]
results = json.load(open(folder + "/results.json"))
html = open(folder + "/report.html", encoding="utf-8").read()
problems = []
for key in ("score", "output", "visibility", "stdout_visibility", "tests"):
    if key not in results: problems.append(f"results.json has no {key}")
for test in results["tests"]:
    for key in ("name", "number", "score", "max_score", "status", "output", "output_format", "tags", "visibility"):
        if key not in test: problems.append(f"test {test.get('name')} has no {key}")
    if test["status"] not in ("passed", "failed"): problems.append(f"{test['name']}: status {test['status']}")
    if test["visibility"] != ("hidden" if test["name"].split(": ")[-1].startswith("Hidden") else "visible"):
        problems.append(f"{test['name']}: visibility {test['visibility']}")
if abs(sum(t["max_score"] for t in results["tests"]) - 100) > 1e-9: problems.append("the maximum is not 100 points")
if re.search(r"https?://", html): problems.append("report.html refers to an http(s) URL")
if re.search(r"(src|href)=\"(?!data:|#)", html): problems.append("report.html loads a file")
if "/tmp/" in json.dumps(results) or "/work/" in json.dumps(results): problems.append("results.json holds an absolute path")
# Every image test has a picture in its card: all four when it ran to the comparison, the reference at least.
cards = {}
for match in re.finditer(r'<div class="test" id="test-([0-9.]+)">(.*?)(?=<div class="test"|<h2>|</body>)', html, re.S):
    cards[match.group(1)] = match.group(2)
for test in results["tests"]:
    if not test.get("extra_data", {}).get("image"): continue
    card = cards.get(test["number"], "")
    pictures = card.count("<img")
    if test["visibility"] == "hidden":
        if pictures: problems.append(f"{test['name']}: a hidden test shows {pictures} pictures in report.html")
        continue
    wanted = 4 if test["extra_data"]["status"] in ("passed", "failed") else 1
    if pictures < wanted: problems.append(f"{test['name']}: {pictures} pictures in report.html, expected {wanted}")
by_lab = {}
for test in results["tests"]:
    by_lab.setdefault(test["extra_data"]["lab"], []).append(test)
def lab_score(lab): return round(sum(t["score"] for t in by_lab[lab]), 2)
def lab_max(lab): return round(sum(t["max_score"] for t in by_lab[lab]), 2)
def statuses(lab): return {t["extra_data"]["status"] for t in by_lab[lab]}
# A hidden test shows only passed or failed (or compile_error, missing, skipped): the visible tests tell how the code ended.
def visible_statuses(lab): return {t["extra_data"]["status"] for t in by_lab[lab] if t["visibility"] != "hidden"}
def ok(condition, text):
    if not condition: problems.append(text)
exec(conditions)
for problem in problems: print("  " + problem)
# What CI shows of a failure is all there is to go on: each named lab's tests that did not pass, with how they ended.
for lab, tests in by_lab.items():
    if not any(lab in problem for problem in problems): continue
    for t in tests:
        if t["extra_data"]["status"] == "passed": continue
        lines = [line for line in t["output"].splitlines() if line.strip()][:3]
        print(f"    {t['name']} ({t['visibility']}): {t['extra_data']['status']}" + "".join("\n      " + line[:200] for line in lines))
sys.exit(1 if problems else 0)
EOF
        echo "FAIL $name: see above"
        failures=$((failures + 1))
    else
        echo "ok   $name"
    fi
}


# same_results FIRST SECOND WHAT: results.json of two gradings must be byte-identical.
same_results() {
    if cmp -s "$work/$1/results.json" "$work/$2/results.json"; then
        echo "ok   $3"
    else
        echo "FAIL not so: $3"
        diff "$work/$1/results.json" "$work/$2/results.json" | head -20
        failures=$((failures + 1))
    fi
}
