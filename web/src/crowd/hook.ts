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
