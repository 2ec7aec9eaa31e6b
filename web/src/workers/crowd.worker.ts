// One crowd stepping worker: holds a copy of the whole
// crowd (CrowdLab built from the page's configuration, metrics off) and on
// each step loads the last complete state (positions, then velocities),
// steps the boids of its vertical strip [lo, hi) (`stepStrip`: separation
// reads every boid within reach, so they get the same bits as on one core)
// and writes them into the next buffer at their indices (shared memory: as
// long as the page asks for steps, `runShared`), or hands them back with
// their indices (no cross-origin isolation: one step per task). Driven by
// CrowdStepper (../crowd/stepper.ts) through WorkerPool.each.

import { CrowdLab, errorText, loadCore } from "../core/wasm";
import type { ResultMessage, TaskMessage } from "../threads/pool";
import { runContinuing, SLOT_RING } from "../threads/continuing";
import { BALANCE, rebalance, SAB, SLOT, stripCuts, type CrowdReply, type CrowdTask } from "../world/crowdstrips";

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
 *  more (../threads/continuing.ts): worker 0 notes the traced boid, the
 *  step's wall ms and buffer in the step's slot, and rebalances the strips
 *  between steps. */
function runShared(l: CrowdLab, shared: SharedArrayBuffer[], task: CrowdTask, t0: number): CrowdReply {
  const ctrl = new Int32Array(shared[SAB.ctrl] as SharedArrayBuffer);
  const slots = new Float32Array(shared[SAB.slots] as SharedArrayBuffer);
  const bal = new Float32Array(shared[SAB.balance] as SharedArrayBuffer);
  let owned = 0;
  runContinuing({
    ctrl,
    worker: task.worker,
    workers: task.workers,
    front: task.front,
    step: (src, dst, s) => {
      const front = new Float32Array(shared[src] as SharedArrayBuffer);
      const back = new Float32Array(shared[dst] as SharedArrayBuffer);
      const cuts = stripCuts(front, front.length >> 2, task.workers, bal.subarray(BALANCE.share));
      // One worker owns every boid: after its first step the core already
      // holds the state it wrote (no load of the whole state per step).
      const ta = performance.now();
      owned = stepInto(l, front, back, task.time + s - 1, cuts[task.worker] ?? 0, cuts[task.worker + 1] ?? Infinity, s === 1 || task.workers > 1);
      // Before the barrier: worker 0 reads them after it (rebalance).
      bal[2 * task.worker + BALANCE.ms] = performance.now() - ta;
      bal[2 * task.worker + BALANCE.boids] = owned;
    },
    note: (s, dst, ms) => {
      const back = new Float32Array(shared[dst] as SharedArrayBuffer);
      const slot = SLOT * ((s - 1) % SLOT_RING);
      slots[slot] = back[2 * task.traced] ?? 0;
      slots[slot + 1] = back[2 * task.traced + 1] ?? 0;
      slots[slot + 2] = ms;
      slots[slot + 3] = dst;
    },
    between: () => {
      if (task.workers > 1) rebalance(bal, task.workers);
    },
  });
  return { stepMs: performance.now() - t0, owned, indices: null, states: null };
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
