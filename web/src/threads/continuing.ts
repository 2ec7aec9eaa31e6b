// Continuing jobs over shared memory: one protocol for the
// crowd's strips (../crowd/stepper.ts) and the lab's slices (../lab/stepping.ts).
//
// - A job steps for as long as the page asks: each frame raises a shared
//   target step (at most a frame's worth and DEPTH steps beyond the drawn
//   state), and the workers go on while the target is ahead, and wait up
//   to TARGET_WAIT_MS for it to rise when it is not (then the job ends:
//   the page paused, or is hidden). No step waits for the page's answer to
//   the one before: a job handed over and back per step would leave the
//   workers idle while the page's thread draws.
// - The page draws the states in order (`ContinuingJobs.take`): a frame's
//   worth beyond the one drawn, but no more than DEPTH behind the newest,
//   so states landing between two frames are drawn one per frame (drawing
//   only the newest would skip the states that land two in one frame).
// - The crowd's protocol (`runContinuing`): its strips read each other's
//   boids, so they meet at a barrier (Atomics) after every step. Worker 0
//   publishes every complete state (its step and buffer) and writes the
//   next step into a buffer that is none of the DEPTH + 1 newest and not
//   the one the page draws: DEPTH + 3 buffers.
// - The lab's protocol (`runIndependent`): its slices never read each
//   other's agents, so there is no barrier. The last worker to finish a
//   step publishes it; up to LEAD steps more are in flight: DEPTH + LEAD
//   + 2 buffers.
// - The page says which buffer it draws, then reads the newest step again:
//   when that moved on by more than DEPTH beyond the step it took, a
//   choice made meanwhile may not have seen it (a choice protects the
//   steps down to its own newest − DEPTH), so it takes again. The chooser
//   reads the drawn buffer only after publishing, so every choice after
//   the page's second read sees the page's.

/** How far the workers may run beyond a frame's worth ahead of the drawn
 *  state, and how far behind the newest state the page may take one. The
 *  page's frames come late while the workers hold every core; with a
 *  target only a step ahead, the workers would wait for it a large share
 *  of the time. Each step of depth costs a state buffer (STATES); 3 keeps
 *  the workers stepping through a late frame or two (another depth is
 *  compared by building it and running `make bench-budget
 *  BENCH_BUDGET_ARGS="--base DIR"`; web/test/protocol.mjs checks the
 *  protocol at depths 1 to 3). */
export const DEPTH = 3;

/** The independent protocol: how many steps beyond the newest published
 *  one a worker may step (the buffers of those steps are chosen): a worker
 *  kept off its core for a while does not stop the other at once. */
export const LEAD = 3;

/** State buffers of a continuing job (`sab[0..STATES)`): DEPTH + 3 for the
 *  barrier's protocol, DEPTH + LEAD + 2 for the independent one (at most
 *  8: `pack`). */
export const STATES = DEPTH + LEAD + 2;
if (STATES > 8) throw new Error("continuing.ts: more than 8 state buffers do not fit `pack`");
/** Per-step words of the independent protocol are rings this long (more
 *  than DEPTH + LEAD: a step's buffer word is read until step + DEPTH is
 *  published). */
const RING = 8;
/** The control words (Int32): barrier arrivals; the step the page asks the
 *  job to reach; the latest complete state (`pack(steps in the job,
 *  buffer)`); decisions made (steps); the next step's buffer (−1: the job
 *  ends); the buffer the page draws; stop. The independent protocol's
 *  rings, indexed by step % RING: arrivals, go / end, buffer; and the last
 *  step whose buffer is chosen. */
export const C = { arrived: 0, target: 1, published: 2, decided: 3, next: 4, drawing: 5, stop: 6, arrivals: 8, choice: 8 + RING, buffers: 8 + 2 * RING, ahead: 8 + 3 * RING } as const;
export const CTRL_BYTES = 4 * (C.ahead + 1);

/** A published state: its step (in the job) and its buffer in one word. */
export function pack(step: number, buffer: number): number {
  return (step << 3) | buffer;
}
/** The step of a published word. */
export function stepOf(p: number): number {
  return p >> 3;
}
/** The buffer of a published word. */
export function bufferOf(p: number): number {
  return p & 7;
}
/** Per-step slots are a ring this long (a job runs at most a frame's worth
 *  and DEPTH steps ahead of the drawn state: ≤ 23 steps, the crowd's). */
export const SLOT_RING = 32;
/** A job whose target stays reached this long (ms) ends. */
export const TARGET_WAIT_MS = 250;
/** A job returns after this many steps (its counts stay small). */
export const MAX_JOB_STEPS = 1 << 20;

/** Worker side of a job: what one worker does per step. */
export interface ContinuingWork {
  ctrl: Int32Array;
  worker: number;
  workers: number;
  /** The buffer the job steps from first (the state drawn when it started). */
  front: number;
  /** This worker's share of step `s` (1 for the job's first) from buffer
   *  `src` into `dst`; runs before the barrier (the independent protocol:
   *  `src` is −1, each worker steps from its own memory). */
  step(src: number, dst: number, s: number): void;
  /** Every worker's step `s` done, before it is published: fills the
   *  step's slot. The barrier's: worker 0, `ms` its wall time since the
   *  last decision; the independent: the last worker to finish, `ms` its
   *  own stepping time. */
  note(s: number, dst: number, ms: number): void;
  /** Worker 0, after the wait, before the next step's decision (the
   *  crowd's strips rebalance here). */
  between?(): void;
}

