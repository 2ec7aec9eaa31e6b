// The lab's world stepped across cores: N stepping workers
// (../workers/step.worker.ts) on the one worker layer (../threads/pool.ts,
// `each`: task i to worker i), each owning a contiguous slice of agents.
// The page holds no copy of the world: this is its `LabWorld`
// (../world/world.ts) while the workers step.
//
// - Start: every worker builds the whole world from the page's recipe
//   (../world/worldcalls.ts, `buildWorld`: the calls the page's own core
//   would make, so the same bits), splits it the same way
//   (`Lab.splitRanges`: about equal ranges whose cuts never separate an
//   agent from the agent its goal faces, paper 000 Fig. 6) and keeps its
//   range (`retainRange`). The world reads other agents only through those
//   links, from the step's start, so each slice steps to the same bits as
//   the whole world, with no exchange between workers. A world whose
//   avoidance couples every agent is not split: `start` resolves with null
//   and the page steps it. Then the page sizes the state buffers from the
//   agent count the build reported and the workers write the state at
//   t = 0 into them.
// - Edits (drags, settings, a new table) go to every worker with the next
//   task; each worker's core checks them (an agent's edit: the worker that
//   owns the agent) and answers in its reply.
// - The page never waits for a worker: a frame with no new complete state
//   draws the last one again.
// - Shared memory where the page is cross-origin isolated (COOP/COEP, see
//   vite.config.ts): STATES SharedArrayBuffers (../threads/continuing.ts)
//   each worker writes its slice into, and steps run as continuing jobs
//   (continuing.ts, as the crowd's): the workers step on while the page
//   asks, each at its own pace, without the crowd's barrier
//   (`runIndependent`: slices never read each other), the last to finish a
//   step publishing it; the worker owning the shown agent leaves its
//   internals in the step's note (../world/slicebuffers.ts), and the page
//   draws every state in order, up to DEPTH states behind the newest: a
//   job handed over and back per step would leave the workers idle while
//   the page draws. A host that cannot
//   keep up runs the world slower than real time instead of stepping states
//   it never draws. Edits and a newly shown agent end the job in flight;
//   the next one carries them.
// - Elsewhere the states come back by message (transferred, no copy), a
//   job of the steps owed per frame (at most MAX_STEPS_PER_JOB, the world
//   in real time), into the back buffer; then the two swap.

import type { Ghost, Internals } from "../core/wasm";
import type { LabWorld, Took } from "../world/world";
import type { BuildInfo, Edit, EditAnswer, Recipe } from "../world/worldcalls";
import type { SentEdit, StepReply, StepTask } from "../world/steptask";
import { stateBuffers } from "../threads/buffers";
import { ContinuingJobs, CTRL_BYTES, SLOT_RING, STATES } from "../threads/continuing";
import { NOTE_BYTES, readNote, SAB, SLOT } from "../world/slicebuffers";
import { SteppingJobs } from "../threads/jobs";
import { WorkerPool } from "../threads/pool";

/** Steps one job runs at most (a frame's worth when the workers keep up). */
const MAX_STEPS_PER_JOB = 4;

/** Agents from which the page steps in workers by default. Below it the
 *  page's own thread steps and draws a frame within the 16.7 ms of a 60 Hz
 *  display on a 2-core host, and workers would only add their start and a
 *  frame of latency; above it, its frames take longer, and the workers
 *  keep it drawing (`make bench-web`, web/test/perf.mjs, measures both). */
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

/** How the world is stepped (the HUD; the test build's hook). */
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
  /** Wall ms the last start took (each worker builds the world, keeps its slice). */
  startMs: number;
  /** Workers asked for (URL or default). */
  wanted: number;
  starting: boolean;
  error: string | null;
}

