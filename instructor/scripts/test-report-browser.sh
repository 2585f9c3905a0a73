#!/usr/bin/env bash
# Opens the grader's report.html in a real browser (CI, after test-grader;
# `make test-report`). Grades the reference solution, then loads its
# report.html in headless Chromium with the network unusable and checks, in the
# page (instructor/scripts/lib/report-check.js):
#   images    every <img> loaded, with naturalWidth > 0, and is laid out;
#   count     as many pictures as results.json's image tests need (4 each:
#             yours, reference, difference, heat map);
#   fetches   nothing fetched or attempted but data: URIs and the report itself
#             (the Resource Timing API);
#   links     no src, href or CSS url() pointing anywhere but data: or #.
# It saves a screenshot of the whole page to $BUILD_DIR/report-screenshot.png.
# Self-check: the same checks on a broken copy of the report (a corrupted
# picture, an <img> from https://example.com, a CSS url(http://...)) must
# report each problem. Prints a line per check; exits non-zero on any failure.
# Needs chromium: bash scripts/install-deps.sh --browser.
set -euo pipefail
cd "$(dirname "$0")/../.."
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    echo "test-report-browser: chromium is not installed; run bash scripts/install-deps.sh --browser" >&2
    exit 1
fi
# shellcheck source=lib/grading-checks.sh
source instructor/scripts/lib/grading-checks.sh test-report-browser
screenshot="$tree/$build/report-screenshot.png"
width=1280

# The network is unusable: no host name resolves, every connection goes to a
# proxy on a closed local port, and, where one can be made, the browser runs in
# a network namespace of its own, which has no network at all.
netns=()
fence="no name resolves, every connection goes to a closed port"
if unshare --net true 2> /dev/null; then
    netns=(unshare --net)
    fence="$fence, a network namespace without network"
fi

# browse NAME ARGS...: headless Chromium with a throwaway profile; output in $work/NAME.{out,err}.
# --no-sandbox: Chromium's own sandbox does not start as root nor in most
# containers, and the pages are the grader's own.
browse() {
    local name=$1 start status=0
    shift
    start=$(date +%s.%N)
    timeout 120 ${netns[@]+"${netns[@]}"} "$browser" --headless --no-sandbox --user-data-dir="$work/profile-$name" \
        --host-resolver-rules="MAP * ~NOTFOUND" --proxy-server="http://127.0.0.1:9" --proxy-bypass-list="<-loopback>" \
        --disable-background-networking --disable-component-update --disable-sync --disable-extensions \
        --no-first-run --no-default-browser-check --disable-gpu --hide-scrollbars --mute-audio \
        --enable-logging=stderr --virtual-time-budget=10000 "$@" > "$work/$name.out" 2> "$work/$name.err" || status=$?
    summary+=("$(printf '%-16s %6s s  exit %d' "chromium $name" "$(python3 -c "print(f'{$(date +%s.%N) - $start:.1f}')")" "$status")")
    return "$status"
}

# verdict NAME REPORT: runs the checker on a copy of REPORT; its findings go to $work/NAME.verdict.
verdict() {
    local name=$1 report=$2
    python3 - "$report" "$work/$name.html" instructor/scripts/lib/report-check.js <<'EOF'
import re, sys
report, copy, checker = sys.argv[1:]
html = open(report, encoding="utf-8").read()
head = re.search(r"<head[^>]*>", html)
if not head: sys.exit(f"test-report-browser: {report} has no <head>")
open(copy, "w", encoding="utf-8").write(html[:head.end()] + "<script>" + open(checker).read() + "</script>" + html[head.end():])
EOF
    browse "$name" --window-size="$width,1000" --dump-dom "file://$work/$name.html" || true
    python3 - "$work/$name.out" > "$work/$name.verdict" <<'EOF'
import html, re, sys
found = re.findall(r'<pre id="report-check">(.*?)</pre>', open(sys.argv[1], encoding="utf-8", errors="replace").read(), re.S)
print(html.unescape(found[-1]).strip() if found else "")
EOF
}

