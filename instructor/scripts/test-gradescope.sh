#!/usr/bin/env bash
# The Gradescope autograder as Gradescope runs it (CI; make test-gradescope):
# builds autograder.zip (make-autograder.sh), unpacks it into a root shaped like
# Gradescope's (/autograder/source, submission, results), runs setup.sh once,
# then run_autograder on submissions as students send them, and checks every
# results.json against Gradescope's format (lib/gradescope_results.py):
#   reference   the ten lab files uploaded alone: full marks
#   stubs       a repository (labs/ with the untouched stubs): 0
#   compile     the reference with a compile error in lab 3: lab 3 0, the others full
#   zipped      a zipped folder, my-project/labs/ (and __MACOSX/): full marks
#   hostile     lab 2 reads the solution, writes results.json and the rubric, prints them: no leak, nothing changed
#   ambiguous   lab files in labs/ and backup/labs/: 0, naming both places
#   died        the grader cannot run: run_autograder still writes a valid results.json
#
#   test-gradescope.sh                 a folder as /autograder (AUTOGRADER_ROOT), on this machine's packages
#   test-gradescope.sh --chroot DIR [--suite bookworm|noble|jammy]
#                                      a fresh minbase root (debootstrap, as root; DIR is made and removed) of
#                                      Debian 12 (the default) or Ubuntu 24.04/22.04, Gradescope's base images:
#                                      setup.sh installs every package itself, as on Gradescope
# Prints the time of setup.sh and of each submission; exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/../.."
tree=$(pwd)
chroot_dir= suite=bookworm
usage() { echo "usage: test-gradescope.sh [--chroot DIR [--suite bookworm|noble|jammy]]" >&2; exit 2; }
while [ $# -gt 0 ]; do
    [ $# -ge 2 ] || usage
    case $1 in
    --chroot) chroot_dir=$2 ;;
    --suite) suite=$2 ;;
    *) usage ;;
    esac
    shift 2
done
case $suite in
bookworm) bootstrap=(bookworm "" http://deb.debian.org/debian) ;;
# Ubuntu's keyring is not Debian's: its signatures go unchecked here. CLI11 and stb are in universe.
noble | jammy) bootstrap=(--no-check-gpg --components=main,universe "$suite" "" http://archive.ubuntu.com/ubuntu /usr/share/debootstrap/scripts/jammy) ;;
*) usage ;;
esac

work=$(mktemp -d "${TMPDIR:-/tmp}/test-gradescope.XXXXXX")
mounted=()
cleanup() {
    for mount in ${mounted[@]+"${mounted[@]}"}; do umount -l "$mount" 2> /dev/null || true; done
    if [ -z "${KEEP_WORK:-}" ]; then
        rm -rf "$work"
        [ -z "$chroot_dir" ] || rm -rf --one-file-system "$chroot_dir"
    fi
}
trap cleanup EXIT
seconds() { python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.1f}')" "$1" "$(date +%s.%N)"; }

bash instructor/scripts/make-autograder.sh --out "$work/autograder.zip" > "$work/make-autograder.log"
echo "test-gradescope: $(head -1 "$work/make-autograder.log")"

if [ -n "$chroot_dir" ]; then
    [ "$(id -u)" -eq 0 ] || { echo "test-gradescope: --chroot needs root (debootstrap, chroot)" >&2; exit 2; }
    [ ! -e "$chroot_dir" ] || { echo "test-gradescope: $chroot_dir exists; give a new folder" >&2; exit 2; }
    command -v debootstrap > /dev/null || { echo "test-gradescope: --chroot needs debootstrap (apt-get install debootstrap)" >&2; exit 2; }
    start=$(date +%s.%N)
    for i in "${!bootstrap[@]}"; do [ -n "${bootstrap[$i]}" ] || bootstrap[$i]=$chroot_dir; done
    debootstrap --variant=minbase "${bootstrap[@]}" > "$work/debootstrap.log" 2>&1 ||
        { tail -20 "$work/debootstrap.log"; echo "test-gradescope: debootstrap failed" >&2; exit 1; }
    echo "test-gradescope: a fresh $suite minbase root in $(seconds "$start") s"
    for mount in proc dev; do
        mount --bind "/$mount" "$chroot_dir/$mount"
        mounted+=("$chroot_dir/$mount")
    done
    cp /etc/resolv.conf "$chroot_dir/etc/resolv.conf"
    root=$chroot_dir/autograder inside=/autograder
    run_in_root() { chroot "$chroot_dir" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 bash -c "cd /autograder && $1"; }
