// The lab's world stepped across cores (issue 17, point 2): N stepping
// workers (step.worker.ts) on the one worker layer (pool.ts, `each`: task i
// to worker i), each owning a contiguous slice of agents.
//
// - Slices: `Lab.splitRanges(N)` (crate/funnelling/world_split.rs) about
//   equal ranges whose cuts never separate an agent from the agent its goal
//   faces (paper 000 Fig. 6): the world reads other agents only through
//   those links, from the step's start, so each slice steps to the same
//   bits as the whole world. No per-step exchange between workers is needed.
//   Avoidance (issue 18) couples every agent: one slice, then.
// - Each worker rebuilds its slice from the page's recipe (the calls the
//   page made: limits, scenario or playground, controller settings): a
//   scenario whole, then `retainRange`; the playground's random crowd only
//   its range (`spawnRandomRange`). Edits (drags, settings, a new table)
//   follow in the next task.
// - The page never waits for a worker: a frame with no new complete state
//   draws the last one again.
// - Shared memory where the page is cross-origin isolated (COOP/COEP, see
//   vite.config.ts): STATES SharedArrayBuffers (continuing.ts: eight) each
//   worker writes its slice into, and steps run as continuing jobs
//   (continuing.ts, as the crowd's): the workers step on while the page
//   asks, each at its own pace, without the crowd's barrier
//   (`runIndependent`: slices never read each other), the last to finish a
//   step publishing it; the worker owning the shown agent leaves its
//   internals in the step's note (slicebuffers.ts), and the page draws
//   every state in order, up to DEPTH states behind the newest. A host that cannot keep
//   up runs the world slower than real time instead of stepping states it
//   never draws.
//   Edits and a newly shown agent end the job in flight; the next one
//   carries them. Issue 17: a job of the steps owed, handed over and back
//   every frame, cost 4–10 ms per step at 100,000 agents in 2 workers, so
//   jobs of two steps followed and the page drew 30–47 new states per
//   second; now 52–56, every one of them (README).
// - Elsewhere the states come back by message (transferred, no copy), a
//   job of the steps owed per frame (at most MAX_STEPS_PER_JOB, the world
//   in real time), into the back buffer; then the two swap.

import type { AgentConfig, FunnelConfig, GoalConfig, Internals, Lab, RelaxedConfig, VehicleParams } from "../wasm";
import { stateBuffers } from "./buffers";
import { ContinuingJobs, CTRL_BYTES, SLOT_RING, STATES } from "./continuing";
import { NOTE_BYTES, readNote, SAB, SLOT } from "./slicebuffers";
import { SteppingJobs } from "./jobs";
import { WorkerPool } from "./pool";

/** Where a worker finds the η table in force: its bytes (a table built for
 *  other limits, issue 14) or the committed table's URL. */
export interface TableSource {
  key: string;
  url: string;
  bytes: Uint8Array | null;
}

/** The calls that built the page's world, replayed by every worker. */
export interface Recipe {
  table: TableSource;
  params: VehicleParams;
  funnel: FunnelConfig;
  relaxed: RelaxedConfig;
  build:
    | { kind: "scenario"; text: string }
    | { kind: "playground"; agent: AgentConfig | null; spawn: { n: number; seed: number; extent: number; speed: number } | null };
}

/** An edit of the running world (`i`: the agent's index in the whole world). */
export type Edit =
  | { kind: "goal"; i: number; goal: GoalConfig }
  | { kind: "pose"; i: number; x: number; y: number; theta: number }
  | { kind: "funnel"; funnel: FunnelConfig; relaxed: RelaxedConfig }
  | { kind: "params"; params: VehicleParams }
  | { kind: "table"; bytes: Uint8Array; key: string };

/** One task: (re)build the slice if `init`, apply `edits`, step `steps`
 *  times, write the states into buffer `buffer`; `shown`: the agent whose
 *  internals the HUD shows. */
