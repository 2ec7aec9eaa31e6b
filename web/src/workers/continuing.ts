// Continuing jobs over shared memory (issue 17): one protocol for the
// crowd's strips (../crowd/stepper.ts) and the lab's slices (stepping.ts).
//
// - A job steps for as long as the page asks: each frame raises a shared
//   target step (at most a frame's worth and one step beyond the drawn
//   state), and the workers, meeting at a barrier (Atomics) after every
//   step, go on while the target is ahead, and wait up to TARGET_WAIT_MS
//   for it to rise when it is not (then the job ends: the page paused, or
//   is hidden). No step waits for the page's answer to the one before:
//   handing a job over and back cost 4–10 ms per step at 100,000 agents.
// - Worker 0 publishes every complete state (its step and buffer) and
//   writes the next step into a buffer that is neither the one just
//   written, nor the one before it, nor the one the page draws: four
//   buffers (the state drawn, the one drawn next, the newest, the one
//   being written).
// - The page draws the states in order, one frame behind at most
//   (`pickState`): the oldest it has not drawn when a newer one is already
//   there, so two states landing between two frames are drawn one per
//   frame. Drawing only the newest skipped one of them: at 100,000 boids
//   one crowd worker stepped 99,161 boids per frame, the page drew 62,599.
// - The page says which buffer it draws, then reads the newest step again:
//   when that moved on by two or more, a choice of worker 0 made meanwhile
//   may not have seen it, so it takes one of the two newest (both avoided).
//   Worker 0 reads the drawn buffer only after publishing, so every choice
//   after the page's second read sees the page's.

/** State buffers of a continuing job (`sab[0..STATES)`). */
export const STATES = 4;
/** The control words (Int32): barrier arrivals; the step the page asks the
 *  job to reach; the latest complete state (`steps in the job << 2 |
 *  buffer`); decisions made (steps); the next step's buffer (−1: the job
 *  ends); the buffer the page draws; stop. */
export const C = { arrived: 0, target: 1, published: 2, decided: 3, next: 4, drawing: 5, stop: 6 } as const;
export const CTRL_BYTES = 4 * 8;
/** Per-step slots are a ring this long (a job runs at most a frame's worth
 *  and one step ahead of the drawn state: ≤ 21 steps). */
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
  /** The step count the target is counted from. */
  time: number;
  /** This worker's share of step `s` (1 for the job's first) from buffer
   *  `src` into `dst`; runs before the barrier. */
  step(src: number, dst: number, s: number): void;
  /** Worker 0, every worker's step `s` done: fills the step's slot (`ms`:
   *  its wall time since the last decision) before it is published. */
  note(s: number, dst: number, ms: number): void;
  /** Worker 0, after the wait, before the next step's decision (the
   *  crowd's strips rebalance here). */
  between?(): void;
}

/** True once the page asks for a step beyond `time` (false: the job is to
 *  stop, or no step was asked for within TARGET_WAIT_MS). */
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

/** Runs one worker's part of a continuing job; returns its steps. */
export function runContinuing(w: ContinuingWork): number {
  const { ctrl, workers } = w;
  let src = w.front;
  let dst = Atomics.load(ctrl, C.next);
  let s = 0;
  let ts = performance.now();
  for (;;) {
    w.step(src, dst, s + 1);
    s++;
    Atomics.add(ctrl, C.arrived, 1);
    Atomics.notify(ctrl, C.arrived);
    const want = s * workers;
    for (let v = Atomics.load(ctrl, C.arrived); v < want; v = Atomics.load(ctrl, C.arrived)) Atomics.wait(ctrl, C.arrived, v, 1000);
    let next: number;
    if (w.worker === 0) {
      w.note(s, dst, performance.now() - ts);
      Atomics.store(ctrl, C.published, (s << 2) | dst);
      const go = waitForTarget(ctrl, w.time + s) && s < MAX_JOB_STEPS;
      // Read after publishing (and waiting): `pickState` relies on it.
      const drawing = Atomics.load(ctrl, C.drawing);
      w.between?.();
      next = go ? Array.from({ length: STATES }, (_, b) => b).find((b) => b !== dst && b !== src && b !== drawing) ?? -1 : -1;
      // The wait is not the step's: the next step's ms start here.
      ts = performance.now();
      Atomics.store(ctrl, C.next, next);
      Atomics.store(ctrl, C.decided, s);
      Atomics.notify(ctrl, C.decided);
    } else {
      for (let v = Atomics.load(ctrl, C.decided); v < s; v = Atomics.load(ctrl, C.decided)) Atomics.wait(ctrl, C.decided, v, 1000);
      next = Atomics.load(ctrl, C.next);
    }
    if (next < 0) return s;
    src = dst;
    dst = next;
  }
}

/** Page side: a new job from buffer `front`, asked to reach `target`. */
export function beginJob(ctrl: Int32Array, front: number, target: number): void {
  ctrl.fill(0);
  Atomics.store(ctrl, C.target, target);
  Atomics.store(ctrl, C.published, front);
  Atomics.store(ctrl, C.drawing, front);
  Atomics.store(ctrl, C.next, (front + 1) % STATES);
}

/** Page side: a frame asks for `steps` more, the drawn state at `drawn`
 *  (`k` a frame's worth): the target rises at most to one step beyond a
 *  frame's worth ahead of it, so a host that cannot keep up runs slower
 *  than real time rather than stepping states the page would never draw. */
export function raiseTarget(ctrl: Int32Array, drawn: number, k: number, steps: number): void {
  const target = Atomics.load(ctrl, C.target);
  Atomics.store(ctrl, C.target, Math.max(target, Math.min(drawn + k + 1, target + steps)));
  // Worker 0 may be waiting for it to rise.
  Atomics.notify(ctrl, C.target);
}

/** Page side: asks the job to end after its present step. */
export function endJob(ctrl: Int32Array): void {
  Atomics.store(ctrl, C.stop, 1);
  Atomics.notify(ctrl, C.target);
}

/** Page side: the state to draw among those published after step `seen`
 *  (steps in the job), or null: the oldest not drawn when a newer one is
 *  there and `perFrame` steps lie before it, else the newest (`newest`:
 *  always). `bufferOf(k)` is the buffer of step k (the job's slots). Says
 *  which buffer it takes (module notes). */
export function pickState(ctrl: Int32Array, seen: number, perFrame: number, newest: boolean, bufferOf: (k: number) => number): { step: number; buffer: number } | null {
  let p = Atomics.load(ctrl, C.published);
  for (;;) {
    const s = p >> 2;
    if (s <= seen) return null;
    const older = !newest && s - 1 > seen && s - 1 >= seen + perFrame;
    const step = older ? s - 1 : s;
    const buffer = older ? bufferOf(step) : p & 3;
    Atomics.store(ctrl, C.drawing, buffer);
    const again = Atomics.load(ctrl, C.published);
    if (step >= (again >> 2) - 1) return { step, buffer };
    p = again;
  }
}
