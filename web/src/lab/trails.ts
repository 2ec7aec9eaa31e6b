// Per-agent trajectory store: feeds the drawn trails and the CSV/JSON export.
// Bounded memory: at most `maxAgents` agents and `maxSamples` samples each
// (oldest dropped); larger crowds are drawn without trails.

import { StateField } from "../core/wasm";

export interface Sample {
  t: number;
  x: number;
  y: number;
  theta: number;
  v: number;
  omega: number;
  mode: number;
}

/** Floats per sample in the packed buffers. */
const F = 7;

export class Trails {
  private bufs: Float32Array[] = [];
  private start: number[] = [];
  private len: number[] = [];

  constructor(readonly maxAgents = 200, readonly maxSamples = 6000) {}

  clear(): void {
    this.bufs = [];
    this.start = [];
    this.len = [];
  }

  /** Drops agent `i`'s samples only. */
  clearAgent(i: number): void {
    if (i < this.len.length) {
      this.len[i] = 0;
      this.start[i] = 0;
    }
  }

  get agents(): number {
    return this.bufs.length;
  }

  /** Appends one sample per agent from the drawn state (`stride` floats per agent, `Lab.stateStride()`). */
  record(t: number, state: Float32Array, stride: number, count: number): void {
    const n = Math.min(count, this.maxAgents);
    while (this.bufs.length < n) {
      this.bufs.push(new Float32Array(this.maxSamples * F));
      this.start.push(0);
      this.len.push(0);
    }
    for (let i = 0; i < n; i++) {
      const b = this.bufs[i]!;
      const len = this.len[i]!;
      const st = this.start[i]!;
      const slot = (st + len) % this.maxSamples;
      const o = slot * F;
      const s = i * stride;
      b[o] = t;
      b[o + 1] = state[s + StateField.X]!;
      b[o + 2] = state[s + StateField.Y]!;
      b[o + 3] = state[s + StateField.Theta]!;
      b[o + 4] = state[s + StateField.V]!;
      b[o + 5] = state[s + StateField.Omega]!;
      b[o + 6] = state[s + StateField.Mode]!;
      if (len < this.maxSamples) this.len[i] = len + 1;
      else this.start[i] = (st + 1) % this.maxSamples;
    }
  }

  /** Visits agent `i`'s points oldest first (x, y). */
  forEachPoint(i: number, f: (x: number, y: number, k: number) => void): void {
    const b = this.bufs[i];
    if (!b) return;
    const len = this.len[i]!;
    const st = this.start[i]!;
    for (let k = 0; k < len; k++) {
      const o = ((st + k) % this.maxSamples) * F;
      f(b[o + 1]!, b[o + 2]!, k);
    }
  }

  samples(i: number): Sample[] {
    const b = this.bufs[i];
    const out: Sample[] = [];
    if (!b) return out;
    const len = this.len[i]!;
    const st = this.start[i]!;
    for (let k = 0; k < len; k++) {
      const o = ((st + k) % this.maxSamples) * F;
      out.push({ t: b[o]!, x: b[o + 1]!, y: b[o + 2]!, theta: b[o + 3]!, v: b[o + 4]!, omega: b[o + 5]!, mode: b[o + 6]! });
    }
    return out;
  }
}