export class WorkerWorld extends SteppingJobs<StepTask, StepReply> implements LabWorld {
  ranges: Array<[number, number]> = [];
  count = 0;
  /** The last complete state (what the page draws). */
  state: Float32Array = new Float32Array(0);
  /** Internals of the shown agent in that state. */
  internals: Internals | null = null;
  /** A newer complete state arrived since the page last looked. */
  private fresh = false;
  private back: Float32Array = new Float32Array(0);
  private sab: SharedArrayBuffer[] | null = null;
  /** The buffers are new: the next task hands them over. */
  private handOver = false;
  private frontIndex = 0;
  /** Shared memory: the continuing jobs (over `sab[SAB.ctrl]`), and the
   *  agent whose internals the one in flight notes. */
  private jobs: ContinuingJobs | null = null;
  private jobShown = 0;
  private edits: SentEdit[] = [];
  private answers = new Map<number, (a: EditAnswer) => void>();
  private nextEdit = 0;
  private shown = 0;
  /** Sum over jobs of the slowest worker's stepping ms, and agent updates
   *  (the workers' own cost per update, beside the jobs' wall time). */
  private workerMs = 0;
  private workerUpdates = 0;

  constructor(
    readonly workers: number,
    private readonly stride: number,
  ) {
    super(new WorkerPool<StepTask, StepReply>(() => new Worker(new URL("../workers/step.worker.ts", import.meta.url), { type: "module" }), workers));
  }

  /** Every worker builds `recipe`'s world and keeps its slice; then the
   *  state buffers for it and the state at t = 0. Resolves with the
   *  build's info, or null when the world cannot be split (or a worker
   *  failed: `error`). */
  async start(recipe: Recipe, shown: number): Promise<BuildInfo | null> {
    let built: StepReply["built"] = undefined;
    this.jobs?.drop();
    await this.restart(async (gen) => {
      this.edits = [];
      this.answers.clear();
      this.jobs = null;
      this.sab = null;
      this.count = 0;
      this.state = new Float32Array(0);
      this.internals = null;
      const workers = this.workers;
      await this.job(
        gen,
        () => Array.from({ length: workers }, (_, k) => this.task(k, { build: recipe, shown, workers })),
        (replies) => void (built = replies[0]?.built),
      );
      if (gen !== this.gen || !built || built.coupled) return;
      const flat = built.ranges;
      this.ranges = [];
      for (let k = 0; k + 1 < flat.length; k += 2) this.ranges.push([flat[k] ?? 0, flat[k + 1] ?? 0]);
      this.count = built.info.count;
      ({ sab: this.sab, state: this.state, back: this.back } = stateBuffers(new Float32Array(this.count * this.stride), this.shared, this.shared ? STATES : 2, [CTRL_BYTES, 4 * SLOT * SLOT_RING, NOTE_BYTES * SLOT_RING]));
      this.jobs = this.sab ? new ContinuingJobs(new Int32Array(this.sab[SAB.ctrl] as SharedArrayBuffer)) : null;
      this.frontIndex = 0;
      this.handOver = true;
      await this.swapJob(gen, (buffer) => this.slices({ steps: 0, buffer, shown, continuing: false }));
    });
    const b = built as StepReply["built"];
    if (!b || b.coupled || this.error !== null) {
      this.stop();
      return null;
    }
    return b.info;
  }

  /** Task `k` with the given fields, the rest as for a plain step. */
  private task(k: number, t: Partial<StepTask>): StepTask {
    return { build: null, edits: [], steps: 0, buffer: this.frontIndex, shown: this.shown, continuing: false, worker: k, workers: this.ranges.length, ...t };
  }

  /** One task per slice; the first after a start hands over the buffers. */
  private slices(t: Partial<StepTask>): StepTask[] {
    const shared = this.handOver ? { shared: this.sab } : {};
    this.handOver = false;
    return this.ranges.map((_, k) => this.task(k, { ...t, ...shared }));
  }

  edit(e: Edit, answer: (a: EditAnswer) => void): void {
    const id = this.nextEdit++;
    this.answers.set(id, answer);
    this.edits.push({ id, edit: e });
    // A continuing job in flight ends, so that the next one carries it.
    if (this.jobs?.running) this.jobs.end();
  }

  tableChanged(bytes: Uint8Array, key: string): void {
    this.edit({ kind: "table", bytes, key }, () => undefined);
  }

