#!/usr/bin/env bash
# Writes the student handout to a folder: the instructor's tree without the
# reference solution, the hidden tests, the mistake catalogue, the grading
# rubric and the instructor-only scripts and documents.
set -euo pipefail
out=${1:?usage: export-handout.sh OUT}
cd "$(dirname "$0")/.."
if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ]; then
    echo "export-handout: $out exists and is not empty; choose a new folder" >&2
    exit 2
fi

# What stays with the instructor.
private='^(solution/|tests/hidden/|tests/fuzz/|scripts/fuzz\.sh$|scripts/lib/|docs/robustness\.md$|tests/mistakes/|tests/calibration/|tests/solution/|tests/grader/|tests/link/|tests/rubric\.json$|scripts/(prove-tests|test-grader|test-report-browser|test-hostile|export-handout|test-handout|calibrate-gate|render-gallery)\.sh$|docs/instructors\.md$|docs/grading\.md$|docs/benchmark\.md$|framework/bench/embree_|tests/bench/embree_|docs/images/bench_chart\.svg$|docs/handout/|\.ci/|README\.md$)'

if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    files=$(git ls-files --cached --others --exclude-standard)
else
    files=$(find . -type f ! -path './build*' ! -path './.git/*' | sed 's|^\./||')
fi
mkdir -p "$out"
printf '%s\n' "$files" | grep -vE "$private" | while IFS= read -r file; do
    [ -f "$file" ] || continue
    mkdir -p "$out/$(dirname "$file")"
    cp -p "$file" "$out/$file"
done
cp docs/handout/README.md "$out/README.md"
# The Makefile's header lists instructor commands and documents; the student's lists what the handout has.
{ cat docs/handout/makefile-header.txt; sed '1,/^[^#]/{/^#/d}' Makefile; } > "$out/Makefile"
echo "handout written to $out ($(find "$out" -type f | wc -l) files)"
echo "check it: cd $out && make test   (every lab's tests fail until its stubs are replaced)"
