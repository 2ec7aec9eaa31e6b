// The crowd stepped across cores: N crowd workers
// (../workers/crowd.worker.ts) on the one worker layer (../threads/pool.ts,
// `each`: task i to worker i), each stepping the boids of one vertical
// strip; what they share with it is ../world/crowdstrips.ts.
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
//   continuing jobs (../threads/continuing.ts: the workers step on while
//   the page asks, meeting at a barrier after every step, and the page
//   draws every state in order, up to DEPTH states behind the newest): a
//   job that ended with every step would leave the workers idle until the
//   page had handled its answer, after its drawing. The page never waits
//   for a worker.
// - Else one step per job: the front state goes to each worker by message
//   and the stepped boids come back with their indices (transferred),
//   copied here into the back buffer, then the two swap.
// - Edits (count, path, seek, …) are made on the page's CrowdLab, loaded
//   with the front state first; then the workers restart from its
//   configuration and state (`start`), after the job in flight.

import type { CrowdConfig } from "../core/wasm";
import { stateBuffers } from "../threads/buffers";
import { ContinuingJobs, CTRL_BYTES, SLOT_RING, STATES } from "../threads/continuing";
import { SteppingJobs } from "../threads/jobs";
import { WorkerPool } from "../threads/pool";
import { BALANCE, BALANCE_FLOATS, MAX_CROWD_WORKERS, SAB, SLOT, stripCuts, type CrowdReply, type CrowdTask } from "../world/crowdstrips";

/** Boids from which the page steps the crowd in workers by default: below
 *  it the page's thread steps and draws them at 60 fps on a 2-core host
 *  (`make bench-web`'s crowd rows). */
export const AUTO_WORKERS_FROM = 20_000;

/** The page's "steps / frame" goes up to 20. */
const MAX_STEPS_PER_FRAME = 20;

/** `?workers=N` (0 = page's thread) or, unset, from AUTO_WORKERS_FROM boids
 *  a worker per core but one (at least one): the page's drawing keeps a
 *  core, where it competes with the workers' (`make bench-web`'s crowd rows
 *  compare 1 worker with one per core). A bad value is reported. */
export function crowdWorkersWanted(count: number, search = location.search): { n: number; problem: string | null } {
  const auto = count >= AUTO_WORKERS_FROM ? Math.max(1, Math.min(8, (navigator.hardwareConcurrency || 2) - 1)) : 0;
  const raw = new URLSearchParams(search).get("workers");
  if (raw === null) return { n: auto, problem: null };
  const n = /^\d{1,2}$/.test(raw) ? Number(raw) : NaN;
  if (!(n >= 0 && n <= MAX_CROWD_WORKERS)) return { n: auto, problem: `workers = ${raw} is not a whole number of workers in [0, ${MAX_CROWD_WORKERS}]; using ${auto}` };
  return { n, problem: null };
}

export class CrowdStepper extends SteppingJobs<CrowdTask, CrowdReply> {
  /** The last complete state, `[positions | velocities]` (what the page draws). */
  state: Float32Array = new Float32Array(0);
  /** Its step count. */
  time = 0;
  count = 0;
  private back: Float32Array = new Float32Array(0);
  private sab: SharedArrayBuffer[] | null = null;
  /** Shared memory: each strip's share of the boids (`rebalance`); empty
   *  before the first balance or without shared memory. */
  shares(): number[] {
    if (!this.sab || this.workers < 2) return [];
    const bal = new Float32Array(this.sab[SAB.balance] as SharedArrayBuffer, 4 * BALANCE.share, this.workers);
    return bal[0] ? Array.from(bal) : [];
  }
  /** Shared memory: the continuing jobs (over `sab[SAB.ctrl]`). */
  private jobs: ContinuingJobs | null = null;
  private frontIndex = 0;
  /** The step the job in flight started from. */
  private jobTime = 0;
  /** Called when a job's last step is the front state (the traced boid:
   *  read it there); before that `onTraced` with its position after each
   *  earlier step of the job. */
  onStep: (state: Float32Array) => void = () => {};
  onTraced: (x: number, y: number) => void = () => {};
  /** Shared memory: steps taken but never drawn (none at one step per frame). */
  get skipped(): number {
    return this.jobs?.skipped ?? 0;
  }
  /** Boids per worker in the last step. */
  owned: number[] = [];

  constructor(readonly workers: number) {
    super(new WorkerPool<CrowdTask, CrowdReply>(() => new Worker(new URL("../workers/crowd.worker.ts", import.meta.url), { type: "module" }), workers));
  }

