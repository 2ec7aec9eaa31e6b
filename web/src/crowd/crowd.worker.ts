// One crowd stepping worker (issue 17, point 3): holds a copy of the whole
// crowd (CrowdLab built from the page's configuration, metrics off) and on
// each step loads the last complete state (positions, then velocities),
// steps the boids of its vertical strip [lo, hi) (`stepStrip`: separation
// reads every boid within reach, so they get the same bits as on one core)
// and writes them into the next buffer at their indices (shared memory: as
// long as the page asks for steps, `runShared`), or hands them back with
// their indices (no cross-origin isolation: one step per task). Driven by
// CrowdStepper (stepper.ts) through WorkerPool.each.

import { CrowdLab, errorText, loadCore } from "../wasm";
import type { ResultMessage, TaskMessage } from "../workers/pool";
import { BALANCE, C, MAX_JOB_STEPS, rebalance, SAB, SLOT, SLOT_RING, STATES, stripCuts, TARGET_WAIT_MS, type CrowdReply, type CrowdTask } from "./stepper";

let lab: CrowdLab | null = null;
let shared: SharedArrayBuffer[] | null = null;

/** One step of this worker's strip from `front` into `back` (shared memory;
 *  `load` false: the core already holds `front`).
 *  The stepped boids are copied straight out of the core's memory
 *  (`stripViews`, read before the next call into the core): all of them in
 *  two bulk copies when this worker owns every boid. */
function stepInto(l: CrowdLab, front: Float32Array, back: Float32Array, time: number, lo: number, hi: number, load = true): number {
  if (load) l.loadState(front, time);
  const owned = l.stepStrip(lo, hi);
  const [indices, pos, vel] = l.stripViews();
  const half = back.length >> 1;
  if (indices.length === half >> 1) {
    back.set(pos, 0);
    back.set(vel, half);
    return owned;
  }
  for (let k = 0; k < indices.length; k++) {
    const i = 2 * (indices[k] ?? 0);
    back[i] = pos[i] ?? 0;
    back[i + 1] = pos[i + 1] ?? 0;
    back[half + i] = vel[i] ?? 0;
    back[half + i + 1] = vel[i + 1] ?? 0;
  }
  return owned;
}

/** Shared memory: steps from buffer `task.front` while the page asks for
 *  more (stepper.ts, "continuing jobs"): after every step (the workers
 *  meet at a barrier) worker 0 notes the traced boid, the step's wall ms
 *  and buffer, publishes it, waits (at most TARGET_WAIT_MS) while the page
 *  asks for no further step, and decides the next step's buffer (neither
 *  the one just written, nor the one stepped from, nor the one the page
 *  draws) or the end of the job; the others follow its decision. */
function runShared(l: CrowdLab, shared: SharedArrayBuffer[], task: CrowdTask, t0: number): CrowdReply {
  const ctrl = new Int32Array(shared[SAB.ctrl] as SharedArrayBuffer);
  const slots = new Float32Array(shared[SAB.slots] as SharedArrayBuffer);
  const bal = new Float32Array(shared[SAB.balance] as SharedArrayBuffer);
  let src = task.front;
  let dst = Atomics.load(ctrl, C.next);
  let owned = 0;
  let s = 0;
  let ts = t0;
  for (;;) {
    const front = new Float32Array(shared[src] as SharedArrayBuffer);
    const back = new Float32Array(shared[dst] as SharedArrayBuffer);
    const cuts = stripCuts(front, front.length >> 2, task.workers, bal.subarray(BALANCE.share));
    // One worker owns every boid: after its first step the core already
    // holds the state it wrote (no load of the whole state per step).
    const ta = performance.now();
    owned = stepInto(l, front, back, task.time + s, cuts[task.worker] ?? 0, cuts[task.worker + 1] ?? Infinity, s === 0 || task.workers > 1);
    // Before the barrier: worker 0 reads them after it (rebalance).
    bal[2 * task.worker + BALANCE.ms] = performance.now() - ta;
    bal[2 * task.worker + BALANCE.boids] = owned;
    s++;
    Atomics.add(ctrl, C.arrived, 1);
    Atomics.notify(ctrl, C.arrived);
    const want = s * task.workers;
    for (let v = Atomics.load(ctrl, C.arrived); v < want; v = Atomics.load(ctrl, C.arrived)) Atomics.wait(ctrl, C.arrived, v, 1000);
    let next: number;
    if (task.worker === 0) {
      const slot = SLOT * ((s - 1) % SLOT_RING);
      slots[slot] = back[2 * task.traced] ?? 0;
      slots[slot + 1] = back[2 * task.traced + 1] ?? 0;
      const now = performance.now();
      slots[slot + 2] = now - ts;
      slots[slot + 3] = dst;
      Atomics.store(ctrl, C.published, (s << 2) | dst);
      const go = waitForTarget(ctrl, task.time + s) && s < MAX_JOB_STEPS;
      // Read after publishing (and waiting): the page's poll relies on it.
      const drawing = Atomics.load(ctrl, C.drawing);
      if (task.workers > 1) rebalance(bal, task.workers);
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
    if (next < 0) break;
    src = dst;
    dst = next;
  }
  return { stepMs: performance.now() - t0, owned, indices: null, states: null };
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

async function run(task: CrowdTask): Promise<CrowdReply> {
  await loadCore();
  if (task.init) {
    const l = new CrowdLab(task.init.config);
    l.setMetricsEnabled(false);
    lab?.free();
    lab = l;
    shared = task.init.shared;
  }
  if (!lab) throw new Error("crowd worker used before its crowd was built");
  if (task.steps === 0) return { stepMs: 0, owned: 0, indices: null, states: null };
  const t0 = performance.now();
  if (shared) return runShared(lab, shared, task, t0);
  const front = task.state;
  if (!front) throw new Error("crowd worker: no state to step");
  lab.loadState(front, task.time);
  const owned = lab.stepStrip(task.lo, task.hi);
  const indices = lab.ownedIndices();
  const states = lab.ownedState();
  return { stepMs: performance.now() - t0, owned, indices, states };
}

self.onmessage = async (ev: MessageEvent<TaskMessage<CrowdTask>>) => {
  const { id, task } = ev.data;
  let reply: ResultMessage<CrowdReply>;
  try {
    const result = await run(task);
    reply = { id, ok: true, result };
    self.postMessage(reply, { transfer: result.indices && result.states ? [result.indices.buffer, result.states.buffer] : [] });
    return;
  } catch (e) {
    reply = { id, ok: false, error: errorText(e) };
  }
  self.postMessage(reply);
};
