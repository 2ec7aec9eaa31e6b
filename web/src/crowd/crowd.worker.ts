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
import type { CrowdReply, CrowdTask } from "./stepper";

let lab: CrowdLab | null = null;
let shared: SharedArrayBuffer[] | null = null;

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
  const front = shared ? new Float32Array(shared[task.front] as SharedArrayBuffer) : task.state;
  if (!front) throw new Error("crowd worker: no state to step");
  lab.loadState(front, task.time);
  const owned = lab.stepStrip(task.lo, task.hi);
  const indices = lab.ownedIndices();
  const states = lab.ownedState();
  if (shared) {
    const back = new Float32Array(shared[1 - task.front] as SharedArrayBuffer);
    const half = back.length >> 1;
    for (let k = 0; k < indices.length; k++) {
      const i = 2 * (indices[k] ?? 0);
      back[i] = states[4 * k] ?? 0;
      back[i + 1] = states[4 * k + 1] ?? 0;
      back[half + i] = states[4 * k + 2] ?? 0;
      back[half + i + 1] = states[4 * k + 3] ?? 0;
    }
    return { stepMs: performance.now() - t0, owned, indices: null, states: null };
  }
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
