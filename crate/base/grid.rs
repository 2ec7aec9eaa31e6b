//! A hashed uniform grid over points: every neighbour within a reach,
//! without an O(n²) scan. Used by the crowd's separation (paper 003) and by
//! avoidance and its proximity metrics.
//!
//! Points are binned into a uniform grid whose cell is the interaction
//! distance, so each point only examines the 3 × 3 cells around its own.
//! Cells map to a table of 4n to 8n buckets by `(ix + iy·P) mod buckets`
//! (P a large odd constant) rather than being laid out over a bounding
//! box: points that fly far off cannot make the grid's memory explode,
//! and the three cells of a row stay in adjacent buckets, so a query reads
//! three contiguous runs of a position array kept in bucket order (cache
//! friendly at tens of thousands of points). Cells sharing a bucket only
//! add candidates, which the exact distance test rejects. Buffers are
//! reused between rebuilds, so a rebuild allocates only when the point
//! count grows. Every candidate pair examined is counted
//! ([`NeighbourGrid::checks`]) so tests can prove the search is not
//! quadratic.

use glam::Vec2;

/// A hashed uniform grid over boid positions, rebuilt every step with a
/// counting sort (stable, so neighbour order — and therefore f32 sums — is
/// deterministic).
#[derive(Clone, Debug, Default)]
pub struct NeighbourGrid {
    inv_cell: f32,
    mask: u32,
    /// Cell of each boid, in the visiting order of the last rebuild (its
    /// bucket follows): computed once, not again when placed.
    cell_of: Vec<[i32; 2]>,
    /// Start of each bucket in `order`; `buckets + 1` entries.
    starts: Vec<u32>,
    /// Boid indices sorted by bucket (ascending index within a bucket).
    order: Vec<u32>,
    /// Positions in the same order as `order`.
    sorted: Vec<Vec2>,
    /// Cell `(ix, iy)` of each boid, in the same order as `order`: lets
    /// [`count_overlaps`] tell a cell's own boids from a colliding cell's.
    cells: Vec<[i32; 2]>,
    /// The visiting order of a rebuild (last step's `order`; kept to reuse
    /// its allocation).
    visit: Vec<u32>,
    /// Per boid: `generation` if a member of the present
    /// [`NeighbourGrid::rebuild_members`], one more once visited.
    mark: Vec<u32>,
    generation: u32,
    /// `order` holds every boid of a [`NeighbourGrid::rebuild`] (not a
    /// member subset): the next full rebuild may visit boids in it.
    order_full: bool,
    checks: u64,
}

#[inline]
fn cell_coord(v: f32, inv_cell: f32) -> i32 {
    // `as` saturates (and maps NaN to 0): never UB, never a panic. Floor by
    // hand: without SSE4.1 `f32::floor` is a libm call, and this runs 10×
    // per boid per step.
    // The correction is subtracted, not branched on: a sign test would
    // mispredict about once per boid per step (boids on both sides of an
    // axis), in the rebuild and the queries alike.
    let x = v * inv_cell;
    let t = x as i32;
    t.saturating_sub(i32::from((t as f32) > x))
}

/// Row pitch of the bucket map: odd, so rows spread over all buckets.
const ROW_PITCH: u32 = 0x9E37_79B1;

#[inline]
fn bucket_of_cell(ix: i32, iy: i32, mask: u32) -> u32 {
    (ix as u32).wrapping_add((iy as u32).wrapping_mul(ROW_PITCH)) & mask
}

impl NeighbourGrid {
    /// An empty grid; buffers grow on the first [`NeighbourGrid::rebuild`].
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Candidate pairs examined since the last [`NeighbourGrid::reset_checks`].
    #[must_use]
    pub fn checks(&self) -> u64 {
        self.checks
    }

    /// Resets the candidate-pair counter.
    pub fn reset_checks(&mut self) {
        self.checks = 0;
    }

