#!/usr/bin/env bash
# Writes the student handout to a folder: the instructor's tree without
# solution/ and instructor/, configured as a handout (cmake/WhittedMode.cmake).
set -euo pipefail
out=${1:?usage: export-handout.sh OUT}
cd "$(dirname "$0")/../.."
if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ]; then
    echo "export-handout: $out exists and is not empty; choose a new folder" >&2
    exit 2
fi

# What stays with the instructor: the reference, everything under instructor/
# (hidden tests, mistakes, grader, benchmark, their scripts and documents), CI,
# and the instructor's README (the handout has its own).
private='^(solution/|instructor/|\.ci/|README\.md$)'

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
cp instructor/docs/handout/README.md "$out/README.md"
# Its presets: the student's builds only (the others need instructor/): release, asan and each lab's (and their base).
python3 - "$out/CMakePresets.json" <<'PRESETS'
import json, re, sys
path = sys.argv[1]
presets = json.load(open(path))
for kind in ("configurePresets", "buildPresets", "testPresets"):
    presets[kind] = [p for p in presets.get(kind, []) if p["name"] in ("release", "asan") or re.fullmatch(r"lab([0-9]+|-base)", p["name"])]
json.dump(presets, open(path, "w"), indent=2)
open(path, "a").write("\n")
PRESETS
# The handout's build mode: the student's tree (see cmake/WhittedMode.cmake).
sed -i 's/^set(WHITTED_DEFAULT_MODE instructor)$/set(WHITTED_DEFAULT_MODE handout)/' "$out/cmake/WhittedMode.cmake"
grep -q '^set(WHITTED_DEFAULT_MODE handout)$' "$out/cmake/WhittedMode.cmake" ||
    { echo "export-handout: could not set the handout's build mode in cmake/WhittedMode.cmake" >&2; exit 1; }
# The GitHub Classroom workflow (the handout as a template repository): one graded step per
# public rule of the rubric, for every lab of the lab table (instructor/scripts/classroom-workflow.py).
python3 instructor/scripts/classroom-workflow.py . "$out/.github/workflows/classroom.yml"
# The Makefile's header lists instructor commands and documents; the student's lists what the handout has.
{ cat instructor/docs/handout/makefile-header.txt; sed '1,/^[^#]/{/^#/d}' Makefile; } > "$out/Makefile"
echo "handout written to $out ($(find "$out" -type f | wc -l) files)"
echo "check it: cd $out && make test   (every lab's tests fail until its stubs are replaced)"
