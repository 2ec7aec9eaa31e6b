// Crowded path following (paper 003) in the browser: the pathway with its
// radius, the boids, a random boid's lap, an editable path, the paper's
// presets (Tests I–IV × five seeks) and live metrics. The core is CrowdLab
// (../wasm); one step per frame by default (one step = one paper frame).
// This file wires the page's parts together.

import { setupCanvas } from "../canvas";
import { button } from "../controls";
import { downloadPng } from "../download";
import { $, showMessage, showVersion } from "../page";
import { CrowdLab, errorText, loadCore, type CrowdConfig } from "../wasm";
import { bench, type CrowdHook } from "./hook";
import { attachCanvas, attachKeys } from "./input";
import { runLoop } from "./loop";
import { buildPanel } from "./panel";
import { fillPresetMenu } from "./presets";
import { CrowdSession } from "./session";

const s = new CrowdSession();
const canvas = $<HTMLCanvasElement>("crowd");
let presets: CrowdConfig[] = [];

const hook: CrowdHook = {
  ready: false,
  error: null,
  frames: 0,
  get playing() {
    return s.playing;
  },
  stepMs: 0,
  drawMs: 0,
  fps: 0,
  get preset() {
    return s.preset;
  },
  count: () => s.lab?.count() ?? 0,
  time: () => s.lab?.time() ?? 0,
  pathPoints: () => Array.from(s.lab?.pathPoints() ?? []),
  pathRadius: () => s.lab?.pathRadius() ?? 0,
  seek: () => (s.lab ? s.lab.config().seek : null),
  separation: () => (s.lab ? s.lab.config().separation : false),
  selected: () => s.editor.selected,
  metrics: () => (s.lab ? s.lab.metrics() : null),
  toScreen: (x, y) => s.view.toScreen(x, y),
  bench: (counts, minMs) => bench(presets, counts, minMs),
};
window.__crowd = hook;

const transport = $("transport");
const playBtn = button(transport, "play", "Pause", "play / pause (space)", () => s.setPlaying(!s.playing));
button(transport, "step", "Step", "one step (s)", () => s.stepOnce());
button(transport, "reset", "Reset", "back to step 0, keeping the edits (r)", () => s.reset());
s.onPlaying = (p) => {
  playBtn.textContent = p ? "Pause" : "Play";
  playBtn.setAttribute("aria-pressed", String(!p));
};
attachKeys(s);
attachCanvas(canvas, s);

async function start(): Promise<void> {
  try {
    showVersion(await loadCore());
    presets = CrowdLab.paperPresets();
  } catch (e) {
    hook.error = errorText(e);
    showMessage(`could not load the steering core: ${hook.error}`, "error");
    return;
  }
  const sel = $<HTMLSelectElement>("preset");
  const index = fillPresetMenu(sel, presets);
  sel.value = String(index);
  sel.addEventListener("change", () => {
    const p = presets[Number(sel.value)];
    if (p) s.load(p, true);
  });

  const first = presets[index];
  if (!first) {
    hook.error = "the core has no crowd presets";
    showMessage(hook.error, "error");
    return;
  }
  s.panel = buildPanel($("panel"), {
    seek: first.seek, separation: first.separation, weight: first.separation_weight, boids: first.boids,
    radius: first.path.radius, closed: first.path.closed,
  }, {
    seek: (k) => s.apply((l) => l.setSeek(k)),
    separation: (on, w) => s.apply((l) => l.setSeparation(on, w)),
    boids: (n) => s.apply((l) => l.setBoidCount(n)),
    radius: (r) => s.apply((l) => l.setPathRadius(r)),
    closed: (c) => s.apply((l) => l.setPathClosed(c)),
    speed: (k) => { s.stepsPerFrame = k; },
    showTrace: (on) => { s.showTrace = on; s.dirty = true; },
    showHandles: (on) => {
      s.showHandles = on;
      if (!on) s.editor.selected = null;
      s.dirty = true;
    },
    addPoint: () => s.editor.insertMidpoint(),
    removePoint: () => s.editor.removeSelected(),
    fit: () => s.fitView(),
    resetMetrics: () => s.apply((l) => l.resetMetrics()),
    newTrace: () => s.apply((l) => {
      const n = l.count();
      if (n > 0) l.selectTraced(Math.floor(Math.random() * n));
    }),
    png: () => downloadPng(canvas),
  });
  const surface = setupCanvas(canvas, (sf) => {
    const firstSize = s.view.width <= 1;
    s.view.resize(sf.width, sf.height);
    if (firstSize) s.fitView();
    s.dirty = true;
  });
  s.load(first, true);
  hook.ready = true;
  runLoop(s, surface, $("hud"), hook);
}

void start();