else
    root=$work/autograder inside=$root
    run_in_root() { (cd "$root" && AUTOGRADER_ROOT=$root bash -c "$1"); }
fi
# What Gradescope does to make the image: the zip in source/, run_autograder copied beside it.
mkdir -p "$root/source" "$root/submission" "$root/results"
(cd "$root/source" && unzip -q "$work/autograder.zip")
cp "$root/source/run_autograder" "$root/run_autograder"

start=$(date +%s.%N)
if ! run_in_root "bash source/setup.sh" > "$work/setup.log" 2>&1; then
    tail -40 "$work/setup.log"
    echo "test-gradescope: setup.sh failed"
    exit 1
fi
setup_time=$(seconds "$start")
grep '^setup:' "$work/setup.log" | sed 's/^/  /'
echo "test-gradescope: setup.sh took $setup_time s on $(nproc) cores"

failures=0
summary=()
# submit NAME: runs run_autograder on what is in $root/submission, then checks results.json with CONDITIONS.
submit() {
    local name=$1 conditions=$2 start
    rm -rf "$root/results" && mkdir -p "$root/results"
    start=$(date +%s.%N)
    run_in_root "./run_autograder" > "$work/$name.log" 2>&1 || { echo "FAIL $name: run_autograder exited with $?"; failures=$((failures + 1)); }
    summary+=("$(printf '%-10s %6s s  score %s' "$name" "$(seconds "$start")" \
        "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["score"])' "$root/results/results.json" 2> /dev/null || echo none)")")
    cp "$root/results/results.json" "$work/$name.json" 2> /dev/null || true
    if ! python3 instructor/scripts/lib/gradescope_results.py "$root/results/results.json" "$conditions"; then
        echo "FAIL $name (its run_autograder output: $work/$name.log); the tests that lost points:"
        python3 -c 'import json, sys
for t in json.load(open(sys.argv[1])).get("tests", []):
    if t["score"] < t["max_score"]: print("   ", t["name"], t["extra_data"]["status"], t["output"].splitlines()[0][:150])' \
            "$root/results/results.json" 2> /dev/null | head -20 || true
        failures=$((failures + 1))
    fi
    rm -rf "$root/submission" && mkdir -p "$root/submission"
}
labs_of() { python3 -c 'import json,sys; print(sorted({t["extra_data"]["lab"] for t in json.load(open(sys.argv[1]))["tests"]}))' "$1"; }
lab_points='
def points(lab, key="score"): return round(sum(t[key] for t in tests if t.get("extra_data", {}).get("lab") == lab), 2)
labs = sorted({t["extra_data"]["lab"] for t in tests})'

# The lab files uploaded alone (Gradescope's upload: the files at the top).
cp solution/[0-9]*.cpp "$root/submission/"
submit reference 'ok(results["score"] == 100, "score %s, expected 100" % results["score"])
ok(len(tests) > 250, "only %d tests" % len(tests))'

