#!/usr/bin/env bash
# The grader against hostile submissions (CI, after `make test`), written by a
# student who has read the grader's source. Every grading must end with a
# valid results.json, a clear status per test, points only where earned,
# nothing secret in results.json or report.html, the instructor's files
# untouched and no process left behind. Grades:
#   reference     the reference solution, first and again at the end: 100
#                 points, byte-identical results.json;
#   refused       (root only) --sandbox none on a tree other users can read:
#                 the grader refuses (exit 3) instead of exposing the answers;
# then in each mode the machine allows, "sandbox" (bubblewrap) and "users"
# (--sandbox none, as root, with the tree unreadable to other users):
#   hostile-a     the reference with one hostile line per lab: abort, throw,
#                 sleep, allocate without end, flood the output, a huge file;
#   hostile-b     exit 0 early, NaN pixels, a fork bomb, reading the solution,
#                 a hidden test, the checker, /etc/shadow and the output of an
#                 earlier grading of the solution, overwriting the
#                 reference images, the rubric, results.json and the checker's
#                 report, an orphan left sleeping;
#   redteam       the untouched stubs with an attack per lab: including the
#                 solution, forging the checker's report from its command
#                 line, a main() of its own with fake tests, reading the
#                 answers, asm(".incbin") of a secret, running the reference
#                 renderer and the checker, writing over the link's shared
#                 memory, an exception dressed as the checker's own words,
#                 leaving files, queues and shared memory for a later run,
#                 opening a socket, sharing the grader's session (terminal);
# in the first of those modes only (nothing in them depends on the fence):
#   hostile-c     vectors and colours right in x with NaN in y and z;
#   lab 10 alone  answered through the framework's BVH builder and its box
#                 primitive, a walk through lab 1's closest_hit() over every
#                 primitive, a walk that never tests a box: 0 points each;
#   constant-*    every lab function answering the same whatever it is asked
#                 (instructor/scripts/lib/constant-labs.py: nothing, something,
#                 passthrough): score 0, every lab 0;
# and once: files (lab files that are links to the solution and to a secret, a
# FIFO, a folder, an oversized file, #include "/dev/zero"), GoogleTest in the
# lab files (its exceptions, tests of its own), a labs/ folder that is a link
# to the solution and a submission that is itself one; and, with a rubric of
# labs 1 and 2 alone, "terminal": folder names, compiler messages and printing
# made of terminal control sequences, graded by grade and grade-all, whose
# bytes on the terminal must hold no control character but newline and tab,
# the grade with a hidden test's worker sleeping till the budget runs out,
# which must leave every visible test as it is without the sleep.
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! command -v bwrap > /dev/null; then bash scripts/install-deps.sh --sandbox || true; fi
# shellcheck source=lib/grading-checks.sh
source instructor/scripts/lib/grading-checks.sh test-hostile
trap 'cleanup; pkill -9 hostile- 2> /dev/null || true; rm -f /tmp/hostile-huge.bin' EXIT

# The files a submission must not change: the tests, the solution, the instructor build's imported parts.
protected_hash() {
    find tests instructor solution "$build/tests" "$build/instructor/tests" -type f ! -path "$build/tests/test-output/*" \
        ! -path "$build/instructor/tests/test-output/*" -print0 2> /dev/null |
        sort -z | xargs -0 sha256sum | sha256sum | cut -d' ' -f1
}
# Brought up to date first, as the first grading would (make rewrites its dependency files after a new configure,
# such as test-bench's in CI): what changes after this is the submissions' doing.
cmake --build "$build" -j"$jobs" --target grading_parts > /dev/null
before=$(protected_hash)

# checked NAME WHAT ARGS... < PYTHON: runs the Python (its ok(condition, text) collects problems; ARGS are its
# sys.argv[1:]) and says "ok NAME: WHAT", or FAIL with the problems.
checked() {
    local name=$1 what=$2
    shift 2
    if python3 -c 'import sys
script = sys.argv.pop(1)
problems = []
def ok(condition, text):
    if not condition: problems.append(text)
exec(script)
for problem in problems: print("  " + problem)
sys.exit(1 if problems else 0)' "$(cat)" "$@"; then
        echo "ok   $name: $what"
    else
        echo "FAIL $name: see above"
        failures=$((failures + 1))
    fi
}

# refused_link NAME LINK: the grading NAME refused the submission LINK, a link to the solution: score 0, the reason in
# results.json and on the terminal, and no file of the solution (by content) in its output folder.
refused_link() {
    checked "$1" "a submission that is a link is refused, nothing copied" "$work/$1" "$2" "$solution_dir" <<'EOF'
import hashlib, json, os
out, link, solution = sys.argv[1:4]
def digests(folder):
    return {hashlib.sha256(open(os.path.join(top, name), "rb").read()).hexdigest(): os.path.join(top, name)
            for top, _, names in os.walk(folder) for name in names if not os.path.islink(os.path.join(top, name))}
results = json.load(open(out + "/results.json"))
ok(results["score"] == 0 and not results["tests"], f"graded: score {results['score']}, {len(results['tests'])} tests")
ok(link + " is a symbolic link" in results["output"], "results.json does not say why: " + results["output"][:200])
ok(link + " is a symbolic link" in open(out + ".log", errors="replace").read(), "the terminal does not say why")
copied = set(digests(out)) & set(digests(solution))
ok(not copied, "the solution was copied: " + ", ".join(sorted(digests(out)[d] for d in copied)))
EOF
}

