// The page `whitted explore` serves: plain HTML, CSS and JavaScript, no build step, nothing fetched from
// elsewhere. It asks for the session's state twice a second (GET /state) and shows the newest picture, the
// build's errors or the render's message; buttons switch to the goal picture, the heat map of the difference
// and the diagnostic passes. A click on a pixel shows its ray tree (GET /tree) and its rays drawn over the
// scene and from the side (GET /tree.png). In two string literals: MSVC refuses one of over 16 KB.
#include "explore/explore_page.hpp"

namespace whitted {

std::string explore_page() {
    static const char* const head = R"PAGE(<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>whitted explore</title>
<style>
body { font: 14px/1.4 system-ui, sans-serif; margin: 1em; background: #1e1e1e; color: #ddd; }
h1 { font-size: 1.3em; margin: 0 0 .3em; } h2 { font-size: 1.1em; margin: .2em 0; }
#layout { display: flex; gap: 1.5em; align-items: flex-start; }
#main { flex: 0 0 auto; max-width: 660px; }
#picture { image-rendering: pixelated; cursor: crosshair; border: 1px solid #555; display: block; }
#views button { margin: 0 .2em .3em 0; } button.on { background: #557; color: #fff; }
#tree ul { list-style: none; padding-left: 1.2em; border-left: 1px dotted #666; margin: 0; }
#tree > ul { padding-left: 0; border: 0; } #tree li { margin: .25em 0; }
#side { flex: 1 1 28em; max-width: 50em; } #tree { max-height: 78vh; overflow: auto; }
#rays { max-width: 100%; border: 1px solid #555; display: block; margin-top: .5em; }
#frame { position: relative; display: inline-block; }
#marker { position: absolute; border: 2px solid #f0f; border-radius: 50%; pointer-events: none; }
.kind { font-weight: bold; } .eye { color: #fff; } .reflected { color: #4dd; } .refracted { color: #5d5; }
.shadow { color: #dd5; } .blocked { color: #e55; } .bad { color: #f66; font-weight: bold; } .good { color: #6d6; }
.error { color: #f88; white-space: pre-wrap; font-family: monospace; } .muted { color: #999; }
.where { color: #fc6; font-family: monospace; } pre { white-space: pre-wrap; max-height: 20em; overflow: auto; }
#problems:empty, #numbers:empty { display: none; } #problems { border: 1px solid #844; padding: .5em; margin: .5em 0; }
table { border-collapse: collapse; } td { padding: 0 .6em 0 0; }
</style></head>
<body>
<h1 id="title">whitted explore</h1>
<p id="status" class="muted">loading…</p>
<div id="problems"></div>
<div id="layout">
  <div id="main">
    <div id="views"></div>
    <div id="frame"><img id="picture" alt="the picture"><div id="marker" hidden></div></div>
    <p id="caption" class="muted">Click a pixel to see its rays.</p>
    <div id="numbers"></div>
    <img id="rays" alt="" hidden>
  </div>
  <div id="side"><div id="pixel"></div><div id="tree"></div></div>
</div>
)PAGE";
    static const char* const script = R"PAGE(<script>
"use strict";
const token = new URLSearchParams(location.search).get("token") || "";
const api = (path, query = {}) => path + "?" + new URLSearchParams({ ...query, token });
const $ = (id) => document.getElementById(id);
const legends = { picture: "your labs' picture", goal: "the goal: the lab's picture in the handout",
  difference: "each pixel's largest error against the goal: black 0, dark blue up to 4/255 (within the tolerance), green 5, yellow 16, red 64, white 255; magenta NaN" };
const fates = { below_min_weight: "not traced: its weight from the eye is below the minimum weight (1/1024)",
  over_budget: "not traced: the pixel's budget of rays is used up" };
let state = null, view = "picture", shownVersion = -1, shownView = "", loading = false, zoom = 1, pixel = null;
let clicks = 0, treeVersion = -1; // the latest click (older answers are dropped), the picture its tree is of

function el(tag, content, cls) { const e = document.createElement(tag); if (content !== undefined) e.textContent = content; if (cls) e.className = cls; return e; }
function num(c) { return typeof c === "number" ? c.toFixed(3) : "not a number"; }
function vec(v) { return v ? "(" + v.map(num).join(", ") + ")" : "–"; }
function byte(v) { return (v * 255).toFixed(1) + "/255"; }

async function answer(path, query) {
  const response = await fetch(api(path, query));
  if (response.ok) return response;
  const body = await response.json().catch(() => ({ error: response.status + " " + response.statusText }));
  throw new Error(body.error || response.statusText);
}
async function getJson(path, query) { return (await answer(path, query)).json(); }
async function getImage(path, query) { return URL.createObjectURL(await (await answer(path, query)).blob()); }

function showProblems() {
  const box = $("problems"); box.replaceChildren();
  if (state.scene_error) box.append(el("div", "The scene does not load:", "bad"), el("div", state.scene_error, "error"));
  const build = state.build;
  if (build && build.state === "failed") {
    box.append(el("div", "Your labs do not build (" + build.why + "). The picture is the last one that built.", "bad"));
    for (const e of build.errors) {
      const line = el("div", "", "compile-error");
      if (e.file) line.append(el("span", e.file + ":" + e.line + (e.column ? ":" + e.column : "") + ": ", "where"));
      line.append(el("span", e.message, "error"));
      box.append(line);
    }
    const details = el("details"); details.append(el("summary", "the compiler's whole output"), el("pre", build.output));
    box.append(details);
  }
  const render = state.render;
  if (render && render.state === "failed") box.append(el("div", "The render failed. The picture is the last one that rendered.", "bad"), el("pre", render.message, "error"));
  else if (render && render.message) box.append(el("pre", render.message, "muted"));
}

function showStatus() {
  const parts = [];
  const since = " (" + Math.floor(state.activity_seconds) + " s)";
  if (state.activity === "building") parts.push("building: " + state.note + since);
  else if (state.activity === "rendering") parts.push("rendering " + state.note + "…" + since);
  else if (state.note) parts.push(state.note);
  if (state.stage) parts.push("stage " + state.stage + (state.preview ? ", a quarter-size preview" : "") + (state.render && state.render.seconds ? ", rendered in " + state.render.seconds.toFixed(2) + " s" : ""));
  if (state.goal && state.stage && state.stage !== state.goal.stage) parts.push("the goal is stage " + state.goal.stage);
  parts.push(state.live ? "watching " + state.live.labs + ": save a lab file to rebuild" : "not rebuilding on saves");
  $("status").textContent = parts.join(" · ");
  $("status").dataset.activity = state.activity;
}

function showViews() {
  const names = ["picture"].concat(state.goal ? ["goal", "difference"] : [], state.passes);
  if ($("views").childElementCount === names.length) return;
  $("views").replaceChildren(...names.map((name) => { const b = el("button", name); b.id = "view-" + name; b.onclick = () => { view = name; showPicture(); }; return b; }));
}

function showNumbers() {
  const d = state.difference, box = $("numbers"); box.replaceChildren();
  if (!d || (view !== "difference" && view !== "goal")) return;
  const rows = [
    ["pixels off by more than " + byte(d.pixel_tolerance), d.failing_pixels + " of " + d.pixels + " (" + (100 * d.failing_fraction).toFixed(3) + " %)", "the gate allows " + (100 * d.max_failing_fraction) + " %", d.failing_fraction <= d.max_failing_fraction],
    ["mean error", byte(d.mean_error), "the gate allows " + byte(d.max_mean_error), d.mean_error <= d.max_mean_error],
    ["largest error", byte(d.max_error) + " at (" + d.worst[0] + ", " + d.worst[1] + ")", "", true],
    ["PSNR", d.psnr === null ? "∞ (identical)" : d.psnr.toFixed(1) + " dB", "for information", true]];
  const table = el("table");
  for (const [name, value, limit, ok] of rows) { const tr = el("tr"); tr.append(el("td", name), el("td", value, ok ? "" : "bad"), el("td", limit, "muted")); table.append(tr); }
  box.append(table, el("p", d.passed ? "pass: your picture matches the goal" : "FAIL: your picture differs from the goal", d.passed ? "good" : "bad"));
  box.dataset.passed = d.passed;
}

async function showPicture() {
  if (!state || loading) return;
  const version = state.version, wanted = view;
  if (version === shownVersion && wanted === shownView) return;
  for (const b of $("views").children) b.className = b.id === "view-" + wanted ? "on" : "";
  if (version === 0 && wanted === "picture") return;
  loading = true;
  $("caption").textContent = "loading the " + wanted + "…";
  try {
    const url = await getImage("/picture.png", { view: wanted, v: version });
    const img = $("picture"); img.src = url;
    await img.decode();
    img.width = state.width * zoom; img.height = state.height * zoom;
    $("caption").textContent = (legends[wanted] || "the " + wanted + " pass") + ". Click a pixel to see its rays.";
    img.dataset.shown = wanted + " " + version;
    showMarker();
    shownVersion = version; shownView = wanted;
  } catch (error) { $("caption").replaceChildren(el("span", error.message, "error")); shownView = wanted; shownVersion = version; }
  loading = false;
  showNumbers();
  if (view !== shownView || state.version !== shownVersion) showPicture();
}

function rayItem(ray) {
  const li = el("li");
  const kind = ray.kind === "shadow" && ray.blocked ? "blocked" : ray.kind;
  li.append(el("span", ray.kind + " ray", "kind " + kind), el("span", " depth " + ray.depth + ", weight " + vec(ray.weight)));
  if (ray.hit) li.append(el("div", "hit " + ray.hit.object + " at t = " + num(ray.hit.t) + (ray.hit.front_face ? "" : " (from inside)")));
  else if (ray.kind !== "shadow") li.append(el("div", "missed everything: background", "muted"));
  if (ray.kind === "shadow") li.append(el("div", ray.blocked ? "blocked" + (ray.blocker ? " by " + ray.blocker.object : "") + (ray.blocked_by_own_surface ? ": by its own surface (shadow acne)" : "") : "reaches its light", ray.blocked_by_own_surface ? "bad" : ""));
  if (ray.local) li.append(el("div", "local colour " + vec(ray.local)));
  if (ray.color) li.append(el("div", "colour " + vec(ray.color) + (ray.path_weight ? ", adds " + vec(ray.color.map((c, i) => c * ray.path_weight[i])) + " to the pixel" : "")));
  if (ray.check) li.append(el("div", ray.check.law + (ray.check.agrees ? " holds" : " is off by " + num(ray.check.off_degrees) + "°"), ray.check.agrees ? "good" : "bad"));
  if (ray.fate && ray.fate !== "traced") li.append(el("div", fates[ray.fate] || ray.fate, "muted"));
  if (ray.children && ray.children.length) { const ul = el("ul"); ray.children.forEach((c) => ul.append(rayItem(c))); li.append(ul); }
  return li;
}

// Rings the pixel shown on the picture.
function showMarker() {
  const img = $("picture"), marker = $("marker");
  if (!pixel || !state || !state.width) { marker.hidden = true; return; }
  const scale = img.clientWidth / state.width, size = Math.max(10, 3 * scale);
  marker.style.left = img.offsetLeft + img.clientLeft + (pixel.x + 0.5) * scale - size / 2 - 2 + "px";
  marker.style.top = img.offsetTop + img.clientTop + (pixel.y + 0.5) * scale - size / 2 - 2 + "px";
  marker.style.width = marker.style.height = size + "px";
  marker.hidden = false;
}

async function showTree(x, y, sample) {
  pixel = { x, y, sample };
  const click = ++clicks;
  showMarker();
  $("tree").replaceChildren(el("p", "tracing pixel (" + x + ", " + y + ")…", "muted"));
  $("rays").hidden = true;
  try {
    const tree = await getJson("/tree", { x, y, sample });
    if (click !== clicks) return; // a later click's tree comes
    treeVersion = tree.version;
    const head = $("pixel");
    head.replaceChildren(el("h2", "pixel (" + x + ", " + y + ") at stage " + tree.stage), el("p", "pixel value " + vec(tree.color)));
    if (tree.sample) {
      head.append(el("span", "sample " + tree.sample.index + " of " + tree.sample.count + ": "));
      for (let k = 0; k < tree.sample.count; ++k) {
        const b = el("button", String(k), k === tree.sample.index ? "on" : "");
        b.onclick = () => showTree(x, y, k);
        head.append(b);
      }
    }
    const ul = el("ul"); ul.append(rayItem(tree.ray));
    $("tree").replaceChildren(ul);
    $("tree").dataset.pixel = x + " " + y + " " + sample;
    const rays = await getImage("/tree.png", { x, y, sample });
    if (click !== clicks) return;
    $("rays").src = rays;
    $("rays").alt = "the rays of pixel (" + x + ", " + y + "): over the scene, and from the side";
    $("rays").hidden = false;
  } catch (error) {
    if (click !== clicks) return;
    $("tree").replaceChildren(el("p", error.message, "error")); $("tree").dataset.pixel = "error";
  }
}

// The pixel under the mouse: inside the picture's border, scaled from the picture as shown to its pixels.
$("picture").addEventListener("click", (event) => {
  if (!state || !state.width) return;
  const img = event.target, r = img.getBoundingClientRect();
  const x = Math.floor((event.clientX - r.left - img.clientLeft) / img.clientWidth * state.width);
  const y = Math.floor((event.clientY - r.top - img.clientTop) / img.clientHeight * state.height);
  showTree(Math.min(Math.max(x, 0), state.width - 1), Math.min(Math.max(y, 0), state.height - 1), 0);
});

async function poll() {
  try {
    state = await getJson("/state");
    $("title").textContent = state.scene;
    zoom = Math.max(1, Math.floor(640 / Math.max(state.width || 1, state.height || 1)));
    document.body.dataset.version = state.version;
    showStatus(); showProblems(); showViews(); showPicture();
    // A new whole picture (a save): the pixel shown is traced again, with the new code.
    if (pixel && state.version !== treeVersion && !state.preview && state.activity === "idle" && treeVersion !== -2) {
      treeVersion = -2; // until its answer
      showTree(pixel.x, pixel.y, pixel.sample);
    }
    if (view === "difference" || view === "goal") showNumbers();
  } catch (error) { $("status").replaceChildren(el("span", "whitted explore does not answer: " + error.message, "error")); }
  setTimeout(poll, 500);
}
poll();
</script></body></html>
)PAGE";
    return std::string(head) + script;
}

} // namespace whitted
