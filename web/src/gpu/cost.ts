// The kernel's cost per agent update, counted (docs/DESIGN.md §20): the
// kernel counts, per agent, the table blends and the axes it located
// (funnel.wgsl `counted`); the bytes follow from the buffers' layout. And
// what that gives on a laptop GPU, a projection from memory bandwidth,
// never a measurement.

import { bucketOfCell, cellCoord } from "./gridcheck";
import { AGENT_COUNTED, AGENT_WORDS, GOAL_WORDS } from "./kernel";
import type { GpuGrid } from "./passes";

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
  /** Compute passes per step: one without avoidance (with separation see SeparationCost). */
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

/** What separation adds per agent update (passes.ts, grid.wgsl, separation.wgsl), counted from a grid the kernel built. */
export interface SeparationCost {
  /** Dispatches per step: plan, clear, count, three for the prefix sum, scatter, sort, separate, move. */
  dispatches: number;
  /** Buckets per agent (the core's table: 4n rounded up to a power of two). */
  bucketsPerAgent: number;
  /** Candidates a planning agent examines (its 3 × 3 cells' slots, itself included). */
  candidates: number;
  /** Bytes per update the avoidance adds: the plan written and read, the grid's passes (per agent and per bucket), the command, and a planning agent's candidates (index and position) over the cadence. */
  bytes: number;
}

/** Bytes per agent: the plan (11 words) written then read twice; its
 *  position read by count and scatter (8 each), their atomics (4 each) and
 *  its slot written (4); its command read and written (16 each); a
 *  planning agent's six bucket bounds (24). */
const AGENT_BYTES = 3 * 44 + 2 * 8 + 2 * 4 + 4 + 2 * 16 + 24;
/** Bytes per bucket: cleared (4), scanned (read and written, 8), offset added and cursor set (12), its range read by the sort (8). */
const BUCKET_BYTES = 4 + 8 + 12 + 8;
/** Bytes per candidate: its index in bucket order and its position. */
const CANDIDATE_BYTES = 4 + 8;

/** Separation's counted cost from `grid` (built from `agents`, the words before that step) with `settings` (GpuWorld::avoidance_settings). */
export function separationCost(grid: GpuGrid, agents: Uint32Array, settings: Float32Array): SeparationCost {
  const n = agents.length / AGENT_WORDS;
  const buckets = grid.starts.length - 1;
  const inv = settings[27] ?? NaN;
  const every = Math.max(1, settings[30] ?? 1);
  const f = new Float32Array(agents.buffer, agents.byteOffset, agents.length);
  const size = (b: number) => (grid.starts[b + 1] ?? 0) - (grid.starts[b] ?? 0);
  let cand = 0;
  for (let i = 0; i < n; i++) {
    const ix = cellCoord(f[i * AGENT_WORDS] ?? 0, inv);
    const iy = cellCoord(f[i * AGENT_WORDS + 1] ?? 0, inv);
    for (let dy = -1; dy <= 1; dy++) {
      // The row's three cells are consecutive buckets (grid.rs bucket_of_cell), round the table.
      const b = bucketOfCell(ix - 1, iy + dy, buckets);
      for (let dx = 0; dx < 3; dx++) cand += size((b + dx) & (buckets - 1));
    }
  }
  const candidates = n > 0 ? cand / n : 0;
  const bucketsPerAgent = n > 0 ? buckets / n : 0;
  return { dispatches: 10, bucketsPerAgent, candidates, bytes: AGENT_BYTES + bucketsPerAgent * BUCKET_BYTES + (candidates * CANDIDATE_BYTES) / every };
}
