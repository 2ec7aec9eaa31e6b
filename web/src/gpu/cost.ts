// The kernel's cost per agent update, counted (docs/DESIGN.md §20): the
// kernel counts, per agent, the table blends and the axes it located
// (funnel.wgsl `counted`); the bytes follow from the buffers' layout. And
// what that gives on a laptop GPU, a projection from memory bandwidth,
// never a measurement.

import { AGENT_COUNTED, AGENT_WORDS, GOAL_WORDS } from "./kernel";

export interface CountedCost {
  updates: number;
  /** Blends of 32 cells per update (the core's 1–3 per lookup). */
  blends: number;
  /** Axes located per update (five per blend's positions, one more for the fallback speed). */
  locates: number;
  /** Bytes per update: the agent read and written, its goal, the blends' cells, the axes' samples. */
  bytes: number;
  /** Of which the η table's (cache-friendly: 5.8 MB read at random). */
  tableBytes: number;
  /** Compute passes per step (grid passes: none, the kernel has no neighbour grid). */
  passes: number;
}

/** Bytes one located axis reads: at most six search steps over ≤ 57 samples, lo, hi, the interval's sample and reciprocal. */
const LOCATE_BYTES = 10 * 4;
/** Bytes one blend reads: 32 cells of four floats. */
const BLEND_BYTES = 32 * 16;

/** The counts of `agents` (the kernel's agent words after `steps` steps from zero counts). */
export function countedCost(agents: Uint32Array, steps: number): CountedCost {
  const n = agents.length / AGENT_WORDS;
  let blends = 0;
  let locates = 0;
  for (let i = 0; i < n; i++) {
    const c = agents[i * AGENT_WORDS + AGENT_COUNTED] ?? 0;
    blends += c & 0xffff;
    locates += c >>> 16;
  }
  const updates = n * steps;
  const b = blends / updates;
  const l = locates / updates;
  const tableBytes = b * BLEND_BYTES + l * LOCATE_BYTES;
  return { updates, blends: b, locates: l, bytes: 2 * AGENT_WORDS * 4 + GOAL_WORDS * 4 + tableBytes, tableBytes, passes: 1 };
}

/** Agents per 16.7 ms a GPU moving `gbPerSecond` GB/s would step at `bytes` per update: a projection, memory-bound. */
export function projectedAgents(bytes: number, gbPerSecond: number): number {
  return (gbPerSecond * 1e9 * (1 / 60)) / bytes;
}
