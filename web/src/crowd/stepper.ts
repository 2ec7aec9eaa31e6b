// The crowd stepped across cores (issue 17, point 3): N crowd workers
// (crowd.worker.ts) on the one worker layer (../workers/pool.ts, `each`:
// task i to worker i), each stepping the boids of one vertical strip.
//
// - Split by space, re-decided every step: the cuts are quantiles of x in
//   the last complete state (a sample of it), so each strip holds about
//   n / N boids wherever the crowd is. A worker reads every position of
//   the last complete state (the core's step is a Jacobi step: separation
//   reads the positions at the step's start), so its strip's boids get the
//   same bits as on one core (`Crowd::step_strip`, tests/crowd_determinism.rs)
//   and no boid has to migrate between workers.
// - The page records the traced boid's lap from every complete state
//   (`CrowdLab.observeStep`).
// - Shared memory where the page is cross-origin isolated (COOP/COEP):
//   three state buffers; the page draws the front one (the last complete
//   state) while a job runs the steps owed (a frame's worth) through the other
//   two, the workers meeting at a barrier (Atomics) between steps, without
//   the page; worker 0 notes the traced boid's position after each step.
//   When every worker has answered the last written buffer becomes the
//   front. The page never waits for a worker.
// - Else one step per job: the front state goes to each worker by message
//   and the stepped boids come back with their indices (transferred),
//   copied here into the back buffer, then the two swap.
// - Edits (count, path, seek, …) are made on the page's CrowdLab, loaded
//   with the front state first; then the workers restart from its
//   configuration and state (`start`), after the job in flight.

import type { CrowdConfig } from "../wasm";
import { stateBuffers } from "../workers/buffers";
import { SteppingJobs } from "../workers/jobs";
import { WorkerPool } from "../workers/pool";

export interface CrowdTask {
  init: { config: CrowdConfig; shared: SharedArrayBuffer[] | null } | null;
  /** 0: only (re)build. */
  steps: number;
  /** Shared buffer holding the state to step (the other one is written). */
  front: number;
  /** The state to step when there is no shared memory. */
  state: Float32Array | null;
  time: number;
  lo: number;
  hi: number;
  /** This worker's strip (shared memory: the cuts are made in the workers, each step). */
  worker: number;
  workers: number;
  /** The traced boid (shared memory: worker 0 notes it after every step but the last). */
  traced: number;
}

export interface CrowdReply {
  stepMs: number;
  owned: number;
  /** Without shared memory: the stepped boids and their `[x, y, vx, vy]`. */
  indices: Uint32Array | null;
  states: Float32Array | null;
}

/** Boids from which the page steps the crowd in workers by default
 *  (measured, README: below it the page's thread keeps 60 fps). */
export const AUTO_WORKERS_FROM = 20_000;

/** Steps one job runs at most (shared memory: the page's "steps / frame"
 *  goes up to 20). */
const MAX_STEPS_PER_JOB = 20;

/** `?workers=N` (0 = page's thread) or, unset, from AUTO_WORKERS_FROM boids
 *  a worker per core but one (at least one): the page's drawing keeps a
 *  core (measured on 2 cores, 100,000 boids at Test IV density, stepped +
 *  drawn per frame: 1 worker 85,126, 2 workers 66,608; 200,000: 78,735 and
 *  79,835; README). A bad value is reported. */
export function crowdWorkersWanted(count: number, search = location.search): { n: number; problem: string | null } {
  const auto = count >= AUTO_WORKERS_FROM ? Math.max(1, Math.min(8, (navigator.hardwareConcurrency || 2) - 1)) : 0;
  const raw = new URLSearchParams(search).get("workers");
  if (raw === null) return { n: auto, problem: null };
  const n = /^\d{1,2}$/.test(raw) ? Number(raw) : NaN;
  if (!(n >= 0 && n <= 16)) return { n: auto, problem: `workers = ${raw} is not a whole number of workers in [0, 16]; using ${auto}` };
  return { n, problem: null };
}

/** Cuts of x into `k` strips of about equal counts, from a sample of `pos`
 *  (flat x, y); the first is −∞ and the last +∞. */
export function stripCuts(state: Float32Array, n: number, k: number): number[] {
  const cuts = [-Infinity];
  if (k > 1 && n > 0) {
    const stride = Math.max(1, Math.floor(n / 4096));
    const xs: number[] = [];
    for (let i = 0; i < n; i += stride) {
      const x = state[2 * i] ?? 0;
      if (Number.isFinite(x)) xs.push(x);
    }
    xs.sort((a, b) => a - b);
    for (let w = 1; w < k; w++) cuts.push(Math.fround(xs[Math.floor((w * xs.length) / k)] ?? 0));
  } else {
    for (let w = 1; w < k; w++) cuts.push(0);
  }
  cuts.push(Infinity);
  return cuts;
}