export interface StepTask {
  init: { recipe: Recipe; start: number; end: number; shared: SharedArrayBuffer[] | null } | null;
  edits: Edit[];
  steps: number;
  /** The buffer written (a continuing job: the drawn one, stepped from). */
  buffer: number;
  shown: number;
  /** Shared memory, steps > 0: a continuing job (continuing.ts). */
  continuing: boolean;
  worker: number;
  workers: number;
}

export interface StepReply {
  time: number;
  internals: Internals | null;
  /** The slice's states when there is no shared memory. */
  state: Float32Array | null;
  /** Wall ms of the worker's `step` calls. */
  stepMs: number;
}

/** Steps one job runs at most (a frame's worth when the workers keep up). */
const MAX_STEPS_PER_JOB = 4;

/** Agents from which the page steps in workers by default, measured with
 *  `make bench-web` (web/test/perf.mjs, README figures) on the 2-core host:
 *  at 10,000 the page's thread steps and draws at 40–60 fps and the workers
 *  only add their start (0.3–0.6 s) and a frame of latency; from 20,000 it
 *  fell to 14–58 fps (12–63 ms of work per frame) while with workers the
 *  page kept 36–60 fps at 1.5–4 ms per frame. Agents stepped per second
 *  were not higher with workers on that loaded host (README). */
export const AUTO_WORKERS_FROM = 20_000;

/** `?workers=N` (0 = off) or, unset, the default for `count` agents:
 *  `navigator.hardwareConcurrency` workers from AUTO_WORKERS_FROM agents.
 *  A bad value is reported by `problem` and the default kept. */
export function workersWanted(count: number, search = location.search): { n: number; problem: string | null } {
  const auto = count >= AUTO_WORKERS_FROM ? Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2)) : 0;
  const raw = new URLSearchParams(search).get("workers");
  if (raw === null) return { n: auto, problem: null };
  const n = /^\d{1,2}$/.test(raw) ? Number(raw) : NaN;
  if (!(n >= 0 && n <= 16)) return { n: auto, problem: `workers = ${raw} is not a whole number of workers in [0, 16]; using ${auto}` };
  return { n, problem: null };
}

/** How the world is stepped (HUD, window.__lab.workers()). */
export interface SteppingInfo {
  /** `main`: on the page's thread; `shared` / `messages`: in workers. */
  mode: "main" | "shared" | "messages";
  workers: number;
  /** Each worker's agents, [start, end). */
  ranges: Array<[number, number]>;
  crossOriginIsolated: boolean;
  cores: number;
  /** The slowest worker's stepping time per agent update of the whole
   *  world, µs (0 before the first step). */
  usPerUpdate: number;
  /** Wall ms the last start took (each worker rebuilds the world, keeps its slice). */
  startMs: number;
  /** Workers asked for (URL or default). */
  wanted: number;
  starting: boolean;
  error: string | null;
}

export class WorldStepper extends SteppingJobs<StepTask, StepReply> {
  ranges: Array<[number, number]> = [];
  /** The last complete state (what the page draws). */
  state: Float32Array = new Float32Array(0);
  /** Internals of the shown agent in that state. */
  internals: Internals | null = null;
  /** A newer complete state arrived since the page last looked. */
  fresh = false;
  private back: Float32Array = new Float32Array(0);
  private sab: SharedArrayBuffer[] | null = null;
  private frontIndex = 0;
  /** Shared memory: the continuing jobs (over `sab[SAB.ctrl]`), and the
   *  agent whose internals the one in flight notes. */
  private jobs: ContinuingJobs | null = null;
  private jobShown = 0;
  private edits: Edit[] = [];
  private shown = 0;
  /** Called with the new front state when the buffers swap (the page
   *  must not keep drawing the buffer the next job writes into). */
  onSwap: (state: Float32Array) => void = () => {};
  /** Sum over jobs of the slowest worker's stepping ms, and agent updates
   *  (the workers' own cost per update, beside the jobs' wall time). */
  workerMs = 0;
  workerUpdates = 0;

  constructor(
    readonly workers: number,
    private readonly stride: number,
  ) {
    super(new WorkerPool<StepTask, StepReply>(() => new Worker(new URL("./step.worker.ts", import.meta.url), { type: "module" }), workers));
  }

