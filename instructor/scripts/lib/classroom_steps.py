#!/usr/bin/env python3
"""The handout's GitHub Classroom workflow, read and run here as GitHub would.

usage: classroom_steps.py check HANDOUT RUBRIC    validate .github/workflows/classroom.yml
       classroom_steps.py build HANDOUT CACHE     run its build step (ccache in CACHE when ccache is here)
       classroom_steps.py grade HANDOUT none|all  run its graded steps; every one must fail (none) or pass (all)

The commands come from the workflow file, not from a copy: each graded step's
`command` runs as classroom-resources/autograding-command-grader@v1 runs it
(/bin/sh -c in the checkout, an environment of PATH and HOME only, its
`timeout` in minutes), and the points are added up as the
autograding-grading-reporter@v1 does: max-score for a pass, 0 otherwise.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

try:
    import yaml
except ImportError:
    print("classroom_steps: python3 has no yaml module; install it (apt-get install python3-yaml, or pip install pyyaml)", file=sys.stderr)
    sys.exit(1)

GRADER = "classroom-resources/autograding-command-grader@v1"
REPORTER = "classroom-resources/autograding-grading-reporter@v1"


class Invalid(Exception):
    pass


def require(condition, message):
    if not condition:
        raise Invalid(message)


def load(handout):
    path = Path(handout) / ".github/workflows/classroom.yml"
    require(path.is_file(), f"{path} is missing")
    try:
        workflow = yaml.safe_load(path.read_text())
    except yaml.YAMLError as error:
        raise Invalid(f"{path} is not valid YAML: {error}")
    require(isinstance(workflow, dict), f"{path} is not a mapping")
    return workflow


def the_job(workflow):
    jobs = workflow.get("jobs")
    require(isinstance(jobs, dict) and len(jobs) == 1, "the workflow needs exactly one job")
    job = next(iter(jobs.values()))
    require(job.get("runs-on") == "ubuntu-latest", "the job does not run on ubuntu-latest")
    steps = job.get("steps")
    require(isinstance(steps, list) and steps, "the job has no steps")
    return job, steps


def graded(steps):
    return [step for step in steps if step.get("uses") == GRADER]


def one_step(steps, predicate, what):
    found = [step for step in steps if predicate(step)]
    require(len(found) == 1, f"the workflow needs exactly one {what} step, it has {len(found)}")
    return found[0]


def check(handout, rubric_path):
    """Structure, and the points against the rubric's public rules; returns the graded steps."""
    workflow = load(handout)
    # YAML 1.1 reads a bare `on` as true: the file quotes it, as GitHub Classroom's own workflows do.
    triggers = workflow.get("on")
    require(isinstance(triggers, list) and {"push", "workflow_dispatch"} <= set(triggers),
            "the workflow does not run on push and workflow_dispatch ('on' must be quoted)")
    perms = workflow.get("permissions", {})
    require(perms.get("checks") == "write", "the workflow needs permissions: checks: write (the reporter's results)")
    job, steps = the_job(workflow)
    require(steps[0].get("uses", "").startswith("actions/checkout@"), "the first step is not actions/checkout")

    # The packages: every one of scripts/install-deps.sh, and ccache.
    install = one_step(steps, lambda s: "apt-get install" in str(s.get("run", "")), "package installation")
    listed = re.search(r"^packages=\(([^)]*)\)$", (Path(handout) / "scripts/install-deps.sh").read_text(), re.M)
    require(listed, "scripts/install-deps.sh has no line packages=(...)")
    missing = set(listed.group(1).split() + ["ccache"]) - set(install["run"].split())
    require(not missing, f"the install step does not install {' '.join(sorted(missing))}")

    # The compiler cache: restored before the build, saved after it whatever the tests say, one folder.
    restore = one_step(steps, lambda s: str(s.get("uses", "")).startswith("actions/cache/restore@"), "cache restore")
    build = one_step(steps, lambda s: s.get("id") == "build", "build (id: build)")
    save = one_step(steps, lambda s: str(s.get("uses", "")).startswith("actions/cache/save@"), "cache save")
    order = [steps.index(s) for s in (install, restore, build, save)]
    require(order == sorted(order), "install, cache restore, build and cache save are not in that order")
    require(restore["with"]["path"] == save["with"]["path"] == build["env"]["CCACHE_DIR"],
            "the cache steps and the build's CCACHE_DIR name different folders")
    require(restore["with"]["key"] == save["with"]["key"], "the cache is restored and saved under different keys")
    require(restore["with"]["key"].startswith(restore["with"].get("restore-keys", "\0")),
            "restore-keys is not a prefix of the key: an earlier run's cache would never be restored")
    require("github.sha" in save["with"]["key"] or "github.run_id" in save["with"]["key"],
            "the cache key is the same for every run: a saved cache is never overwritten, so it would never grow")
    require("cancelled()" in str(save.get("if", "")) or "always()" in str(save.get("if", "")),
            "the cache save does not run when a test fails")
    require(build["env"].get("CMAKE_CXX_COMPILER_LAUNCHER") == "ccache", "the build does not compile through ccache")
    require(build["run"].strip() == "bash scripts/classroom-check.sh build", "the build step does not run scripts/classroom-check.sh build")

    # The graded steps, then the reporter reading each one's result.
    steps_graded = graded(steps)
    require(steps_graded, "the workflow has no graded steps")
    require(steps.index(steps_graded[0]) > steps.index(save), "a graded step runs before the build is saved")
    ids = [s.get("id", "") for s in steps_graded]
    require(all(re.fullmatch(r"[a-z0-9]+", i) for i in ids), f"graded step ids must be letters and digits: {ids}")
    require(len(set(ids)) == len(ids), "two graded steps share an id")
    names = [s["with"].get("test-name") for s in steps_graded]
    require(all(names) and len(set(names)) == len(names), "graded steps need distinct test-names")
    for step in steps_graded:
        inputs = step["with"]
        require(set(inputs) <= {"test-name", "setup-command", "command", "timeout", "max-score"},
                f"{step['id']}: inputs the command grader does not have: {sorted(set(inputs) - {'test-name', 'setup-command', 'command', 'timeout', 'max-score'})}")
        require(re.fullmatch(r"bash scripts/classroom-check\.sh (\d+ (unit|image)|integration)", inputs.get("command", "")),
                f"{step['id']}: its command is not scripts/classroom-check.sh LAB unit|image or integration")
        require(isinstance(inputs.get("timeout"), (int, float)) and 0 < inputs["timeout"] <= 360, f"{step['id']}: timeout is not 1..360 minutes")
        require(isinstance(inputs.get("max-score"), int) and inputs["max-score"] > 0, f"{step['id']}: max-score is not a positive number")
        require("cancelled()" in str(step.get("if", "")), f"{step['id']}: it does not run after a failed build (if: ${{{{ !cancelled() }}}})")
    reporter = steps[-1]
    require(reporter.get("uses") == REPORTER, "the last step is not the grading reporter")
    require("cancelled()" in str(reporter.get("if", "")), "the reporter does not run when a step failed")
    require(reporter["with"]["runners"] == ",".join(ids), "the reporter's runners are not the graded steps, in order")
    expected_env = {f"{i.upper()}_RESULTS": f"${{{{ steps.{i}.outputs.result }}}}" for i in ids}
    require(reporter.get("env") == expected_env, "the reporter's env is not <ID>_RESULTS: ${{ steps.<id>.outputs.result }} for each graded step")

    # Every lab of the lab table is graded, and the points are the rubric's public ones.
    table = (Path(handout) / "framework/include/whitted/lab_table.hpp").read_text()
    labs = [int(n) for n in re.findall(r"^ *LabInfo\{(\d+), ", table, re.M)]
    commands = [s["with"]["command"].split()[2:] for s in steps_graded]
    for lab in labs:
        for part in ("unit", "image"):
            require([str(lab), part] in commands, f"lab {lab}'s {part} tests are not graded")
    require(["integration"] in commands, "the integration tests are not graded")
    rubric = json.loads(Path(rubric_path).read_text())
    public = {}
    for section in rubric["labs"]:
        key = "integration" if section["lab"] == "integration" else str(int(section["lab"][:2]))
        public[key] = sum(r["points"] for r in section["rules"] if not all(t.startswith("Hidden") for t in r["tests"]))
    graded_points = {}
    for step, command in zip(steps_graded, commands):
        graded_points[command[0]] = graded_points.get(command[0], 0) + step["with"]["max-score"]
    require(graded_points == public, f"points per lab {graded_points} are not the rubric's public points {public}")
    return steps_graded


