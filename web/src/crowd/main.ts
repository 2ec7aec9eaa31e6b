// Crowded path following (paper 003) in the browser: the pathway with its
// radius, the boids, a random boid's lap, an editable path, the paper's
// presets (Tests I–IV × five seeks) and live metrics. The core is CrowdLab
// (../wasm); one step per frame by default (one step = one paper frame).

import { setupCanvas, type Surface } from "../canvas";
import { button } from "../controls";
import { downloadPng } from "../export";
import { attachPointer, type Drag } from "../pointer";
import type { Vec } from "../view";
import { WideView } from "../wideview";
import { CrowdLab, errorText, loadCore, type CrowdConfig, type CrowdMetrics, type CrowdSeek } from "../wasm";
import { buildPanel, SEEKS, type Panel } from "./controls";
import { PathEditor } from "./patheditor";
import { drawCrowd } from "./render";

/** Per-N step cost, from CrowdHook.bench. */
export interface BenchRow {
  boids: number;
  /** "paper": Test IV's pathway and separation (density grows with N);
   *  "scaled": separation on, pathway stretched by N/300 (Test IV's density);
   *  "no-sep": Test IV's pathway, separation off (path following alone). */
  setup: "paper" | "scaled" | "no-sep";
  steps: number;
  msPerStep: number;
  boidsPerFrame: number;
}

/** What the end-to-end test reads and drives (window.__crowd). */
export interface CrowdHook {
  ready: boolean;
  error: string | null;
  frames: number;
  playing: boolean;
  /** Mean step and draw times over the last second, ms. */
  stepMs: number;
  drawMs: number;
  fps: number;
  preset: string;
  count(): number;
  time(): number;
  pathPoints(): number[];
  pathRadius(): number;
  seek(): CrowdSeek | null;
  separation(): boolean;
  selected(): number | null;
  metrics(): CrowdMetrics | null;
  toScreen(x: number, y: number): Vec;
  /** Step cost (metrics on, as on the page) at each boid count, three set-ups (see BenchRow), timed with performance.now. */
  bench(counts: number[], minMs: number): BenchRow[];
}

declare global {
  interface Window {
    __crowd?: CrowdHook;
  }
}

const $ = <T extends HTMLElement>(id: string): T => {
  const e = document.getElementById(id);
  if (!e) throw new Error(`#${id} missing from crowd.html`);
  return e as T;
};

const message = $("message");
function showMessage(text: string | null, error = false): void {
  message.hidden = text === null;
  message.textContent = text ?? "";
  message.classList.toggle("error", error);
}

let lab: CrowdLab | null = null;
let presets: CrowdConfig[] = [];
let presetIndex = 0;
let playing = true;
let stepsPerFrame = 1;
let singleSteps = 0;
let showTrace = true;
let showHandles = true;
let dirty = true;

const view = new WideView();
const canvas = $<HTMLCanvasElement>("crowd");
let surface: Surface | null = null;

const hook: CrowdHook = {
  ready: false,
  error: null,
  frames: 0,
  playing,
  stepMs: 0,
  drawMs: 0,
  fps: 0,
  preset: "",
  count: () => lab?.count() ?? 0,
  time: () => lab?.time() ?? 0,
  pathPoints: () => Array.from(lab?.pathPoints() ?? []),
  pathRadius: () => lab?.pathRadius() ?? 0,
  seek: () => (lab ? lab.config().seek : null),
  separation: () => (lab ? lab.config().separation : false),
  selected: () => editor.selected,
  metrics: () => (lab ? lab.metrics() : null),
  toScreen: (x, y) => view.toScreen(x, y),
  bench: (counts, minMs) => bench(counts, minMs),
};
window.__crowd = hook;

