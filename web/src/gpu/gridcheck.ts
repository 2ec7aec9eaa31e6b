// The GPU-built neighbour grid (grid.wgsl) against the core's table,
// counted here on the CPU from the same positions (crate/base/grid.rs
// cell_coord, bucket_of_cell; the parity checks, docs/DESIGN.md §20):
// every agent in exactly one slot, each bucket's range as long as the
// agents the CPU puts in it, each slot's agent in its range's bucket, and
// ascending index within a bucket (the core's order).

import { AGENT_WORDS } from "./kernel";
import type { GpuGrid } from "./passes";

/** grid.rs ROW_PITCH. */
const ROW_PITCH = 0x9e3779b1;
/** Settings' index of 1/reach (GpuWorld::avoidance_settings). */
const SETTING_INV_CELL = 27;

export interface GridParity {
  buckets: number;
  agents: number;
  /** Agents not in exactly one slot. */
  misplaced: number;
  /** Buckets whose range differs from the CPU's count. */
  countsDiffer: number;
  /** Slots whose agent belongs to another bucket, or out of index order. */
  disordered: number;
  /** The most agents in one bucket. */
  fullest: number;
}

/** grid.rs cell_coord in f32: the floor of v·(1/cell), the conversion saturating. */
export function cellCoord(v: number, inv: number): number {
  const x = Math.fround(v * inv);
  const t = Math.max(-2147483648, Math.min(2147483647, Math.trunc(x)));
  return t - (t > x ? 1 : 0);
}

/** grid.rs bucket_of_cell: cell (ix, iy)'s bucket of `buckets` (a power of two). */
export function bucketOfCell(ix: number, iy: number, buckets: number): number {
  return ((ix + Math.imul(iy, ROW_PITCH)) >>> 0) & (buckets - 1);
}

/** The core's bucket of an agent at (x, y). */
export function bucketOf(x: number, y: number, inv: number, buckets: number): number {
  return bucketOfCell(cellCoord(x, inv), cellCoord(y, inv), buckets);
}

/** The grid `g` built from `agents` (the kernel's words before the step) against the CPU's counts. */
export function checkGrid(g: GpuGrid, agents: Uint32Array, settings: Float32Array): GridParity {
  const n = agents.length / AGENT_WORDS;
  const buckets = g.starts.length - 1;
  const inv = settings[SETTING_INV_CELL] ?? NaN;
  const f = new Float32Array(agents.buffer, agents.byteOffset, agents.length);
  const bucket = new Uint32Array(n);
  const count = new Uint32Array(buckets);
  for (let i = 0; i < n; i++) {
    const b = bucketOf(f[i * AGENT_WORDS] ?? NaN, f[i * AGENT_WORDS + 1] ?? NaN, inv, buckets);
    bucket[i] = b;
    count[b] = (count[b] ?? 0) + 1;
  }
  const out: GridParity = { buckets, agents: n, misplaced: 0, countsDiffer: 0, disordered: 0, fullest: 0 };
  const seen = new Uint32Array(n);
  for (const i of g.order) if (i < n) seen[i] = (seen[i] ?? 0) + 1;
  for (let i = 0; i < n; i++) if (seen[i] !== 1) out.misplaced++;
  if (g.starts[buckets] !== n || g.order.length !== n) out.misplaced = Math.max(out.misplaced, 1);
  for (let b = 0; b < buckets; b++) {
    const lo = g.starts[b] ?? 0;
    const hi = g.starts[b + 1] ?? 0;
    if (hi - lo !== count[b]) out.countsDiffer++;
    out.fullest = Math.max(out.fullest, hi - lo);
    for (let s = lo; s < hi && s < n; s++) {
      const i = g.order[s] ?? n;
      if (bucket[i] !== b || (s > lo && (g.order[s - 1] ?? 0) >= i)) out.disordered++;
    }
  }
  return out;
}