def expand(value, handout, cache):
    """The workflow's ${{ }} expressions that the build step uses, as on the runner."""
    known = {"runner.temp": str(cache.parent), "github.workspace": str(handout)}

    def one(match):
        require(match.group(1) in known, f"the build step uses ${{{{ {match.group(1)} }}}}, which this check cannot play")
        return known[match.group(1)]
    return re.sub(r"\$\{\{\s*([a-z.]+)\s*\}\}", one, str(value))


def build(handout, cache):
    handout = Path(handout).resolve()
    cache = Path(cache).resolve()
    _, steps = the_job(load(handout))
    step = one_step(steps, lambda s: s.get("id") == "build", "build")
    env = dict(os.environ)
    env.update({key: expand(value, handout, cache / "ccache") for key, value in step.get("env", {}).items()})
    require(Path(env["CCACHE_DIR"]) == cache / "ccache", "the build's CCACHE_DIR is not ${{ runner.temp }}/ccache")
    if env.get("CMAKE_CXX_COMPILER_LAUNCHER") == "ccache" and not shutil.which("ccache"):
        print("classroom_steps: no ccache here (apt-get install ccache): building without it; GitHub's runner has it")
        del env["CMAKE_CXX_COMPILER_LAUNCHER"]
    log = cache / "build-step.log"
    start = time.monotonic()
    with open(log, "w") as out:
        status = subprocess.run(["bash", "-e", "-c", step["run"]], cwd=handout, env=env, stdout=out, stderr=subprocess.STDOUT).returncode
    seconds = time.monotonic() - start
    text = log.read_text()
    if status != 0:
        print(text[-3000:])
        raise Invalid(f"the build step failed (exit {status}); its log: {log}")
    compiled = re.findall(r"Building CXX object (\S+)", text)
    hits = re.search(r"^\s*Hits:\s+(\d+)\s*/\s*(\d+)", text, re.M)
    cached = sum(f.stat().st_size for f in (cache / "ccache").rglob("*") if f.is_file()) if (cache / "ccache").is_dir() else 0
    print(f"build step: {seconds:.0f} s, {len(compiled)} files compiled"
          + (f", ccache hits {hits.group(1)}/{hits.group(2)}, the cache {cached / 2**20:.0f} MiB" if hits else ""))
    return seconds, compiled, text