    /// Re-bins the boids at `pos` (flat `[x0, y0, x1, y1, ...]`) into cells
    /// of side `cell` (> 0, world units).
    ///
    /// From the second rebuild of the same boids on, they are visited in
    /// the previous rebuild's bucket order, not by index. The counting sort
    /// writes each boid's slot in three arrays; visited by index (spatially
    /// random in a moving crowd) those writes miss the cache one by one,
    /// visited in last step's order they land almost in sequence (most
    /// boids stay in their cell from one step to the next). Within a bucket
    /// the boids then follow last step's order, so each bucket is put back
    /// into ascending index by an insertion sort (runs already sorted but
    /// for the boids that changed cell): the same order, and so the same
    /// bits, as the by-index sort. `diagnostics/crowd_profile.rs` times the
    /// crowd's step at Test IV's density.
    pub fn rebuild(&mut self, pos: &[f32], cell: f32) {
        let n = pos.len() / 2;
        if self.order_full && self.order.len() == n && n > 0 {
            let mut prev = core::mem::take(&mut self.visit);
            prev.clear();
            prev.extend_from_slice(&self.order);
            self.rebuild_from(pos, cell, n, prev.iter().map(|&i| i as usize));
            self.sort_buckets_by_index();
            self.visit = prev;
        } else {
            self.rebuild_from(pos, cell, n, 0..n);
            // The next rebuild's visiting order: grown now, so steps after
            // the first allocate nothing (`tests/crowd_alloc.rs`).
            self.visit.clear();
            self.visit.reserve(n);
        }
        self.order_full = true;
    }

    /// Restores ascending index within every bucket after a rebuild that
    /// visited boids out of index order (insertion sort of `order`,
    /// `sorted` and `cells` together; `starts` holds each bucket's start).
    fn sort_buckets_by_index(&mut self) {
        for s in 1..self.order.len() {
            let id = self.order[s];
            if self.order[s - 1] <= id {
                continue;
            }
            let [ix, iy] = self.cells[s];
            let start = self.starts[bucket_of_cell(ix, iy, self.mask) as usize] as usize;
            if s == start {
                continue;
            }
            let (p, c) = (self.sorted[s], self.cells[s]);
            let mut t = s;
            while t > start && self.order[t - 1] > id {
                self.order[t] = self.order[t - 1];
                self.sorted[t] = self.sorted[t - 1];
                self.cells[t] = self.cells[t - 1];
                t -= 1;
            }
            self.order[t] = id;
            self.sorted[t] = p;
            self.cells[t] = c;
        }
    }

    /// Re-bins only the boids `members` (ascending indices into `pos`) with
    /// the bucket table of all `pos.len() / 2` boids (a stepping worker's strip):
    /// any boid's neighbours among the members come in the order
    /// [`NeighbourGrid::rebuild`] gives them, so sums over them are the
    /// same bits when every neighbour within reach is a member.
    ///
    /// The table is sized for the members, not for all boids: a table of
    /// any power-of-two size ≥ 64 gives the same order. A query visits
    /// rows `iy−1..=iy+1`, each the run of buckets of cells `ix−1..=ix+1`
    /// and boids by ascending index within a bucket, so boids within reach
    /// come in (row, cell, index) order unless two of the nine cells share
    /// a bucket; the buckets of cells one or two rows apart differ by
    /// `ROW_PITCH` or `2·ROW_PITCH` (mod the size) plus at most 2, which is
    /// never 0 mod a power of two ≥ 64 (`ROW_PITCH` ≡ 49 mod 64): the
    /// rows of a query never share a bucket (`candidate_runs`), and a colliding far cell's
    /// boids only add rejected candidates.
    pub fn rebuild_members(&mut self, pos: &[f32], cell: f32, members: &[u32]) {
        debug_assert!(members.windows(2).all(|w| w[0] < w[1]));
        self.order_full = false;
        let n_all = pos.len() / 2;
        if self.order.is_empty() || members.is_empty() {
            self.rebuild_from(
                pos,
                cell,
                members.len(),
                members.iter().map(|&i| i as usize),
            );
            self.visit.clear();
            self.visit.reserve(n_all);
            self.mark.resize(n_all, 0);
            return;
        }
        // As `rebuild`: last rebuild's order first (the members still in
        // it), then the new members; generation marks tell them apart
        // without clearing an array per step.
        if self.generation >= u32::MAX - 2 {
            self.mark.fill(0);
            self.generation = 0;
        }
        self.generation += 2;
        let (member, seen) = (self.generation, self.generation + 1);
        self.mark.resize(n_all, 0);
        for &m in members {
            self.mark[m as usize] = member;
        }
        let mut visit = core::mem::take(&mut self.visit);
        visit.clear();
        for &i in &self.order {
            if let Some(k) = self.mark.get_mut(i as usize) {
                if *k == member {
                    *k = seen;
                    visit.push(i);
                }
            }
        }
        for &m in members {
            if self.mark[m as usize] == member {
                visit.push(m);
            }
        }
        self.rebuild_from(pos, cell, members.len(), visit.iter().map(|&i| i as usize));
        self.sort_buckets_by_index();
        self.visit = visit;
    }

