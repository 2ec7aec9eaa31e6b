// The lab's shared memory beside its state buffers (../lab/stepping.ts and
// ../workers/step.worker.ts; no import of the pool, so the stepping
// worker's bundle stays small): where the control words, the step slots
// and the shown agent's internals per step lie, and how the internals are
// written and read.

import type { Internals } from "../core/wasm";
import { SLOT_RING, STATES } from "../threads/continuing";

/** The state buffers (`sab[0..STATES)`), then the control words, the step
 *  slots (`[ms, buffer]` per step, a ring of SLOT_RING) and the shown
 *  agent's internals per step (`NOTE_BYTES` each: byte length, then JSON). */
export const SAB = { ctrl: STATES, slots: STATES + 1, notes: STATES + 2 } as const;
export const SLOT = 2;
export const NOTE_BYTES = 2048;

function isNumberNote(v: unknown): v is { num: string } {
  return typeof v === "object" && v !== null && Object.keys(v).length === 1 && typeof (v as { num?: unknown }).num === "string";
}

/** The shown agent's internals noted for step `k` of a continuing job
 *  (null if its worker noted none). */
export function readNote(notes: SharedArrayBuffer, k: number): Internals | null {
  const at = NOTE_BYTES * ((k - 1) % SLOT_RING);
  const len = new Int32Array(notes, at, 1)[0] ?? 0;
  if (len <= 0 || len > NOTE_BYTES - 4) return null;
  // TextDecoder refuses views of shared memory: copy the bytes out first.
  const bytes = new Uint8Array(notes, at + 4, len).slice();
  return JSON.parse(new TextDecoder().decode(bytes), (_, v: unknown) => (isNumberNote(v) ? Number(v.num) : v)) as Internals;
}

/** Worker side: notes `internals` (null: none) for step `k`. */
export function writeNote(notes: SharedArrayBuffer, k: number, internals: Internals | null): void {
  const at = NOTE_BYTES * ((k - 1) % SLOT_RING);
  const head = new Int32Array(notes, at, 1);
  if (!internals) {
    head[0] = 0;
    return;
  }
  // JSON has no NaN or infinities (an unreachable aim's η is NaN).
  const text = JSON.stringify(internals, (_, v: unknown) => (typeof v === "number" && !Number.isFinite(v) ? { num: String(v) } : v));
  const bytes = new TextEncoder().encode(text);
  if (bytes.length > NOTE_BYTES - 4) {
    head[0] = 0;
    return;
  }
  new Uint8Array(notes, at + 4, bytes.length).set(bytes);
  head[0] = bytes.length;
}
