"""Drives `whitted explore` in headless Chromium as a student would (test-explore-browser.sh).

    explore_check.py check CHROMIUM HANDOUT WORK
        In HANDOUT (an exported handout, every lab done, built in HANDOUT/build): opens the page of
        scenes/05_refraction.p3f; clicks a pixel on the glass ball and checks the tree shown against
        `whitted trace --json` of that pixel; shows the normal pass and the difference from the goal (which must
        pass); breaks labs/05_refraction.cpp and waits for its error with its line; mends it and waits for the new
        picture. Prints a line per check; exits non-zero on the first failure.
    explore_check.py screenshot CHROMIUM WHITTED SCENE X Y OUT
        A picture of the page for SCENE with pixel (X, Y)'s tree open (docs/labs/debugging.md)."""
import json
import math
import os
import re
import select
import signal
import subprocess
import sys
import time
import urllib.error
import urllib.request

sys.path.insert(0, os.path.dirname(__file__))
from cdp import Browser  # noqa: E402

PICTURE = "document.getElementById('picture')"


def say(text):
    print(f"test-explore-browser: {text}", flush=True)


def start_explore(whitted, scene, cwd, log):
    """Starts `whitted explore SCENE` in a session of its own; returns the process and the link it prints."""
    process = subprocess.Popen([whitted, "explore", scene], cwd=cwd, stdout=subprocess.PIPE, stderr=log, text=True,
                               start_new_session=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        ready, _, _ = select.select([process.stdout], [], [], max(0.0, deadline - time.monotonic()))
        line = process.stdout.readline() if ready else ""
        if not line:
            break
        found = re.search(r"(http://127\.0\.0\.1:\d+/\?token=[0-9a-f]{32})", line)
        if found:
            return process, found.group(1)
    stop_explore(process)
    raise SystemExit("test-explore-browser: whitted explore printed no link")


def stop_explore(process):
    """Ctrl-C's signal to explore, which ends its session and removes its scratch folder; then its whole group."""
    process.send_signal(signal.SIGTERM)
    try:
        process.wait(timeout=30)
    except subprocess.TimeoutExpired:
        pass
    try:
        os.killpg(process.pid, signal.SIGKILL)  # anything it left running (a render, a build)
    except ProcessLookupError:
        pass
    process.wait()


def wait_for_picture(browser, view="picture", after=0, timeout=120):
    """Waits until the page shows the whole picture (not the preview) of `view`, newer than version `after`."""
    return browser.wait_for(
        f"(() => {{ const shown = ({PICTURE}.dataset.shown || '').split(' ');"
        f" return shown[0] === '{view}' && Number(shown[1]) > {after}"
        " && document.getElementById('status').dataset.activity === 'idle' && Number(shown[1]) === Number(document.body.dataset.version)"
        " && !document.getElementById('status').textContent.includes('preview') ? Number(shown[1]) : 0; })()",
        timeout=timeout, what=f"the {view} to show")


def click_pixel(browser, x, y, width, height):
    # Inside the picture's border, as a student's click lands.
    left, top, w, h = browser.evaluate(f"(() => {{ const p = {PICTURE}, r = p.getBoundingClientRect();"
                                       " return [r.left + p.clientLeft, r.top + p.clientTop, p.clientWidth, p.clientHeight]; })()")
    # Chromium gives the page a click's coordinates as whole numbers (truncated): click at the first whole
    # coordinate inside the pixel, as a student's mouse would land.
    def inside(start, index, size, count):
        low = start + index * size / count
        return math.ceil(low) + 0.25
    browser.click(inside(left, x, w, width), inside(top, y, h, height))


DOM_TREE = """(() => {
  const walk = (li) => ({ kind: li.querySelector(':scope > .kind').textContent,
    lines: [...li.querySelectorAll(':scope > div')].map((d) => d.textContent),
    children: [...li.querySelectorAll(':scope > ul > li')].map(walk) });
  return walk(document.querySelector('#tree > ul > li'));
})()"""


def numbers(text):
    return [float(n) for n in re.findall(r"-?\d+\.\d+", text)]


def compare_trees(dom, ray, path="eye"):
    """Each ray of `ray` (whitted trace --json) against the page's item `dom`; returns the rays compared."""
    if dom["kind"] != ray["kind"] + " ray":
        raise SystemExit(f"test-explore-browser: {path}: the page shows a {dom['kind']}, trace a {ray['kind']} ray")
    text = "\n".join(dom["lines"])
    if "hit" in ray:
        line = next((l for l in dom["lines"] if l.startswith("hit ")), "")
        if ray["hit"]["object"] not in line or abs(numbers(line)[-1] - ray["hit"]["t"]) > 6e-4:
            raise SystemExit(f"test-explore-browser: {path}: the page says '{line}', trace: {ray['hit']['object']} at t = {ray['hit']['t']}")
    if "color" in ray:
        line = next((l for l in dom["lines"] if l.startswith("colour ")), "")
        shown = numbers(line)[:3]
        if len(shown) != 3 or any(abs(a - b) > 6e-4 for a, b in zip(shown, ray["color"])):
            raise SystemExit(f"test-explore-browser: {path}: the page's '{line}' against trace's colour {ray['color']}")
    if "check" in ray and (ray["check"]["law"] not in text or ("holds" in text) != ray["check"]["agrees"]):
        raise SystemExit(f"test-explore-browser: {path}: the page's check '{text}' against trace's {ray['check']}")
    if ray["kind"] == "shadow" and ("blocked" in text) != ray["blocked"]:
        raise SystemExit(f"test-explore-browser: {path}: the page's '{text}', trace's blocked = {ray['blocked']}")
    children = ray.get("children", [])
    if len(dom["children"]) != len(children):
        raise SystemExit(f"test-explore-browser: {path}: the page shows {len(dom['children'])} rays under it, trace {len(children)}")
    return 1 + sum(compare_trees(d, r, f"{path}/{r['kind']}") for d, r in zip(dom["children"], children))


def kinds(ray):
    return [ray["kind"]] + [k for child in ray.get("children", []) for k in kinds(child)]


def check(chromium, handout, work):
    whitted = os.path.join(handout, "build", "whitted")
    scene = "scenes/05_refraction.p3f"
    log = open(os.path.join(work, "explore.log"), "w")
    started = time.monotonic()
    process, url = start_explore(whitted, scene, handout, log)
    browser = None
    try:
        browser = Browser(chromium, os.path.join(work, "profile"))
        try:
            urllib.request.urlopen(url.split("?")[0] + "state", timeout=10)
            raise SystemExit("test-explore-browser: /state answered without the token")
        except urllib.error.HTTPError as refused:
            if refused.code != 403:
                raise SystemExit(f"test-explore-browser: /state without the token: {refused.code}, not 403")
        say("ok  a request without the token gets 403")

        browser.open(url)
        version = wait_for_picture(browser)
        state = json.loads(urllib.request.urlopen(url.replace("/?", "/state?"), timeout=10).read())
        width, height, stage = state["width"], state["height"], state["stage"]
        say(f"ok  the picture shows ({width}x{height}, stage {stage}) {time.monotonic() - started:.1f} s after the start")

        # A pixel on the glass ball: its eye ray is refracted (found with trace, then clicked).
        for x, y in [(110, 125), (100, 120), (120, 130), (105, 110)]:
            traced = json.loads(subprocess.run([whitted, "trace", scene, "--pixel", str(x), str(y), "--stage", str(stage), "--json", "-"],
                                               cwd=handout, check=True, capture_output=True, text=True).stdout)
            if "refracted" in kinds(traced["ray"]):
                break
        else:
            raise SystemExit("test-explore-browser: no pixel tried is on the glass")
        click_pixel(browser, x, y, width, height)
        browser.wait_for(f"document.getElementById('tree').dataset.pixel === '{x} {y} 0' && !document.getElementById('rays').hidden"
                         " && document.getElementById('rays').naturalWidth > 0", what="the tree of the pixel clicked")
        compared = compare_trees(browser.evaluate(DOM_TREE), traced["ray"])
        say(f"ok  pixel ({x}, {y}) on the glass: the page's tree is trace --json's ({compared} rays, "
            f"{kinds(traced['ray']).count('refracted')} refracted), with its picture of the rays")

        browser.click_element("#view-normal")
        wait_for_picture(browser, "normal")
        if browser.evaluate(f"{PICTURE}.naturalWidth") != width:
            raise SystemExit("test-explore-browser: the normal pass is not the picture's size")
        say("ok  the normal pass shows")
        browser.click_element("#view-difference")
        wait_for_picture(browser, "difference")
        passed = browser.wait_for("document.getElementById('numbers').dataset.passed", what="the difference's numbers")
        if passed != "true":
            raise SystemExit("test-explore-browser: the reference labs' picture differs from the goal: "
                             + browser.evaluate("document.getElementById('numbers').innerText"))
        say("ok  the difference from the goal shows, with its numbers: " + browser.evaluate("document.getElementById('numbers').innerText").splitlines()[-1])

        lab = os.path.join(handout, "labs", "05_refraction.cpp")
        original = open(lab, encoding="utf-8").read()
        broken = original + ("" if original.endswith("\n") else "\n") + "this line is not C++\n"
        line = broken.count("\n")
        saved = time.monotonic()
        with open(lab, "w", encoding="utf-8") as out:
            out.write(broken)
        shown = browser.wait_for("[...document.querySelectorAll('#problems .compile-error')].map((e) => e.textContent).join('\\n')",
                                 timeout=180, what="the compile error")
        if not re.search(rf"05_refraction\.cpp:{line}(:\d+)?: ", shown):
            raise SystemExit(f"test-explore-browser: the error shown does not name 05_refraction.cpp:{line}: {shown}")
        if not browser.evaluate(f"{PICTURE}.naturalWidth > 0"):
            raise SystemExit("test-explore-browser: the last good picture is gone")
        say(f"ok  a lab that does not compile: '{shown.splitlines()[0]}' {time.monotonic() - saved:.1f} s after the save; the last picture stays")

        browser.click_element("#view-picture")
        saved = time.monotonic()
        with open(lab, "w", encoding="utf-8") as out:
            out.write(original)
        new_version = wait_for_picture(browser, "picture", after=version, timeout=180)
        if browser.evaluate("document.getElementById('problems').textContent.includes('do not build')"):
            raise SystemExit("test-explore-browser: the compile error is still shown after the fix")
        say(f"ok  mended: the new picture (version {new_version}) {time.monotonic() - saved:.1f} s after the save")
    finally:
        if browser:
            browser.close()
        stop_explore(process)


def screenshot(chromium, whitted, scene, x, y, out, work):
    log = open(os.path.join(work, "explore.log"), "w")
    process, url = start_explore(whitted, scene, os.getcwd(), log)
    browser = None
    try:
        browser = Browser(chromium, os.path.join(work, "profile"), width=1500, height=1250)
        browser.open(url)
        wait_for_picture(browser)
        state = json.loads(urllib.request.urlopen(url.replace("/?", "/state?"), timeout=10).read())
        click_pixel(browser, x, y, state["width"], state["height"])
        browser.wait_for("!document.getElementById('rays').hidden && document.getElementById('rays').complete"
                         " && document.getElementById('rays').naturalWidth > 0", what="the tree")
        time.sleep(0.5)
        browser.screenshot(out)
    finally:
        if browser:
            browser.close()
        stop_explore(process)


if __name__ == "__main__":
    if sys.argv[1] == "check":
        check(*sys.argv[2:5])
    elif sys.argv[1] == "screenshot":
        chromium, whitted, scene, x, y, out = sys.argv[2:8]
        screenshot(chromium, whitted, scene, int(x), int(y), out, os.environ.get("TMPDIR", "/tmp"))
    else:
        raise SystemExit(__doc__)
