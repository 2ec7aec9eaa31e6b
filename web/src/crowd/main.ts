// Crowded path following (paper 003) in the browser: the pathway with its
// radius, the boids, a random boid's lap, an editable path, the paper's
// presets (Tests I–IV × five seeks) and live metrics. The core is CrowdLab
// (../wasm); one step per frame by default (one step = one paper frame).
// This file wires the page's parts together.

import { setupCanvas } from "../ui/canvas";
import { button } from "../ui/controls";
import { downloadPng } from "../ui/download";
import { $, showMessage, showVersion } from "../ui/page";
import { CrowdLab, errorText, loadCore } from "../core/wasm";
import type { CrowdPage } from "./app";
import { installHook } from "./hook";
import { attachCanvas, attachKeys } from "./input";
import { runLoop } from "./loop";
import { buildPanel } from "./panel";
import { fillPresetMenu } from "./presets";
import { CrowdSession } from "./session";

const s = new CrowdSession();
const canvas = $<HTMLCanvasElement>("crowd");
const page: CrowdPage = {
  ready: false,
  error: null,
  session: s,
  presets: [],
  stats: { frames: 0, drawnFrames: 0, steps: 0, updates: 0, jobMs: 0, workerStepMs: 0, stepMs: NaN, drawMs: NaN, fps: 0, stepsPerSecond: 0, askedPerSecond: 0 },
  probe: null,
};
// The test build's window.__crowd; the shipped build drops this line and hook.ts.
if (import.meta.env.MODE === "test") installHook(page);

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
    page.presets = CrowdLab.paperPresets();
  } catch (e) {
    page.error = errorText(e);
    showMessage(`could not load the steering core: ${page.error}`, "error");
    return;
  }
  const sel = $<HTMLSelectElement>("preset");
  const presets = page.presets;
  const index = fillPresetMenu(sel, presets);
  sel.value = String(index);
  sel.addEventListener("change", () => {
    const p = presets[Number(sel.value)];
    if (p) s.load(p, true);
  });

  const first = presets[index];
  if (!first) {
    page.error = "the core has no crowd presets";
    showMessage(page.error, "error");
    return;
  }
  s.panel = buildPanel($("panel"), {
    seek: first.seek, separation: first.separation, weight: first.separation_weight, boids: first.boids,
    radius: first.path.radius, closed: first.path.closed,
  }, {
    seek: (k) => s.apply((l) => l.setSeek(k)),
    separation: (on, w) => s.apply((l) => l.setSeparation(on, w)),
    boids: (n) => s.apply((l) => {
      const n0 = l.count();
      // Test IV density: the pathway scales about its centroid by n / n0.
      if (s.scaleWithCount && n0 > 0 && n > 0 && n !== n0) {
        const xy = l.pathPoints();
        const m = xy.length >> 1;
        let cx = 0, cy = 0;
        for (let i = 0; i < m; i++) { cx += (xy[2 * i] ?? 0) / m; cy += (xy[2 * i + 1] ?? 0) / m; }
        const k = n / n0;
        l.setPathPoints(xy.map((v, j) => (j % 2 ? cy + (v - cy) * k : cx + (v - cx) * k)));
        l.setBoidCount(n);
        s.fitView();
      } else l.setBoidCount(n);
    }),
    radius: (r) => s.apply((l) => l.setPathRadius(r)),
    closed: (c) => s.apply((l) => l.setPathClosed(c)),
    speed: (k) => { s.stepsPerFrame = k; },
    density: (on) => { s.scaleWithCount = on; },
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
  page.ready = true;
  runLoop(page, surface, $("hud"));
}

void start();
