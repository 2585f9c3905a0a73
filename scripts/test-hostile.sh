#!/usr/bin/env bash
# The grader against hostile submissions (CI, after `make test`). Each lab of a
# submission is the reference with one hostile line at the start of one of its
# functions; every grading must end with a valid results.json, a clear status
# per test, points only where earned, the instructor's files untouched and no
# process left behind. Grades, sharing one build cache:
#   reference   the reference solution, first and again at the end: 100 points
#               and byte-identical results.json (a hostile submission cannot
#               change how the next one is graded);
#   hostile-a   abort, throw, sleep, allocate without end, flood the output,
#               write a huge file; with --sandbox none (resource limits only);
#   hostile-b   exit 0 early, NaN pixels, a fork bomb that also escapes its
#               process group, reading the solution and the hidden tests,
#               overwriting reference images, the rubric and results.json, an
#               orphan left sleeping; with --sandbox bubblewrap (installed
#               first when missing and possible).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v bwrap > /dev/null; then bash scripts/install-deps.sh --sandbox || true; fi
# shellcheck source=lib/grading-checks.sh
source scripts/lib/grading-checks.sh test-hostile
trap '[ -n "${KEEP_WORK:-}" ] || rm -rf "$work"; pkill -9 hostile- 2> /dev/null || true' EXIT

# The files a submission must not change: the tests, the solution, the instructor build's imported parts.
protected_hash() {
    find tests solution "$build/tests" -type f ! -path "$build/tests/test-output/*" -print0 2> /dev/null |
        sort -z | xargs -0 sha256sum | sha256sum | cut -d' ' -f1
}
before=$(protected_hash)