  /** (Re)starts the workers on `config` from `state` (`CrowdLab.state()`) at step `time`. */
  start(config: CrowdConfig, state: Float32Array, time: number): Promise<void> {
    return this.restart((gen) => {
      this.count = state.length >> 2;
      this.jobs?.drop();
      // The states, the control words, the step slots, the balance.
      ({ sab: this.sab, state: this.state, back: this.back } = stateBuffers(state, this.shared, STATES, [CTRL_BYTES, 4 * SLOT * SLOT_RING, 4 * BALANCE_FLOATS]));
      this.jobs = this.sab ? new ContinuingJobs(new Int32Array(this.sab[SAB.ctrl] as SharedArrayBuffer)) : null;
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
   *  batching steps the page would never draw (one step per frame: every
   *  state drawn). Shared memory: the target of the job in flight rises
   *  too, up to one step beyond a frame's worth ahead of the drawn state,
   *  so a worker slower than the frames never stops to wait for the page. */
  request(steps: number): void {
    const k = Math.min(MAX_STEPS_PER_FRAME, steps);
    const jobs = this.jobs;
    if (jobs) jobs.perFrame = k;
    if (jobs?.running) jobs.raise(k, steps);
    else this.owed = Math.min(k, this.owed + steps);
  }

  /** Starts a step if none is in flight and one is owed; never waits. */
  pump(): void {
    if (!this.ready || !this.idle || this.owed === 0) return;
    const k = this.sab ? this.owed : 1;
    this.owed = 0;
    void this.step(k);
  }

  /** Runs `k` steps (shared memory: and more while frames ask; else one
   *  step) as one job; resolves when its last state is the front one. */
  step(k = 1): Promise<void> {
    const steps = this.sab ? Math.max(1, k) : 1;
    return this.job(
      this.gen,
      () => {
        const cuts = this.sab ? [] : stripCuts(this.state, this.count, this.workers);
        if (this.jobs) {
          this.jobs.begin(this.frontIndex, steps);
          this.jobTime = this.time;
        }
        const traced = this.traced();
        return Array.from({ length: this.workers }, (_, w) => ({
          init: null, steps, front: this.frontIndex, state: this.sab ? null : this.state, time: this.time,
          lo: cuts[w] ?? 0, hi: cuts[w + 1] ?? Infinity, worker: w, workers: this.workers, traced,
        }));
      },
      (replies, t0) => this.land(replies, t0),
    );
  }

  /** Shared memory: takes the state to draw among those the job in flight
   *  has published since the last call (`ContinuingJobs.take`: in order, up to
   *  DEPTH behind the newest; `newest`: the newest, a job that ended leaves none
   *  behind). The traced boid of each step it passes goes to `onTraced`,
   *  the drawn state to `onStep`. Called every frame, before drawing. */
  poll(newest = false): void {
    const sab = this.sab;
    if (!sab || !this.jobs) return;
    const slots = new Float32Array(sab[SAB.slots] as SharedArrayBuffer);
    const picked = this.jobs.take(newest, (k) => slots[SLOT * ((k - 1) % SLOT_RING) + 3] ?? 0);
    if (!picked) return;
    const { from, step: c, buffer: buf } = picked;
    let ms = 0;
    for (let k = from + 1; k <= c; k++) {
      const slot = SLOT * ((k - 1) % SLOT_RING);
      if (k < c) this.onTraced(slots[slot] ?? 0, slots[slot + 1] ?? 0);
      ms += slots[slot + 2] ?? 0;
    }
    this.frontIndex = buf;
    this.state = new Float32Array(sab[buf] as SharedArrayBuffer);
    this.time = this.jobTime + c;
    this.done.steps += c - from;
    this.done.workerMs += ms;
    this.onStep(this.state);
  }


  override stop(): void {
    this.jobs?.drop();
    super.stop();
  }

  /** The boid whose lap the page records (set by the page). */
  traced: () => number = () => 0;

  /** A step job's replies: its last state becomes the front one. */
  private land(replies: CrowdReply[], t0: number): void {
    if (this.jobs) {
      this.poll(true);
      // Steps a frame asked for after the workers' last decision.
      this.owed = Math.max(this.owed, this.jobs.finish(MAX_STEPS_PER_FRAME));
      this.done.ms += performance.now() - t0;
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
      this.time += 1;
      this.done.steps += 1;
      this.done.workerMs += Math.max(...replies.map((r) => r.stepMs));
      this.done.ms += performance.now() - t0;
      this.onStep(this.state);
    }
    this.owned = replies.map((r) => r.owned);
  }

  protected afterJob(): void {
    // The next step starts at once if one is owed (not at the next frame).
    this.pump();
  }
}