const editor = new PathEditor(
  {
    points: () => lab?.pathPoints() ?? new Float32Array(),
    closed: () => lab?.pathClosed() ?? true,
    commit: (xy) => {
      if (!lab) return "the core is not loaded";
      try {
        lab.setPathPoints(xy);
        return null;
      } catch (e) {
        return errorText(e);
      }
    },
    report: (m) => showMessage(m),
    changed: () => {
      dirty = true;
    },
  },
  view,
);

/** Runs a setter on the core; shows its message if it refuses. */
function apply(f: (l: CrowdLab) => void): void {
  if (!lab) return;
  try {
    f(lab);
    showMessage(null);
  } catch (e) {
    showMessage(errorText(e), true);
  }
  dirty = true;
}

function fitView(): void {
  if (!lab) return;
  const xy = lab.pathPoints();
  const r = lab.pathRadius();
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i + 1 < xy.length; i += 2) {
    const x = xy[i] ?? 0;
    const y = xy[i + 1] ?? 0;
    x0 = Math.min(x0, x);
    x1 = Math.max(x1, x);
    y0 = Math.min(y0, y);
    y1 = Math.max(y1, y);
  }
  if (!Number.isFinite(x0)) return;
  view.fit(x0 - r, y0 - r, x1 + r, y1 + r, 40);
  dirty = true;
}

let panel: Panel | null = null;

function syncPanel(): void {
  if (!lab || !panel) return;
  const c = lab.config();
  panel.set({
    seek: c.seek,
    separation: c.separation,
    weight: c.separation_weight,
    boids: lab.count(),
    radius: lab.pathRadius(),
    closed: lab.pathClosed(),
  });
}

function load(config: CrowdConfig, fit: boolean): void {
  try {
    const next = new CrowdLab(config);
    lab?.free();
    lab = next;
    editor.selected = null;
    hook.preset = config.name ?? "";
    showMessage(null);
  } catch (e) {
    showMessage(errorText(e), true);
    return;
  }
  syncPanel();
  if (fit) fitView();
  dirty = true;
}

/** Back to step 0 keeping the edits (path, count, seek, separation). */
function reset(): void {
  if (lab) load(lab.config(), false);
}

function bench(counts: number[], minMs: number): BenchRow[] {
  const base = presets.find((p) => p.boids === 300 && p.seek.kind === "parker" && Math.abs(p.seek.fraction - 0.1) < 1e-6) ?? presets[0];
  if (!base) return [];
  const rows: BenchRow[] = [];
  for (const n of counts) {
    for (const setup of ["paper", "scaled", "no-sep"] as const) {
      const k = n / 300;
      const cfg: CrowdConfig = {
        ...base,
        boids: n,
        separation: setup !== "no-sep",
        path: setup === "scaled" ? { ...base.path, points: base.path.points.map(([x, y]) => [x * k, y * k]) } : base.path,
      };
      const l = new CrowdLab(cfg);
      l.step(20);
      let steps = 0;
      const t0 = performance.now();
      let t = t0;
      while (t - t0 < minMs || steps < 5) {
        l.step(1);
        steps++;
        t = performance.now();
      }
      l.free();
      const ms = (t - t0) / steps;
      rows.push({ boids: n, setup, steps, msPerStep: ms, boidsPerFrame: Math.round((n * (1000 / 60)) / ms) });
    }
  }
  return rows;
}

// --- transport and keys
const transport = $("transport");
const playBtn = button(transport, "play", "Pause", "play / pause (space)", () => setPlaying(!playing));
button(transport, "step", "Step", "one step (s)", () => {
  setPlaying(false);
  singleSteps++;
});
button(transport, "reset", "Reset", "back to step 0, keeping the edits (r)", reset);

function setPlaying(p: boolean): void {
  playing = p;
  hook.playing = p;
  playBtn.textContent = p ? "Pause" : "Play";
  playBtn.setAttribute("aria-pressed", String(!p));
}

