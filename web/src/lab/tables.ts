// The η table of the vehicle in use, built off the main thread:
// from the browser's cache if it holds the table for these limits
// (tablecache.ts), else split across Web Workers (../threads/pool.ts, one slice of
// entries per task, several tasks per worker so the far, slow rows spread
// out), assembled and checked by the core (`assembleTable`, byte-identical
// to `eta-table --vehicle`), then cached. The caller's `install` loads the
// bytes into its lab once, checking them against the key (a corrupt or
// foreign cache record is refused there and rebuilt).

import { assembleTable, tableJob, type VehicleParams } from "../core/wasm";
import { Cancelled, WorkerPool } from "../threads/pool";
import { cacheGet, cachePut } from "./tablecache";
import type { SliceTask } from "../workers/table.worker";

/** Tasks per worker: small enough to balance, large enough to be cheap. */
const TASKS_PER_WORKER = 12;

export interface BuiltTable {
  key: string;
  /** Read from the cache rather than built. */
  cached: boolean;
  /** Wall time until the table was installed, ms. */
  ms: number;
  workers: number;
  /** Where the wall time went, ms: `job` (key), `cache` (IndexedDB read),
   *  `compute` (the workers), `assemble`, `install` (the core loading and
   *  checking the bytes). */
  phases: Record<string, number>;
  /** Settles once a built table is in the browser's cache. */
  stored: Promise<void>;
}

let pool: WorkerPool<SliceTask, Float32Array> | null = null;

function workers(): WorkerPool<SliceTask, Float32Array> {
  pool ??= new WorkerPool<SliceTask, Float32Array>(
    () => new Worker(new URL("../workers/table.worker.ts", import.meta.url), { type: "module" }),
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

/** Puts `bytes` in force if they are the table of `key` (`Lab.setTable`
 *  with the expected key: loads and checks them once); throws otherwise,
 *  changing nothing. */
export type Install = (bytes: Uint8Array, key: string) => void;

/** The table for `params`, installed with `install`: from the cache, or
 *  built in workers with `onProgress(fraction)`, then stored in the cache
 *  (in the background: `stored`). A newer call cancels this one (it
 *  rejects with `Cancelled`). */
export async function buildTable(params: VehicleParams, onProgress: (f: number) => void, install: Install): Promise<BuiltTable> {
  const t0 = performance.now();
  const phases: Record<string, number> = {};
  let last = t0;
  const lap = (name: string): void => {
    const now = performance.now();
    phases[name] = now - last;
    last = now;
  };
  const job = tableJob(params);
  lap("job");
  const hit = await cacheGet(job.key);
  lap("cache");
  if (hit) {
    try {
      install(hit, job.key);
      lap("install");
      return { key: job.key, cached: true, ms: performance.now() - t0, workers: 0, phases, stored: Promise.resolve() };
    } catch (e) {
      if (e instanceof Cancelled) throw e;
      /* corrupt or foreign: rebuilt below */
      lap("refused");
    }
  }
  const p = workers();
  const n = Math.max(1, Math.min(job.entries, p.size * TASKS_PER_WORKER));
  const tasks: SliceTask[] = [];
  for (let k = 0; k < n; k++) {
    tasks.push({ params, counts: null, start: Math.floor((k * job.entries) / n), end: Math.floor(((k + 1) * job.entries) / n) });
  }
  const parts = await p.run(tasks, (done, total) => onProgress(done / total));
  lap("compute");
  const data = new Float32Array(3 * job.entries);
  let at = 0;
  for (const part of parts) {
    data.set(part, at);
    at += part.length;
  }
  const bytes = assembleTable(params, undefined, data);
  lap("assemble");
  install(bytes, job.key);
  lap("install");
  const ms = performance.now() - t0;
  return { key: job.key, cached: false, ms, workers: p.size, phases, stored: cachePut(job.key, bytes) };
}
