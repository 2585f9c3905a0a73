"""Checks a results.json against Gradescope's documented format, then a case's own conditions.

    python3 gradescope_results.py RESULTS.json 'PYTHON CONDITIONS'

The format (gradescope-autograders.readthedocs.io, "Autograder Specifications"):
a top-level `score` (or a score on every test), optional `output`,
`visibility` and `stdout_visibility` (visible, hidden, after_due_date,
after_published), and `tests[]`, each with `score`, `max_score`, `name`,
`output`, `visibility` and `status` (passed or failed). The conditions see
`results`, `tests`, `output` and `ok(condition, message)`.
"""
import json
import sys

path, conditions = sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else ""
problems = []


def ok(condition, message):
    if not condition:
        problems.append(message)


visibilities = {"visible", "hidden", "after_due_date", "after_published"}
try:
    results = json.load(open(path, encoding="utf-8"))
except (OSError, ValueError) as error:
    sys.exit(f"{path}: not valid JSON: {error}")
ok(isinstance(results, dict), "the top level is not an object")
ok(isinstance(results.get("score"), (int, float)), "no numeric top-level score")
ok(isinstance(results.get("output", ""), str), "output is not text")
for key in ("visibility", "stdout_visibility"):
    ok(results.get(key, "visible") in visibilities, f"{key} is {results.get(key)!r}")
ok(results.get("stdout_visibility") == "hidden", "the grader's terminal output would be shown to the student")
tests = results.get("tests", [])
ok(isinstance(tests, list), "tests is not a list")
for test in tests:
    name = test.get("name")
    ok(isinstance(name, str) and name, f"a test without a name: {test}")
    ok(isinstance(test.get("score"), (int, float)), f"{name}: no numeric score")
    ok(isinstance(test.get("max_score"), (int, float)), f"{name}: no numeric max_score")
    ok(0 <= test.get("score", -1) <= test.get("max_score", -1), f"{name}: score outside 0..max_score")
    ok(isinstance(test.get("output"), str), f"{name}: no output")
    ok(test.get("visibility") in visibilities, f"{name}: visibility {test.get('visibility')!r}")
    ok(test.get("status") in ("passed", "failed"), f"{name}: status {test.get('status')!r}")
if tests:
    total = sum(test["score"] for test in tests)
    ok(abs(total - results["score"]) < 0.011 * len(tests), f"the tests' scores add up to {total}, not {results['score']}")
output = results.get("output", "")
# What is for the instructor only: the fences that ran, and paths inside the autograder.
text = json.dumps(results)
for secret in ("student code ran in", "sandbox mode", "users mode", "exposed mode", "/autograder/source", "whitted-grade-"):
    ok(secret not in text, f"instructor-only text in results.json: {secret!r}")
exec(conditions)
for problem in problems:
    print(f"  {path}: {problem}")
sys.exit(1 if problems else 0)