    /// The counting sort behind both rebuilds. The placing pass runs
    /// backwards with a falling cursor per bucket (ascending index within a
    /// bucket), which leaves each cursor at its bucket's start: no pass over
    /// the table to restore it, and each boid's cell is computed once.
    fn rebuild_from(
        &mut self,
        pos: &[f32],
        cell: f32,
        n_all: usize,
        members: impl DoubleEndedIterator<Item = usize> + ExactSizeIterator + Clone,
    ) {
        let m = members.len();
        let buckets = (4 * n_all).next_power_of_two().max(64);
        self.mask = (buckets - 1) as u32;
        self.inv_cell = 1.0 / cell;
        self.cell_of.resize(m, [0, 0]);
        self.order.resize(m, 0);
        self.sorted.resize(m, Vec2::ZERO);
        self.cells.resize(m, [0, 0]);
        self.starts.clear();
        self.starts.resize(buckets + 1, 0);
        // Counts, then running ends: starts[b] = end of bucket b.
        for (k, i) in members.clone().enumerate() {
            let ix = cell_coord(pos[2 * i], self.inv_cell);
            let iy = cell_coord(pos[2 * i + 1], self.inv_cell);
            let b = bucket_of_cell(ix, iy, self.mask);
            self.cell_of[k] = [ix, iy];
            self.starts[b as usize] += 1;
        }
        let mut run = 0;
        for s in &mut self.starts[..buckets] {
            run += *s;
            *s = run;
        }
        self.starts[buckets] = m as u32;
        for (k, i) in members.enumerate().rev() {
            // The cell as counted (the same position: the same cell), its
            // bucket recomputed (three operations, where the cell's floors
            // took about twenty).
            let [ix, iy] = self.cell_of[k];
            let b = bucket_of_cell(ix, iy, self.mask) as usize;
            let slot = self.starts[b] - 1;
            self.starts[b] = slot;
            let p = Vec2::new(pos[2 * i], pos[2 * i + 1]);
            self.order[slot as usize] = i as u32;
            self.sorted[slot as usize] = p;
            self.cells[slot as usize] = [ix, iy];
        }
    }

    /// Boids binned by the last rebuild.
    #[inline]
    #[must_use]
    pub fn binned(&self) -> usize {
        self.order.len()
    }

    /// The `k`-th boid in bucket order (`k < n` of the last rebuild). Boids
    /// of one cell are consecutive, so visiting boids in this order makes
    /// consecutive neighbour queries hit the same, already cached buckets.
    #[inline]
    #[must_use]
    pub fn boid_in_bucket_order(&self, k: usize) -> usize {
        self.order[k] as usize
    }

    /// The position of the `k`-th boid in bucket order, as binned.
    #[inline]
    #[must_use]
    pub fn position_in_bucket_order(&self, k: usize) -> Vec2 {
        self.sorted[k]
    }

    /// Calls `f(j, pᵢ − pⱼ, |pᵢ − pⱼ|²)` for every boid `j ≠ i` with
    /// `|pᵢ − pⱼ| < reach` (`reach` ≤ the cell size given to `rebuild`),
    /// in a deterministic order.
    #[inline]
    pub fn for_each_neighbour(
        &mut self,
        pos: &[f32],
        i: usize,
        reach: f32,
        f: impl FnMut(usize, Vec2, f32),
    ) {
        self.for_each_neighbour_at(Vec2::new(pos[2 * i], pos[2 * i + 1]), i, reach, f);
    }

