// A pool of Web Workers that splits one job into tasks (reusable:
// any worker module that answers `{ id, task }` with `{ id, ok, result }`).
// `navigator.hardwareConcurrency` workers by default, created on first use
// and kept (a worker's wasm instantiation is paid once); tasks are handed
// out one at a time to whichever worker is free, so a slow task does not
// hold the others back; results come back in task order. `cancel()` ends
// the job in flight (its workers are terminated, its promise rejects).
// `each()` (the lab's and the crowd's stepping workers) is the other way to use
// it: task i to worker i, every worker at once, for workers that keep state
// between calls (each owns a slice of the world).

/** What a pool worker receives. */
export interface TaskMessage<T> {
  id: number;
  task: T;
}

/** What a pool worker answers. */
export type ResultMessage<R> = { id: number; ok: true; result: R } | { id: number; ok: false; error: string };

export class Cancelled extends Error {
  constructor() {
    super("cancelled");
  }
}

export class WorkerPool<T, R> {
  private workers: Worker[] = [];
  private job = 0;
  private abort: (() => void) | null = null;

  /** `make` creates one worker; `size` workers at most. */
  constructor(
    private readonly make: () => Worker,
    readonly size = Math.max(1, Math.min(16, navigator.hardwareConcurrency || 2)),
  ) {}

  /** Runs every task; `onProgress(done, total)` after each. One job at a
   *  time: a new run cancels the one in flight. */
  run(tasks: readonly T[], onProgress: (done: number, total: number) => void = () => {}): Promise<R[]> {
    this.cancel();
    const job = ++this.job;
    while (this.workers.length < Math.min(this.size, tasks.length)) this.workers.push(this.make());
    const results: R[] = new Array<R>(tasks.length);
    let next = 0;
    let done = 0;
    return new Promise<R[]>((resolve, reject) => {
      const fail = this.failer(reject);
      const feed = (w: Worker): void => {
        if (next >= tasks.length) return;
        const id = next++;
        const msg: TaskMessage<T> = { id, task: tasks[id] as T };
        w.postMessage(msg);
      };
      for (const w of this.workers) {
        w.onmessage = (ev: MessageEvent<ResultMessage<R>>) => {
          if (job !== this.job) return;
          const m = ev.data;
          if (!m.ok) {
            // Not `cancel()`: that rejects the job with `Cancelled`, which
            // callers take for a newer job and ignore (a table build whose
            // workers cannot load the core would stand at 0 % with no word).
            this.halt();
            fail(new Error(m.error));
            return;
          }
          results[m.id] = m.result;
          done++;
          onProgress(done, tasks.length);
          if (done === tasks.length) {
            this.abort = null;
            resolve(results);
          } else feed(w);
        };
        w.onerror = (ev: ErrorEvent) => {
          if (job !== this.job) return;
          this.halt();
          fail(new Error(`worker failed: ${ev.message || "its script did not load"}`));
        };
        feed(w);
      }
      if (tasks.length === 0) resolve(results);
    });
  }

  /** Sends task i to worker i (created if needed; at most `size`), all at
   *  once, and resolves with their answers in order: for stateful workers
   *  (each steps its own slice of agents) that must see every
   *  call. `transfer(task)` lists what to move instead of copy. One job at a
   *  time, like `run`. */
  each(tasks: readonly T[], transfer: (task: T) => Transferable[] = () => []): Promise<R[]> {
    if (tasks.length > this.size) return Promise.reject(new Error(`${tasks.length} tasks for ${this.size} workers`));
    const job = ++this.job;
    while (this.workers.length < tasks.length) this.workers.push(this.make());
    const results: R[] = new Array<R>(tasks.length);
    let done = 0;
    return new Promise<R[]>((resolve, reject) => {
      const fail = this.failer(reject);
      tasks.forEach((task, id) => {
        const w = this.workers[id] as Worker;
        w.onmessage = (ev: MessageEvent<ResultMessage<R>>) => {
          if (job !== this.job) return;
          const m = ev.data;
          if (!m.ok) {
            this.job++;
            fail(new Error(m.error));
            return;
          }
          results[id] = m.result;
          if (++done === tasks.length) {
            this.abort = null;
            resolve(results);
          }
        };
        w.onerror = (ev: ErrorEvent) => {
          if (job !== this.job) return;
          this.job++;
          fail(new Error(`worker failed: ${ev.message || "its script did not load"}`));
        };
        const msg: TaskMessage<T> = { id, task };
        w.postMessage(msg, transfer(task));
      });
      if (tasks.length === 0) resolve(results);
    });
  }

  /** The job's failure: rejects with `e` and forgets the job; `cancel()`
   *  fails it with `Cancelled`. */
  private failer(reject: (e: Error) => void): (e: Error) => void {
    const fail = (e: Error): void => {
      this.abort = null;
      reject(e);
    };
    this.abort = () => fail(new Cancelled());
    return fail;
  }

  /** Ends the job in flight, if any (its workers are replaced on the next
   *  run); its promise rejects with `Cancelled`. */
  cancel(): void {
    if (!this.abort) return;
    const abort = this.abort;
    this.abort = null;
    this.halt();
    abort();
  }

  /** Forgets the job in flight and terminates its workers (replaced on the
   *  next run), without settling its promise. */
  private halt(): void {
    this.job++;
    for (const w of this.workers) w.terminate();
    this.workers = [];
  }

  /** Terminates every worker. */
  terminate(): void {
    this.cancel();
    for (const w of this.workers) w.terminate();
    this.workers = [];
  }
}