# A repository with the untouched stubs (Gradescope's GitHub submission: a tree with labs/).
mkdir -p "$root/submission/labs" "$root/submission/.git"
cp labs/*.cpp "$root/submission/labs/"
cp README.md CMakeLists.txt "$root/submission/"
submit stubs 'ok(results["score"] == 0, "score %s, expected 0" % results["score"])'

# A compile error in lab 3.
cp solution/[0-9]*.cpp "$root/submission/"
python3 instructor/scripts/lib/inject.py "$root/submission" 03_blinn_phong blinn_phong 'int oops = undeclared_variable;'
submit compile "$lab_points"'
ok(points("03_blinn_phong") == 0, "lab 3 earned points")
ok(all(points(lab) == points(lab, "max_score") for lab in ("01_ray_casting", "02_shadows", "10_bvh")), "a lab without the error lost points")
ok("undeclared_variable" in results["output"], "the compiler error is not shown (once, at the top)")'

# A zipped folder, as Gradescope unzips it, with what macOS adds.
mkdir -p "$root/submission/my-project/labs" "$root/submission/__MACOSX/my-project/labs"
cp solution/[0-9]*.cpp "$root/submission/my-project/labs/"
echo junk > "$root/submission/__MACOSX/my-project/labs/._01_ray_casting.cpp"
submit zipped 'ok(results["score"] == 100, "score %s, expected 100" % results["score"])'

# A hostile lab 2 that has read this script: it prints the solution and the
# rubric, tries to write results.json and the rubric, then answers wrongly.
cp solution/[0-9]*.cpp "$root/submission/"
rubric_before=$(sha256sum "$root/source/whitted/instructor/rubric.json")
python3 instructor/scripts/lib/inject.py "$root/submission" 02_shadows is_lit "#include <cstdio>
{ for (const char* path : {\"$inside/source/whitted/solution/02_shadows.cpp\", \"$inside/source/whitted/instructor/rubric.json\"}) {
    if (std::FILE* in = std::fopen(path, \"r\")) { char line[256]; while (std::fgets(line, sizeof line, in)) std::printf(\"LEAK %s\", line); std::fclose(in); }
    else std::printf(\"HOSTILE could not read %s\\n\", path); }
  for (const char* path : {\"$inside/results/results.json\", \"$inside/source/whitted/instructor/rubric.json\"})
    if (std::FILE* out = std::fopen(path, \"w\")) { std::fputs(\"{\\\"score\\\": 100}\", out); std::fclose(out); }
  return false; }"
submit hostile "$lab_points"'
ok(results["score"] < 100, "a wrong lab 2 got full marks")
ok(points("02_shadows") < points("02_shadows", "max_score"), "lab 2 lost nothing")
ok("LEAK" not in json.dumps(results), "the solution or the rubric reached results.json")
ok(any("HOSTILE could not read" in t["output"] for t in tests), "the attack did not run (no output of it is shown)")'
[ "$rubric_before" = "$(sha256sum "$root/source/whitted/instructor/rubric.json")" ] ||
    { echo "FAIL hostile: the rubric changed"; failures=$((failures + 1)); }

# Lab files in two places: not guessed between.
mkdir -p "$root/submission/labs" "$root/submission/backup/labs"
cp solution/[0-9]*.cpp "$root/submission/labs/"
cp solution/02_shadows.cpp "$root/submission/backup/labs/"
submit ambiguous 'ok(results["score"] == 0, "graded anyway")
ok("labs/ (10 files) and backup/labs/ (1 file)" in output, "the places are not named: " + output)'

# The grader cannot run at all (here: its program is gone): run_autograder still answers.
mv "$root/source/whitted/build/whitted" "$root/source/whitted/build/whitted.away"
cp solution/[0-9]*.cpp "$root/submission/"
submit died 'ok(results["score"] == 0, "a score without a grader")
ok("not your fault" in output, "the student is not told: " + output)'
mv "$root/source/whitted/build/whitted.away" "$root/source/whitted/build/whitted"

echo
echo "setup.sh: $setup_time s; run_autograder per submission:"
printf '  %s\n' "${summary[@]}"
if [ "$failures" -ne 0 ]; then
    echo "test-gradescope: $failures check(s) failed (KEEP_WORK=1 keeps $work)"
    exit 1
fi
echo "test-gradescope: all checks passed"
