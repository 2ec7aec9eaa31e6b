// window.__lab, in the test build only (`vite build --mode test`, the
// e2e suites' and the benches' build; main.ts installs it under
// `import.meta.env.MODE === "test"`, so the shipped bundle holds none of
// it): what the tests read and drive, read from the page's record
// (app.ts), and the frame-time record behind perfStats().

import { fnvHex } from "../ui/fnv";
import { Mode, StateField, type FunnelConfig, type Internals, type VehicleParams } from "../core/wasm";
import type { SteppingInfo } from "./stepping";
import { cacheKeys } from "./tablecache";
import type { Vec } from "../ui/view";
import type { FrameProbe, LabPage, LabParts } from "./app";
import type { TableStatus } from "./sim";
import { pick, type Handles } from "./handles";
import type { PeerGhost } from "./compare";
import { obstacleKnobs } from "./obstacles";
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
   *  time (agents stepped per 16.7 ms = updates / (spanMs / 16.7)). */
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
  /** performance.now() when the first frame with agents was drawn (before
   *  the η table has arrived, the scene at t = 0; for the default
   *  playground, drawn by the HTML's own script before the core is in,
   *  src/lab/firstframe.ts). */
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
  /** The core's control modes by name (the bindings' `Mode`). */
  coreModes(): string[];
  /** The handle a press at canvas point (x, y), CSS px, would grab, or null. */
  handleKindAt(x: number, y: number): string | null;
  presets(): string[];
  setPaused(p: boolean): void;
  perfReset(): void;
  perfStats(): PerfStats;
  /** The η table's status. */
  table(): TableStatus | null;
  /** The vehicle parameters in force in the core. */
  params(): VehicleParams | null;
  /** Keys in the browser's table cache. */
  cachedTables(): Promise<string[]>;
  /** How the world is stepped (this thread or N workers). */
  workers(): SteppingInfo | null;
  /** FNV-1a (hex) of the bits of every agent's state as drawn. */
  stateHash(): string;
  /** Runs k steps (paused) and resolves once they are drawn. */
  stepN(k: number): Promise<void>;
  /** Rebuilds the world at t = 0 (workers included) without unpausing. */
  restart(): Promise<void>;
  /** The avoidance method in force in the world. */
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
  /** The CSS-pixel canvas point of world point (x, y) in the view now. */
  screenOf(x: number, y: number): Vec | null;
  /** Agent i's goal position as drawn (null: no such agent). */
  goal(i: number): Vec | null;
  /** Agent i's pose, speed, angular speed and mode as drawn (null: no such agent). */
  agentRecord(i: number): { x: number; y: number; theta: number; v: number; omega: number; mode: number } | null;
  /** The compare view's ghosts as last drawn (ours, Yuka arrive, Yuka seek) and its note. */
  peerGhosts(): { ghosts: PeerGhost[]; note: string } | null;
}

declare global {
  interface Window {
    __lab?: LabHook;
  }
}

/** The last 2000 frames' timings (ms) and the core's update cost. */
export class Perf implements FrameProbe {
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

/** The hook's answer before the page has started (`parts` null). */
function started<T>(page: LabPage, f: (p: LabParts) => T, none: T): () => T {
  return () => (page.parts ? f(page.parts) : none);
}

/** Installs window.__lab over `page` (its probe: a new Perf). */
export function installHook(page: LabPage): void {
  const perf = new Perf();
  page.probe = perf;
  const { status, loop } = page;
  const on = <T>(f: (p: LabParts) => T, none: T): (() => T) => started(page, f, none);
  const core = (p: LabParts) => p.sim.world.core();
  const hook: LabHook = {
    get ready() { return status.ready; },
    get error() { return status.error; },
    get problems() { return status.problems; },
    get version() { return status.version; },
    get tableMs() { return status.tableAt; },
    get frames() { return loop.frames; },
    // The default playground's frame drawn from the HTML (firstframe.ts), if it came first.
    get firstFrameMs() { return window.__firstFrame?.ms ?? loop.firstDrawnMs; },
    live: on((p) => p.sim.live, false),
    count: on((p) => p.sim.count, 0),
    mode: on((p) => p.sim.internals?.mode ?? null, null),
    internals: on((p) => p.sim.internals, null),
    funnel: on((p) => core(p)?.funnel() ?? null, null),
    state: on((p) => structuredClone(p.sim.st), defaultState()),
    handles: on((p) => p.handles(), null),
    coreModes: () => Object.keys(Mode).filter((k) => Number.isNaN(Number(k))),
    handleKindAt: (x, y) => {
      const p = page.parts;
      const h = p?.handles() ?? null;
      return p && h ? pick({ x, y }, h, p.sim.st.dTol * p.view.scale) : null;
    },
    setPreset: (name) => page.parts?.transport.setPreset(name) ?? Promise.resolve(),
    presets: () => presetNames(),
    setPaused: (b) => page.parts?.transport.setPaused(b),
    perfReset: () => perf.reset(),
    perfStats: () => perf.stats(page.parts?.sim.count ?? 0),
    table: on((p) => ({ ...p.sim.table }), null),
    params: on((p) => core(p)?.params() ?? p.sim.params(), null),
    cachedTables: cacheKeys,
    workers: on((p) => p.sim.stepper?.info(p.sim.workersWanted) ?? null, null),
    stateHash: on((p) => fnvHex(p.sim.state), ""),
    stepN: (k) => page.parts?.sim.stepNow(k) ?? Promise.resolve(),
    restart: () => page.parts?.sim.rebuild(false) ?? Promise.resolve(),
    avoidance: on((p) => core(p)?.avoidance() ?? p.sim.avoid.method, null),
    replanEvery: on((p) => core(p)?.avoidanceReplanEvery() ?? p.sim.avoid.replanEvery, 0),
    overlaps: on((p) => core(p)?.overlaps() ?? 0, 0),
    obstacles: on((p) => Array.from(core(p)?.obstacles() ?? p.sim.avoid.obstacles), []),
    obstacleKnobs: (i) => (page.parts ? obstacleKnobs(page.parts.view, page.parts.sim.avoid.obstacles, i) : []),
    finished: on((p) => {
      let n = 0;
      for (let i = 0; i < p.sim.count; i++) if (p.sim.field(i, StateField.Mode) === Mode.EndOfSteering) n++;
      return n;
    }, 0),
    simTime: on((p) => p.sim.time, 0),
    viewScale: on((p) => p.view.scale, 1),
    screenOf: (x, y) => page.parts?.view.toScreen(x, y) ?? null,
    goal: (i) => {
      const sim = page.parts?.sim;
      if (!sim || i < 0 || i >= sim.count) return null;
      return { x: sim.field(i, StateField.GoalX) ?? NaN, y: sim.field(i, StateField.GoalY) ?? NaN };
    },
    peerGhosts: on((p) => ({ ghosts: p.compare.ghosts, note: p.compare.note }), null),
    agentRecord: (i) => {
      const sim = page.parts?.sim;
      if (!sim || i < 0 || i >= sim.count) return null;
      const f = (k: StateField): number => sim.field(i, k) ?? NaN;
      return { x: f(StateField.X), y: f(StateField.Y), theta: f(StateField.Theta), v: f(StateField.V), omega: f(StateField.Omega), mode: f(StateField.Mode) };
    },
  };
  window.__lab = hook;
}