  /** Splits `lab`'s world (just built by `recipe`, at t = 0) across the
   *  workers; `initial` (its state) is drawn until they are ready. */
  start(recipe: Recipe, lab: Lab, initial: Float32Array, shown: number): Promise<void> {
    return this.restart((gen) => {
      this.edits = [];
      const flat = lab.splitRanges(this.workers);
      const ranges: Array<[number, number]> = [];
      for (let k = 0; k + 1 < flat.length; k += 2) ranges.push([flat[k] ?? 0, flat[k + 1] ?? 0]);
      this.ranges = ranges;
      this.jobs?.drop();
      ({ sab: this.sab, state: this.state, back: this.back } = stateBuffers(initial, this.shared, this.shared ? STATES : 2, [CTRL_BYTES, 4 * SLOT * SLOT_RING, NOTE_BYTES * SLOT_RING]));
      this.jobs = this.sab ? new ContinuingJobs(new Int32Array(this.sab[SAB.ctrl] as SharedArrayBuffer)) : null;
      this.frontIndex = 0;
      const sab = this.sab;
      return this.swapJob(gen, (buffer) =>
        ranges.map(([start, end], k) => ({ init: { recipe, start, end, shared: sab }, edits: [], steps: 0, buffer, shown, continuing: false, worker: k, workers: ranges.length })),
      );
    });
  }

  /** `steps` more steps are owed (at most a job's worth wait: a slow host
   *  drops the rest). Shared memory: the target of the job in flight rises
   *  (`ContinuingJobs.raise`: a host that cannot keep up runs slower than real time
   *  rather than stepping states the page never draws). */
  request(steps: number): void {
    const jobs = this.jobs;
    if (jobs && steps > 0) jobs.perFrame = Math.min(MAX_STEPS_PER_JOB, steps);
    if (jobs?.running) jobs.raise(jobs.perFrame, steps);
    else this.owed = Math.min(MAX_STEPS_PER_JOB, this.owed + steps);
  }

  /** An edit for the next job (a continuing job in flight ends, so that
   *  the next one carries it). */
  edit(e: Edit): void {
    this.edits.push(e);
    if (this.jobs?.running) this.jobs.end();
  }

  /** Starts a job if none is in flight and something is owed; never waits.
   *  A continuing job noting another agent's internals ends. */
  pump(shown: number): void {
    this.shown = shown;
    if (this.jobs?.running && shown !== this.jobShown) this.jobs.end();
    if (!this.ready || !this.idle || (this.owed === 0 && this.edits.length === 0)) return;
    const steps = this.owed;
    this.owed = 0;
    void this.dispatch(steps, shown);
  }

  /** Runs `steps` steps (and the pending edits) as one job; resolves when
   *  its state is the front one (tests, single steps; paused, exactly
   *  `steps`: a continuing job also takes the steps frames ask meanwhile). */
  run(steps: number, shown: number): Promise<void> {
    return this.dispatch(steps, shown);
  }

  private dispatch(steps: number, shown: number): Promise<void> {
    const edits = this.edits;
    this.edits = [];
    const workers = this.ranges.length;
    if (this.jobs && steps > 0) return this.continuingJob(this.jobs, steps, shown, edits);
    return this.swapJob(this.gen, (buffer) => this.ranges.map((_, k) => ({ init: null, edits, steps, buffer, shown, continuing: false, worker: k, workers })), steps);
  }

  /** Shared memory: a continuing job from the drawn state, asked for
   *  `steps` (more as frames ask); resolves when it has ended and its last
   *  state is the front one. */
  private continuingJob(jobs: ContinuingJobs, steps: number, shown: number, edits: Edit[]): Promise<void> {
    const workers = this.ranges.length;
    return this.job(
      this.gen,
      () => {
        jobs.begin(this.frontIndex, steps);
        this.jobShown = shown;
        return this.ranges.map((_, k) => ({ init: null, edits, steps, buffer: this.frontIndex, shown, continuing: true, worker: k, workers }));
      },
      // The internals come with each state's note (`poll`), not the replies.
      (_replies, t0) => {
        this.poll(true);
        // Steps a frame asked for after the workers' last decision.
        this.owed = Math.max(this.owed, jobs.finish(MAX_STEPS_PER_JOB));
        this.done.ms += performance.now() - t0;
      },
    );
  }