  /** Each edit's answer, once: the first refusal among the workers' (an
   *  agent's edit is refused by the one worker that owns the agent). */
  private answer(replies: StepReply[]): void {
    const byId = new Map<number, EditAnswer>();
    for (const r of replies) {
      for (const a of r.answers) {
        const had = byId.get(a.id);
        if (!had || (had.error === null && a.error !== null)) byId.set(a.id, { error: a.error, avoid: had?.avoid ?? a.avoid });
      }
    }
    for (const [id, a] of byId) {
      this.answers.get(id)?.(a);
      this.answers.delete(id);
    }
  }

  frame(k: number, shown: number): Took {
    // Shared memory: this frame's state first (before asking for more: the
    // workers then leave its buffer alone).
    this.poll();
    this.request(k);
    this.pump(shown);
    return this.took();
  }

  async run(k: number, shown: number): Promise<Took> {
    await this.dispatch(k, shown);
    return this.took();
  }

  private took(): Took {
    if (!this.fresh) return { steps: 0, ms: 0, stepMs: 0, fresh: false };
    this.fresh = false;
    const d = this.takeCompleted();
    return { steps: d.steps, ms: d.ms, stepMs: d.workerMs, fresh: true };
  }

  ghost(): Ghost | null {
    return null;
  }

  ring(): Float32Array | null {
    return null;
  }

  core(): null {
    return null;
  }

  /** `steps` more steps are owed (at most a job's worth wait: a slow host
   *  drops the rest). Shared memory: the target of the job in flight rises
   *  (`ContinuingJobs.raise`: a host that cannot keep up runs slower than
   *  real time rather than stepping states the page never draws). */
  private request(steps: number): void {
    if (steps <= 0) return;
    const jobs = this.jobs;
    if (jobs) jobs.perFrame = Math.min(MAX_STEPS_PER_JOB, steps);
    if (jobs?.running) jobs.raise(jobs.perFrame, steps);
    else this.owed = Math.min(MAX_STEPS_PER_JOB, this.owed + steps);
  }

  /** Starts a job if none is in flight and something is owed; never waits.
   *  A continuing job noting another agent's internals ends. */
  private pump(shown: number): void {
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
  private dispatch(steps: number, shown: number): Promise<void> {
    this.shown = shown;
    const edits = this.edits;
    this.edits = [];
    if (this.jobs && steps > 0) return this.continuingJob(this.jobs, steps, shown, edits);
    return this.swapJob(this.gen, (buffer) => this.slices({ edits, steps, buffer, shown }), steps);
  }

  /** Shared memory: a continuing job from the drawn state, asked for
   *  `steps` (more as frames ask); resolves when it has ended and its last
   *  state is the front one. */
  private continuingJob(jobs: ContinuingJobs, steps: number, shown: number, edits: SentEdit[]): Promise<void> {
    return this.job(
      this.gen,
      () => {
        jobs.begin(this.frontIndex, steps);
        this.jobShown = shown;
        return this.slices({ edits, steps, buffer: this.frontIndex, shown, continuing: true });
      },
      // The internals come with each state's note (`poll`), not the replies.
      (replies, t0) => {
        this.answer(replies);
        this.poll(true);
        // Steps a frame asked for after the workers' last decision.
        this.owed = Math.max(this.owed, jobs.finish(MAX_STEPS_PER_JOB));
        this.done.ms += performance.now() - t0;
      },
    );
  }

  /** Shared memory: takes the state to draw among those the continuing job
   *  has published since the last call (`ContinuingJobs.take`: in order, up
   *  to DEPTH behind the newest; `newest`: the newest), with the shown
   *  agent's internals noted for it. Called every frame, before drawing. */
  private poll(newest = false): void {
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
    this.workerUpdates += steps * this.count;
    this.fresh = true;
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
        this.answer(replies);
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
        const slowest = Math.max(0, ...replies.map((r) => r.stepMs));
        this.workerMs += slowest;
        this.done.workerMs += slowest;
        this.workerUpdates += steps * this.count;
        this.done.ms += performance.now() - t0;
        this.fresh = true;
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
    this.answers.clear();
  }
}