# hostile NAME CODE...: a copy of the reference with the injected lines.
hostile() {
    local name=$1
    shift
    mkdir -p "$work/$name-labs"
    cp solution/*.cpp "$work/$name-labs/"
    python3 instructor/scripts/lib/inject.py "$work/$name-labs" "$@"
}

common='ok(statuses("integration") == {"skipped"}, "integration: " + str(statuses("integration")))
for t in results["tests"]:
    if t["extra_data"]["status"] in ("crash", "timeout", "exception", "skipped"):
        ok(t["score"] == 0, t["name"] + ": " + str(t["score"]) + " points for a " + t["extra_data"]["status"])
import os
ok(os.path.getsize(folder + "/results.json") < 2_000_000, "results.json is larger than 2 MB")
ok(os.path.getsize(folder + "/report.html") < 20_000_000, "report.html is larger than 20 MB")
def shown(lab, text): return text in results["output"] or any(text in t["output"] for t in by_lab[lab])
def lost(lab): ok(lab_score(lab) < lab_max(lab), lab + ": full marks for a hostile lab")
# How a hidden test ended is chosen by the student code, maybe from its inputs: only passed or failed is shown.
import re
for label, name in re.findall(r"<span class=\"badge [^\"]*\">([^<]*)</span><b>(Hidden[^<]*)</b>", html):
    ok(label in ("passed", "failed", "compile error", "missing", "skipped"), "a hidden test shows a status its code chose: " + name + ": " + label)
for t in results["tests"]:
    if t["visibility"] == "hidden":
        ok(t["extra_data"]["status"] in ("passed", "failed", "compile_error", "missing", "skipped"), "results.json: a hidden test shows " + t["extra_data"]["status"])
'

grade reference-first "$tree/solution" 0

tests_dir="$tree/tests" hidden_dir="$tree/instructor/tests/hidden" rubric="$tree/instructor/rubric.json" solution_dir="$tree/solution"
checker="$tree/$build/instructor/tests/check_04_reflection"
# Text that must never reach what the student sees.
secrets='secret_texts = ["LEAKED", "FORGED", "RAN the reference", "OVERWROTE"] + [line for line in (open("/etc/shadow").read().splitlines()[:1] if os.access("/etc/shadow", os.R_OK) else []) if line]
for text in secret_texts:
    ok(text not in json.dumps(results) and text not in html, "a secret reached the student: " + text[:40])'

# lab10_cheat NAME FUNCTION CODE...: the untouched lab 10 stub, alone, with the cheating lines.
lab10_cheat() {
    local name=$1
    shift
    mkdir -p "$work/$name-labs"
    cp labs/10_bvh.cpp "$work/$name-labs/"
    local args=()
    while [ $# -gt 0 ]; do args+=(10_bvh "$1" "$2"); shift 2; done
    python3 instructor/scripts/lib/inject.py "$work/$name-labs" "${args[@]}"
}
boxless_closest='{ const BvhTree& tree = scene.lab_bvh(); std::optional<Hit> nearest; for (const BvhNode& node : tree.nodes) for (std::uint32_t i = node.first; i < node.first + node.count; ++i) if (std::optional<Hit> hit = intersect(ray, scene.bounded_primitives()[tree.order[i]], t_range)) { t_range.max = hit->t; nearest = hit; } return nearest; }'
boxless_occluded='{ const BvhTree& tree = scene.lab_bvh(); for (const BvhNode& node : tree.nodes) for (std::uint32_t i = node.first; i < node.first + node.count; ++i) if (intersect(ray, scene.bounded_primitives()[tree.order[i]], t_range)) return true; return false; }'
lab10_zero='def shown(lab, text): return text in results["output"] or any(text in t["output"] for t in by_lab[lab])
ok(results["score"] == 0, "points for lab 10 answered by a cheat alone: " + str(results["score"]))
ok(statuses("integration") <= {"skipped", "compile_error"}, "integration: " + str(statuses("integration")))'

# The two modes: bubblewrap where it works, and users and permissions as root.
modes=()
if bwrap --dev-bind / / true 2> /dev/null; then modes+=(sandbox); else echo "note: bubblewrap does not work here: no sandbox mode"; fi
if [ "$(id -u)" -eq 0 ]; then
    # Refused while other users (nobody) can read the tree; graded once it cannot.
    chmod o+rx "$tree"
    if python3 -c 'import os, sys; os.setgid(65534); os.setuid(65534); sys.exit(0 if os.access(sys.argv[1], os.R_OK) else 1)' "$solution_dir/01_ray_casting.cpp"; then
        grade refused "$tree/solution" 3 --sandbox none
        if grep -q "cannot keep the answers from the student's code" "$work/refused/results.json"; then
            echo "ok   refused: no grading where other users can read the answers"
        else
            echo "FAIL refused: graded with the answers readable"
            failures=$((failures + 1))
        fi
    fi
    chmod "$tree_mode" "$tree"
    modes+=(users)
else
    echo "note: not root: no users mode (the student's code would run as the grader's own user)"
fi

# Lab files whose every function returns a constant, one submission per kind of constant.
python3 instructor/scripts/lib/constant-labs.py "$work/constant-labs"
constant_variants=$(python3 instructor/scripts/lib/constant-labs.py --list)

for mode in "${modes[@]}"; do
    options=()
    if [ "$mode" = users ]; then
        chmod o-rwx "$tree"
        options+=(--sandbox none)
    else
        options+=(--sandbox bubblewrap)
    fi
    mode_line='ok(("sandbox mode" if "'"$mode"'" == "sandbox" else "users mode") in open(folder + ".log").read(), "the mode is not reported to the instructor")
ok("mode:" not in json.dumps(results) and "mode:" not in html, "the mode line reached the student")'

    hostile "hostile-a-$mode" \
        01_ray_casting primary_ray '#include <cstdlib> std::abort();' \
        02_shadows spawn_ray '#include <stdexcept> throw std::runtime_error("hostile: thrown on purpose");' \
        07_anti_aliasing pixel_color '#include <chrono> #include <thread> std::this_thread::sleep_for(std::chrono::hours(1));' \
        04_reflection reflection 'for (;;) { char* block = new char[1 << 26]; for (int i = 0; i < (1 << 26); i += 4096) block[i] = 1; }' \
        05_refraction refraction '#include <cstdio> for (;;) std::fputs("hostile: flooding the output with one line after another\n", stdout);' \
        06_fresnel fresnel_reflectance '#include <cstdio> { static char block[1 << 20]; std::FILE* file = std::fopen("/tmp/hostile-huge.bin", "wb"); if (!file) std::abort(); for (;;) std::fwrite(block, 1, sizeof block, file); }'
    # Each attack sits in a function few tests call, since each of those tests waits for its end: the sleep in lab 7's
    # pixel_color() (8 tests), the allocation in reflection() (14), the flood in refraction() (14).
    grade "hostile-a-$mode" "$work/hostile-a-$mode-labs" 1 "${options[@]}" --timeout 1
    check "hostile-a-$mode" "$common$secrets
$mode_line"'
for lab in ("01_ray_casting", "02_shadows", "04_reflection", "05_refraction", "06_fresnel", "07_anti_aliasing"): lost(lab)
ok("crash" in statuses("01_ray_casting") and shown("01_ray_casting", "SIGABRT"), "abort: not a crash by SIGABRT")
ok("exception" in statuses("02_shadows") and shown("02_shadows", "hostile: thrown on purpose"), "throw: not an exception")
ok("timeout" in statuses("07_anti_aliasing"), "sleep: no timeout")
ok(statuses("04_reflection") & {"exception", "crash", "timeout"}, "allocation without end: " + str(statuses("04_reflection")))
ok("timeout" in statuses("05_refraction") and shown("05_refraction", "more lines"), "flood: no timeout or output not cut")
ok("crash" in statuses("06_fresnel") and (shown("06_fresnel", "SIGXFSZ") or shown("06_fresnel", "SIGABRT")), "huge file: not stopped")'

    out_b="$work/hostile-b-$mode"
    bomb='#include <sys/prctl.h> #include <unistd.h> if (fork() == 0) { setsid(); prctl(PR_SET_NAME, "hostile-bomb"); for (;;) fork(); } for (;;) fork();'
    read_secrets='#include <cstdio> #include <fstream> #include <string> static const bool tried = [] { int secret = 0; for (const char* path : {"'"$solution_dir"'/04_reflection.cpp", "'"$hidden_dir"'/04_reflection/hidden_reflection_test.cpp", "'"$checker"'", "'"$tests_dir"'/images/whitted_1980.png", "/etc/shadow", "'"$work"'/reference-first/labs/04_reflection.cpp", "'"$work"'/reference-first/report.html"}) { ++secret; std::ifstream file(path); std::string line; if (std::getline(file, line)) std::printf("LEAKED secret %d: %.40s\n", secret, line.c_str()); else std::printf("could not read secret %d\n", secret); } return true; }(); (void)tried;'
    overwrite='#include <cstdio> static const bool tried = [] { for (const char* path : {"'"$tests_dir"'/images/whitted_1980.png", "'"$rubric"'", "'"$out_b"'/results.json", "'"$out_b"'/tests/05_refraction/Refraction.FollowsSnellsLaw/gtest.json"}) { std::FILE* file = std::fopen(path, "wb"); std::printf("%s a grader file\n", file ? "OVERWROTE" : "could not overwrite"); if (file) { std::fputs("hostile", file); std::fclose(file); } } return true; }(); (void)tried;'
    hostile "hostile-b-$mode" \
        01_ray_casting primary_ray '#include <cstdlib> std::exit(0);' \
        02_shadows lambert '#include <cmath> return Color(std::nan(""));' \
        07_anti_aliasing pixel_color "$bomb" \
        04_reflection reflection "$read_secrets" \
        05_refraction refraction "$overwrite" \
        06_fresnel fresnel_blend '#include <sys/prctl.h> #include <unistd.h> static const bool left = [] { if (fork() == 0) { setsid(); prctl(PR_SET_NAME, "hostile-orphan"); sleep(3600); _exit(0); } return true; }(); (void)left;'
    # The correct labs keep a wide margin: lab 6's image test, the slowest, uses under 1 s of CPU on each side on an
    # idle 2-core machine, more on a slow or busy one. The fork bomb costs --timeout for each of the 8 tests that call
    # pixel_color().
    grade "hostile-b-$mode" "$work/hostile-b-$mode-labs" 1 "${options[@]}" --timeout 6
    check "hostile-b-$mode" "$common$secrets
$mode_line"'
for lab in ("01_ray_casting", "02_shadows", "07_anti_aliasing"): lost(lab)
ok("crash" in statuses("01_ray_casting") and shown("01_ray_casting", "ended the program (exit code 0) before the test was over"), "early exit 0: not a crash")
ok("failed" in statuses("02_shadows") and shown("02_shadows", "NaN"), "NaN pixels: not failed, or NaN not named")
ok("timeout" in statuses("07_anti_aliasing"), "fork bomb: no timeout: " + str(statuses("07_anti_aliasing")))
for lab in ("03_blinn_phong", "04_reflection", "05_refraction", "06_fresnel"):
    ok(lab_score(lab) == lab_max(lab), lab + ": correct code lost points: " + str(statuses(lab)))
ok(open(folder + "/results.json").read(1) == "{", "results.json was overwritten")'

    # Something left for a later run or a later grading, a socket, and the grader's session (its terminal).
    leave='#include <cstdio> #include <cstring> #include <fcntl.h> #include <mqueue.h> #include <sys/shm.h> #include <sys/socket.h> #include <unistd.h> static const bool kept = [] { std::printf(getsid(0) == getpid() ? "a session of its own\n" : "SHARES a session\n"); const int made = open("/run/lock/hostile-lock", O_CREAT | O_WRONLY, 0666); mq_attr attr{}; attr.mq_maxmsg = 1; attr.mq_msgsize = 8; const mqd_t queue = mq_open("/hostile-queue", O_CREAT | O_RDWR, 0666, &attr); const int tcp = socket(AF_INET, SOCK_STREAM, 0); const int tmp = open("/tmp/hostile-kept", O_CREAT | O_WRONLY, 0666); std::printf("left: lock %d, queue %d, socket %d, tmp %d\n", made, (int)queue, tcp, tmp); const int id = shmget(0x686f7374, 4096, IPC_CREAT | 0600); char* text = id >= 0 ? static_cast<char*>(shmat(id, nullptr, 0)) : nullptr; if (text && text != reinterpret_cast<char*>(-1)) { if (*text) std::printf("LEAKED across runs: %s\n", text); else std::strcpy(text, "written by an earlier run"); } std::printf("shared memory %d\n", id); return true; }(); (void)kept;'
    # The untouched stubs, each with an attack on the grader.
    mkdir -p "$work/redteam-$mode-labs"
    cp labs/*.cpp "$work/redteam-$mode-labs/"
    forge='#include <cstdio> #include <dirent.h> #include <fstream> #include <string> static const bool forged = [] { DIR* proc = opendir("/proc"); int seen = 0; while (dirent* entry = proc ? readdir(proc) : nullptr) { std::ifstream file(std::string("/proc/") + entry->d_name + "/cmdline"); std::string text((std::istreambuf_iterator<char>(file)), {}); const std::size_t at = text.find("--gtest_output=json:"); if (at == std::string::npos) continue; ++seen; std::string path = text.substr(at + 20); path = path.substr(0, path.find(std::string(1, 0))); std::ofstream report(path); report << "{\"testsuites\": [{\"name\": \"ShadowFeelers\", \"testsuite\": [{\"name\": \"x\", \"failures\": []}]}]}"; std::printf(report ? "FORGED %s\n" : "could not forge %s\n", path.c_str()); } std::printf("checkers seen: %d\n", seen); return true; }(); (void)forged;'
    python3 instructor/scripts/lib/inject.py "$work/redteam-$mode-labs" \
        02_shadows spawn_ray "$forge" \
        02_shadows is_lit "$overwrite" \
        02_shadows lambert "$leave" \
        04_reflection mirror_direction "$read_secrets" \
        04_reflection reflection '#include <sys/mman.h> #include <cstring> static const bool corrupted = [] { void* ring = mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_SHARED, 3, 0); if (ring != MAP_FAILED) std::memset(ring, 0xff, 4096); return true; }(); (void)corrupted;' \
        06_fresnel fresnel_blend '#include <stdexcept> throw std::runtime_error("fake\ngrading link broken: the worker said goodbye\n[       OK ] FresnelBlend.Fake (0 ms)");' \
        06_fresnel fresnel_reflectance '#include <cstdio> #include <cstdlib> static const bool ran = [] { for (const char* command : {"'"$tree/$build"'/whitted render '"$tree"'/scenes/whitted_1980.p3f -o hostile-render.png", "'"$checker"' --gtest_list_tests"}) std::printf(std::system(command) == 0 ? "RAN the reference\n" : "could not run the reference\n"); return true; }(); (void)ran;'
    printf '#include "../../solution/01_ray_casting.cpp"\n#include "%s/solution/01_ray_casting.cpp"\n' "$tree" | cat - labs/01_ray_casting.cpp > "$work/redteam-$mode-labs/01_ray_casting.cpp"
    printf '#include <cstdio>\nint main() { std::puts("BlinnPhong.\\n  Fake"); return 0; }\n' >> "$work/redteam-$mode-labs/03_blinn_phong.cpp"
    printf 'asm(".incbin \\"/etc/shadow\\"");\nasm(".incbin \\"%s/solution/05_refraction.cpp\\"");\n' "$tree" >> "$work/redteam-$mode-labs/05_refraction.cpp"
    grade "redteam-$mode" "$work/redteam-$mode-labs" 1 "${options[@]}" --timeout 1
    check "redteam-$mode" "$common$secrets
$mode_line"'
ok(results["score"] == 0, "points for stubs that attack: " + str(results["score"]))
ok(statuses("01_ray_casting") == {"compile_error"}, "including the solution compiled: " + str(statuses("01_ray_casting")))
ok(statuses("03_blinn_phong") == {"compile_error"}, "a main() of its own linked: " + str(statuses("03_blinn_phong")))
ok(statuses("05_refraction") == {"compile_error"}, ".incbin of a secret compiled: " + str(statuses("05_refraction")))
ok(shown("02_shadows", "checkers seen:"), "the forging attack did not run")
ok(shown("02_shadows", "left: lock -1, queue -1, socket -1, tmp -1") and shown("02_shadows", "shared memory -1"), "a file, a queue, a socket or shared memory was made: " + str([t["output"][:300] for t in by_lab["02_shadows"] if "left:" in t["output"]][:1]))
ok("'"$mode"'" != "users" or not shown("02_shadows", "SHARES a session"), "the worker shares the grader'"'"'s session (and its terminal)")
ok(shown("02_shadows", "could not overwrite"), "the overwriting attack did not run")
ok(shown("04_reflection", "could not read"), "the reading attack did not run")
ok(shown("06_fresnel", "could not run"), "the running attack did not run")
ok(shown("04_reflection", "the grading link broke: the other side broke the link"), "writing over the link: the broken link not named")
ok("crash" not in statuses("06_fresnel"), "an exception dressed as checker output: " + str(statuses("06_fresnel")))'

    # What follows does not depend on how the student's code is fenced (the checker's comparisons, the link's
    # refusals, constant answers): graded once, in the first mode.
    if [ "$mode" = "${modes[0]}" ]; then
    # Vectors and colours right in x and NaN in y and z: a comparison that drops NaN would pass them.
    hostile "hostile-c-$mode" \
        04_reflection mirror_direction '#include <cmath> { const Vec3 r = 2.0 * glm::dot(wo, n) * n - wo; return Vec3(r.x, std::nan(""), std::nan("")); }' \
        04_reflection reflection '#include <cmath> { const Material& m = tracer.scene().material(hit); const Color c = tracer.trace(spawn_ray(hit, mirror_direction(wo, hit.normal)), depth + 1, RayKind::reflected, m.specular * m.specular_color); return Color(c.r, std::nan(""), std::nan("")); }'
    grade "hostile-c-$mode" "$work/hostile-c-$mode-labs" 1 "${options[@]}" --timeout 2
    check "hostile-c-$mode" "$common$secrets"'
lost("04_reflection")
for t in by_lab["04_reflection"]:
    if t["name"].split(": ")[-1].split(".")[0] in ("MirrorDirection", "HiddenMirrorDirection", "Reflection", "HiddenReflection"):
        ok(t["extra_data"]["status"] != "passed", "a vector with NaN in y and z passed: " + t["name"])'

    # Lab 10 answered by what the framework or the checker would hand over, each alone (the other labs are
    # missing, so only lab 10 is tested): the framework's builder and box slab test (refused at the link), a
    # walk through lab 1's closest_hit() over every primitive (refused at the link, and by the checker), and a
    # walk that never tests a box (every primitive tested: more than the framework's walk of the same tree).
    lab10_cheat "builder-$mode" build_bvh 'BvhTree framework_bvh_tree(std::span<const Aabb>); return framework_bvh_tree(boxes);' \
        box_entry '{ const std::optional<Hit> hit = intersect_box(ray, Box{box.min, box.max}, t_range); if (hit) return hit->t; return std::nullopt; }'
    lab10_cheat "lab1-walk-$mode" bvh_closest_hit 'return closest_hit(ray, scene.bounded_primitives(), t_range);' \
        bvh_occluded 'return closest_hit(ray, scene.bounded_primitives(), t_range).has_value();'
    lab10_cheat "boxless-walk-$mode" bvh_closest_hit "$boxless_closest" bvh_occluded "$boxless_occluded"
    for cheat in builder lab1-walk boxless-walk; do
        grade "$cheat-$mode" "$work/$cheat-$mode-labs" 1 "${options[@]}" --timeout 2
    done
    check "builder-$mode" "$lab10_zero"'
ok(statuses("10_bvh") == {"compile_error"} and shown("10_bvh", "calls whitted::framework_bvh_tree(") and shown("10_bvh", "calls whitted::intersect_box("), "the framework builder and box: " + str(statuses("10_bvh")))'
    check "lab1-walk-$mode" "$lab10_zero"'
ok(statuses("10_bvh") == {"compile_error"} and shown("10_bvh", "calls whitted::closest_hit("), "the walk through lab 1: " + str(statuses("10_bvh")))'
    check "boxless-walk-$mode" "$lab10_zero"'
walks = [t for t in by_lab["10_bvh"] if t["name"].split(": ")[-1].split(".")[0] in ("BvhClosestHit", "BvhOccluded")]
ok(walks and all(t["extra_data"]["status"] in ("failed", "timeout") for t in walks), "the walk without boxes passed a walk test: " + str([t["extra_data"]["status"] for t in walks]))'
    # Constant answers earn nothing: every test of a function has a case that no constant answers right.
    for variant in $constant_variants; do
        grade "constant-$variant-$mode" "$work/constant-labs/$variant" 1 "${options[@]}" --timeout 2
        check "constant-$variant-$mode" "$common$mode_line"'
ok(results["score"] == 0, "points for constant answers: " + str(results["score"]))
for lab in by_lab:
    ok(lab_score(lab) == 0, lab + ": " + str(lab_score(lab)) + " points for constant answers: " + ", ".join(t["name"] for t in by_lab[lab] if t["score"] > 0))'
    done
    fi
    chmod "$tree_mode" "$tree"
done

# Files that are not lab files, and a labs/ folder that is a link to the solution.
mkdir -p "$work/files-labs/05_refraction.cpp" "$work/linked-submission"
printf '#include "/dev/zero"\n' > "$work/files-labs/01_ray_casting.cpp"
mkfifo "$work/files-labs/02_shadows.cpp"
ln -s "$solution_dir/03_blinn_phong.cpp" "$work/files-labs/03_blinn_phong.cpp"
ln -s /etc/shadow "$work/files-labs/04_reflection.cpp"
head -c 2000000 /dev/zero | tr '\0' ' ' > "$work/files-labs/06_fresnel.cpp"
ln -s "$solution_dir" "$work/linked-submission/labs"
file_options=(--timeout 1)
[ "${#modes[@]}" -eq 0 ] && file_options+=(--allow-exposed-answers)
[ "${modes[0]:-}" = users ] && chmod o-rwx "$tree" && file_options+=(--sandbox none)
grade files "$work/files-labs" 1 "${file_options[@]}"
check files "$common$secrets"'
ok(results["score"] == 0, "points for files that are not lab files: " + str(results["score"]))
ok(statuses("01_ray_casting") == {"compile_error"}, "#include \"/dev/zero\": " + str(statuses("01_ray_casting")))
for lab, what in (("02_shadows", "not a regular file"), ("03_blinn_phong", "symbolic link"), ("04_reflection", "symbolic link"), ("05_refraction", "not a regular file"), ("06_fresnel", "larger than")):
    ok(statuses(lab) == {"missing"} and shown(lab, what), lab + ": " + str(statuses(lab)) + ", expected missing: " + what)'
# GoogleTest in the student's file: its "already reported" exception thrown by a stub, and tests of its own
# (one named as a public test): the worker has no GoogleTest, so neither links.
mkdir -p "$work/gtest-labs"
cp labs/*.cpp "$work/gtest-labs/"
python3 instructor/scripts/lib/inject.py "$work/gtest-labs" 01_ray_casting primary_ray \
    '#include <gtest/gtest.h> throw ::testing::AssertionException(::testing::TestPartResult(::testing::TestPartResult::kFatalFailure, "x", 1, "already reported"));'
printf '#include <gtest/gtest.h>\nTEST(IsLit, NothingInTheWayMeansLit) { SUCCEED(); }\nTEST(HiddenIsLit, Forged) { SUCCEED(); }\n' >> "$work/gtest-labs/02_shadows.cpp"
grade gtest "$work/gtest-labs" 1 "${file_options[@]}"
check gtest "$common$secrets"'
ok(results["score"] == 0, "points for GoogleTest in the lab files: " + str(results["score"]))
ok(statuses("01_ray_casting") == {"compile_error"}, "GoogleTest exception: " + str(statuses("01_ray_casting")))
ok(statuses("02_shadows") == {"compile_error"}, "tests of its own: " + str(statuses("02_shadows")))
ok(not any("Forged" in t["name"] for t in results["tests"]), "a test the submission registered is listed")'
grade linked-folder "$work/linked-submission" 1 "${file_options[@]}"
check linked-folder "$common$secrets"'
ok(results["score"] == 0, "points for a labs/ folder linked to the solution: " + str(results["score"]))'
# A submission that is itself a link to the solution: refused (exit 2, a results.json saying why), nothing copied.
ln -s "$solution_dir" "$work/linked-top-submission"
grade linked-top "$work/linked-top-submission" 2 "${file_options[@]}"
refused_link linked-top linked-top-submission

# A rubric of 100 points on labs 1 and 2 alone (the others must be listed: for no points, and a missing lab's tests do
# not run): the cases below cost a few seconds each.
cat > "$work/two-labs.json" <<'EOF'
{ "labs": [
  { "lab": "01_ray_casting", "title": "Lab 1: ray casting", "rules": [
    { "id": "unit", "tests": ["*"], "exclude": ["Hidden*", "Lab1Image"], "points": 40 },
    { "id": "hidden", "tests": ["Hidden*"], "points": 10, "optional": true },
    { "id": "image", "tests": ["Lab1Image"], "points": 10, "requires": ["unit"], "image": true } ] },
  { "lab": "02_shadows", "title": "Lab 2: shadows", "rules": [
    { "id": "unit", "tests": ["*"], "exclude": ["Hidden*", "Lab2Image"], "points": 20 },
    { "id": "hidden", "tests": ["Hidden*"], "points": 10, "optional": true },
    { "id": "image", "tests": ["Lab2Image"], "points": 10, "requires": ["unit"], "image": true } ] },
  { "lab": "03_blinn_phong", "title": "Lab 3", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "04_reflection", "title": "Lab 4", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "05_refraction", "title": "Lab 5", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "06_fresnel", "title": "Lab 6", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "07_anti_aliasing", "title": "Lab 7", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "08_soft_shadows", "title": "Lab 8", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "09_depth_of_field", "title": "Lab 9", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "10_bvh", "title": "Lab 10", "rules": [ { "id": "unit", "tests": ["*"], "exclude": ["Hidden*"], "points": 0 } ] },
  { "lab": "integration", "title": "Integration", "rules": [ { "id": "all", "tests": ["*"], "points": 0, "requires": ["*:unit"] } ] } ] }
EOF
two_labs=(--rubric "$work/two-labs.json" "${file_options[@]:2}")

# The terminal is not the student's: folder names made of control sequences (the window title by OSC 0, the
# clipboard by OSC 52, a cleared screen with a fake line, CSI as the C1 code point and as a lone byte, a carriage
# return), the compiler's messages about them (#error, an #include of such a name) and what the code prints in
# failing tests. grade (without -q: its progress too) and grade-all print none of it raw. The grade is also the case
# of the budget: a hidden test's worker sleeps (on the camera at (10, 20, 30), an input of HiddenPrimaryRay) till the
# budget runs out; hidden tests run after every visible test, so each visible test ends as it does without the sleep
# (passed or failed: none is "not run") and only hidden tests are cut short. The budget is half as long again as
# grade-all's grading of the same submission without the sleep took (at least 10 s), so that a machine busy with
# other work still runs every visible test within it.
esc=$'\e]0;pwned-title\a\e]52;c;aGFja2Vk\a\e[2J\e[Hfull marks 100 of 100\xc2\x9b31m\x9b1m\r'
student="$work/terminal/student$esc"
mkdir -p "$student/labs" "$work/terminal-out" "$work/terminal-ambiguous/labs" "$work/terminal-ambiguous/old$esc" "$work/terminal-class"
cp solution/01_ray_casting.cpp solution/02_shadows.cpp "$student/labs/"
python3 instructor/scripts/lib/inject.py "$student/labs" 01_ray_casting primary_ray \
    '#include <cstdio> std::fputs("\x1b]0;pwned-title\x07\x1b]52;c;aGFja2Vk\x07\x1b[2J\x1b[Hfull marks\xc2\x9b" "31m\x9b" "1m\r\n", stdout); return Ray{camera.eye, camera.ze};'
printf '#error \e]0;pwned-title\a\e[2J\xc2\x9b31m\x9b1m\n#include "\e]52;c;aGFja2Vk\a.h"\n' >> "$student/labs/02_shadows.cpp"
cp -r "$student" "$work/terminal-class/"
python3 instructor/scripts/lib/inject.py "$student/labs" 01_ray_casting primary_ray \
    '#include <chrono> #include <thread> if (camera.eye == Point3(10, 20, 30)) std::this_thread::sleep_for(std::chrono::hours(1));'
cp solution/01_ray_casting.cpp "$work/terminal-ambiguous/labs/"
cp solution/01_ray_casting.cpp "$work/terminal-ambiguous/old$esc/"
ln -s "$solution_dir" "$work/terminal-class/linked$esc"
ln -s "$solution_dir" "$work/terminal-link$esc"
echo "not a student" > "$work/terminal-class/file$esc"
# terminal NAME EXPECTED_EXIT COMMAND...: runs a whitted command, its stdout and stderr in $work/NAME.out and .err,
# the seconds it took in $seconds.
terminal() {
    local name=$1 expected=$2
    shift 2
    timed "$name" "$expected" "$work/$name.out" "$work/$name.err" "$whitted" "$@" --jobs "$jobs" "${two_labs[@]}"
}
terminal terminal-class 0 grade-all "$work/terminal-class" --csv "$work/terminal-class.csv" --out "$work/terminal-grades" --timeout 2
budget=$(python3 -c "print(max(10, round(1.5 * $seconds)))")
terminal terminal-grade 1 grade "$student" --out "$work/terminal-out/student$esc" --budget "$budget"
terminal terminal-ambiguous 2 grade "$work/terminal-ambiguous" --out "$work/terminal-ambiguous-out"
terminal terminal-link 2 grade "$work/terminal-link$esc" --out "$work/terminal-link-out"
checked terminal "no control character of a submission reaches the terminal (grade, grade-all); no budget channel (--budget $budget)" "$work" "$esc" <<'EOF'
import csv, json, os
work, esc = sys.argv[1], os.fsencode(sys.argv[2])
shown = b"\\x1b]0;pwned-title\\x07\\x1b]52;c;aGFja2Vk\\x07\\x1b[2J\\x1b[Hfull marks 100 of 100\\u009b31m\\x9b1m\\x0d"
def terminal_bytes(name):
    data = open(f"{work}/{name}.out", "rb").read() + open(f"{work}/{name}.err", "rb").read()
    for raw in (b"\x1b", b"\x07", b"\x9b", b"\x9d", b"\x7f"): ok(raw not in data, f"{name}: byte {raw!r} on the terminal")
    try:
        text = data.decode("utf-8")
        bad = sorted({hex(ord(c)) for c in text if (ord(c) < 0x20 and c not in "\n\t") or 0x7f <= ord(c) < 0xa0})
        ok(not bad, f"{name}: control characters on the terminal: {bad}")
    except UnicodeDecodeError as error:
        ok(False, f"{name}: not UTF-8 on the terminal at byte {error.start}")
    return data
grade = terminal_bytes("terminal-grade")
ok(b"wrote " in grade and b"student" + shown in grade, "grade: the output folder's name is not shown escaped")
ok(b"old" + shown + b"/" in terminal_bytes("terminal-ambiguous"), "grade: lab files in two places: the folder is not named escaped")
ok(b"terminal-link" + shown + b" is a symbolic link" in terminal_bytes("terminal-link"), "grade: the link is not named escaped")
grade_all = terminal_bytes("terminal-class")
ok(b"student" + shown + b": " in grade_all, "grade-all: the student is not shown escaped in the progress")
ok(grade_all.count(b"linked" + shown + b": ") >= 2, "grade-all: the link is not shown escaped in the progress and the summary")
ok(b"file" + shown in grade_all, "grade-all: the file at the top is not named escaped")
rows = {os.fsencode(row[0]): row for row in csv.reader(open(f"{work}/terminal-class.csv", newline="", errors="surrogateescape"))}
ok(rows.get(b"linked" + esc, [""] * 4)[3] == "not_graded", "grade-all: a student folder that is a link is not not_graded")
ok(0 < float(rows.get(b"student" + esc, ["", "0"])[1] or 0) < 100, "grade-all: the student is not graded")
# The submission did reach the grader: its printing in results.json (escaped by JSON) and the compiler's message.
folder = f"{work}/terminal-out/".encode() + b"student" + esc
raw = open(folder + b"/results.json", "rb").read()
for byte in (b"\x1b", b"\x07", b"\x7f", b"\xc2\x9b", b"\xc2\x9d"): ok(byte not in raw, f"results.json holds {byte!r} raw")
graded = json.loads(raw)
tests = graded["tests"]
lab1 = [t for t in tests if "01_ray_casting" in t["tags"]]
ok(any("\x1b]0;pwned-title" in t["output"] for t in lab1), "the printing of the failing tests is not in results.json")
ok("pwned-title" in graded["output"] and any(t["extra_data"]["status"] == "compile_error" for t in tests),
   "the compiler's message is not in results.json (once, at the top)")
html = open(folder + b"/report.html", "rb").read()
ok(b"\x1b" not in html and b"\\x1b]0;pwned-title" in html, "report.html: the printing is not shown escaped")
try:
    html.decode("utf-8")
except UnicodeDecodeError as error:
    ok(False, f"report.html is not UTF-8 at byte {error.start}")
# No budget channel: the visible tests ended as without the sleep, which only cut hidden tests short.
visible = {t["extra_data"]["status"] for t in lab1 if t["visibility"] != "hidden"}
ok(visible == {"passed", "failed", "skipped"}, f"the hidden test's time changed the visible tests of lab 1: {sorted(visible)}")
ok(any(t["visibility"] == "hidden" and t["extra_data"]["status"] == "failed" for t in lab1), "no hidden test was cut short")
EOF
chmod "$tree_mode" "$tree"

after=$(protected_hash)
if [ "$before" = "$after" ]; then
    echo "ok   the tests, the solution and the instructor build are unchanged"
else
    echo "FAIL a hostile submission changed the instructor's files:"
    git status --short -- tests solution
    git checkout -- tests solution
    failures=$((failures + 1))
fi
if [ -e /run/lock/hostile-lock ] || [ -e /tmp/hostile-kept ] || python3 -c 'import ctypes, os, sys; sys.exit(0 if ctypes.CDLL(None).mq_open(b"/hostile-queue", os.O_RDONLY) != -1 else 1)'; then
    echo "FAIL files or message queues left behind (/run/lock/hostile-lock, /tmp/hostile-kept, /hostile-queue)"
    rm -f /run/lock/hostile-lock /tmp/hostile-kept
    python3 -c 'import ctypes; ctypes.CDLL(None).mq_unlink(b"/hostile-queue")'
    failures=$((failures + 1))
else
    echo "ok   nothing left in /run/lock, /tmp or the POSIX message queues"
fi
if pgrep hostile- > /dev/null; then
    echo "FAIL processes left behind: $(pgrep -l hostile- | head -5 | tr '\n' ' ')"
    failures=$((failures + 1))
else
    echo "ok   no process left behind"
fi

grade reference-again "$tree/solution" 0
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