# hostile NAME CODE...: a copy of the reference with the injected lines.
hostile() {
    local name=$1
    shift
    mkdir -p "$work/$name-labs"
    cp solution/*.cpp "$work/$name-labs/"
    python3 scripts/lib/inject.py "$work/$name-labs" "$@"
}

common='ok(statuses("integration") == {"skipped"}, "integration: " + str(statuses("integration")))
for t in results["tests"]:
    if t["extra_data"]["status"] in ("crash", "timeout", "exception", "skipped"):
        ok(t["score"] == 0, t["name"] + ": " + str(t["score"]) + " points for a " + t["extra_data"]["status"])
import os
ok(os.path.getsize(folder + "/results.json") < 2_000_000, "results.json is larger than 2 MB")
ok(os.path.getsize(folder + "/report.html") < 20_000_000, "report.html is larger than 20 MB")
def shown(lab, text): return any(text in t["output"] for t in by_lab[lab])
def lost(lab): ok(lab_score(lab) < lab_max(lab), lab + ": full marks for a hostile lab")
import glob
def probes(lab): return "".join(open(p).read() for p in glob.glob(folder + "/tests/" + lab + "/*/hostile-probe.txt"))
'

grade reference-first "$tree/solution" 0 --build-cache "$work/cache"

hostile hostile-a \
    01_ray_casting primary_ray '#include <cstdlib> std::abort();' \
    02_shadows spawn_ray '#include <stdexcept> throw std::runtime_error("hostile: thrown on purpose");' \
    03_blinn_phong blinn_phong '#include <chrono> #include <thread> std::this_thread::sleep_for(std::chrono::hours(1));' \
    04_reflection mirror_direction 'for (;;) { char* block = new char[1 << 26]; for (int i = 0; i < (1 << 26); i += 4096) block[i] = 1; }' \
    05_refraction refracted_direction '#include <cstdio> for (;;) std::fputs("hostile: flooding the output with one line after another\n", stdout);' \
    06_fresnel fresnel_reflectance '#include <cstdio> { static char block[1 << 20]; std::FILE* file = std::fopen("huge.bin", "wb"); for (;;) std::fwrite(block, 1, sizeof block, file); }'
grade hostile-a "$work/hostile-a-labs" 1 --build-cache "$work/cache" --timeout 1 --sandbox none
check hostile-a "$common"'
for lab in ("01_ray_casting", "02_shadows", "03_blinn_phong", "04_reflection", "05_refraction", "06_fresnel"): lost(lab)
ok("crash" in statuses("01_ray_casting") and shown("01_ray_casting", "SIGABRT"), "abort: not a crash by SIGABRT")
ok("exception" in statuses("02_shadows") and shown("02_shadows", "hostile: thrown on purpose"), "throw: not an exception")
ok("timeout" in statuses("03_blinn_phong"), "sleep: no timeout")
ok(statuses("04_reflection") & {"exception", "crash", "timeout"}, "allocation without end: " + str(statuses("04_reflection")))
ok("timeout" in statuses("05_refraction") and shown("05_refraction", "more lines]"), "flood: no timeout or output not cut")
ok("crash" in statuses("06_fresnel") and shown("06_fresnel", "SIGXFSZ"), "huge file: not stopped by SIGXFSZ")
ok("rlimits mode" in results["output"], "the mode is not reported: " + results["output"])'

tests_dir="$tree/tests" solution_dir="$tree/solution" out_b="$work/hostile-b"
# A fork bomb only where the grader can bound it: not root, or root with tests run as nobody.
exposed=0
bomb='#include <sys/prctl.h> #include <unistd.h> if (fork() == 0) { setsid(); prctl(PR_SET_NAME, "hostile-bomb"); for (;;) fork(); } for (;;) fork();'
if [ "$(id -u)" -eq 0 ] && ! python3 -c 'import os, sys; os.setgid(65534); os.setuid(65534); sys.exit(0 if all(os.access(p, os.R_OK | os.X_OK) for p in sys.argv[1:]) else 1)' \
        "$tree/tests" "$tree/$build/tests" "$work"; then
    echo "note: user nobody cannot reach this tree, so tests would run as root without a process limit: no fork bomb"
    bomb='for (;;) {}'
    exposed=1
fi
# The sandbox where bwrap works here (not, for instance, inside a chroot, where it cannot pivot_root).
sandbox=bubblewrap
if ! command -v bwrap > /dev/null; then
    sandbox=none
    echo "note: bubblewrap is not installed: hostile-b runs without the sandbox"
elif ! bwrap --dev-bind / / true 2> /dev/null; then
    sandbox=none
    echo "note: bubblewrap does not work on this machine: hostile-b runs without the sandbox"
fi
# Tests that run as root outside bubblewrap can write the instructor's files: there the grader
# must notice and stop (exit 3), and that is checked apart, on copies put back afterwards.
overwrite_targets='"'"$tests_dir"'/images/whitted_1980.png", "'"$tests_dir"'/rubric.json", "'"$out_b"'/results.json"'
unprotected=0
if [ "$exposed" = 1 ] && [ "$sandbox" = none ]; then
    unprotected=1
    overwrite_targets='"'"$out_b"'/results.json"'
fi
hostile hostile-b \
    01_ray_casting primary_ray '#include <cstdlib> std::exit(0);' \
    02_shadows lambert '#include <cmath> return Color(std::nan(""));' \
    03_blinn_phong blinn_phong "$bomb" \
    04_reflection reflection '#include <fstream> #include <string> static const bool tried = [] { for (const char* path : {"'"$solution_dir"'/04_reflection.cpp", "'"$tests_dir"'/hidden/04_reflection/hidden_reflection_test.cpp"}) { std::ifstream file(path); std::string line; std::ofstream probe("hostile-probe.txt", std::ios::app); if (std::getline(file, line)) probe << "LEAKED " << path << ": " << line << "\n"; else probe << "could not read " << path << "\n"; } return true; }(); (void)tried;' \
    05_refraction refraction '#include <cstdio> #include <fstream> static const bool tried = [] { for (const char* path : {'"$overwrite_targets"'}) { std::FILE* file = std::fopen(path, "wb"); std::ofstream("hostile-probe.txt", std::ios::app) << (file ? "OVERWROTE " : "could not overwrite ") << path << "\n"; if (file) { std::fputs("hostile", file); std::fclose(file); } } return true; }(); (void)tried;' \
    06_fresnel fresnel_blend '#include <sys/prctl.h> #include <unistd.h> static const bool left = [] { if (fork() == 0) { setsid(); prctl(PR_SET_NAME, "hostile-orphan"); sleep(3600); _exit(0); } return true; }(); (void)left;'
grade hostile-b "$work/hostile-b-labs" 1 --build-cache "$work/cache" --timeout 1 --sandbox "$sandbox"
check hostile-b "$common"'
for lab in ("01_ray_casting", "02_shadows", "03_blinn_phong"): lost(lab)
ok("crash" in statuses("01_ray_casting") and shown("01_ray_casting", "exited with code 0 before reporting a result"), "early exit 0: not a crash")
ok("failed" in statuses("02_shadows") and shown("02_shadows", "NaN"), "NaN pixels: not failed, or NaN not named")
ok("timeout" in statuses("03_blinn_phong"), "fork bomb: no timeout: " + str(statuses("03_blinn_phong")))
for lab in ("04_reflection", "05_refraction", "06_fresnel"):
    ok(lab_score(lab) == lab_max(lab), lab + ": correct code lost points: " + str(statuses(lab)))
# Inside bubblewrap, writing where results.json would go "succeeds" in the private view of the sandbox:
# what counts is the real file (valid, checked above) and the files of the instructor (hashed below).
ok("could not overwrite" in probes("05_refraction") or "OVERWROTE" in probes("05_refraction"), "the overwriting test did not run")
ok(open(folder + "/results.json").read(1) == "{", "results.json was overwritten")
sandboxed = "sandbox mode" in results["output"]
ok(sandboxed or "'"$sandbox"'" == "none", "bubblewrap was asked for and not used: " + results["output"])
if sandboxed:
    ok("LEAKED" not in probes("04_reflection"), "a test read the solution or a hidden test: " + probes("04_reflection")[:300])
    ok("could not read" in probes("04_reflection"), "the reading test did not run")'

if [ "$unprotected" = 1 ]; then
    mkdir -p "$work/backup"
    cp tests/images/whitted_1980.png tests/rubric.json "$work/backup/"
    out_b="$work/hostile-overwrite"
    hostile hostile-overwrite 05_refraction refraction '#include <cstdio> static const bool tried = [] { for (const char* path : {"'"$tests_dir"'/images/whitted_1980.png", "'"$tests_dir"'/rubric.json"}) { if (std::FILE* file = std::fopen(path, "wb")) { std::fputs("hostile", file); std::fclose(file); } } return true; }(); (void)tried;'
    grade hostile-overwrite "$work/hostile-overwrite-labs" 3 --build-cache "$work/cache" --timeout 1 --sandbox none
    if grep -q "a file the grader relies on changed: tests/" "$work/hostile-overwrite/results.json"; then
        echo "ok   unprotected tests overwrote the instructor's files: the grader noticed and stopped"
    else
        echo "FAIL unprotected tests overwrote the instructor's files and the grader did not stop"
        failures=$((failures + 1))
    fi
    cp "$work/backup/whitted_1980.png" tests/images/ && cp "$work/backup/rubric.json" tests/
fi

after=$(protected_hash)
if [ "$before" = "$after" ]; then
    echo "ok   the tests, the solution and the instructor build are unchanged"
else
    echo "FAIL a hostile submission changed the instructor's files:"
    git status --short -- tests solution
    git checkout -- tests solution
    failures=$((failures + 1))
fi
if pgrep hostile- > /dev/null; then
    echo "FAIL processes left behind: $(pgrep -l hostile- | head -5 | tr '\n' ' ')"
    failures=$((failures + 1))
else
    echo "ok   no process left behind"
fi

grade reference-again "$tree/solution" 0 --build-cache "$work/cache"
check reference-again 'ok(results["score"] == 100, "score " + str(results["score"]) + ", expected 100")'
same_results reference-first reference-again "the reference grades the same before and after the hostile submissions"

echo
echo "grading times ($jobs jobs):"
printf '  %s\n' "${summary[@]}"
if [ "$failures" -ne 0 ]; then
    echo "test-hostile: $failures check(s) failed"
    exit 1
fi
echo "test-hostile: all checks passed"
