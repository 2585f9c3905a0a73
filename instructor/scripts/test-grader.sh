#!/usr/bin/env bash
# End-to-end check of `whitted grade` (CI, after `make test`). Grades:
#   reference  the reference solution as a submission: full marks, twice, with
#              byte-identical results.json (once as a tree, once as its labs/);
#   stubs      the untouched stubs: 0 points, every test not implemented or
#              skipped for a failed prerequisite;
#   broken     the reference with a compile error in lab 3, a segfault in lab 2
#              and an endless loop in lab 7's pixel_color(): those tests get
#              their status, the other tests and labs full marks, integration
#              is skipped;
#   budget     the reference with an endless loop in lab 2, --timeout 4 and
#              --budget 20: lab 1's visible tests pass, the tests not started
#              in time (the hidden ones, which run last, among them) are
#              timeouts that say so, and results.json is still valid;
#   grade-all  a class of three (the reference, the stubs, a compile error in
#              lab 3, named with a comma and quotes): the CSV's header, rows,
#              quoting, statuses and per-lab points;
#   failing    grade-all with a rubric that does not parse and a student whose
#              grading folder is someone else's: exit 3, every student listed
#              as grader_failure or error, with the reason.
# Every results.json must be valid Gradescope JSON; every report.html must be
# self-contained, with pictures for every image test. Prints how long each
# grading took; exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/../.."
# shellcheck source=lib/grading-checks.sh
source instructor/scripts/lib/grading-checks.sh test-grader

# (a) The reference solution, as a student tree, then as its labs/ folder.
mkdir -p "$work/reference-tree"
cp -r solution "$work/reference-tree/labs"
grade reference "$work/reference-tree" 0
grade reference-again "$work/reference-tree/labs" 0
check reference 'ok(results["score"] == 100, "score " + str(results["score"]) + ", expected 100")
ok(all(t["status"] == "passed" for t in results["tests"]), "a test did not pass")'
same_results reference reference-again "results.json is byte-identical for the same submission"

# (b) The untouched stubs.
mkdir -p "$work/stub-tree"
cp -r labs "$work/stub-tree/labs"
grade stubs "$work/stub-tree" 1
check stubs 'ok(results["score"] == 0, "score " + str(results["score"]) + ", expected 0")
for t in results["tests"]:
    s = t["extra_data"]["status"]
    if t["visibility"] == "hidden":
        ok(s in ("failed", "skipped"), t["name"] + ": a hidden test shows " + s)
    else:
        ok(s == "not_implemented" or (s == "skipped" and "needs every test of" in t["output"]), t["name"] + ": " + s)
ok(any(t["extra_data"]["status"] == "not_implemented" for t in results["tests"]), "no test was not implemented")'

