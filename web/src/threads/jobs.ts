// What the two world steppers share (the lab's ../lab/stepping.ts and
// the crowd's ../crowd/stepper.ts): a queue of jobs on a worker pool, one job in
// flight at a time, each a task per worker; a generation number so that a
// restart or a stop drops the answers of jobs from before it; a failing
// worker stops the stepping with its message (the page's thread takes
// over); the counts the HUD and the benches read. A subclass builds the
// tasks and applies the replies (its own buffers and state).

import { WorkerPool } from "./pool";

export abstract class SteppingJobs<Task, Reply> {
  /** The workers hold the world and step it (set when a start completes). */
  ready = false;
  /** Started and neither stopped nor failed: the workers own the world
   *  (while `!ready` they are still building it). */
  active = false;
  /** The failing worker's message (stepping stopped), or null. */
  error: string | null = null;
  /** Wall ms from the last start until the workers owned the world. */
  startMs = 0;
  /** Shared memory: the page is cross-origin isolated (COOP/COEP). */
  readonly shared = typeof SharedArrayBuffer === "function" && globalThis.crossOriginIsolated === true;
  /** Steps owed to the next job. */
  protected owed = 0;
  protected gen = 0;
  /** Steps completed, wall ms of their jobs, the slowest worker's stepping ms. */
  protected done = { steps: 0, ms: 0, workerMs: 0 };
  private queue: Promise<void> = Promise.resolve();
  private pending = 0;

  constructor(protected readonly pool: WorkerPool<Task, Reply>) {}

  /** No job queued or in flight. */
  get idle(): boolean {
    return this.pending === 0;
  }

  /** Steps completed since the last call, the wall ms their jobs took and
   *  the slowest worker's stepping ms in them. */
  takeCompleted(): { steps: number; ms: number; workerMs: number } {
    const d = this.done;
    this.done = { steps: 0, ms: 0, workerMs: 0 };
    return d;
  }

  /** Runs `tasks()` (one per worker, built when the job starts) after the
   *  job in flight; `apply` takes the replies and the job's start time,
   *  unless the generation moved on meanwhile or a worker failed. After
   *  each job `afterJob` may start the next. */
  protected job(gen: number, tasks: () => Task[], apply: (replies: Reply[], t0: number) => void): Promise<void> {
    const next = this.queue.then(async () => {
      if (gen !== this.gen) return;
      const t0 = performance.now();
      let replies: Reply[];
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
      if (gen === this.gen) apply(replies, t0);
    });
    this.pending++;
    this.queue = next.finally(() => {
      this.pending--;
      this.afterJob();
    });
    return next;
  }

  /** A (re)start: a new generation, the workers active and not yet ready,
   *  nothing owed; `build` is the job that hands them the world, after
   *  which they are ready (unless stopped, restarted or failed meanwhile). */
  protected restart(build: (gen: number) => Promise<void>): Promise<void> {
    const gen = ++this.gen;
    this.ready = false;
    this.active = true;
    this.error = null;
    this.owed = 0;
    const t0 = performance.now();
    return build(gen).then(() => {
      if (gen === this.gen && this.error === null) {
        this.ready = true;
        this.startMs = performance.now() - t0;
      }
    });
  }

  /** Called after every job (the next one starts at once if one is owed). */
  protected abstract afterJob(): void;

  /** Stops stepping (the page's thread takes over); the workers are kept. */
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
