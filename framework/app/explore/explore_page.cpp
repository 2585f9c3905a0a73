// The page `whitted explore` serves: plain HTML, CSS and JavaScript, no build step, nothing fetched from
// elsewhere. It shows the picture; a click on a pixel shows that pixel's ray tree (GET /tree), each ray with
// what it hit, its weight, what it added and the mirror-law / Snell checks, and, on a pixel of several samples,
// which sample is shown, with the others a click away.
#include "explore/explore_page.hpp"

namespace whitted {

const char* explore_page() {
    return R"PAGE(<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>whitted explore</title>
<style>
body { font: 14px/1.4 system-ui, sans-serif; margin: 1em; background: #1e1e1e; color: #ddd; }
#layout { display: flex; gap: 1.5em; align-items: flex-start; }
#picture { image-rendering: pixelated; cursor: crosshair; border: 1px solid #555; }
#tree ul { list-style: none; padding-left: 1.2em; border-left: 1px dotted #666; margin: 0; }
#tree li { margin: .2em 0; }
.kind { font-weight: bold; } .eye { color: #fff; } .reflected { color: #4dd; } .refracted { color: #5d5; }
.shadow { color: #dd5; } .blocked { color: #e55; } .bad { color: #f66; font-weight: bold; }
.error { color: #f66; white-space: pre-wrap; } .muted { color: #999; } button.on { background: #557; color: #fff; }
</style></head>
<body>
<h1 id="title">whitted explore</h1>
<p id="status" class="muted">loading…</p>
<div id="layout">
  <div><img id="picture" alt="the picture"><p class="muted">Click a pixel to see its rays.</p></div>
  <div id="side"><div id="samples"></div><div id="tree"></div></div>
</div>
<script>
"use strict";
const token = new URLSearchParams(location.search).get("token") || "";
const api = (path, query = {}) => path + "?" + new URLSearchParams({ ...query, token });
const $ = (id) => document.getElementById(id);
let scene = null, zoom = 1, shown = null;

function text(tag, content, cls) { const e = document.createElement(tag); e.textContent = content; if (cls) e.className = cls; return e; }
function num(c) { return typeof c === "number" ? c.toFixed(3) : "not a number"; }
function vec(v) { return v ? "(" + v.map(num).join(", ") + ")" : "–"; }

async function getJson(path, query) {
  const response = await fetch(api(path, query));
  const body = await response.json().catch(() => ({ error: "the answer was not JSON (" + response.status + ")" }));
  if (!response.ok) throw new Error(body.error || response.statusText);
  return body;
}

function rayItem(ray) {
  const li = document.createElement("li");
  const kind = ray.kind === "shadow" && ray.blocked ? "blocked" : ray.kind;
  li.append(text("span", ray.kind + " ray", "kind " + kind), text("span", " depth " + ray.depth + ", weight " + vec(ray.weight)));
  if (ray.hit) li.append(text("div", "hit " + ray.hit.object + " at t = " + num(ray.hit.t) + (ray.hit.front_face ? "" : " (from inside)")));
  else if (ray.kind !== "shadow") li.append(text("div", "missed everything: background", "muted"));
  if (ray.kind === "shadow") li.append(text("div", ray.blocked ? "blocked" + (ray.blocker ? " by " + ray.blocker.object : "") + (ray.blocked_by_own_surface ? ": by its own surface (shadow acne)" : "") : "reaches its light", ray.blocked_by_own_surface ? "bad" : ""));
  if (ray.local) li.append(text("div", "local colour " + vec(ray.local)));
  if (ray.color) li.append(text("div", "colour " + vec(ray.color)));
  if (ray.check) li.append(text("div", ray.check.law + (ray.check.agrees ? " holds" : " is off by " + num(ray.check.off_degrees) + "°"), ray.check.agrees ? "" : "bad"));
  if (ray.fate && ray.fate !== "traced") li.append(text("div", ray.fate, "muted"));
  if (ray.children && ray.children.length) { const ul = document.createElement("ul"); ray.children.forEach((c) => ul.append(rayItem(c))); li.append(ul); }
  return li;
}

async function showTree(x, y, sample) {
  shown = { x, y, sample };
  $("tree").replaceChildren(text("p", "tracing pixel (" + x + ", " + y + ")…", "muted"));
  try {
    const tree = await getJson("/tree", { x, y, sample });
    const samples = $("samples");
    samples.replaceChildren(text("h2", "pixel (" + x + ", " + y + ")"), text("p", "pixel value " + vec(tree.color)));
    if (tree.sample) {
      samples.append(text("span", "sample "));
      for (let k = 0; k < tree.sample.count; ++k) {
        const b = text("button", String(k), k === tree.sample.index ? "on" : "");
        b.onclick = () => showTree(x, y, k);
        samples.append(b);
      }
    }
    const ul = document.createElement("ul"); ul.append(rayItem(tree.ray));
    $("tree").replaceChildren(ul);
  } catch (error) { $("tree").replaceChildren(text("p", error.message, "error")); }
}

$("picture").addEventListener("click", (event) => {
  if (!scene) return;
  const r = event.target.getBoundingClientRect();
  const x = Math.floor((event.clientX - r.left) / r.width * scene.width), y = Math.floor((event.clientY - r.top) / r.height * scene.height);
  showTree(Math.min(Math.max(x, 0), scene.width - 1), Math.min(Math.max(y, 0), scene.height - 1), 0);
});

(async () => {
  try {
    scene = await getJson("/scene");
    $("title").textContent = scene.scene + " (stage " + scene.stage + ")";
    zoom = Math.max(1, Math.floor(640 / Math.max(scene.width, scene.height)));
    $("picture").width = scene.width * zoom; $("picture").height = scene.height * zoom;
    $("picture").src = api("/picture.png");
    $("status").textContent = scene.width + "×" + scene.height + " pixels" + (scene.samples ? ", " + scene.samples + " samples a pixel" : "");
  } catch (error) { $("status").replaceChildren(text("span", error.message, "error")); }
})();
</script></body></html>
)PAGE";
}

} // namespace whitted
