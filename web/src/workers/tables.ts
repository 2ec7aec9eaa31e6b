// The η table of the vehicle in use, built off the main thread (issue 14):
// from the browser's cache if it holds the table for these limits
// (tablecache.ts), else split across Web Workers (pool.ts, one slice of
// entries per task, several tasks per worker so the far, slow rows spread
// out), assembled and checked by the core (`assembleTable`, byte-identical
// to `eta-table --vehicle`), then cached.

import { assembleTable, tableJob, tableKeyOf, type VehicleParams } from "../wasm";
import { WorkerPool } from "./pool";
import { cacheGet, cachePut } from "./tablecache";
import type { SliceTask } from "./table.worker";

/** Tasks per worker: small enough to balance, large enough to be cheap. */
const TASKS_PER_WORKER = 12;

export interface BuiltTable {
  key: string;
  bytes: Uint8Array;
  /** Read from the cache rather than built. */
  cached: boolean;
  /** Wall time, ms. */
  ms: number;
  workers: number;
}

let pool: WorkerPool<SliceTask, Float32Array> | null = null;

function workers(): WorkerPool<SliceTask, Float32Array> {
  pool ??= new WorkerPool<SliceTask, Float32Array>(
    () => new Worker(new URL("./table.worker.ts", import.meta.url), { type: "module" }),
  );
  return pool;
}

/** Stops the build in flight, if any (its promise rejects with `Cancelled`). */
export function cancelBuild(): void {
  pool?.cancel();
}

/** The key of `params`' table (throws the core's message, field named,
 *  when no table can be built for them). */
export function tableKeyFor(params: VehicleParams): string {
  return tableJob(params).key;
}

/** The table for `params`: cached, or built in workers with
 *  `onProgress(fraction)`. A newer call cancels this one (it rejects
 *  with `Cancelled`). */
export async function buildTable(params: VehicleParams, onProgress: (f: number) => void): Promise<BuiltTable> {
  const t0 = performance.now();
  const job = tableJob(params);
  const hit = await cacheGet(job.key);
  if (hit) {
    try {
      if (tableKeyOf(hit) === job.key) {
        return { key: job.key, bytes: hit, cached: true, ms: performance.now() - t0, workers: 0 };
      }
    } catch {
      /* corrupt: rebuilt below */
    }
  }
  const p = workers();
  const n = Math.max(1, Math.min(job.entries, p.size * TASKS_PER_WORKER));
  const tasks: SliceTask[] = [];
  for (let k = 0; k < n; k++) {
    tasks.push({ params, counts: null, start: Math.floor((k * job.entries) / n), end: Math.floor(((k + 1) * job.entries) / n) });
  }
  const parts = await p.run(tasks, (done, total) => onProgress(done / total));
  const data = new Float32Array(3 * job.entries);
  let at = 0;
  for (const part of parts) {
    data.set(part, at);
    at += part.length;
  }
  const bytes = assembleTable(params, undefined, data);
  await cachePut(job.key, bytes);
  return { key: job.key, bytes, cached: false, ms: performance.now() - t0, workers: p.size };
}