# judge NAME EXPECTED_IMAGES [SELF_CHECK]: one line per check of $work/NAME.verdict;
# with SELF_CHECK, each planted problem must be reported instead.
judge() {
    python3 - "$work/$1.verdict" "$2" "${3:-}" "$work/$1.err" <<'EOF' || failures=$((failures + $?))
import sys
verdict, expected, self_check, errors = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
lines = open(verdict).read().splitlines()
found = {}
for line in lines:
    kind, _, rest = line.partition(" ")
    found.setdefault(kind, []).append(rest)
failed = 0
def report(good, text, details=()):
    global failed
    print(("ok   " if good else "FAIL ") + text)
    for detail in [] if good else list(details)[:5]: print("       " + detail)
    failed += not good
if "done" not in found:
    log = [line for line in open(errors, errors="replace").read().splitlines() if "dbus" not in line]
    report(False, "the checker did not finish in the browser; the browser said:", ([l for l in log if ":CONSOLE" in l] or log)[-5:])
    sys.exit(failed)
total, loaded, shown = (int(number) for number in found["images"][0].split()[0::2])
problems = {kind: found.get(kind, []) for kind in ("image-failed", "fetch", "link", "css")}
if not self_check:
    report(loaded == total and not problems["image-failed"], f"images: {loaded} of {total} loaded, naturalWidth > 0", problems["image-failed"])
    report(shown == total, f"layout: {shown} of {total} pictures shown in a box of some size")
    report(total == expected, f"count: {total} pictures in the page, {expected} expected (4 per image test in results.json)")
    report(not problems["fetch"], "fetches: nothing but data: and the report itself (Resource Timing)", problems["fetch"])
    report(not problems["link"] and not problems["css"], "links: no src, href or CSS url() outside data: and #", problems["link"] + problems["css"])
else:
    def has(kind, text): return any(text in finding for finding in problems[kind])
    report(has("image-failed", "data:image/png"), "self-check: the corrupted picture is reported as not loaded")
    report(has("fetch", "https://example.com/x.png") and has("link", "img src: https://example.com/x.png"),
           "self-check: <img src=\"https://example.com/x.png\"> is reported as fetched and as a link")
    report(has("fetch", "http://example.com/background.png") and has("css", "http://example.com/background.png"),
           "self-check: CSS url(http://example.com/background.png) is reported as fetched and as a url()")
    report(total == expected + 1, f"self-check: the extra picture is counted ({total} in the page, {expected} expected)")
sys.exit(failed)
EOF
}

# The reference solution, graded as a student tree.
mkdir -p "$work/reference-tree"
cp -r solution "$work/reference-tree/labs"
grade reference "$work/reference-tree" 0
check reference 'ok(results["score"] == 100, "score " + str(results["score"]) + ", expected 100")
ok(all(t["status"] == "passed" for t in results["tests"]), "a test did not pass")'
report="$work/reference/report.html"

# The expected number of pictures comes from results.json, not from the page
# (counting <img in report.html would miss a card that lost a picture): 4 for
# each image test that is not hidden, as all ran to the comparison (the
# reference passes them); hidden tests show none (their scene is the secret).
expected=$(python3 -c '
import json, sys
tests = [t for t in json.load(open(sys.argv[1]))["tests"] if t.get("extra_data", {}).get("image") and t["visibility"] != "hidden"]
print(4 * len(tests))' "$work/reference/results.json")

echo "chromium: $("$browser" --version 2> /dev/null | head -1); network: $fence"
verdict page "$report"
judge page "$expected"

# The screenshot, of the untouched report, as tall as the page.
height=$(sed -n 's/^height //p' "$work/page.verdict")
whole="the whole page"
[ -n "$height" ] || { height=2000; whole="the top: the page's height is unknown"; }
rm -f "$screenshot"
browse shot --screenshot="$screenshot" --window-size="$width,$height" "file://$report" || true
size=$(python3 -c '
import struct, sys
data = open(sys.argv[1], "rb").read(24)
print("%dx%d" % struct.unpack(">II", data[16:24]) if data[:8] == b"\x89PNG\r\n\x1a\n" else "none")' "$screenshot" 2> /dev/null || echo none)
if [ "$size" = "${width}x$height" ]; then
    echo "ok   screenshot: $screenshot ($size, $whole)"
else
    echo "FAIL screenshot: $screenshot is $size, expected ${width}x$height"
    grep -v dbus "$work/shot.err" | tail -5
    failures=$((failures + 1))
fi

# Self-check: a broken copy of the report, whose every problem must be reported.
python3 - "$report" "$work/broken.html" <<'EOF'
import base64, re, sys
html = open(sys.argv[1], encoding="utf-8").read()
picture = re.search(r'src="data:image/png;base64,([^"]*)"', html)
html = html[:picture.start(1)] + base64.b64encode(b"this is not a PNG file" * 8).decode() + html[picture.end(1):]
html = html.replace("</style>", "h1{background-image:url(http://example.com/background.png)}</style>", 1)
html = re.sub(r"(<body[^>]*>)", r'\1<img alt="outside" src="https://example.com/x.png">', html, count=1)
open(sys.argv[2], "w", encoding="utf-8").write(html)
EOF
verdict broken "$work/broken.html"
judge broken "$expected" self-check

echo
echo "times (2 jobs):"
printf '  %s\n' "${summary[@]}"
if [ "$failures" -ne 0 ]; then
    echo "test-report-browser: $failures check(s) failed"
    exit 1
fi
echo "test-report-browser: all checks passed"