export class CrowdStepper extends SteppingJobs<CrowdTask, CrowdReply> {
  /** The last complete state, `[positions | velocities]` (what the page draws). */
  state: Float32Array = new Float32Array(0);
  /** Its step count. */
  time = 0;
  count = 0;
  private back: Float32Array = new Float32Array(0);
  private sab: SharedArrayBuffer[] | null = null;
  private frontIndex = 0;
  /** Called when a job's last step is the front state (the traced boid:
   *  read it there); before that `onTraced` with its position after each
   *  earlier step of the job. */
  onStep: (state: Float32Array) => void = () => {};
  onTraced: (x: number, y: number) => void = () => {};
  /** Boids per worker in the last step. */
  owned: number[] = [];

  constructor(readonly workers: number) {
    super(new WorkerPool<CrowdTask, CrowdReply>(() => new Worker(new URL("./crowd.worker.ts", import.meta.url), { type: "module" }), workers));
  }

  /** (Re)starts the workers on `config` from `state` (`CrowdLab.state()`) at step `time`. */
  start(config: CrowdConfig, state: Float32Array, time: number): Promise<void> {
    return this.restart((gen) => {
      this.count = state.length >> 2;
      // Three states (front, back, spare), the barrier's counter, the step slots.
      ({ sab: this.sab, state: this.state, back: this.back } = stateBuffers(state, this.shared, 3, [4, 4 * 2 * MAX_STEPS_PER_JOB]));
      this.frontIndex = 0;
      this.time = time;
      const init = { config, shared: this.sab };
      const w = this.workers;
      return this.job(
        gen,
        () => Array.from({ length: w }, (_, k) => ({ init, steps: 0, front: 0, state: null, time, lo: 0, hi: 0, worker: k, workers: w, traced: 0 })),
        () => {},
      );
    });
  }

  /** A frame asks for `steps` steps. At most one frame's worth waits: a
   *  host that cannot keep up runs slower than real time rather than
   *  batching steps the page would never draw (one step per frame: one
   *  step per job, every state drawn). */
  request(steps: number): void {
    this.owed = Math.min(Math.min(MAX_STEPS_PER_JOB, steps), this.owed + steps);
  }

  /** Starts a step if none is in flight and one is owed; never waits. */
  pump(): void {
    if (!this.ready || !this.idle || this.owed === 0) return;
    const k = this.sab ? this.owed : 1;
    this.owed -= k;
    void this.step(k);
  }

  /** Runs `k` steps (shared memory; else one) as one job; resolves when its state is the front one. */
  step(k = 1): Promise<void> {
    const steps = this.sab ? Math.max(1, Math.min(MAX_STEPS_PER_JOB, k)) : 1;
    return this.job(
      this.gen,
      () => {
        const cuts = this.sab ? [] : stripCuts(this.state, this.count, this.workers);
        if (this.sab) Atomics.store(new Int32Array(this.sab[3] as SharedArrayBuffer), 0, 0);
        const traced = this.traced();
        return Array.from({ length: this.workers }, (_, w) => ({
          init: null, steps, front: this.frontIndex, state: this.sab ? null : this.state, time: this.time,
          lo: cuts[w] ?? 0, hi: cuts[w + 1] ?? Infinity, worker: w, workers: this.workers, traced,
        }));
      },
      (replies, t0) => this.land(replies, steps, t0),
    );
  }

  /** The boid whose lap the page records (set by the page). */
  traced: () => number = () => 0;

  /** A step job's replies: its last state becomes the front one. */
  private land(replies: CrowdReply[], steps: number, t0: number): void {
    if (this.sab) {
      const sab = this.sab;
      const others = [0, 1, 2].filter((b) => b !== this.frontIndex);
      const last = others[(steps - 1) % 2] ?? 0;
      const slots = new Float32Array(sab[4] as SharedArrayBuffer);
      for (let s = 0; s + 1 < steps; s++) this.onTraced(slots[2 * s] ?? 0, slots[2 * s + 1] ?? 0);
      this.frontIndex = last;
      this.state = new Float32Array(sab[last] as SharedArrayBuffer);
    } else {
      const back = this.back;
      const half = back.length >> 1;
      back.set(this.state);
      for (const r of replies) {
        const idx = r.indices;
        const st = r.states;
        if (!idx || !st) continue;
        for (let k = 0; k < idx.length; k++) {
          const i = 2 * (idx[k] ?? 0);
          back[i] = st[4 * k] ?? 0;
          back[i + 1] = st[4 * k + 1] ?? 0;
          back[half + i] = st[4 * k + 2] ?? 0;
          back[half + i + 1] = st[4 * k + 3] ?? 0;
        }
      }
      this.back = this.state;
      this.state = back;
    }
    this.time += steps;
    this.owned = replies.map((r) => r.owned);
    this.done.steps += steps;
    this.done.workerMs += Math.max(...replies.map((r) => r.stepMs));
    this.done.ms += performance.now() - t0;
    this.onStep(this.state);
  }

  protected afterJob(): void {
    // The next step starts at once if one is owed (not at the next frame).
    this.pump();
  }
}
