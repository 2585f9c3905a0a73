#!/usr/bin/env python3
"""Writes the handout's GitHub Classroom workflow (.github/workflows/classroom.yml).

usage: classroom-workflow.py TREE OUT
TREE is the instructor's tree: the template instructor/docs/handout/classroom.yml.in
gets one graded step per public rule of instructor/rubric.json, for every lab of
the lab table (framework/include/whitted/lab_table.hpp) and the integration tier,
each calling scripts/classroom-check.sh, then the reporter. The packages are
those of scripts/install-deps.sh. Adding a lab is a row of the lab table and
its section of the rubric: nothing here changes.
"""
import json
import re
import sys
from pathlib import Path


def fail(message):
    print(f"classroom-workflow: {message}", file=sys.stderr)
    sys.exit(1)


def lab_rows(table):
    # The same form CMake reads (cmake/WhittedLabs.cmake): one row a line.
    rows = re.findall(r'^ *LabInfo\{(\d+), "(\d\d_[a-z0-9_]+)", "([^"]+)",', table.read_text(), re.M)
    if not rows:
        fail(f"{table}: no rows of kLabs found")
    return [(int(n), stem, title) for n, stem, title in rows]


def packages(install_deps):
    match = re.search(r"^packages=\(([^)]*)\)$", install_deps.read_text(), re.M)
    if not match:
        fail(f"{install_deps}: no line packages=(...) to take the packages from")
    return match.group(1).split()


def public_steps(labs, rubric_path):
    """(id, test name, command, points) for each public rule, in the rubric's order."""
    rubric = json.loads(rubric_path.read_text())
    sections = rubric.get("labs", [])
    names = [section.get("lab") for section in sections]
    expected = [stem for _, stem, _ in labs] + ["integration"]
    if names != expected:
        fail(f"{rubric_path}: its labs are {', '.join(map(str, names))}; the lab table asks for {', '.join(expected)}")
    steps = []
    for (number, stem, title), section in zip(labs + [(None, "integration", None)], sections):
        for rule in section["rules"]:
            tests, exclude, points = rule["tests"], sorted(rule.get("exclude", [])), rule["points"]
            where = f"{rubric_path}: {stem}, rule {rule['id']}"
            if all(test.startswith("Hidden") for test in tests):
                continue  # hidden tests: not in the handout, graded by the instructor only
            if points <= 0:
                continue
            # The rules scripts/classroom-check.sh knows how to run; any other is refused, not guessed.
            if number is None:
                if tests != ["*"] or exclude or rule.get("requires") != ["*:unit"]:
                    fail(f"{where}: the workflow knows the integration rule as tests [\"*\"] requiring [\"*:unit\"]; "
                         "teach scripts/classroom-check.sh and this script the new one")
                steps.append(("integration", f"{section['title']}", "integration", points))
            elif tests == [f"Lab{number}Image"] and rule.get("requires") == ["unit"]:
                steps.append((f"lab{number}image", f"Lab {number} ({title}): image test", f"{number} image", points))
            elif tests == ["*"] and exclude == sorted(["Hidden*", f"Lab{number}Image"]) and not rule.get("requires"):
                steps.append((f"lab{number}unit", f"Lab {number} ({title}): unit tests", f"{number} unit", points))
            else:
                fail(f"{where}: the workflow knows a lab's public rules as unit (tests [\"*\"] excluding Hidden* and "
                     f"Lab{number}Image) and image (tests [\"Lab{number}Image\"] requiring [\"unit\"]); "
                     "teach scripts/classroom-check.sh and this script the new one")
    total = sum(rule["points"] for section in sections for rule in section["rules"])
    return steps, total


def graded_yaml(steps):
    q = json.dumps  # a JSON string is a YAML double-quoted string
    lines = []
    for step_id, name, args, points in steps:
        lines += [
            f"      - name: {q(f'{name}, {points} points')}",
            f"        id: {step_id}",
            "        if: ${{ !cancelled() }}",
            "        uses: classroom-resources/autograding-command-grader@v1",
            "        with:",
            f"          test-name: {q(name)}",
            f"          command: {q(f'bash scripts/classroom-check.sh {args}')}",
            "          timeout: 10",  # minutes: a build the build step left unfinished, then tests of a few seconds
            f"          max-score: {points}",
        ]
    lines += [
        "      - name: Autograding Reporter",
        "        if: ${{ !cancelled() }}",
        "        uses: classroom-resources/autograding-grading-reporter@v1",
        "        env:",
    ]
    # The reporter reads each step's result from <STEP ID IN CAPITALS>_RESULTS.
    lines += [f"          {step_id.upper()}_RESULTS: \"${{{{ steps.{step_id}.outputs.result }}}}\"" for step_id, *_ in steps]
    lines += ["        with:", f"          runners: {','.join(step_id for step_id, *_ in steps)}"]
    return "\n".join(lines)


def main():
    if len(sys.argv) != 3:
        print("usage: classroom-workflow.py TREE OUT", file=sys.stderr)
        sys.exit(2)
    tree, out = Path(sys.argv[1]), Path(sys.argv[2])
    labs = lab_rows(tree / "framework/include/whitted/lab_table.hpp")
    steps, total = public_steps(labs, tree / "instructor/rubric.json")
    text = (tree / "instructor/docs/handout/classroom.yml.in").read_text()
    for key, value in {
        "@PACKAGES@": " ".join(packages(tree / "scripts/install-deps.sh")),
        "@PUBLIC_POINTS@": str(sum(points for *_, points in steps)),
        "@TOTAL_POINTS@": str(total),
        "@GRADED_STEPS@": graded_yaml(steps),
    }.items():
        if key not in text:
            fail(f"the template has no {key}")
        text = text.replace(key, value)
    if "@" in re.sub(r"autograding-[a-z-]+@v1|actions/[a-z/]+@v4", "", text):
        fail("the template has a placeholder this script does not fill")
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text)


main()
