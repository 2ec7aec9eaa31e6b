// One crowd stepping worker (issue 17, point 3): holds a copy of the whole
// crowd (CrowdLab built from the page's configuration, metrics off) and on
// each task loads the last complete state (positions, then velocities),
// steps the boids of its vertical strip [lo, hi) (`stepStrip`: separation
// reads every boid within reach, so they get the same bits as on one core)
// and writes them into the back buffer at their indices (shared memory), or
// hands them back with their indices (no cross-origin isolation). Driven by
// CrowdStepper (stepper.ts) through WorkerPool.each.

import { CrowdLab, errorText, loadCore } from "../wasm";
import type { ResultMessage, TaskMessage } from "../workers/pool";
import { stripCuts, type CrowdReply, type CrowdTask } from "./stepper";

let lab: CrowdLab | null = null;
let shared: SharedArrayBuffer[] | null = null;

/** One step of this worker's strip from `front` into `back` (shared memory).
 *  The stepped boids are copied straight out of the core's memory
 *  (`stripViews`, read before the next call into the core): all of them in
 *  two bulk copies when this worker owns every boid. */
function stepInto(l: CrowdLab, front: Float32Array, back: Float32Array, time: number, lo: number, hi: number): number {
  l.loadState(front, time);
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
  if (shared) {
    // Shared memory: `steps` steps without the page, through the two
    // buffers it is not drawing, the workers meeting at a barrier (control
    // word 0) between steps; worker 0 notes the traced boid after each.
    const ctrl = new Int32Array(shared[3] as SharedArrayBuffer);
    const slots = new Float32Array(shared[4] as SharedArrayBuffer);
    const others = [0, 1, 2].filter((b) => b !== task.front);
    let src = task.front;
    let owned = 0;
    for (let s = 0; s < task.steps; s++) {
      const dst = others[s % 2] ?? 0;
      const front = new Float32Array(shared[src] as SharedArrayBuffer);
      const cuts = stripCuts(front, front.length >> 2, task.workers);
      owned = stepInto(lab, front, new Float32Array(shared[dst] as SharedArrayBuffer), task.time + s, cuts[task.worker] ?? 0, cuts[task.worker + 1] ?? Infinity);
      if (s + 1 < task.steps) {
        Atomics.add(ctrl, 0, 1);
        Atomics.notify(ctrl, 0);
        const want = (s + 1) * task.workers;
        for (let v = Atomics.load(ctrl, 0); v < want; v = Atomics.load(ctrl, 0)) Atomics.wait(ctrl, 0, v, 1000);
        if (task.worker === 0) {
          const back = new Float32Array(shared[dst] as SharedArrayBuffer);
          slots[2 * s] = back[2 * task.traced] ?? 0;
          slots[2 * s + 1] = back[2 * task.traced + 1] ?? 0;
        }
      }
      src = dst;
    }
    return { stepMs: performance.now() - t0, owned, indices: null, states: null };
  }
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
