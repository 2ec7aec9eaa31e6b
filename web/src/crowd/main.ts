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
import { bench, fnvHex, scaledConfig, type CrowdHook } from "./hook";
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
  workerUpdates: 0,
  workerSteps: 0,
  workerJobMs: 0,
  workerStepMs: 0,
  drawnFrames: 0,
  workMs: [],
  workers: () => {
    const st = s.stepper;
    const on = st?.active === true;
    return {
      mode: on && st ? (st.shared ? "shared" : "messages") : "main",
      workers: on && st ? st.workers : 0,
      wanted: s.workersWanted,
      crossOriginIsolated: globalThis.crossOriginIsolated === true,
      cores: navigator.hardwareConcurrency || 0,
      starting: on && st ? !st.ready : false,
      error: st?.error ?? null,
      owned: on && st ? st.owned : [],
      shares: on && st ? st.shares() : [],
      startMs: st?.startMs ?? 0,
    };
  },
  stateHash: () => {
    const l = s.lab;
    if (!l) return "";
    const st = s.stepper?.active ? s.stepper.state : l.state();
    return fnvHex(st);
  },
  snapshot: () => {
    s.syncFromWorkers();
    const l = s.lab;
    if (!l) throw new Error("no crowd");
    return { config: l.config(), state: Array.from(l.state()), time: l.time() };
  },
  reference: (snap, edit, steps) => {
    const l = new CrowdLab(snap.config);
    try {
      l.loadState(new Float32Array(snap.state), snap.time);
      if (edit.boids !== undefined) l.setBoidCount(edit.boids);
      if (edit.path) l.setPathPoints(new Float32Array(edit.path));
      l.step(steps);
      return fnvHex(l.state());
    } finally {
      l.free();
    }
  },
  runSteps: async (n) => {
    const st = s.stepper;
    if (st?.active) {
      // A job runs any number of steps with shared memory, one by message.
      const per = st.shared ? n : 1;
      for (let k = 0; k < n; k += per) await st.step(Math.min(per, n - k));
    } else s.lab?.step(n);
    s.dirty = true;
  },
  idle: () => !s.stepper?.active || (s.stepper.ready && s.stepper.idle),
  skippedSteps: () => s.stepper?.skipped ?? 0,
  loadScaled: (n) => {
    const c = scaledConfig(presets, n);
    if (c) s.load(c, true);
  },
  perfReset: () => {
    hook.workMs = [];
    perfAt = { t: performance.now(), frames: hook.frames, updates: hook.workerUpdates, drawn: hook.drawnFrames, skipped: hook.skippedSteps(), steps: hook.workerSteps, jobMs: hook.workerJobMs, stepMs: hook.workerStepMs };
  },
  perfStats: () => {
    const now = performance.now();
    const frames = hook.frames - perfAt.frames;
    const w = [...hook.workMs].sort((a, b) => a - b);
    return {
      frames,
      spanMs: now - perfAt.t,
      updates: hook.workerUpdates - perfAt.updates,
      drawnFrames: hook.drawnFrames - perfAt.drawn,
      skippedSteps: hook.skippedSteps() - perfAt.skipped,
      meanIntervalMs: (now - perfAt.t) / Math.max(1, frames),
      meanWorkMs: w.reduce((a, b) => a + b, 0) / Math.max(1, w.length),
      p95WorkMs: w[Math.min(w.length - 1, Math.floor(0.95 * w.length))] ?? 0,
      jobMsPerStep: (hook.workerJobMs - perfAt.jobMs) / Math.max(1, hook.workerSteps - perfAt.steps),
      workerMsPerStep: (hook.workerStepMs - perfAt.stepMs) / Math.max(1, hook.workerSteps - perfAt.steps),
    };
  },
};
let perfAt = { t: 0, frames: 0, updates: 0, drawn: 0, skipped: 0, steps: 0, jobMs: 0, stepMs: 0 };
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
  hook.ready = true;
  runLoop(s, surface, $("hud"), hook);
}

void start();
