// window.__lab: what the end-to-end tests and the perf harness read and
// drive, and the frame-time record behind perfStats().

import type { FunnelConfig, Internals, VehicleParams } from "../wasm";
import type { SteppingInfo } from "../workers/stepping";
import type { TableStatus } from "./sim";
import type { Handles } from "./handles";
import type { Vec } from "../view";
import { presetNames } from "./presets";
import { defaultState, type LabState } from "./state";

export interface PerfStats {
  frames: number;
  meanIntervalMs: number;
  meanWorkMs: number;
  p95WorkMs: number;
  meanStepMs: number;
  meanDrawMs: number;
  usPerUpdate: number;
  agents: number;
  /** Agent updates finished in the sampled frames, and those frames' wall
   *  time (issue 17: agents stepped per 16.7 ms = updates / (spanMs / 16.7)). */
  updates: number;
  spanMs: number;
  /** Frames that drew a newly stepped state. */
  steppedFrames: number;
}

/** What the end-to-end tests and the perf harness read (window.__lab). */
export interface LabHook {
  ready: boolean;
  error: string | null;
  problems: string[];
  version: string;
  /** performance.now() when the first frame with agents was drawn (issue
   *  17: before the η table has arrived, the scene at t = 0; for the
   *  default playground, drawn by the HTML's own script before the core
   *  is in, src/lab/firstframe.ts). */
  firstFrameMs: number;
  /** performance.now() when the η table was in force and the clock free. */
  tableMs: number;
  /** Whether the η table is in (the clock runs). */
  live(): boolean;
  frames: number;
  count(): number;
  mode(): number | null;
  internals(): Internals | null;
  /** The funnelling settings in force in the core. */
  funnel(): FunnelConfig | null;
  state(): LabState;
  /** CSS-pixel canvas coordinates of the focus target's centre, rim, handles and of the vehicle. */
  handles(): Handles | null;
  setPreset(name: string): Promise<void>;
  presets(): string[];
  setPaused(p: boolean): void;
  perfReset(): void;
  perfStats(): PerfStats;
  /** The η table's status (issue 14). */
  table(): TableStatus | null;
  /** The vehicle parameters in force in the core. */
  params(): VehicleParams | null;
  /** Keys in the browser's table cache. */
  cachedTables(): Promise<string[]>;
  /** Issue 17: how the world is stepped (this thread or N workers). */
  workers(): SteppingInfo | null;
  /** FNV-1a (hex) of the bits of every agent's state as drawn. */
  stateHash(): string;
  /** Runs k steps (paused) and resolves once they are drawn. */
  stepN(k: number): Promise<void>;
  /** Rebuilds the world at t = 0 (workers included) without unpausing. */
  restart(): Promise<void>;
  /** Issue 18: the avoidance method in force in the core. */
  avoidance(): string | null;
  /** Steps between an agent's avoidance plans in the core. */
  replanEvery(): number;
  /** Pairs of agents whose bodies overlap now (the core's count). */
  overlaps(): number;
  /** The core's obstacles (lab/obstacles.ts layout). */
  obstacles(): number[];
  /** CSS-pixel canvas positions of obstacle i's knobs (disc: centre, rim; wall: ends). */
  obstacleKnobs(i: number): Vec[];
  /** Agents in End_of_Steering, as last read from the core. */
  finished(): number;
  /** Simulated seconds since the last (re)build. */
  simTime(): number;
  /** The view's CSS pixels per metre. */
  viewScale(): number;
}

declare global {
  interface Window {
    __lab?: LabHook;
  }
}

/** Installs the hook with its not-yet-started answers; start() fills it in. */
export function installHook(): LabHook {
  const hook: LabHook = {
    ready: false,
    error: null,
    problems: [],
    version: "",
    // Issue 17: the default playground's frame drawn from the HTML (firstframe.ts), if it came first.
    firstFrameMs: window.__labFirst?.ms ?? NaN,
    tableMs: NaN,
    live: () => false,
    frames: 0,
    count: () => 0,
    mode: () => null,
    table: () => null,
    params: () => null,
    cachedTables: () => Promise.resolve([]),
    workers: () => null,
    stateHash: () => "",
    stepN: async () => {},
    restart: async () => {},
    avoidance: () => null,
    replanEvery: () => 0,
    overlaps: () => 0,
    obstacles: () => [],
    obstacleKnobs: () => [],
    finished: () => 0,
    simTime: () => 0,
    viewScale: () => 1,
    internals: () => null,
    funnel: () => null,
    state: () => defaultState(),
    handles: () => null,
    setPreset: async () => {},
    presets: () => presetNames(),
    setPaused: () => {},
    perfReset: () => {},
    perfStats: () => new Perf().stats(0),
  };
  window.__lab = hook;
  return hook;
}

/** The last 2000 frames' timings (ms) and the core's update cost. */
export class Perf {
  private intervals: number[] = [];
  private work: number[] = [];
  private step: number[] = [];
  private draw: number[] = [];
  private updates = 0;
  private updateMs = 0;
  private steppedFrames = 0;

  /** `updates` agent updates took `ms` in the core. */
  stepped(updates: number, ms: number): void {
    this.updates += updates;
    this.updateMs += ms;
    this.steppedFrames++;
  }

  frame(interval: number, work: number, step: number, draw: number): void {
    this.intervals.push(interval);
    this.work.push(work);
    this.step.push(step);
    this.draw.push(draw);
    if (this.intervals.length > 2000) {
      this.intervals.shift();
      this.work.shift();
      this.step.shift();
      this.draw.shift();
    }
  }

  reset(): void {
    this.intervals = [];
    this.work = [];
    this.step = [];
    this.draw = [];
    this.updates = 0;
    this.updateMs = 0;
    this.steppedFrames = 0;
  }

  stats(agents: number): PerfStats {
    const mean = (a: number[]): number => (a.length ? a.reduce((x, y) => x + y, 0) / a.length : 0);
    const sorted = [...this.work].sort((a, b) => a - b);
    return {
      frames: this.intervals.length,
      meanIntervalMs: mean(this.intervals),
      meanWorkMs: mean(this.work),
      p95WorkMs: sorted[Math.floor(sorted.length * 0.95)] ?? 0,
      meanStepMs: mean(this.step),
      meanDrawMs: mean(this.draw),
      usPerUpdate: this.updates ? (this.updateMs * 1000) / this.updates : 0,
      agents,
      updates: this.updates,
      spanMs: this.intervals.reduce((x, y) => x + y, 0),
      steppedFrames: this.steppedFrames,
    };
  }
}

/** FNV-1a, 32 bits, over the bit patterns of `a` (the worker/one-core check). */
export function fnvHex(a: Float32Array): string {
  const u = new Uint32Array(a.buffer, a.byteOffset, a.length);
  let h = 0x811c9dc5;
  for (let i = 0; i < u.length; i++) {
    const w = u[i] ?? 0;
    for (let b = 0; b < 32; b += 8) {
      h ^= (w >>> b) & 0xff;
      h = Math.imul(h, 0x01000193) >>> 0;
    }
  }
  return h.toString(16).padStart(8, "0");
}