    /// [`NeighbourGrid::for_each_neighbour`] for boid `i` at `pi` (its
    /// position as binned: a caller visiting boids in bucket order reads it
    /// from [`NeighbourGrid::position_in_bucket_order`], in sequence).
    #[inline]
    pub fn for_each_neighbour_at(
        &mut self,
        pi: Vec2,
        i: usize,
        reach: f32,
        mut f: impl FnMut(usize, Vec2, f32),
    ) {
        let r2 = reach * reach;
        let (runs, n_runs) = self.candidate_runs(pi);
        for &(lo, hi) in &runs[..n_runs] {
            self.scan(i, pi, r2, lo, hi, &mut f);
        }
    }

    /// The runs of bucket-order slots (`lo..hi`, into the order of
    /// [`NeighbourGrid::boid_in_bucket_order`]) that hold the candidates
    /// of a neighbour query at `p`, in the order
    /// [`NeighbourGrid::for_each_neighbour`] visits them: the 3 × 3 cells
    /// round `p`'s, each bucket once. A caller keeping its own per-slot
    /// copy of the boids (the avoidance's) scans the same candidates
    /// in the same order without the callback.
    #[inline(always)]
    #[must_use]
    pub fn candidate_runs(&self, p: Vec2) -> ([(u32, u32); 9], usize) {
        let [ix, iy] = self.cell_of(p);
        self.cell_runs([ix.wrapping_sub(1), iy.wrapping_sub(1)], 3, 3)
    }

    /// The cell `[ix, iy]` a query at `p` is binned in.
    #[inline]
    #[must_use]
    pub fn cell_of(&self, p: Vec2) -> [i32; 2] {
        [
            cell_coord(p.x, self.inv_cell),
            cell_coord(p.y, self.inv_cell),
        ]
    }

    /// The runs of bucket-order slots holding the boids of the `nx × ny`
    /// cells (each at most 3) from `first` up, row by row, each bucket
    /// once; [`NeighbourGrid::candidate_runs`] is the 3 × 3 block round a
    /// point. Cells sharing a bucket with one of them add their boids, as
    /// in any query.
    #[inline(always)]
    #[must_use]
    pub fn cell_runs(&self, first: [i32; 2], nx: u32, ny: u32) -> ([(u32, u32); 9], usize) {
        debug_assert!(nx <= 3 && ny <= 3);
        let buckets = self.mask + 1;
        // Each row's cells are buckets b..b+nx (mod buckets): at most two
        // non-wrapping intervals per row.
        let mut ranges = [(0u32, 0u32); 9];
        let mut n_ranges = 0;
        for dy in 0..ny as i32 {
            let b = bucket_of_cell(first[0], first[1].wrapping_add(dy), self.mask);
            if b + nx <= buckets {
                ranges[n_ranges] = (b, b + nx);
                n_ranges += 1;
            } else {
                ranges[n_ranges] = (b, buckets);
                ranges[n_ranges + 1] = (0, b + nx - buckets);
                n_ranges += 2;
            }
        }
        // Rows never land on overlapping buckets: the buckets of rows one
        // or two apart differ by `ROW_PITCH` or `2·ROW_PITCH` mod the table
        // size, ≡ 49 or 34 mod 64, so at least 15 apart round the table of
        // ≥ 64 buckets (`rebuild_from`), and a row spans at most 3 (see
        // `rebuild_members`). So a release build has no pairwise overlap
        // test and fallback: in wasm, where this function is not inlined,
        // such a test is a large share of the crowd's step, for a case that
        // cannot occur; the debug assertion checks it in tests.
        debug_assert!((1..n_ranges)
            .all(|a| (0..a).all(|b| ranges[a].0 >= ranges[b].1 || ranges[b].0 >= ranges[a].1)));
        for r in &mut ranges[..n_ranges] {
            *r = (self.starts[r.0 as usize], self.starts[r.1 as usize]);
        }
        (ranges, n_ranges)
    }