def grade(handout, expect):
    """Every graded step as the command grader runs it; returns (points, max points)."""
    handout = Path(handout).resolve()
    _, steps = the_job(load(handout))
    steps_graded = graded(steps)
    logs = Path(tempfile.mkdtemp(prefix="classroom-steps-"))
    # The command grader gives the command only these variables (its src/main.js).
    env = {"PATH": os.environ["PATH"], "FORCE_COLOR": "true", "DOTNET_CLI_HOME": "/tmp", "DOTNET_NOLOGO": "true",
           "HOME": os.environ.get("HOME", "/root")}
    total = maximum = 0
    wrong = []
    rows = []
    for step in steps_graded:
        inputs = step["with"]
        log = logs / f"{step['id']}.log"
        start = time.monotonic()
        try:
            with open(log, "w") as out:
                code = subprocess.run(["/bin/sh", "-c", inputs["command"]], cwd=handout, env=env, stdout=out,
                                      stderr=subprocess.STDOUT, timeout=float(inputs["timeout"]) * 60).returncode
            status = "pass" if code == 0 else "fail"
        except subprocess.TimeoutExpired:
            status = "error"
        seconds = time.monotonic() - start
        score = inputs["max-score"] if status == "pass" else 0
        total += score
        maximum += inputs["max-score"]
        mark = "✅" if status == "pass" else "❌"
        print(f"{mark} {inputs['test-name']}: {score}/{inputs['max-score']} ({seconds:.1f} s)")
        rows.append((step["id"], score, inputs["max-score"]))
        text = log.read_text()
        if expect == "all" and status != "pass":
            wrong.append(f"{step['id']} did not pass: {text[-1500:]}")
        if expect == "none":
            # It fails for the right reason: a stub says so, or a rule it needs does not pass yet.
            reason = re.search(r"is not implemented yet|counts? only once", text)
            if status != "fail" or not reason:
                wrong.append(f"{step['id']} should fail on a stub or an unmet requirement; it gave {status}: {text[-1500:]}")
    print("\n".join(f"  {i:<14} {s:>4} {m:>4}" for i, s, m in rows))
    print(f"Points {total}/{maximum}   (the reporter's 'Autograding complete' notice)")
    shutil.rmtree(logs)
    if wrong:
        raise Invalid("\n".join(wrong))
    require(total == (maximum if expect == "all" else 0), f"expected {'every' if expect == 'all' else 'no'} point")
    return total, maximum


def main():
    args = sys.argv[1:]
    try:
        if len(args) == 3 and args[0] == "check":
            steps = check(args[1], args[2])
            points = sum(s["with"]["max-score"] for s in steps)
            print(f"classroom.yml: valid; {len(steps)} graded steps, {points} points")
        elif len(args) == 3 and args[0] == "build":
            build(args[1], args[2])
        elif len(args) == 3 and args[0] == "grade" and args[2] in ("none", "all"):
            grade(args[1], args[2])
        else:
            print(__doc__.split("\n\n")[1], file=sys.stderr)
            sys.exit(2)
    except (Invalid, KeyError, TypeError) as error:
        print(f"classroom_steps: {error if isinstance(error, Invalid) else 'the workflow lacks ' + repr(error)}", file=sys.stderr)
        sys.exit(1)


main()