window.addEventListener("keydown", (e) => {
  const t = e.target;
  if (t instanceof HTMLSelectElement || t instanceof HTMLTextAreaElement) return;
  if (t instanceof HTMLInputElement && (t.type === "number" || t.type === "text")) return;
  if (e.ctrlKey || e.metaKey || e.altKey) return;
  if (e.key === " ") {
    e.preventDefault();
    setPlaying(!playing);
  } else if (e.key === "s") {
    setPlaying(false);
    singleSteps++;
  } else if (e.key === "r") {
    reset();
  } else if (e.key === "Delete" || e.key === "Backspace") {
    if (editor.selected !== null) {
      e.preventDefault();
      editor.removeSelected();
    }
  } else if (e.key === "Escape") {
    editor.selected = null;
    dirty = true;
  }
});

// --- canvas interaction
attachPointer(
  canvas,
  (p: Vec): Drag | null => {
    if (!lab) return null;
    const i = showHandles ? editor.hitPoint(p) : null;
    if (i !== null) return editor.drag(i, p);
    editor.selected = null;
    dirty = true;
    let last = p;
    canvas.style.cursor = "grabbing";
    return {
      move: (q) => {
        view.panBy(q.x - last.x, q.y - last.y);
        last = q;
        dirty = true;
      },
      end: () => {
        canvas.style.cursor = "";
      },
    };
  },
  (p) => {
    const h = p && showHandles ? editor.hitPoint(p) : null;
    if (h !== editor.hover) {
      editor.hover = h;
      canvas.style.cursor = h !== null ? "move" : "";
      dirty = true;
    }
  },
);
canvas.addEventListener("dblclick", (e) => {
  if (!lab || !showHandles) return;
  const r = canvas.getBoundingClientRect();
  const p = { x: e.clientX - r.left, y: e.clientY - r.top };
  if (editor.hitPoint(p) !== null) return;
  editor.insertAt(p, Math.max(12, lab.pathRadius() * view.scale));
});
canvas.addEventListener("wheel", (e) => {
  e.preventDefault();
  const r = canvas.getBoundingClientRect();
  view.zoomAt(e.clientX - r.left, e.clientY - r.top, Math.exp(-e.deltaY * 0.0015));
  dirty = true;
}, { passive: false });

// --- the loop
let stepAcc = 0;
let drawAcc = 0;
let frameAcc = 0;
let windowStart = performance.now();
let lastMetrics = 0;
const hud = $("hud");

function frame(now: number): void {
  requestAnimationFrame(frame);
  if (!lab || !surface) return;
  const t0 = performance.now();
  const n = playing ? stepsPerFrame : Math.min(singleSteps, 1);
  if (n > 0) {
    lab.step(n);
    if (!playing) singleSteps = 0;
    dirty = true;
  }
  const t1 = performance.now();
  if (dirty) {
    drawCrowd(surface, view, {
      path: lab.pathPoints(),
      radius: lab.pathRadius(),
      closed: lab.pathClosed(),
      positions: lab.positions(),
      velocities: lab.velocities(),
      trace: showTrace ? lab.trace() : new Float32Array(),
      traced: lab.tracedBoid(),
      boidRadius: lab.boidRadius(),
      showTrace,
      showHandles,
      selected: editor.selected,
      hover: editor.hover,
    });
    dirty = false;
  }
  const t2 = performance.now();
  stepAcc += t1 - t0;
  drawAcc += t2 - t1;
  frameAcc++;
  hook.frames++;
  if (now - windowStart >= 1000) {
    hook.stepMs = stepAcc / frameAcc;
    hook.drawMs = drawAcc / frameAcc;
    hook.fps = (1000 * frameAcc) / (now - windowStart);
    stepAcc = drawAcc = frameAcc = 0;
    windowStart = now;
  }
  if (now - lastMetrics > 250) {
    lastMetrics = now;
    panel?.showMetrics(lab.metrics(), lab.lastOverlaps(), lab.count());
    const c = lab.config();
    const seek = c.seek;
    hud.textContent = [
      `step ${lab.time().toFixed(0)}`,
      `${lab.count().toLocaleString("en")} boids`,
      seek.kind === "reynolds" ? "Reynolds" : `Parker ${+(seek.fraction * 100).toPrecision(3)} %`,
      c.separation ? `separation ${+c.separation_weight.toPrecision(3)}` : "no separation",
      `${hook.fps.toFixed(0)} fps`,
      `step ${hook.stepMs.toFixed(2)} ms`,
      `draw ${hook.drawMs.toFixed(2)} ms`,
    ].join("  ·  ");
  }
}