    /// True when no two different cells at most `w` cells apart on each
    /// axis share a bucket (the table is large enough): then a query over
    /// part of a block of cells within that distance of each other finds
    /// exactly the boids of those cells in it that the whole block's query
    /// finds, no colliding cell's.
    #[must_use]
    pub fn buckets_distinct_within(&self, w: i32) -> bool {
        // Buckets are linear in the cell mod the table size: two cells
        // share one when their difference maps to bucket 0.
        (0..=w).all(|dy| {
            (-w..=w).all(|dx| (dy, dx) <= (0, 0) || bucket_of_cell(dx, dy, self.mask) != 0)
        })
    }

    /// Adds `n` to [`NeighbourGrid::checks`] (candidate pairs a caller of
    /// [`NeighbourGrid::candidate_runs`] examined itself).
    #[inline]
    pub fn add_checks(&mut self, n: u64) {
        self.checks += n;
    }

    /// Visits the boids of bucket-order slots `s0..s1` (one contiguous run).
    #[inline]
    fn scan(
        &mut self,
        i: usize,
        pi: Vec2,
        r2: f32,
        s0: u32,
        s1: u32,
        f: &mut impl FnMut(usize, Vec2, f32),
    ) {
        let (s0, s1) = (s0 as usize, s1 as usize);
        let mut checks = 0u64;
        for (&j, &pj) in self.order[s0..s1].iter().zip(&self.sorted[s0..s1]) {
            let j = j as usize;
            if j == i {
                continue;
            }
            checks += 1;
            let d = pi - pj;
            let d2 = d.length_squared();
            if d2 < r2 {
                f(j, d, d2);
            }
        }
        self.checks += checks;
    }
}

impl NeighbourGrid {
    /// Unordered pairs closer than `reach` (≤ the cell size given to
    /// `rebuild`), each examined from one side only: the boid at bucket
    /// slot `k` looks at later slots of its own cell and at the four
    /// "forward" cells `(ix+1, iy)`, `(ix-1..=ix+1, iy+1)` — the other four
    /// neighbours see it from their side. Half the candidates of nine-cell
    /// queries, the same count. A candidate counts only if its stored cell
    /// is the cell scanned for, so cells sharing a bucket neither add nor
    /// double pairs.
    pub fn count_pairs_forward(&mut self, reach: f32) -> u64 {
        let r2 = reach * reach;
        let buckets = self.mask + 1;
        let (mut pairs, mut checks) = (0u64, 0u64);
        for k in 0..self.order.len() {
            let pi = self.sorted[k];
            let [ix, iy] = self.cells[k];
            let own = bucket_of_cell(ix, iy, self.mask) as usize;
            // Later boids of this cell (its bucket from slot k + 1 on).
            let end = self.starts[own + 1] as usize;
            for s in k + 1..end {
                checks += 1;
                let hit = self.cells[s] == [ix, iy] && (pi - self.sorted[s]).length_squared() < r2;
                pairs += u64::from(hit);
            }
            // The cell to the right.
            let right = [ix.wrapping_add(1), iy];
            let b = bucket_of_cell(right[0], right[1], self.mask) as usize;
            for s in self.starts[b] as usize..self.starts[b + 1] as usize {
                checks += 1;
                let hit = self.cells[s] == right && (pi - self.sorted[s]).length_squared() < r2;
                pairs += u64::from(hit);
            }
            // The row above: buckets b .. b + 3, possibly wrapping.
            let up = iy.wrapping_add(1);
            let b = bucket_of_cell(ix.wrapping_sub(1), up, self.mask);
            let runs = if b + 3 <= buckets {
                [(b, b + 3), (0, 0)]
            } else {
                [(b, buckets), (0, b + 3 - buckets)]
            };
            for (lo, hi) in runs {
                for s in self.starts[lo as usize] as usize..self.starts[hi as usize] as usize {
                    checks += 1;
                    let [cx, cy] = self.cells[s];
                    let in_row = cy == up && (cx.wrapping_sub(ix).wrapping_add(1) as u32) <= 2;
                    let hit = in_row && (pi - self.sorted[s]).length_squared() < r2;
                    pairs += u64::from(hit);
                }
            }
        }
        self.checks += checks;
        pairs
    }
}
