// The neighbour grid on the GPU: the core's hashed uniform grid
// (crate/base/grid.rs NeighbourGrid, cell = the avoidance's reach) built
// by a counting sort. Compiled after funnel.wgsl (kernel.ts joins the
// sources): it reads its settings, agents and frame.
//
// The same table as the core's: cell (ix, iy) = the floors of x/reach and
// y/reach (cell_coord), its bucket (ix + iy·ROW_PITCH) mod the table's
// size (bucket_of_cell), a size of 4n rounded up to a power of two, at
// least 64 (GpuWorld::avoidance_settings); within a bucket, ascending
// agent index. So a query's candidates come in the core's order and ties
// among equal distances fall as they fall in the core.
//
// The passes, each over agents or buckets: clear the counts (clear_counts),
// count the agents per bucket (count_agents, atomicAdd), the exclusive
// prefix sum of the counts (scan_blocks: a workgroup scan of 256 buckets
// each, their totals to block_sums; scan_sums: one workgroup scans the
// totals, each invocation a run of them, so the table has no size limit
// but the buffers': a storage binding of WebGPU's default 128 MiB holds
// the starts of fewer than 32M buckets, so crowds up to 4M agents (16M
// buckets), the lab's largest; scan_add: each bucket's block offset added, the
// cursors set to the starts, starts[buckets] = n), scatter the agent
// indices to their bucket's slots (scatter_agents, atomicAdd on the
// cursors: any order within a bucket), then each bucket's slots put back
// into ascending index (sort_buckets, an insertion sort: buckets hold a
// few agents). Buckets are dispatched in two dimensions (a dispatch has
// at most 65535 workgroups a side).

// grid.rs ROW_PITCH.
const ROW_PITCH: u32 = 0x9E3779B1u;
const SCAN: u32 = 256u;

@group(0) @binding(13) var<storage, read_write> counts: array<atomic<u32>>;
@group(0) @binding(14) var<storage, read_write> starts: array<u32>;
@group(0) @binding(15) var<storage, read_write> block_sums: array<u32>;
@group(0) @binding(16) var<storage, read_write> cursor: array<atomic<u32>>;
@group(0) @binding(17) var<storage, read_write> order: array<u32>;

var<workgroup> scan_tmp: array<u32, SCAN>;

fn bucket_count() -> u32 { return u32(S(BUCKETS)); }

// grid.rs cell_coord: the floor of v/cell by truncation and a correction
// (the conversion saturates, as Rust's `as` does).
fn cell_coord(v: f32) -> i32 {
  let x = v * S(INV_CELL);
  let t = i32(x);
  return t - select(0, 1, f32(t) > x);
}

// grid.rs bucket_of_cell (wrapping arithmetic, as WGSL's u32 is).
fn bucket_of_cell(ix: i32, iy: i32) -> u32 {
  return (u32(ix) + u32(iy) * ROW_PITCH) & (bucket_count() - 1u);
}

fn bucket_of_agent(i: u32) -> u32 {
  return bucket_of_cell(cell_coord(agents[i].x), cell_coord(agents[i].y));
}

// The bucket (or scan element) of a two-dimensional dispatch of SCAN-wide
// workgroups.
fn flat_index(id: vec3<u32>, n: vec3<u32>) -> u32 { return id.x + id.y * n.x * SCAN; }

@compute @workgroup_size(256)
fn clear_counts(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) nw: vec3<u32>) {
  let b = flat_index(id, nw);
  if (b <= bucket_count()) { starts[b] = 0u; }
}

@compute @workgroup_size(64)
fn count_agents(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= frame.n) { return; }
  atomicAdd(&counts[bucket_of_agent(i)], 1u);
}

// The inclusive scan of scan_tmp in place (Hillis–Steele), by SCAN invocations.
fn scan_workgroup(lid: u32) {
  for (var off = 1u; off < SCAN; off *= 2u) {
    var t = 0u;
    if (lid >= off) { t = scan_tmp[lid - off]; }
    workgroupBarrier();
    scan_tmp[lid] += t;
    workgroupBarrier();
  }
}

@compute @workgroup_size(256)
fn scan_blocks(@builtin(global_invocation_id) id: vec3<u32>, @builtin(local_invocation_index) lid: u32,
               @builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nw: vec3<u32>) {
  let b = flat_index(id, nw);
  let nb = bucket_count();
  var v = 0u;
  if (b < nb) { v = starts[b]; }
  scan_tmp[lid] = v;
  workgroupBarrier();
  scan_workgroup(lid);
  if (b < nb) { starts[b] = scan_tmp[lid] - v; }
  let block = wid.x + wid.y * nw.x;
  if (lid == SCAN - 1u && block * SCAN < nb) { block_sums[block] = scan_tmp[lid]; }
}

@compute @workgroup_size(256)
fn scan_sums(@builtin(local_invocation_index) lid: u32) {
  let blocks = (bucket_count() + SCAN - 1u) / SCAN;
  let run = (blocks + SCAN - 1u) / SCAN;
  let lo = min(lid * run, blocks);
  let hi = min(lo + run, blocks);
  var total = 0u;
  for (var k = lo; k < hi; k++) { total += block_sums[k]; }
  scan_tmp[lid] = total;
  workgroupBarrier();
  scan_workgroup(lid);
  var at = scan_tmp[lid] - total;
  for (var k = lo; k < hi; k++) {
    let t = block_sums[k];
    block_sums[k] = at;
    at += t;
  }
}

@compute @workgroup_size(256)
fn scan_add(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) nw: vec3<u32>) {
  let b = flat_index(id, nw);
  let nb = bucket_count();
  if (b < nb) {
    let s = starts[b] + block_sums[b / SCAN];
    starts[b] = s;
    atomicStore(&cursor[b], s);
  } else if (b == nb) {
    starts[b] = frame.n;
  }
}

@compute @workgroup_size(64)
fn scatter_agents(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= frame.n) { return; }
  order[atomicAdd(&cursor[bucket_of_agent(i)], 1u)] = i;
}

@compute @workgroup_size(256)
fn sort_buckets(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) nw: vec3<u32>) {
  let b = flat_index(id, nw);
  if (b >= bucket_count()) { return; }
  let lo = starts[b];
  let hi = starts[b + 1u];
  for (var s = lo + 1u; s < hi; s++) {
    let v = order[s];
    var t = s;
    loop {
      if (t <= lo || order[t - 1u] <= v) { break; }
      order[t] = order[t - 1u];
      t -= 1u;
    }
    order[t] = v;
  }
}
