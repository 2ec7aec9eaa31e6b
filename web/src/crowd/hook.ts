// window.__crowd, in the test build only (`vite build --mode test`, the
// e2e suites' and the benches' build; main.ts installs it under
// `import.meta.env.MODE === "test"`, so the shipped bundle holds none of
// it): what the tests read and drive, read from the page's session and the
// loop's counters, and the step cost measurement behind it (bench).

import { fnvHex } from "../ui/fnv";
import type { Vec } from "../ui/view";
import { CrowdLab, type CrowdConfig, type CrowdMetrics, type CrowdSeek } from "../core/wasm";
import type { CrowdPage } from "./app";
import { isDefaultPreset } from "./presets";
import type { CrowdSession } from "./session";

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

/** How the crowd is stepped (window.__crowd.workers()). */
export interface CrowdWorkersInfo {
  mode: "main" | "shared" | "messages";
  workers: number;
  wanted: number;
  crossOriginIsolated: boolean;
  cores: number;
  starting: boolean;
  error: string | null;
  /** Boids each worker stepped in the last step. */
  owned: number[];
  /** Shared memory, 2 workers or more: each strip's share of the boids, balanced by the workers' speeds (stepper.ts, `rebalance`). */
  shares: number[];
  startMs: number;
}

/** A crowd at one step, to replay on one core (tests). */
export interface CrowdSnapshot {
  config: CrowdConfig;
  state: number[];
  time: number;
}

/** Frame figures since perfReset (make bench-web). */
export interface CrowdPerf {
  frames: number;
  spanMs: number;
  /** Boid updates completed (page's thread or workers). */
  updates: number;
  /** Frames that drew a new state. */
  drawnFrames: number;
  /** Workers with shared memory: steps taken but not drawn (the page
   *  drew a newer state instead). */
  skippedSteps: number;
  meanIntervalMs: number;
  meanWorkMs: number;
  p95WorkMs: number;
  /** Workers: wall ms per step of their jobs, and the slowest worker's stepping ms per step. */
  jobMsPerStep: number;
  workerMsPerStep: number;
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
  /** Steps completed per second over the last second. */
  stepsPerSecond: number;
  /** Steps completed since the page started (this thread or the workers). */
  stepsDone: number;
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
  workers(): CrowdWorkersInfo;
  /** FNV-1a (hex) of the drawn state, positions then velocities. */
  stateHash(): string;
  snapshot(): CrowdSnapshot;
  /** The hash `snap` reaches on one core (the page's thread) after `edit` and `steps` steps. */
  reference(snap: CrowdSnapshot, edit: { boids?: number; path?: number[] }, steps: number): string;
  /** Runs `n` steps (workers: one job each) and resolves when they are drawn state. */
  runSteps(n: number): Promise<void>;
  /** No step in flight. */
  idle(): boolean;
  /** Workers with shared memory: steps taken but not drawn since they started. */
  skippedSteps(): number;
  /** Test IV Parker 10 % with `n` boids at Test IV's density (pathway scaled by n / 300). */
  loadScaled(n: number): void;
  perfReset(): void;
  perfStats(): CrowdPerf;
}

/** Test IV Parker 10 % with `n` boids, pathway scaled by n / 300 (Test IV's density). */
export function scaledConfig(presets: readonly CrowdConfig[], n: number): CrowdConfig | null {
  const base = presets.find(isDefaultPreset) ?? presets[0];
  if (!base) return null;
  const k = n / 300;
  return { ...base, boids: n, path: { ...base.path, points: base.path.points.map(([x, y]) => [x * k, y * k]) } };
}

declare global {
  interface Window {
    __crowd?: CrowdHook;
  }
}

/** Step cost at each count in `counts`, each set-up timed for at least `minMs` (and 5 steps). */
export function bench(presets: readonly CrowdConfig[], counts: number[], minMs: number): BenchRow[] {
  const base = presets.find(isDefaultPreset) ?? presets[0];
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

/** Installs window.__crowd over `page` (its probe: the frames' work record). */
export function installHook(page: CrowdPage): void {
  const s = page.session;
  const stats = page.stats;
  let workMs: number[] = [];
  page.probe = (ms) => void workMs.push(ms);
  const skipped = (): number => s.stepper?.skipped ?? 0;
  let at = { t: 0, frames: 0, updates: 0, drawn: 0, skipped: 0, steps: 0, jobMs: 0, stepMs: 0 };
  const hook: CrowdHook = {
    get ready() { return page.ready; },
    get error() { return page.error; },
    get frames() { return stats.frames; },
    get playing() { return s.playing; },
    get stepMs() { return stats.stepMs; },
    get drawMs() { return stats.drawMs; },
    get fps() { return stats.fps; },
    get stepsPerSecond() { return stats.stepsPerSecond; },
    get stepsDone() { return stats.steps; },
    get preset() { return s.preset; },
    count: () => s.lab?.count() ?? 0,
    time: () => s.lab?.time() ?? 0,
    pathPoints: () => Array.from(s.lab?.pathPoints() ?? []),
    pathRadius: () => s.lab?.pathRadius() ?? 0,
    seek: () => (s.lab ? s.lab.config().seek : null),
    separation: () => (s.lab ? s.lab.config().separation : false),
    selected: () => s.editor.selected,
    metrics: () => (s.lab ? s.lab.metrics() : null),
    toScreen: (x, y) => s.view.toScreen(x, y),
    bench: (counts, minMs) => bench(page.presets, counts, minMs),
    workers: () => workersInfo(s),
    stateHash: () => {
      const l = s.lab;
      if (!l) return "";
      return fnvHex(s.stepper?.active ? s.stepper.state : l.state());
    },
    snapshot: () => {
      s.syncFromWorkers();
      const l = s.lab;
      if (!l) throw new Error("no crowd");
      return { config: l.config(), state: Array.from(l.state()), time: l.time() };
    },
    reference: (snap, edit, steps) => reference(snap, edit, steps),
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
    skippedSteps: skipped,
    loadScaled: (n) => {
      const c = scaledConfig(page.presets, n);
      if (c) s.load(c, true);
    },
    perfReset: () => {
      workMs = [];
      at = { t: performance.now(), frames: stats.frames, updates: stats.updates, drawn: stats.drawnFrames, skipped: skipped(), steps: stats.steps, jobMs: stats.jobMs, stepMs: stats.workerStepMs };
    },
    perfStats: () => {
      const now = performance.now();
      const frames = stats.frames - at.frames;
      const w = [...workMs].sort((a, b) => a - b);
      const steps = Math.max(1, stats.steps - at.steps);
      return {
        frames,
        spanMs: now - at.t,
        updates: stats.updates - at.updates,
        drawnFrames: stats.drawnFrames - at.drawn,
        skippedSteps: skipped() - at.skipped,
        meanIntervalMs: (now - at.t) / Math.max(1, frames),
        meanWorkMs: w.reduce((a, b) => a + b, 0) / Math.max(1, w.length),
        p95WorkMs: w[Math.min(w.length - 1, Math.floor(0.95 * w.length))] ?? 0,
        jobMsPerStep: (stats.jobMs - at.jobMs) / steps,
        workerMsPerStep: (stats.workerStepMs - at.stepMs) / steps,
      };
    },
  };
  window.__crowd = hook;
}

/** How the session's crowd is stepped. */
function workersInfo(s: CrowdSession): CrowdWorkersInfo {
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
}

/** The hash `snap` reaches on one core after `edit` and `steps` steps. */
function reference(snap: CrowdSnapshot, edit: { boids?: number; path?: number[] }, steps: number): string {
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
}
