#!/usr/bin/env bash
# End-to-end check of `whitted grade` (CI, after `make test`). Grades:
#   reference  the reference solution as a submission: full marks, three times
#              with byte-identical results.json: cold (importing the shared
#              parts from the instructor build), again with --build-cache, and
#              with --no-prebuilt (everything compiled for this grading);
#   stubs      the untouched stubs: 0 points, every test not implemented or
#              skipped for a failed prerequisite;
#   broken     the reference with a compile error in lab 3, a segfault in lab 2
#              and an endless loop in lab 5: those labs get their status, the
#              other labs full marks, integration is skipped.
# Every results.json must be valid Gradescope JSON; every report.html must be
# self-contained, with pictures for every image test. Prints how long each
# grading took; exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
tree=$(pwd)
build=${BUILD_DIR:-build}
jobs=${JOBS:-2}
whitted="$tree/$build/whitted"

test -f "$build/CMakeCache.txt" || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j"$jobs" --target whitted > /dev/null

work=$(mktemp -d "${TMPDIR:-/tmp}/test-grader.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
summary=()

# grade NAME SUBMISSION EXPECTED_EXIT [options...]: grades into $work/NAME, records the time.
grade() {
    local name=$1 submission=$2 expected=$3
    shift 3
    local start end status=0
    start=$(date +%s.%N)
    "$whitted" grade "$submission" --out "$work/$name" --jobs "$jobs" -q "$@" > "$work/$name.log" 2>&1 || status=$?
    end=$(date +%s.%N)
    local seconds
    seconds=$(python3 -c "print(f'{$end - $start:.1f}')")
    summary+=("$(printf '%-16s %6s s  exit %d' "$name" "$seconds" "$status")")
    if [ "$status" -ne "$expected" ]; then
        echo "FAIL $name: exit code $status, expected $expected"
        cat "$work/$name.log"
        failures=$((failures + 1))
    fi
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
    wanted = 4 if test["extra_data"]["status"] in ("passed", "failed") else 1
    if pictures < wanted: problems.append(f"{test['name']}: {pictures} pictures in report.html, expected {wanted}")
by_lab = {}
for test in results["tests"]:
    by_lab.setdefault(test["extra_data"]["lab"], []).append(test)
def lab_score(lab): return round(sum(t["score"] for t in by_lab[lab]), 2)
def lab_max(lab): return round(sum(t["max_score"] for t in by_lab[lab]), 2)
def statuses(lab): return {t["extra_data"]["status"] for t in by_lab[lab]}
def ok(condition, text):
    if not condition: problems.append(text)
exec(conditions)
for problem in problems: print("  " + problem)
sys.exit(1 if problems else 0)
EOF
        echo "FAIL $name: see above"
        failures=$((failures + 1))
    else
        echo "ok   $name"
    fi
}

labs="01_ray_casting 02_shadows 03_blinn_phong 04_reflection 05_refraction 06_fresnel"

# (a) The reference solution, as a student tree: cold, then again through a
# build cache, then compiling everything (the fallback when the instructor
# build cannot be imported from).
mkdir -p "$work/reference-tree"
cp -r solution "$work/reference-tree/labs"
grade reference-cold "$work/reference-tree" 0 --build-cache "$work/cache"
grade reference-cached "$work/reference-tree/labs" 0 --build-cache "$work/cache"
grade reference-full "$work/reference-tree" 0 --no-prebuilt
check reference-cold 'ok(results["score"] == 100, "score " + str(results["score"]) + ", expected 100")
ok(all(t["status"] == "passed" for t in results["tests"]), "a test did not pass")'
for again in reference-cached reference-full; do
    if cmp -s "$work/reference-cold/results.json" "$work/$again/results.json"; then
        echo "ok   results.json is byte-identical for the same submission ($again)"
    else
        echo "FAIL results.json differs between two gradings of the same submission ($again)"
        diff "$work/reference-cold/results.json" "$work/$again/results.json" | head -20
        failures=$((failures + 1))
    fi
done

# (b) The untouched stubs.
mkdir -p "$work/stub-tree"
cp -r labs "$work/stub-tree/labs"
grade stubs "$work/stub-tree" 1 --build-cache "$work/cache"
check stubs 'ok(results["score"] == 0, "score " + str(results["score"]) + ", expected 0")
for t in results["tests"]:
    s = t["extra_data"]["status"]
    ok(s == "not_implemented" or (s == "skipped" and "needs every test of" in t["output"]), t["name"] + ": " + s)
ok(any(t["extra_data"]["status"] == "not_implemented" for t in results["tests"]), "no test was not implemented")'

# (c) A compile error in lab 3, a segfault in lab 2, an endless loop in lab 5.
mkdir -p "$work/broken-labs"
cp solution/*.cpp "$work/broken-labs/"
python3 - "$work/broken-labs" <<'EOF'
import re, sys
folder = sys.argv[1]
def insert(lab, function, line):
    path = f"{folder}/{lab}.cpp"
    text = open(path).read()
    text, count = re.subn(r"(\n[^\n]*\b" + function + r"\([^)]*\) \{\n)", r"\1    " + line + "\n", text, count=1)
    assert count == 1, (lab, function)
    open(path, "w").write(text)
insert("02_shadows", "spawn_ray", "volatile int* nowhere = nullptr; *nowhere = 1;")
insert("03_blinn_phong", "blinn_phong", "int oops = undeclared_variable;")
insert("05_refraction", "refracted_direction", "for (volatile unsigned long spin = 0;; spin = spin + 1) {}")
EOF
grade broken "$work/broken-labs" 1 --build-cache "$work/cache" --timeout 2
check broken 'for lab in ("01_ray_casting", "04_reflection", "06_fresnel"):
    ok(lab_score(lab) == lab_max(lab), lab + ": " + str(lab_score(lab)) + " of " + str(lab_max(lab)))
ok(statuses("02_shadows") == {"crash", "skipped"}, "02_shadows: " + str(statuses("02_shadows")))
ok(statuses("03_blinn_phong") == {"compile_error"}, "03_blinn_phong: " + str(statuses("03_blinn_phong")))
ok(statuses("05_refraction") == {"timeout", "skipped"}, "05_refraction: " + str(statuses("05_refraction")))
ok(statuses("integration") == {"skipped"}, "integration: " + str(statuses("integration")))
ok(all(lab_score(lab) == 0 for lab in ("02_shadows", "03_blinn_phong", "05_refraction", "integration")), "points for a broken lab")
ok(any("undeclared_variable" in t["output"] and "labs/03_blinn_phong.cpp:" in t["output"] for t in by_lab["03_blinn_phong"]), "no compiler error shown")
ok(any("SIGSEGV" in t["output"] for t in by_lab["02_shadows"]), "no SIGSEGV shown")'

echo
echo "grading times (2 jobs):"
printf '  %s\n' "${summary[@]}"
if [ "$failures" -ne 0 ]; then
    echo "test-grader: $failures check(s) failed"
    exit 1
fi
echo "test-grader: all checks passed"
