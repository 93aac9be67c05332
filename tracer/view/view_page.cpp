#include "view/view_page.h"

namespace tracer {

// Drag: orbit about the target; right-drag or shift-drag: pan; wheel: dolly; W/S forward and
// back, A/D left and right, Q/E down and up. Moves post {"moving": true}; 250 ms after the
// last one the camera is posted at rest and the image refines at full size. Pan and walk steps
// follow the distance to the target, at least a tenth of the scene's size.
const char* view_page_html() {
  return R"PAGE(<!doctype html>
<html><head><meta charset="utf-8"><title>tracer view</title>
<style>
body { margin: 0; background: #202020; color: #ddd; font: 13px sans-serif; }
#bar { padding: 6px 8px; display: flex; gap: 10px; align-items: center; flex-wrap: wrap; }
#view { display: block; margin: 0 8px; image-rendering: pixelated; cursor: grab; outline: none; }
#msg { color: #fc6; }
</style></head>
<body>
<div id="bar">
  <span id="spp">-</span><span id="rate">-</span><span id="ms">-</span>
  <label>integrator <select id="integrator">
    <option>path</option><option>whitted</option><option>normals</option><option>albedo</option><option>depth</option>
  </select></label>
  <label>spp <input id="target" type="number" min="1" style="width: 6em"></label>
  <button id="copy">copy camera</button><button id="save">save</button>
  <span id="msg"></span>
</div>
<canvas id="view" tabindex="0" width="320" height="240"></canvas>
<script>
"use strict";
const q = "?token=" + encodeURIComponent(new URLSearchParams(location.search).get("token") || "");
const canvas = document.getElementById("view"), ctx = canvas.getContext("2d");
const $ = (id) => document.getElementById(id);
let cam = null, shown = 0, interacting = false, sending = false, queued = null, restTimer = null, sceneSize = 0;

const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const mul = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => mul(a, 1 / Math.hypot(a[0], a[1], a[2]));
// Rodrigues: v turned by angle t about the unit axis k.
const turn = (v, k, t) => add(add(mul(v, Math.cos(t)), mul(cross(k, v), Math.sin(t))), mul(k, dot(k, v) * (1 - Math.cos(t))));

async function post(path, body) {
  const r = await fetch(path + q, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
  const j = await r.json();
  if (!r.ok) throw new Error(j.error || r.statusText);
  return j;
}
function say(text) { $("msg").textContent = text; }

function send(moving) {
  queued = { camera: { from: cam.from, to: cam.to, up: cam.up, vfov: cam.vfov }, moving: moving };
  if (sending) return;
  sending = true;
  const body = queued; queued = null;
  post("/camera", body).catch((e) => say(e.message)).finally(() => { sending = false; if (queued) send(queued.moving); });
}
function moved() {
  send(true);
  clearTimeout(restTimer);
  restTimer = setTimeout(() => { interacting = false; send(false); }, 250);
}

function orbit(dx, dy) {
  const up = norm(cam.up);
  let offset = turn(sub(cam.from, cam.to), up, -dx * 0.01);
  const right = norm(cross(offset, up));
  const pitched = turn(offset, right, dy * 0.01);
  if (Math.abs(dot(norm(pitched), up)) < 0.995) offset = pitched;
  cam.from = add(cam.to, offset);
}
// Steps scale with the distance to the target, but never below a tenth of the scene's size: a
// camera whose target is just ahead of it (a glTF camera's) still crosses the scene.
const reach = () => Math.max(Math.hypot(...sub(cam.from, cam.to)), 0.1 * sceneSize);
function pan(dx, dy) {
  const forward = norm(sub(cam.to, cam.from)), right = norm(cross(forward, cam.up)), up = cross(right, forward);
  const r = reach() * 0.002;
  const d = add(mul(right, -dx * r), mul(up, dy * r));
  cam.from = add(cam.from, d); cam.to = add(cam.to, d);
}
function walk(key) {
  const forward = norm(sub(cam.to, cam.from)), right = norm(cross(forward, cam.up)), up = norm(cam.up);
  const step = reach() * 0.05;
  const d = { w: forward, s: mul(forward, -1), d: right, a: mul(right, -1), e: up, q: mul(up, -1) }[key];
  if (!d) return false;
  cam.from = add(cam.from, mul(d, step)); cam.to = add(cam.to, mul(d, step));
  return true;
}

// #drag-check, for a headless browser: once the first frame has all its samples, drag across
// it through the page's own handlers; when a finished frame shows another camera, mark the page
// and stop polling.
const check = location.hash === "#drag-check" ? { first: null } : null;
function dragCheck(st) {
  if (!check || st.preview || st.spp !== st.target_spp) return;
  if (check.first === null) {
    check.first = JSON.stringify(st.camera);
    const r = canvas.getBoundingClientRect();
    const at = (type, x) => canvas.dispatchEvent(new MouseEvent(type, { clientX: r.left + x, clientY: r.top + 10, bubbles: true }));
    at("mousedown", 10); at("mousemove", 50); at("mouseup", 50);
  } else if (JSON.stringify(st.camera) !== check.first) {
    document.body.dataset.check = "camera moved";
  }
}

let drag = null;
canvas.addEventListener("contextmenu", (e) => e.preventDefault());
canvas.addEventListener("mousedown", (e) => { if (cam) { drag = { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey }; interacting = true; } });
window.addEventListener("mouseup", () => { drag = null; });
window.addEventListener("mousemove", (e) => {
  if (!drag) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  drag.x = e.clientX; drag.y = e.clientY;
  if (drag.pan) pan(dx, dy); else orbit(dx, dy);
  moved();
});
canvas.addEventListener("wheel", (e) => {
  if (!cam) return;
  e.preventDefault(); interacting = true;
  cam.from = add(cam.to, mul(sub(cam.from, cam.to), Math.exp(e.deltaY * 0.001)));
  moved();
}, { passive: false });
canvas.addEventListener("keydown", (e) => { if (cam && walk(e.key.toLowerCase())) { interacting = true; moved(); } });

$("integrator").addEventListener("change", (e) => post("/settings", { integrator: e.target.value }).then(() => say("")).catch((x) => say(x.message)));
$("target").addEventListener("change", (e) => post("/settings", { spp: e.target.value }).then(() => say("")).catch((x) => say(x.message)));
$("copy").addEventListener("click", async () => {
  const r = await fetch("/state" + q); const st = await r.json();
  const text = '"camera": ' + JSON.stringify(st.camera);
  try { await navigator.clipboard.writeText(text); say("camera copied"); } catch (e) { say(text); }
});
$("save").addEventListener("click", () => post("/save", {}).then((j) => say("wrote " + j.files.join(", "))).catch((e) => say(e.message)));

async function poll() {
  try {
    const st = await (await fetch("/state" + q)).json();
    if (!interacting) cam = st.camera;
    sceneSize = st.scene_size;
    $("spp").textContent = st.spp + " / " + st.target_spp + " spp" + (st.preview ? " (moving)" : "");
    $("rate").textContent = (st.rays_per_second / 1e6).toFixed(2) + " Mrays/s";
    $("ms").textContent = (st.pass_seconds * 1000).toFixed(0) + " ms/frame";
    if (document.activeElement !== $("integrator")) $("integrator").value = st.integrator;
    if (document.activeElement !== $("target")) $("target").value = st.target_spp;
    if (st.error) say(st.error);
    if (st.frame > shown) {
      const img = new Image();
      img.src = "/frame" + q + "&f=" + st.frame;
      await img.decode();
      if (!st.preview && (canvas.width !== st.width || canvas.height !== st.height)) { canvas.width = st.width; canvas.height = st.height; }
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(img, 0, 0, canvas.width, canvas.height);
      shown = st.frame;
      canvas.dataset.frame = st.frame;
      dragCheck(st);
    }
  } catch (e) { say("viewer unreachable: " + e.message); }
  if (check && document.body.dataset.check) return;  // checked: idle, so a headless browser's virtual clock ends
  setTimeout(poll, 100);
}
poll();
</script></body></html>
)PAGE";
}

}  // namespace tracer
