#!/usr/bin/env bash
# Writes the Gradescope autograder zip (make gradescope): setup.sh and
# run_autograder at the top (instructor/gradescope/), autograder.conf with the
# choices below, and the instructor tree in whitted/ without what grading does
# not need (documents, the benchmark, CI).
#   make-autograder.sh [--out FILE] [--hidden-visibility hidden|after_due_date|after_published|visible]
#                      [--timeout SECONDS_PER_TEST] [--budget SECONDS_PER_SUBMISSION]
set -euo pipefail
cd "$(dirname "$0")/../.."
out=autograder.zip visibility=hidden timeout=20 budget=600
usage() { echo "usage: make-autograder.sh [--out FILE.zip] [--hidden-visibility hidden|after_due_date|after_published|visible] [--timeout S] [--budget S]" >&2; exit 2; }
while [ $# -gt 0 ]; do
    [ $# -ge 2 ] || usage
    case $1 in
    --out) out=$2 ;;
    --hidden-visibility) visibility=$2 ;;
    --timeout) timeout=$2 ;;
    --budget) budget=$2 ;;
    *) usage ;;
    esac
    shift 2
done
case $visibility in hidden | after_due_date | after_published | visible) ;; *)
    echo "make-autograder: --hidden-visibility must be hidden, after_due_date, after_published or visible, not '$visibility'" >&2; exit 2 ;;
esac
[[ $timeout =~ ^[0-9]+$ ]] && [ "$timeout" -ge 1 ] && [ "$timeout" -le 600 ] ||
    { echo "make-autograder: --timeout is whole seconds per test, 1 to 600, not '$timeout'" >&2; exit 2; }
[[ $budget =~ ^[0-9]+$ ]] && [ "$budget" -ge 60 ] && [ "$budget" -le 7200 ] ||
    { echo "make-autograder: --budget is whole seconds per submission, 60 to 7200, not '$budget'" >&2; exit 2; }
case $out in *.zip) ;; *) echo "make-autograder: --out must end in .zip, not '$out'" >&2; exit 2 ;; esac
[ -d "$(dirname "$out")" ] || { echo "make-autograder: --out: no such folder: $(dirname "$out")" >&2; exit 2; }

# What grading does not need: documents (the handouts' pictures are most of the
# bytes), the benchmark, CI, the instructor's README.
skip='^(\.ci/|\.github/|docs/|instructor/docs/|instructor/bench/|instructor/tests/bench/|README\.md$)'
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    files=$(git ls-files --cached --others --exclude-standard)
else
    files=$(find . -type f ! -path './build*' ! -path './.git/*' | sed 's|^\./||')
fi
printf '%s\n' "$files" | grep -vE "$skip" | while IFS= read -r file; do [ -f "$file" ] && printf '%s\n' "$file"; done > "$out.files"

python3 - "$out" "$out.files" "$visibility" "$timeout" "$budget" <<'ZIP'
import os, sys, zipfile
out, listing, visibility, timeout, budget = sys.argv[1:]
conf = ("# Written by make-autograder.sh; run_autograder reads it.\n"
        f"HIDDEN_VISIBILITY={visibility}\nTEST_TIMEOUT={timeout}\nBUDGET={budget}\n")
def add(archive, name, data, executable=False):
    info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))  # the same tree gives the same bytes
    info.external_attr = (0o755 if executable else 0o644) << 16
    info.compress_type = zipfile.ZIP_DEFLATED
    archive.writestr(info, data)
with zipfile.ZipFile(out + ".part", "w") as archive:
    for script in ("setup.sh", "run_autograder"):
        add(archive, script, open(f"instructor/gradescope/{script}", "rb").read(), executable=True)
    add(archive, "autograder.conf", conf)
    for path in sorted(open(listing).read().split("\n")):
        if path:
            add(archive, "whitted/" + path, open(path, "rb").read(), os.access(path, os.X_OK))
os.replace(out + ".part", out)
ZIP
rm -f "$out.files"
cat <<DONE
wrote $out ($(du -k "$out" | cut -f1) KiB): setup.sh, run_autograder, autograder.conf and the instructor tree in whitted/
On Gradescope, in the programming assignment's Configure Autograder page:
  - Base image: Ubuntu 24.04, Ubuntu 22.04 or Debian 12 (each checked with test-gradescope.sh --chroot); upload $out.
    Building the image runs setup.sh: 3-4 minutes on 2 idle cores, ending with the reference solution graded at full marks.
  - Autograder timeout: at least $((budget + 180)) s (each submission has a budget of $budget s, $timeout s a test; most take 10-20 s).
  - Points: 100, as instructor/rubric.json gives them (hidden tests: visibility $visibility).
  - Submission method: upload and/or GitHub. Students may upload the lab files, a zip of labs/ or of the
    project, or their repository: the grader finds the lab files at the top, in labs/ or one folder down.
Check it first on this machine: bash instructor/scripts/test-gradescope.sh (a root shaped like Gradescope's).
DONE
