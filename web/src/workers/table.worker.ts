// One η-table worker: computes a slice of entries with the
// core's `tableSlice` (the generator's own code, so the assembled bytes
// equal `eta-table --vehicle`'s) and hands the Float32Array back without a
// copy. Driven by `WorkerPool` (../threads/pool.ts) from ../lab/tables.ts.

import { errorText, loadCore, tableSlice, type VehicleParams } from "../core/wasm";
import type { ResultMessage, TaskMessage } from "../threads/pool";

/** One worker's share: entries `start..end` of `params`' table. */
export interface SliceTask {
  params: VehicleParams;
  counts: number[] | null;
  start: number;
  end: number;
}

self.onmessage = async (ev: MessageEvent<TaskMessage<SliceTask>>) => {
  const { id, task } = ev.data;
  let reply: ResultMessage<Float32Array>;
  try {
    await loadCore();
    const out = tableSlice(task.params, task.counts === null ? undefined : Uint32Array.from(task.counts), task.start, task.end);
    reply = { id, ok: true, result: out };
    self.postMessage(reply, { transfer: [out.buffer] });
    return;
  } catch (e) {
    reply = { id, ok: false, error: errorText(e) };
  }
  self.postMessage(reply);
};
