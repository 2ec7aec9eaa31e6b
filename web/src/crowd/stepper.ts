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
// - One step per job, so the page sees every complete state: it records
//   the traced boid's lap from it (`CrowdLab.observeStep`).
// - Double buffer: workers write into the back buffer while the page draws
//   the front one (the last complete state); when every worker has
//   answered, the two swap. The page never waits for a worker.
// - Shared memory where the page is cross-origin isolated (COOP/COEP): the
//   two buffers are SharedArrayBuffers the workers read and write. Else the
//   front state goes to each worker by message and the stepped boids come
//   back with their indices (transferred), copied here into the back buffer.
// - Edits (count, path, seek, …) are made on the page's CrowdLab, loaded
//   with the front state first; then the workers restart from its
//   configuration and state (`start`), after the job in flight.

import type { CrowdConfig } from "../wasm";
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

/** `?workers=N` (0 = page's thread) or, unset, `navigator.hardwareConcurrency`
 *  workers from AUTO_WORKERS_FROM boids; a bad value is reported. */
export function crowdWorkersWanted(count: number, search = location.search): { n: number; problem: string | null } {
  const auto = count >= AUTO_WORKERS_FROM ? Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2)) : 0;
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

export class CrowdStepper {
  private readonly pool: WorkerPool<CrowdTask, CrowdReply>;
  readonly shared: boolean;
  /** The last complete state, `[positions | velocities]` (what the page draws). */
  state: Float32Array = new Float32Array(0);
  /** Its step count. */
  time = 0;
  count = 0;
  ready = false;
  active = false;
  error: string | null = null;
  private back: Float32Array = new Float32Array(0);
  private sab: SharedArrayBuffer[] | null = null;
  private frontIndex = 0;
  private queue: Promise<void> = Promise.resolve();
  private pending = 0;
  private owed = 0;
  private gen = 0;
  /** Called after each completed step with the new front state. */
  onStep: (state: Float32Array) => void = () => {};
  /** Steps completed, wall ms of their jobs, the slowest worker's ms. */
  private done = { steps: 0, ms: 0, workerMs: 0 };
  startMs = 0;
  /** Boids per worker in the last step. */
  owned: number[] = [];

  constructor(readonly workers: number) {
    this.pool = new WorkerPool<CrowdTask, CrowdReply>(() => new Worker(new URL("./crowd.worker.ts", import.meta.url), { type: "module" }), workers);
    this.shared = typeof SharedArrayBuffer === "function" && globalThis.crossOriginIsolated === true;
  }

  /** (Re)starts the workers on `config` from `state` (`CrowdLab.state()`) at step `time`. */
  start(config: CrowdConfig, state: Float32Array, time: number): Promise<void> {
    const gen = ++this.gen;
    this.ready = false;
    this.active = true;
    this.error = null;
    this.owed = 0;
    this.count = state.length >> 2;
    this.sab = this.shared ? [new SharedArrayBuffer(state.length * 4), new SharedArrayBuffer(state.length * 4)] : null;
    this.frontIndex = 0;
    if (this.sab) {
      this.state = new Float32Array(this.sab[0] as SharedArrayBuffer);
      this.back = new Float32Array(this.sab[1] as SharedArrayBuffer);
    } else {
      this.state = new Float32Array(state.length);
      this.back = new Float32Array(state.length);
    }
    this.state.set(state);
    this.time = time;
    const sab = this.sab;
    const t0 = performance.now();
    const init = { config, shared: sab };
    return this.job(gen, () => Array.from({ length: this.workers }, () => ({ init, steps: 0, front: 0, state: null, time, lo: 0, hi: 0 })), 0).then(() => {
      if (gen === this.gen && this.error === null) {
        this.ready = true;
        this.startMs = performance.now() - t0;
      }
    });
  }

  /** `steps` more steps are owed (at most four wait: a slow host drops the rest). */
  request(steps: number): void {
    this.owed = Math.min(4, this.owed + steps);
  }

  /** No job queued or in flight. */
  get idle(): boolean {
    return this.pending === 0;
  }

  /** Starts a step if none is in flight and one is owed; never waits. */
  pump(): void {
    if (!this.ready || this.pending > 0 || this.owed === 0) return;
    this.owed--;
    void this.step();
  }

  /** Runs one step; resolves when its state is the front one. */
  step(): Promise<void> {
    const gen = this.gen;
    return this.job(gen, () => {
      const cuts = stripCuts(this.state, this.count, this.workers);
      return cuts.slice(0, -1).map((lo, w) => ({
        init: null, steps: 1, front: this.frontIndex, state: this.sab ? null : this.state, time: this.time, lo, hi: cuts[w + 1] ?? Infinity,
      }));
    }, 1);
  }

  /** Steps completed since the last call, wall ms of their jobs, the slowest worker's stepping ms. */
  takeCompleted(): { steps: number; ms: number; workerMs: number } {
    const d = this.done;
    this.done = { steps: 0, ms: 0, workerMs: 0 };
    return d;
  }

  private job(gen: number, tasks: () => CrowdTask[], steps: number): Promise<void> {
    const next = this.queue.then(async () => {
      if (gen !== this.gen) return;
      const t0 = performance.now();
      let replies: CrowdReply[];
      try {
        replies = await this.pool.each(tasks());
      } catch (e) {
        if (gen === this.gen) {
          this.error = e instanceof Error ? e.message : String(e);
          this.ready = false;
          this.active = false;
        }
        return;
      }
      if (gen !== this.gen || steps === 0) return;
      if (!this.sab) {
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
      }
      const front = this.back;
      this.back = this.state;
      this.state = front;
      this.frontIndex = 1 - this.frontIndex;
      this.time += steps;
      this.owned = replies.map((r) => r.owned);
      this.done.steps += steps;
      this.done.workerMs += Math.max(...replies.map((r) => r.stepMs));
      this.done.ms += performance.now() - t0;
      this.onStep(front);
    });
    this.pending++;
    this.queue = next.finally(() => {
      this.pending--;
      // The next step starts at once if one is owed (not at the next frame).
      this.pump();
    });
    return next;
  }

  /** Stops stepping (the page's thread takes over); workers are kept. */
  stop(): void {
    this.gen++;
    this.ready = false;
    this.active = false;
    this.owed = 0;
  }

  terminate(): void {
    this.stop();
    this.pool.terminate();
  }
}
