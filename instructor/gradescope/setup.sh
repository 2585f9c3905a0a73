#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image
# (the zip unpacked in /autograder/source; make-autograder.sh made the zip).
# It installs what grading needs, builds only the grading parts of the tree
# (the whitted command and the checkers, not the ~1000 tests), closes the tree
# to other users (the student's code runs as one, and the tree holds the
# answers), and grades the reference solution once: an autograder that cannot
# give the reference full marks fails here, at upload, not on the students.
# AUTOGRADER_ROOT replaces /autograder (instructor/scripts/test-gradescope.sh).
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
tree=$root/source/whitted
start=$SECONDS
step() { printf 'setup: %4d s  %s\n' $((SECONDS - start)) "$*"; }

step "installing the packages (scripts/install-deps.sh; bubblewrap if the image has it)"
bash "$tree/scripts/install-deps.sh" --sandbox
step "configuring a Release build"
cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release > "$root/source/cmake-configure.log" 2>&1 ||
    { tail -30 "$root/source/cmake-configure.log"; echo "setup: configuring failed (above)" >&2; exit 1; }
step "building the grader and the checkers on $(nproc) cores"
cmake --build "$tree/build" -j"$(nproc)" --target whitted grading_parts > "$root/source/cmake-build.log" 2>&1 ||
    { grep -m 20 -B2 -A8 'error' "$root/source/cmake-build.log" || tail -40 "$root/source/cmake-build.log"; echo "setup: building failed (above)" >&2; exit 1; }
# The student's code runs as another user: it must not read the solution, the
# hidden tests, the rubric or the checkers (see "Fences" in grading.md).
chmod -R o-rwx "$root/source"
step "self-check: grading the reference solution"
check=$(mktemp -d "$root/self-check.XXXXXX")
if "$tree/build/whitted" grade "$tree/solution" --out "$check" --jobs "$(nproc)" -q; then
    rm -rf "$check"
else
    code=$?
    echo "setup: the reference solution did not get full marks (exit code $code); the table above says where" >&2
    exit 1
fi
step "done: the autograder is ready"