  /** Shared memory: takes the state to draw among those the continuing job
   *  has published since the last call (`ContinuingJobs.take`: in order, up to
   *  DEPTH behind the newest; `newest`: the newest), with the shown agent's
   *  internals noted for it. Called every frame, before drawing. */
  poll(newest = false): void {
    const sab = this.sab;
    if (!sab || !this.jobs) return;
    const slots = new Float32Array(sab[SAB.slots] as SharedArrayBuffer);
    const picked = this.jobs.take(newest, (k) => slots[SLOT * ((k - 1) % SLOT_RING) + 1] ?? 0);
    if (!picked) return;
    const { from, step: c, buffer } = picked;
    let ms = 0;
    for (let k = from + 1; k <= c; k++) ms += slots[SLOT * ((k - 1) % SLOT_RING)] ?? 0;
    this.internals = readNote(sab[SAB.notes] as SharedArrayBuffer, c) ?? this.internals;
    this.frontIndex = buffer;
    this.state = new Float32Array(sab[buffer] as SharedArrayBuffer);
    const steps = c - from;
    this.done.steps += steps;
    this.done.workerMs += ms;
    this.workerMs += ms;
    this.workerUpdates += steps * (this.ranges.at(-1)?.[1] ?? 0);
    this.fresh = true;
    this.onSwap(this.state);
  }


  /** One job on every worker writing the back buffer (`buffer`), then the
   *  two swap (a worker answers in order, and `each` hands each answer to
   *  the job in force). */
  private swapJob(gen: number, tasks: (buffer: number) => StepTask[], steps = 0): Promise<void> {
    let buffer = 0;
    return this.job(
      gen,
      () => {
        buffer = this.sab ? (this.frontIndex + 1) % STATES : 1 - this.frontIndex;
        return tasks(buffer);
      },
      (replies, t0) => {
        let front: Float32Array;
        if (this.sab) front = new Float32Array(this.sab[buffer] as SharedArrayBuffer);
        else {
          replies.forEach((r, k) => {
            const start = this.ranges[k]?.[0] ?? 0;
            if (r.state) this.back.set(r.state, start * this.stride);
          });
          front = this.back;
          this.back = this.state;
        }
        this.state = front;
        this.frontIndex = buffer;
        this.internals = replies.find((r) => r.internals !== null)?.internals ?? null;
        this.done.steps += steps;
        const slowest = Math.max(...replies.map((r) => r.stepMs));
        this.workerMs += slowest;
        this.done.workerMs += slowest;
        this.workerUpdates += steps * (this.ranges.at(-1)?.[1] ?? 0);
        this.done.ms += performance.now() - t0;
        this.fresh = true;
        this.onSwap(front);
      },
    );
  }

  protected afterJob(): void {
    // The next job starts at once if steps are owed (not at the next frame).
    this.pump(this.shown);
  }

  info(wanted: number): SteppingInfo {
    return {
      mode: this.active ? (this.sab ? "shared" : "messages") : "main",
      workers: this.ranges.length,
      ranges: this.ranges,
      crossOriginIsolated: globalThis.crossOriginIsolated === true,
      cores: navigator.hardwareConcurrency || 0,
      usPerUpdate: this.workerUpdates > 0 ? (this.workerMs * 1000) / this.workerUpdates : 0,
      startMs: this.startMs,
      wanted,
      starting: this.active && !this.ready,
      error: this.error,
    };
  }

  /** Stops stepping (a newer world, or back to the page's thread); the
   *  workers are kept for the next start. */
  override stop(): void {
    this.jobs?.drop();
    super.stop();
    this.edits = [];
  }
}
