// One stepping worker (issue 17, point 2): owns agents start..end of the
// lab's world. It rebuilds the world from the page's recipe (the same calls
// the page made, so the same bits): a scenario whole, then keeps its range
// (`retainRange`: facing links never cut, crate/funnelling/world_split.rs);
// the playground's random crowd only its range (`spawnRandomRange`). On each
// task applies the page's edits, steps k times and writes its states at its
// offset of the shared back buffer, or hands them back (no isolation).
// Driven by `WorldStepper` (stepping.ts) through `WorkerPool.each`.

import { errorText, fetchTable, Lab, loadCore, type Internals } from "../wasm";
import { runIndependent, SLOT_RING } from "./continuing";
import type { ResultMessage, TaskMessage } from "./pool";
import { SAB, SLOT, writeNote } from "./slicebuffers";
import type { StepReply, StepTask, TableSource } from "./stepping";

let lab: Lab | null = null;
let range = { start: 0, end: 0 };
let shared: SharedArrayBuffer[] | null = null;
let stride = 0;
/** The last table loaded, by key: a new world on it is a `fork` (no reload). */
let base: { key: string; lab: Lab } | null = null;

async function tableLab(src: TableSource): Promise<Lab> {
  if (base && base.key === src.key) return base.lab.fork();
  let bytes: Uint8Array;
  if (src.bytes) bytes = src.bytes;
  else bytes = await fetchTable(src.url);
  const l = new Lab(bytes);
  base?.lab.free();
  base = { key: src.key, lab: l };
  return l.fork();
}

async function run(task: StepTask): Promise<StepReply> {
  await loadCore();
  if (task.init) {
    const r = task.init.recipe;
    const l = await tableLab(r.table);
    l.setParams(r.params);
    const { start, end } = task.init;
    if (r.build.kind === "scenario") {
      l.loadScenario(r.build.text);
      l.setParams(r.params);
    } else {
      // The playground: agent 0, then the random crowd; only this slice is
      // built (`spawnRandomRange`: the same agents without the others).
      const first = r.build.agent ? 1 : 0;
      if (r.build.agent && start === 0) l.addAgent(r.build.agent);
      const s = r.build.spawn;
      const a = Math.max(0, start - first);
      const b = Math.max(0, end - first);
      if (s && b > a) l.spawnRandomRange(s.n, s.seed, s.extent, s.speed, a, b);
    }
    l.setFunnel(r.funnel);
    l.setRelaxed(r.relaxed);
    // A scenario is built whole and keeps its slice (facing links renumbered).
    if (r.build.kind === "scenario") l.retainRange(start, end);
    lab?.free();
    lab = l;
    range = { start: task.init.start, end: task.init.end };
    shared = task.init.shared;
    stride = Lab.stateStride();
  }
  if (!lab) throw new Error("stepping worker used before its world was built");
  for (const e of task.edits) {
    const i = e.kind === "goal" || e.kind === "pose" ? e.i - range.start : -1;
    if (i >= range.end - range.start) continue;
    switch (e.kind) {
      case "goal":
        if (i >= 0) lab.setGoal(i, e.goal);
        break;
      case "pose":
        if (i >= 0) lab.setPose(i, e.x, e.y, e.theta);
        break;
      case "funnel":
        lab.setFunnel(e.funnel);
        lab.setRelaxed(e.relaxed);
        break;
      case "params":
        lab.setParams(e.params);
        break;
      case "table":
        lab.setTable(e.bytes, e.key);
        break;
    }
  }
  const local = task.shown - range.start;
  const mine = local >= 0 && local < range.end - range.start;
  if (shared && task.continuing) return runShared(lab, shared, task, mine ? local : -1);
  const t0 = performance.now();
  if (task.steps > 0) lab.step(task.steps);
  const stepMs = performance.now() - t0;
  let internals: Internals | null = null;
  if (mine) internals = lab.internals(local);
  if (shared) {
    // Straight from the core's memory into this worker's slice of the
    // shared buffer (one copy; `state()` made three: 4 MB each at 50,000 agents).
    const buf = shared[task.buffer] as SharedArrayBuffer;
    lab.stateInto(new Float32Array(buf, range.start * stride * 4, lab.count() * stride));
    return { time: lab.time(), internals, state: null, stepMs };
  }
  return { time: lab.time(), internals, state: lab.state(), stepMs };
}

/** Shared memory: a continuing job (continuing.ts). Each step: this
 *  worker's slice one step on, its states into the step's buffer, and (the
 *  worker owning the shown agent, `local` ≥ 0) its internals into the
 *  step's note; the last worker to finish a step notes its stepping ms and
 *  the step's buffer (`runIndependent`). */
function runShared(l: Lab, sab: SharedArrayBuffer[], task: StepTask, local: number): StepReply {
  const ctrl = new Int32Array(sab[SAB.ctrl] as SharedArrayBuffer);
  const slots = new Float32Array(sab[SAB.slots] as SharedArrayBuffer);
  const notes = sab[SAB.notes] as SharedArrayBuffer;
  let stepMs = 0;
  // Slices never read each other's agents: no barrier (`runIndependent`).
  runIndependent({
    ctrl,
    worker: task.worker,
    workers: task.workers,
    front: task.buffer,
    step: (_src, dst, s) => {
      // The step and its states in one pass (`stepInto`); timed together.
      const t0 = performance.now();
      l.stepInto(new Float32Array(sab[dst] as SharedArrayBuffer, range.start * stride * 4, l.count() * stride));
      stepMs += performance.now() - t0;
      if (local >= 0) writeNote(notes, s, l.internals(local));
    },
    note: (s, dst, ms) => {
      const slot = SLOT * ((s - 1) % SLOT_RING);
      slots[slot] = ms;
      slots[slot + 1] = dst;
    },
  });
  return { time: l.time(), internals: local >= 0 ? l.internals(local) : null, state: null, stepMs };
}

self.onmessage = async (ev: MessageEvent<TaskMessage<StepTask>>) => {
  const { id, task } = ev.data;
  let reply: ResultMessage<StepReply>;
  try {
    const result = await run(task);
    reply = { id, ok: true, result };
    self.postMessage(reply, { transfer: result.state ? [result.state.buffer] : [] });
    return;
  } catch (e) {
    reply = { id, ok: false, error: errorText(e) };
  }
  self.postMessage(reply);
};
