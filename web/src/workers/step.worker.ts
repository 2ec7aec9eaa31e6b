// One stepping worker: owns agents start..end of the lab's world. Its
// first task builds the whole world from the page's recipe
// (../world/worldcalls.ts, the calls the page's own core would make, so the
// same bits), splits it as every other worker does (`splitRanges`) and
// keeps its range (`retainRange`: facing links never cut,
// crate/world/split.rs). Each later task applies the page's
// edits (checked here, answered in the reply), steps k times and writes its
// states at its offset of the shared buffer, or hands them back (no
// cross-origin isolation). Driven by `WorkerWorld` (../lab/stepping.ts) through
// `WorkerPool.each`.

import { applyEdit, buildWorld, type Recipe, type TableSource } from "../world/worldcalls";
import { errorText, fetchTable, Lab, loadCore, type Internals } from "../core/wasm";
import { runIndependent, SLOT_RING } from "../threads/continuing";
import type { ResultMessage, TaskMessage } from "../threads/pool";
import { SAB, SLOT, writeNote } from "../world/slicebuffers";
import type { StepReply, StepTask } from "../world/steptask";

let lab: Lab | null = null;
let range = { start: 0, end: 0 };
let shared: SharedArrayBuffer[] | null = null;
let stride = 0;
/** The last table loaded, by key: a new world on it is a `fork` (no reload). */
let base: { key: string; lab: Lab } | null = null;

async function tableLab(src: TableSource): Promise<Lab> {
  if (base && base.key === src.key) return base.lab.fork();
  const bytes = src.bytes ?? (await fetchTable(src.url));
  const l = new Lab(bytes);
  base?.lab.free();
  base = { key: src.key, lab: l };
  return l.fork();
}

/** Builds the whole world and keeps slice `worker` of it (none when
 *  avoidance couples the agents: the page steps such a world). */
async function build(recipe: Recipe, worker: number, workers: number): Promise<StepReply> {
  const l = await tableLab(recipe.table);
  const info = buildWorld(l, recipe);
  const ranges = Array.from(l.splitRanges(workers));
  const coupled = info.avoid.method !== "off";
  lab?.free();
  lab = null;
  range = { start: 0, end: 0 };
  const start = ranges[2 * worker];
  const end = ranges[2 * worker + 1];
  if (!coupled && start !== undefined && end !== undefined) {
    l.retainRange(start, end);
    lab = l;
    range = { start, end };
  } else l.free();
  return { internals: null, state: null, stepMs: 0, answers: [], built: { info, ranges, coupled } };
}

async function run(task: StepTask): Promise<StepReply> {
  await loadCore();
  stride = Lab.stateStride();
  if (task.build) return build(task.build, task.worker, task.workers);
  if (task.shared !== undefined) shared = task.shared;
  if (!lab) throw new Error("stepping worker used before its world was built");
  const l = lab;
  const answers = task.edits.map(({ id, edit }) => ({ id, ...applyEdit(l, edit, range.start, range.end) }));
  const local = task.shown - range.start;
  const mine = local >= 0 && local < range.end - range.start;
  if (shared && task.continuing) return runShared(l, shared, task, mine ? local : -1, answers);
  const t0 = performance.now();
  if (task.steps > 0) l.step(task.steps);
  const stepMs = performance.now() - t0;
  const internals: Internals | null = mine ? l.internals(local) : null;
  if (shared) {
    // Straight from the core's memory into this worker's slice of the shared buffer.
    const buf = shared[task.buffer] as SharedArrayBuffer;
    l.stateInto(new Float32Array(buf, range.start * stride * 4, l.count() * stride));
    return { internals, state: null, stepMs, answers };
  }
  return { internals, state: l.state(), stepMs, answers };
}

/** Shared memory: a continuing job (../threads/continuing.ts). Each step: this
 *  worker's slice one step on, its states into the step's buffer, and (the
 *  worker owning the shown agent, `local` ≥ 0) its internals into the
 *  step's note; the last worker to finish a step notes its stepping ms and
 *  the step's buffer (`runIndependent`). */
function runShared(l: Lab, sab: SharedArrayBuffer[], task: StepTask, local: number, answers: StepReply["answers"]): StepReply {
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
  return { internals: local >= 0 ? l.internals(local) : null, state: null, stepMs, answers };
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
