// What the lab's page and its stepping workers say to each other
// (../lab/stepping.ts, `WorkerWorld`, and ../workers/step.worker.ts): a
// task per worker and its reply. Plain data: both bundles import it.

import type { Internals } from "../core/wasm";
import type { BuildInfo, Edit, EditAnswer, Recipe } from "./worldcalls";

/** An edit on its way, numbered for its answer. */
export interface SentEdit {
  id: number;
  edit: Edit;
}

/** One task. `build`: build the whole world from the recipe and keep
 *  slice `worker` of `workers`. Else: take `shared` (the state buffers,
 *  when given), apply `edits`, step `steps` times, write the states into
 *  buffer `buffer`; `shown`: the agent whose internals the HUD shows. */
export interface StepTask {
  build: Recipe | null;
  shared?: SharedArrayBuffer[] | null;
  edits: SentEdit[];
  steps: number;
  /** The buffer written (a continuing job: the drawn one, stepped from). */
  buffer: number;
  shown: number;
  /** Shared memory, steps > 0: a continuing job (../threads/continuing.ts). */
  continuing: boolean;
  worker: number;
  workers: number;
}

export interface StepReply {
  internals: Internals | null;
  /** The slice's states when there is no shared memory. */
  state: Float32Array | null;
  /** Wall ms of the worker's `step` calls. */
  stepMs: number;
  answers: Array<EditAnswer & { id: number }>;
  /** A build's: what it made, the slices (flat start, end pairs) and
   *  whether avoidance couples the agents (no slices kept). */
  built?: { info: BuildInfo; ranges: number[]; coupled: boolean };
}