# (c) A compile error in lab 3, a segfault in lab 2, an endless loop in lab 7's pixel_color(). The loop costs --timeout
# of CPU for each of the 8 tests that call it, so it sits where few tests reach; the timeout leaves the passing tests a
# wide margin (the slowest, lab 6's image test, uses under 1 s of CPU on each side on an idle 2-core machine, and
# more on a slow or busy one: CI once saw it pass the 2 s this case used to give).
mkdir -p "$work/broken-labs"
cp solution/*.cpp "$work/broken-labs/"
python3 instructor/scripts/lib/inject.py "$work/broken-labs" \
    02_shadows spawn_ray 'volatile int* nowhere = nullptr; *nowhere = 1;' \
    03_blinn_phong blinn_phong 'int oops = undeclared_variable;' \
    07_anti_aliasing pixel_color 'for (volatile unsigned long spin = 0;; spin = spin + 1) {}'
grade broken "$work/broken-labs" 1 --timeout 6
check broken 'for lab in ("01_ray_casting", "04_reflection", "05_refraction", "06_fresnel", "08_soft_shadows", "09_depth_of_field", "10_bvh"):
    ok(lab_score(lab) == lab_max(lab), lab + ": " + str(lab_score(lab)) + " of " + str(lab_max(lab)))
ok(visible_statuses("02_shadows") == {"crash", "skipped"}, "02_shadows: " + str(visible_statuses("02_shadows")))
ok(statuses("03_blinn_phong") == {"compile_error"}, "03_blinn_phong: " + str(statuses("03_blinn_phong")))
# A timeout costs its own test only: every test that calls pixel_color() times out (the image test runs too, and
# times out as well), lab 7'"'"'s stratified_sample() tests pass.
looped = lambda t: "PixelColor" in t["name"] or "Image" in t["name"]
ok({t["extra_data"]["status"] for t in by_lab["07_anti_aliasing"] if t["visibility"] == "visible" and looped(t)} == {"timeout"},
   "07_anti_aliasing: a visible pixel_color() test did not time out")
ok(all(t["extra_data"]["status"] == "passed" for t in by_lab["07_anti_aliasing"] if not looped(t)),
   "07_anti_aliasing: a stratified_sample() test did not pass")
ok(statuses("02_shadows") | statuses("07_anti_aliasing") <= {"crash", "timeout", "failed", "skipped", "passed"}, "hidden tests: " + str(statuses("02_shadows") | statuses("07_anti_aliasing")))
ok(statuses("integration") == {"skipped"}, "integration: " + str(statuses("integration")))
ok(all(lab_score(lab) == 0 for lab in ("02_shadows", "03_blinn_phong", "integration")), "points for a broken lab")
ok(0 < lab_score("07_anti_aliasing") < lab_max("07_anti_aliasing"), "07_anti_aliasing: " + str(lab_score("07_anti_aliasing")))
ok("undeclared_variable" in results["output"] and "labs/03_blinn_phong.cpp:" in results["output"], "no compiler error shown (once, at the top)")
ok(all("said once for 03_blinn_phong" in t["output"] for t in by_lab["03_blinn_phong"] if t["visibility"] == "visible"), "a lab 3 test does not point at the top")
ok(any("SIGSEGV" in t["output"] for t in by_lab["02_shadows"]), "no SIGSEGV shown")
ok(any("crash: your code crashed in spawn_ray() (labs/02_shadows.cpp): killed by SIGSEGV" in t["output"] for t in by_lab["02_shadows"]),
   "no crash names spawn_ray()")'

# (d) A time budget that runs out: a valid results.json, the tests not run are timeouts that say why. Lab 1's visible
# tests are graded within about 8 s even on a machine twice as slow as the project's; each of lab 2's tests then waits
# 4 s, and the hidden tests, which run after every visible test, are not run.
mkdir -p "$work/budget-labs"
cp solution/*.cpp "$work/budget-labs/"
python3 instructor/scripts/lib/inject.py "$work/budget-labs" 02_shadows is_lit 'for (volatile unsigned long spin = 0;; spin = spin + 1) {}'
grade budget "$work/budget-labs" 1 --timeout 4 --budget 20
check budget 'ok(visible_statuses("01_ray_casting") == {"passed"}, "01_ray_casting: " + str(visible_statuses("01_ray_casting")))
ok(0 < results["score"] < 100, "score " + str(results["score"]) + " with a budget of 20 s")
ok(any("time budget of 20 s ran out" in t["output"] for t in results["tests"]), "no test says the budget ran out")'

# (e) A class with grade-all: the reference (ana), the untouched stubs (ben) and the reference with a compile error
# in lab 3 (a name with a comma and quotes), dee with lab files in two places (not graded: hers to fix, the class's
# grading still exits 0), beside a file, a hidden folder and __MACOSX, which are no students.
# One grading at a time: two at once took twice as long on 2 cores (instructor/docs/grading.md).
class="$work/class"
broken_student='cho, "broken"'
mkdir -p "$class/ana" "$class/ben" "$class/$broken_student" "$class/.git" "$class/__MACOSX/ana"
cp -r solution "$class/ana/labs"
cp -r labs "$class/ben/labs"
cp solution/*.cpp "$class/$broken_student/"
python3 instructor/scripts/lib/inject.py "$class/$broken_student" 03_blinn_phong blinn_phong 'int oops = undeclared_variable;'
mkdir -p "$class/dee/labs" "$class/dee/old"
cp solution/*.cpp "$class/dee/labs/"
cp solution/01_ray_casting.cpp "$class/dee/old/"
echo "not a student" > "$class/README.txt"
start=$(date +%s.%N)
status=0
"$whitted" grade-all "$class" --csv "$work/class.csv" --out "$work/class-grades" --parallel 1 --jobs "$jobs" \
    "${fence_options[@]}" > "$work/class.log" 2>&1 || status=$?
summary+=("$(printf '%-16s %6s s  exit %d' "grade-all (4)" "$(python3 -c "print(f'{$(date +%s.%N) - $start:.1f}')")" "$status")")
if [ "$status" -ne 0 ] || ! python3 - "$work/class.csv" "$work/class-grades" solution <<'EOF'; then
import csv, os, sys
path, grades, solution = sys.argv[1:]
problems = []
def ok(condition, text):
    if not condition: problems.append(text)
raw = open(path, "rb").read().decode()
rows = list(csv.reader(raw.splitlines()))
labs = sorted(name[:-4] for name in os.listdir(solution) if name.endswith(".cpp")) + ["integration"]
ok(rows[0] == ["student", "score", "max_score", "status"] + labs, "header " + ",".join(rows[0]))
ok([row[0] for row in rows[1:]] == ["ana", "ben", 'cho, "broken"', "dee"], "students " + str([row[0] for row in rows[1:]]))
ok('\n"cho, ""broken""",' in raw, "the name with a comma and quotes is not quoted as RFC 4180 says")
by_name = {row[0]: row for row in rows[1:]}
dee = by_name.pop("dee")
ok(dee[1:4] == ["0", "0", "not_graded"], "dee (lab files in two places): " + ",".join(dee))
ok("lab files were found in 2 places" in open(os.path.join(grades, "dee", "results.json")).read(), "dee is not told why")
for name, row in by_name.items():
    ok(len(row) == len(rows[0]), name + ": " + str(len(row)) + " fields")
    ok(row[3] == "graded", name + ": status " + row[3])
    ok(float(row[2]) == 100, name + ": max_score " + row[2])
    ok(abs(sum(float(points) for points in row[4:]) - float(row[1])) < 0.005, name + ": the labs do not sum to the score " + row[1])
    ok(os.path.getsize(os.path.join(grades, name, "grade.log")) > 0, name + ": no grade.log")
ok(float(by_name["ana"][1]) == 100, "ana (the reference): " + by_name["ana"][1])
ok(float(by_name["ben"][1]) == 0, "ben (the stubs): " + by_name["ben"][1])
broken = by_name['cho, "broken"']
ok(0 < float(broken[1]) < 100, "cho (a compile error): " + broken[1])
ok(float(broken[4 + labs.index("03_blinn_phong")]) == 0, "cho: points for lab 3, which does not compile")
for problem in problems: print("  " + problem)
sys.exit(1 if problems else 0)
EOF
    echo "FAIL grade-all: exit code $status, expected 0; see above"
    cat "$work/class.log"
    failures=$((failures + 1))
else
    echo "ok   grade-all"
fi

# (f) grade-all when gradings fail: a rubric that does not parse (each grading a grader failure, exit 3), then again
# into the same folder with a third student whose grading folder is someone else's (an error): the CSV lists them all.
mkdir -p "$work/failing-class/a" "$work/failing-class/b"
echo '{"labs": 3' > "$work/bad-rubric.json"
status=0
"$whitted" grade-all "$work/failing-class" --csv "$work/failing.csv" --out "$work/failing-grades" --rubric "$work/bad-rubric.json" \
    -q > "$work/failing.log" 2>&1 || status=$?
mkdir -p "$work/failing-class/zed" "$work/failing-grades/zed"
echo "not the grader's" > "$work/failing-grades/zed/notes.txt"
"$whitted" grade-all "$work/failing-class" --csv "$work/failing.csv" --out "$work/failing-grades" --rubric "$work/bad-rubric.json" \
    -q >> "$work/failing.log" 2>&1 || status=$((status * 10 + $?))
if [ "$status" -ne 33 ] || ! python3 - "$work/failing.csv" "$work/failing.log" <<'EOF'; then
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
log = open(sys.argv[2]).read()
problems = []
statuses = [(row[0], row[3]) for row in rows[1:]]
if statuses != [("a", "grader_failure"), ("b", "grader_failure"), ("zed", "error")]: problems.append("statuses " + str(statuses))
if "a: grader failure: " not in log or "bad-rubric.json:2:" not in log: problems.append("the summary does not give a's reason")
if "zed: error: " not in log or "is not a grading's folder" not in log: problems.append("the summary does not give zed's reason")
for problem in problems: print("  " + problem)
sys.exit(1 if problems else 0)
EOF
    echo "FAIL grade-all with failing gradings: exit codes $status, expected 3 and 3 (33); see above"
    cat "$work/failing.log"
    failures=$((failures + 1))
else
    echo "ok   grade-all with failing gradings"
fi

echo
echo "grading times (2 jobs):"
printf '  %s\n' "${summary[@]}"
if [ "$failures" -ne 0 ]; then
    echo "test-grader: $failures check(s) failed"
    exit 1
fi
echo "test-grader: all checks passed"