/** True once the page asks for a step beyond `time` (steps in the job;
 *  false: the job is to stop, or no step was asked for within
 *  TARGET_WAIT_MS). */
function waitForTarget(ctrl: Int32Array, time: number): boolean {
  const until = performance.now() + TARGET_WAIT_MS;
  for (;;) {
    if (Atomics.load(ctrl, C.stop) !== 0) return false;
    const target = Atomics.load(ctrl, C.target);
    if (time < target) return true;
    const left = until - performance.now();
    if (left <= 0) return false;
    Atomics.wait(ctrl, C.target, target, left);
  }
}

/** Waits until `ctrl[at]` is at least `v`. */
function waitAtLeast(ctrl: Int32Array, at: number, v: number): void {
  for (let x = Atomics.load(ctrl, at); x < v; x = Atomics.load(ctrl, at)) Atomics.wait(ctrl, at, x, 1000);
}

/** Runs one worker's part of a continuing job; returns its steps. */
export function runContinuing(w: ContinuingWork): number {
  const { ctrl, workers } = w;
  let src = w.front;
  // The buffers of steps s − DEPTH … s − 2: the page may take them.
  const older: number[] = [];
  let dst = Atomics.load(ctrl, C.next);
  let s = 0;
  let ts = performance.now();
  for (;;) {
    w.step(src, dst, s + 1);
    s++;
    Atomics.add(ctrl, C.arrived, 1);
    Atomics.notify(ctrl, C.arrived);
    waitAtLeast(ctrl, C.arrived, s * workers);
    let next: number;
    if (w.worker === 0) {
      w.note(s, dst, performance.now() - ts);
      Atomics.store(ctrl, C.published, pack(s, dst));
      const go = waitForTarget(ctrl, s) && s < MAX_JOB_STEPS;
      // Read after publishing (and waiting): `ContinuingJobs.take` relies on it.
      const drawing = Atomics.load(ctrl, C.drawing);
      w.between?.();
      next = go ? Array.from({ length: STATES }, (_, b) => b).find((b) => b !== dst && b !== src && b !== drawing && !older.includes(b)) ?? -1 : -1;
      // The wait is not the step's: the next step's ms start here.
      ts = performance.now();
      Atomics.store(ctrl, C.next, next);
      Atomics.store(ctrl, C.decided, s);
      Atomics.notify(ctrl, C.decided);
    } else {
      waitAtLeast(ctrl, C.decided, s);
      next = Atomics.load(ctrl, C.next);
    }
    if (next < 0) return s;
    older.push(src);
    if (older.length > DEPTH - 1) older.shift();
    src = dst;
    dst = next;
  }
}

/** Runs one worker's part of a continuing job whose workers never read
 *  each other's state (the lab's slices: no facing link crosses a cut,
 *  crate/funnelling/world_split.rs); returns its steps.
 *
 *  No barrier: a worker steps on as soon as its next step's buffer is
 *  chosen, up to LEAD steps ahead of the published state, so a worker the
 *  page's thread (or the other worker) kept off its core does not hold the
 *  others at a barrier (what still idles them is the page's target, DEPTH
 *  steps beyond the drawn state).
 *  - The last worker to finish step s publishes it, notes it (`ms`: that
 *    worker's own stepping time) and chooses the buffer of step s + LEAD:
 *    not the one the page draws, nor those of steps s − DEPTH … s (the
 *    page may take any of them next), nor those of s + 1 … s + LEAD − 1
 *    (in flight): DEPTH + LEAD + 2 buffers. It reads the drawn buffer
 *    after publishing, so `ContinuingJobs.take`'s check holds as with the
 *    barrier.
 *  - Whether step s + 1 runs is decided once, by the first worker to reach
 *    it (compare-and-swap): go when the target rises beyond s within
 *    TARGET_WAIT_MS, else end. Every worker obeys that word, so all end
 *    after the same step, and the last published state is it. */
