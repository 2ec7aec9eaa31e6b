//! Separation (paper 003, "Separation") over a uniform neighbour grid.
//!
//! The paper's rule, after Conrad Parker: for every other boid closer than
//! two boid radii, `sep_vel ← sep_vel − (other.pos − this.pos)`; the sum is
//! added to the boid's velocity ("double the distance between them", so
//! boids may overlap briefly and repel smoothly). We multiply the sum by a
//! configurable weight (1 = the paper's literal rule); the paper's Test IV
//! discussion is about exactly this balance between separation and seek.
//!
//! The neighbours come from the [`NeighbourGrid`], so each boid examines
//! only the 3 × 3 cells around its own, not every other boid.

use glam::Vec2;

use crate::base::grid::NeighbourGrid;

/// Paper 003 separation for every boid, through `grid` (rebuilt here).
///
/// Writes `weight · Σ (pᵢ − pⱼ)` over boids `j` closer than `2·boid_radius`
/// into `out` (flat, same layout as `pos`) and returns the number of
/// overlapping pairs (unordered pairs closer than two radii: their discs
/// overlap). Two boids at exactly the same spot get a tiny deterministic
/// push apart along ±x (lower index to −x), otherwise they would stay
/// stacked forever. Allocation-free once the grid has grown to `n` boids.
pub fn separate(
    grid: &mut NeighbourGrid,
    pos: &[f32],
    boid_radius: f32,
    weight: f32,
    out: &mut [f32],
) -> u64 {
    let reach = 2.0 * boid_radius;
    grid.rebuild(pos, reach);
    let n = pos.len() / 2;
    let mut ordered_pairs = 0u64;
    let nudge = 1e-3 * boid_radius;
    // Bucket order for cache locality; each boid's sum is the same whatever
    // the visiting order, so results do not depend on it.
    for k in 0..n {
        let i = grid.boid_in_bucket_order(k);
        let (sum, visited) = separation_sum(grid, k, reach, nudge);
        ordered_pairs += visited;
        out[2 * i] = sum.x * weight;
        out[2 * i + 1] = sum.y * weight;
    }
    ordered_pairs / 2
}

/// The sum `Σ (pᵢ − pⱼ)` of boid `i`, the `k`-th in bucket order, over the boids within `reach` (a nudge of
/// ±`nudge` along x for one at the same spot), and how many it visited:
/// one body for [`separate`] and [`separate_owned`], so a strip's boids get
/// the whole crowd's bits.
#[inline]
fn separation_sum(grid: &mut NeighbourGrid, k: usize, reach: f32, nudge: f32) -> (Vec2, u64) {
    let i = grid.boid_in_bucket_order(k);
    let mut sum = Vec2::ZERO;
    let mut visited = 0u64;
    let pi = grid.position_in_bucket_order(k);
    grid.for_each_neighbour_at(pi, i, reach, |j, d, d2| {
        visited += 1;
        if d2 > 0.0 {
            sum += d;
        } else {
            sum.x += if i < j { -nudge } else { nudge };
        }
    });
    (sum, visited)
}

/// [`separate`] for the boids `owned` only (one worker's strip),
/// through a grid of `members` (ascending; must hold every boid within
/// `2·boid_radius` of an owned one). Writes `out` at the owned boids' slots
/// only, the same bits as [`separate`] there.
pub fn separate_owned(
    grid: &mut NeighbourGrid,
    pos: &[f32],
    members: &[u32],
    owned: &[bool],
    boid_radius: f32,
    weight: f32,
    out: &mut [f32],
) {
    let reach = 2.0 * boid_radius;
    grid.rebuild_members(pos, reach, members);
    let nudge = 1e-3 * boid_radius;
    for k in 0..grid.binned() {
        let i = grid.boid_in_bucket_order(k);
        if !owned[i] {
            continue;
        }
        let (sum, _) = separation_sum(grid, k, reach, nudge);
        out[2 * i] = sum.x * weight;
        out[2 * i + 1] = sum.y * weight;
    }
}

/// Counts overlapping pairs (closer than `2·boid_radius`) without computing
/// separation: the metric for runs with separation switched off.
///
/// Why one side: with separation off nothing spreads the boids, so Test
/// IV's pathway holds about twice as many boids per cell as with
/// separation, and the cost of exact pair counting grows with the square
/// of that density; counted from both sides, stepping *without*
/// separation would cost more than stepping with it. Each pair is
/// therefore examined once, from one side
/// ([`NeighbourGrid::count_pairs_forward`]): half the candidates, the
/// same count.
pub fn count_overlaps(grid: &mut NeighbourGrid, pos: &[f32], boid_radius: f32) -> u64 {
    let reach = 2.0 * boid_radius;
    grid.rebuild(pos, reach);
    grid.count_pairs_forward(reach)
}

/// [`count_overlaps`] through nine-cell queries (every pair examined from
/// both sides): the reference the tests and the crowd bench compare with.
pub fn count_overlaps_both_sides(grid: &mut NeighbourGrid, pos: &[f32], boid_radius: f32) -> u64 {
    let reach = 2.0 * boid_radius;
    grid.rebuild(pos, reach);
    let mut ordered_pairs = 0u64;
    for k in 0..pos.len() / 2 {
        let i = grid.boid_in_bucket_order(k);
        grid.for_each_neighbour(pos, i, reach, |_, _, _| ordered_pairs += 1);
    }
    ordered_pairs / 2
}