async function start(): Promise<void> {
  try {
    const v = await loadCore();
    $("version").textContent = `core ${v}`;
    presets = CrowdLab.paperPresets();
  } catch (e) {
    hook.error = errorText(e);
    showMessage(`could not load the steering core: ${hook.error}`, true);
    return;
  }
  const sel = $<HTMLSelectElement>("preset");
  let group: HTMLOptGroupElement | null = null;
  presets.forEach((p, i) => {
    const test = /^Test (\d+)/.exec(p.name ?? "")?.[1] ?? "?";
    const label = `Test ${["", "I", "II", "III", "IV"][Number(test)] ?? test} (${p.boids} ${p.boids === 1 ? "boid" : "boids"}${p.separation ? ", separation" : ""})`;
    if (!group || group.label !== label) {
      group = document.createElement("optgroup");
      group.label = label;
      sel.append(group);
    }
    const seek = SEEKS.find((s) => s.seek.kind === p.seek.kind && (s.seek.kind === "reynolds" || (p.seek.kind === "parker" && s.seek.kind === "parker" && Math.abs(s.seek.fraction - p.seek.fraction) < 1e-6)));
    group.append(new Option(`${label.split(" (")[0]} — ${seek?.label ?? p.seek.kind}`, String(i)));
  });
  presetIndex = Math.max(0, presets.findIndex((p) => p.boids === 300 && p.seek.kind === "parker" && Math.abs(p.seek.fraction - 0.1) < 1e-6));
  sel.value = String(presetIndex);
  sel.addEventListener("change", () => {
    presetIndex = Number(sel.value);
    const p = presets[presetIndex];
    if (p) load(p, true);
  });

  const first = presets[presetIndex];
  if (!first) {
    hook.error = "the core has no crowd presets";
    showMessage(hook.error, true);
    return;
  }
  panel = buildPanel($("panel"), {
    seek: first.seek, separation: first.separation, weight: first.separation_weight, boids: first.boids,
    radius: first.path.radius, closed: first.path.closed,
  }, {
    seek: (s) => apply((l) => l.setSeek(s)),
    separation: (on, w) => apply((l) => l.setSeparation(on, w)),
    boids: (n) => apply((l) => l.setBoidCount(n)),
    radius: (r) => apply((l) => l.setPathRadius(r)),
    closed: (c) => apply((l) => l.setPathClosed(c)),
    speed: (k) => {
      stepsPerFrame = k;
    },
    showTrace: (on) => {
      showTrace = on;
      dirty = true;
    },
    showHandles: (on) => {
      showHandles = on;
      if (!on) editor.selected = null;
      dirty = true;
    },
    addPoint: () => editor.insertMidpoint(),
    removePoint: () => editor.removeSelected(),
    fit: fitView,
    resetMetrics: () => apply((l) => l.resetMetrics()),
    newTrace: () => apply((l) => {
      const n = l.count();
      if (n > 0) l.selectTraced(Math.floor(Math.random() * n));
    }),
    png: () => downloadPng(canvas),
  });
  surface = setupCanvas(canvas, (s) => {
    const first = view.width <= 1;
    view.resize(s.width, s.height);
    if (first) fitView();
    dirty = true;
  });
  load(first, true);
  hook.ready = true;
  requestAnimationFrame(frame);
}

void start();