export function runIndependent(w: ContinuingWork): number {
  const { ctrl, workers } = w;
  const GO = 1;
  const END = 2;
  let s = 0;
  for (;;) {
    const n = s + 1;
    waitAtLeast(ctrl, C.ahead, n);
    const dst = Atomics.load(ctrl, C.buffers + (n % RING));
    let choice = Atomics.load(ctrl, C.choice + (n % RING));
    if (choice === 0) {
      const mine = waitForTarget(ctrl, s) && n <= MAX_JOB_STEPS ? GO : END;
      const was = Atomics.compareExchange(ctrl, C.choice + (n % RING), 0, mine);
      choice = was === 0 ? mine : was;
    }
    if (choice === END) return s;
    const t0 = performance.now();
    w.step(-1, dst, n);
    const ms = performance.now() - t0;
    s = n;
    if (Atomics.add(ctrl, C.arrivals + (s % RING), 1) + 1 < workers) continue;
    // Every worker has stepped s (none can reach s + RING, which reuses
    // the arrival word, before s + RING − LEAD is published).
    Atomics.store(ctrl, C.arrivals + (s % RING), 0);
    w.note(s, dst, ms);
    Atomics.store(ctrl, C.published, pack(s, dst));
    // Steps s − DEPTH … s + LEAD − 1 (`begin` fills those before step 0).
    const used = [Atomics.load(ctrl, C.drawing)];
    for (let k = s - DEPTH; k < s + LEAD; k++) used.push(Atomics.load(ctrl, C.buffers + ((k + RING) % RING)));
    const next = Array.from({ length: STATES }, (_, b) => b).find((b) => !used.includes(b)) ?? 0;
    // The ring's words for s + LEAD held step s + LEAD − RING's, long passed by all.
    Atomics.store(ctrl, C.choice + ((s + LEAD) % RING), 0);
    Atomics.store(ctrl, C.buffers + ((s + LEAD) % RING), next);
    Atomics.store(ctrl, C.ahead, s + LEAD);
    Atomics.notify(ctrl, C.ahead);
  }
}

/** The page's side of one stepper's continuing jobs (the crowd's and the
 *  lab's): whether a job is in flight, its steps the page has taken, the
 *  steps a frame asks for; targets count steps from the job's start. */
export class ContinuingJobs {
  running = false;
  /** Steps of the job in flight the page has taken (the drawn state's). */
  seen = 0;
  /** Steps a frame asks for (the last request). */
  perFrame = 1;
  /** Steps taken but never drawn (the page passed them for a newer state;
   *  none at one step per frame). */
  skipped = 0;

  constructor(readonly ctrl: Int32Array) {}

  /** A new job from buffer `front`, asked for `steps`. */
  begin(front: number, steps: number): void {
    const ctrl = this.ctrl;
    ctrl.fill(0);
    Atomics.store(ctrl, C.target, steps);
    Atomics.store(ctrl, C.published, front);
    Atomics.store(ctrl, C.drawing, front);
    Atomics.store(ctrl, C.next, (front + 1) % STATES);
    // The independent protocol: steps 0 (drawn) … LEAD have their buffers;
    // the words of "steps" −DEPTH … −1 (read when the first are published) the drawn one.
    for (let k = 0; k <= LEAD; k++) Atomics.store(ctrl, C.buffers + k, (front + k) % STATES);
    for (let k = 1; k <= DEPTH; k++) Atomics.store(ctrl, C.buffers + RING - k, front);
    Atomics.store(ctrl, C.ahead, LEAD);
    this.seen = 0;
    this.running = true;
  }

  /** A frame asks for `steps` more (`k`: a frame's worth): the target
   *  rises at most to DEPTH steps beyond a frame's worth ahead of the
   *  drawn state, so a host that cannot keep up runs slower than real time
   *  rather than stepping states the page would never draw. */
  raise(k: number, steps: number): void {
    const ctrl = this.ctrl;
    const target = Atomics.load(ctrl, C.target);
    Atomics.store(ctrl, C.target, Math.max(target, Math.min(this.seen + k + DEPTH, target + steps)));
    // Worker 0 may be waiting for it to rise.
    Atomics.notify(ctrl, C.target);
  }

  /** Asks the job to end after its present step. */
  end(): void {
    Atomics.store(this.ctrl, C.stop, 1);
    Atomics.notify(this.ctrl, C.target);
  }

  /** Ends the job in flight and drops its states (a new world). */
  drop(): void {
    if (this.running) this.end();
    this.running = false;
  }

  /** The job has ended: the steps asked for beyond the last taken (at
   *  most `cap`), owed to the next job. */
  finish(cap: number): number {
    this.running = false;
    return Math.max(0, Math.min(cap, Atomics.load(this.ctrl, C.target) - this.seen));
  }

  /** Takes the state to draw among those published since the last take,
   *  or null: a frame's worth of steps beyond the drawn one when that is
   *  published, but no more than DEPTH behind the newest, else the
   *  newest (`newest`: always). `bufferAt(k)` is the buffer of step k (the
   *  stepper's slots). Says which buffer it takes (module notes); `from` is
   *  the step drawn before. */
  take(newest: boolean, bufferAt: (k: number) => number): { from: number; step: number; buffer: number } | null {
    if (!this.running) return null;
    const ctrl = this.ctrl;
    let p = Atomics.load(ctrl, C.published);
    for (;;) {
      const s = stepOf(p);
      if (s <= this.seen) return null;
      const step = newest ? s : Math.min(s, Math.max(this.seen + this.perFrame, s - DEPTH));
      const buffer = step < s ? bufferAt(step) : bufferOf(p);
      Atomics.store(ctrl, C.drawing, buffer);
      // A choice made before this store protects steps down to its own
      // published step − DEPTH (module notes).
      const again = Atomics.load(ctrl, C.published);
      if (step >= stepOf(again) - DEPTH) {
        const from = this.seen;
        this.skipped += step - from - 1;
        this.seen = step;
        return { from, step, buffer };
      }
      p = again;
    }
  }
}
