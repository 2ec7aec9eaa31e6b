// window.__crowd: what the end-to-end test reads and drives, and the step
// cost measurement behind it (bench).

import type { Vec } from "../view";
import { CrowdLab, type CrowdConfig, type CrowdMetrics, type CrowdSeek } from "../wasm";
import { isDefaultPreset } from "./presets";

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

/** Issue 17: how the crowd is stepped (window.__crowd.workers()). */
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
  /** Issue 17: counters the loop keeps (perfReset / perfStats read them). */
  workerUpdates: number;
  workerSteps: number;
  /** Wall ms of the workers' jobs, and of the slowest worker's stepping in them. */
  workerJobMs: number;
  workerStepMs: number;
  drawnFrames: number;
  workMs: number[];
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

/** FNV-1a over the bytes of `arrays` (hex). */
export function fnvHex(...arrays: Float32Array[]): string {
  let h = 0x811c9dc5;
  for (const a of arrays) {
    const b = new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
    for (let k = 0; k < b.length; k++) h = Math.imul(h ^ (b[k] ?? 0), 0x01000193);
  }
  return (h >>> 0).toString(16).padStart(8, "0");
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
