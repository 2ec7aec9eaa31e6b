// What the crowd's page and its crowd workers share (../crowd/stepper.ts,
// `CrowdStepper`, and ../workers/crowd.worker.ts): a task per worker and
// its reply, the shared memory's layout, and how the crowd is cut into
// vertical strips and their shares balanced. No DOM: both bundles import it.

import type { CrowdConfig } from "../core/wasm";
import { STATES } from "../threads/continuing";

export interface CrowdTask {
  init: { config: CrowdConfig; shared: SharedArrayBuffer[] | null } | null;
  /** 0: only (re)build. */
  steps: number;
  /** Shared buffer holding the state to step (the other one is written). */
  front: number;
  /** The state to step when there is no shared memory. */
  state: Float32Array | null;
  time: number;
  lo: number;
  hi: number;
  /** This worker's strip (shared memory: the cuts are made in the workers, each step). */
  worker: number;
  workers: number;
  /** The traced boid (shared memory: worker 0 notes it after every step but the last). */
  traced: number;
}

export interface CrowdReply {
  stepMs: number;
  owned: number;
  /** Without shared memory: the stepped boids and their `[x, y, vx, vy]`. */
  indices: Uint32Array | null;
  states: Float32Array | null;
}

/** Shared memory: the state buffers (`sab[0..STATES)`, ../threads/continuing.ts),
 *  then the control words, the step slots and the balance. */
export const SAB = { ctrl: STATES, slots: STATES + 1, balance: STATES + 2 } as const;
/** Per step `[x, y, ms, buffer]` of the traced boid, the step's wall time
 *  and the buffer it was written to (a ring of SLOT_RING). */
export const SLOT = 4;
/** `?workers=` goes up to this (the balance has a place per worker). */
export const MAX_CROWD_WORKERS = 16;
/** Shared memory, `sab[SAB.balance]` (Float32), the strips' balance: per worker its
 *  last step's wall ms and boids, then each strip's share of the boids for
 *  the next step (worker 0 sets them at every decision; all 0 at the
 *  start: equal shares). */
export const BALANCE = { ms: 0, boids: 1, share: 2 * MAX_CROWD_WORKERS } as const;
export const BALANCE_FLOATS = 3 * MAX_CROWD_WORKERS;
/** Weight of the last step's rates in the new shares (the rest: the old). */
const BALANCE_GAIN = 0.3;

/** Strips of equal counts take unequal times (unequal density, and the
 *  page or the compositor taking a core from one worker), and at the
 *  barrier the faster worker waits for the slower. Each strip's next share
 *  of the boids follows its worker's measured boids per ms (smoothed by
 *  BALANCE_GAIN, at least a tenth of an equal share): the slower worker
 *  gets fewer, and both finish a step at about the same time. The split
 *  never changes a bit of the state (strips step their boids as one core
 *  would), only who waits. Writes the new shares into `bal`. */
export function rebalance(bal: Float32Array, workers: number): void {
  const rates: number[] = [];
  for (let w = 0; w < workers; w++) {
    const ms = bal[2 * w + BALANCE.ms] ?? 0;
    const boids = bal[2 * w + BALANCE.boids] ?? 0;
    rates.push(ms > 0 && boids > 0 ? boids / ms : 0);
  }
  const total = rates.reduce((a, b) => a + b, 0);
  if (!(total > 0) || rates.some((r) => !(r > 0))) return;
  const floor = 0.1 / workers;
  const next = rates.map((r, w) => {
    const old = bal[BALANCE.share + w] ?? 0;
    const was = old > 0 ? old : 1 / workers;
    return Math.max(floor, (1 - BALANCE_GAIN) * was + (BALANCE_GAIN * r) / total);
  });
  const sum = next.reduce((a, b) => a + b, 0);
  next.forEach((v, w) => (bal[BALANCE.share + w] = v / sum));
}

/** Cuts of x into `k` strips of about equal counts (or of `shares` of
 *  the boids, [`rebalance`], when given and set), from a sample of `pos`
 *  (flat x, y); the first is −∞ and the last +∞. */
export function stripCuts(state: Float32Array, n: number, k: number, shares?: Float32Array): number[] {
  const cuts = [-Infinity];
  if (k > 1 && n > 0) {
    const stride = Math.max(1, Math.floor(n / 4096));
    const xs: number[] = [];
    for (let i = 0; i < n; i += stride) {
      const x = state[2 * i] ?? 0;
      if (Number.isFinite(x)) xs.push(x);
    }
    xs.sort((a, b) => a - b);
    const set = shares !== undefined && (shares[0] ?? 0) > 0;
    let q = 0;
    for (let w = 1; w < k; w++) {
      q += set ? (shares[w - 1] ?? 0) : 1 / k;
      cuts.push(Math.fround(xs[Math.min(xs.length - 1, Math.floor(q * xs.length))] ?? 0));
    }
  } else {
    for (let w = 1; w < k; w++) cuts.push(0);
  }
  cuts.push(Infinity);
  return cuts;
}
