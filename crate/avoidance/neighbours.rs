//! Every planning agent's neighbours: the agents' records in the neighbour
//! grid's bucket order, the candidates in reach gathered four at a time
//! without a branch, and the k nearest ranked (a sorting network up to 16
//! candidates), the keep-right rule reading them on the way.

use glam::{BVec4A, Mat4, Vec2, Vec4};

use crate::avoidance::orca::{self, MAX_NEIGHBOURS};
use crate::avoidance::passing::Passing;
use crate::base::grid::NeighbourGrid;
use crate::base::vehicle::VehicleState;

/// One agent as the pass reads it, kept in the grid's bucket order: a
/// neighbour's data is one 32-byte record beside its cell-mates', not
/// five arrays in world order read per neighbour.
#[derive(Clone, Copy, Debug, Default)]
#[repr(align(32))]
pub(crate) struct Peer {
    pub(crate) pos: Vec2,
    /// Unit heading.
    pub(crate) fwd: Vec2,
    /// Speed along it, m/s.
    pub(crate) v: f32,
    /// [`Avoider::priority`](crate::avoidance::avoider::Avoider::priority)'s value; NaN when none is given.
    pub(crate) prio: f32,
    /// Index in the world.
    pub(crate) index: u32,
}

impl Peer {
    /// Position and heading, four lanes (x, y, x, y).
    #[inline]
    pub(crate) fn head(&self) -> Vec4 {
        Vec4::new(self.pos.x, self.pos.y, self.fwd.x, self.fwd.y)
    }
}

/// The buffers of [`Avoider`](crate::avoidance::avoider::Avoider) that the
/// neighbour queries read (reused every step): the grid, the agents'
/// records in its bucket order, and one query's candidates.
#[derive(Clone, Debug, Default)]
pub(crate) struct Neighbours {
    pub(crate) grid: NeighbourGrid,
    pos: Vec<f32>,
    /// The agents in the grid's bucket order.
    pub(crate) peers: Vec<Peer>,
    /// Their positions' and unit headings' x and y, in the same order,
    /// then four padding lanes: the candidates are read four at a time.
    pub(crate) lanes: [Vec<f32>; 5],
    /// One query's candidates: squared distance, slot in `peers`.
    cand_d2: Vec<f32>,
    cand_slot: Vec<u32>,
}

impl Neighbours {
    /// Rebuilds the grid (cell = `reach`) over the agents' positions, and
    /// their records in its bucket order: one [`Peer`] each, and the
    /// same positions, headings and speeds as lanes read four at a time.
    pub(crate) fn index_agents(&mut self, states: &[VehicleState], reach: f32, priority: &[f32]) {
        let n = states.len();
        self.pos.clear();
        for s in states {
            self.pos.push(s.pos.x);
            self.pos.push(s.pos.y);
        }
        self.grid.rebuild(&self.pos, reach);
        self.peers.clear();
        self.peers.extend((0..n).map(|slot| {
            let i = self.grid.boid_in_bucket_order(slot);
            let s = &states[i];
            Peer {
                pos: s.pos,
                fwd: s.forward(),
                v: s.v,
                prio: priority.get(i).copied().unwrap_or(f32::NAN),
                index: i as u32,
            }
        }));
        // One pass over the records (five passes read them five times).
        let lanes = &mut self.lanes;
        for lane in lanes.iter_mut() {
            lane.clear();
            lane.resize(n + 4, 0.0);
        }
        let [lx, ly, lfx, lfy, lv] = lanes.each_mut().map(|l| &mut l[..n]);
        for (k, q) in self.peers.iter().enumerate() {
            lx[k] = q.pos.x;
            ly[k] = q.pos.y;
            lfx[k] = q.fwd.x;
            lfy[k] = q.fwd.y;
            lv[k] = q.v;
        }
    }

    /// Gathers the candidates in reach of the agent at `slot` (at `pos`)
    /// from the grid's nine cells round it into [`Neighbours::cand_d2`] and
    /// [`Neighbours::cand_slot`], in grid order, without a branch: four at a
    /// time, each written and the count advanced by its lane's "in reach"
    /// bit. Returns how many.
    #[inline(always)]
    pub(crate) fn gather(&mut self, slot: usize, pos: Vec2, r2: f32) -> usize {
        let (runs, n_runs) = self.grid.candidate_runs(pos);
        let total = runs[..n_runs]
            .iter()
            .map(|&(lo, hi)| (hi - lo) as usize)
            .sum::<usize>();
        // Room for a run's last four lanes past its end, rounded up to
        // a power of two: indices masked by it need no bounds check.
        let wrap = (total + 4).next_power_of_two() - 1;
        // At least RANKED: the ranking reads that many.
        if self.cand_d2.len() <= wrap.max(RANKED - 1) {
            self.cand_d2.resize(wrap.max(RANKED - 1) + 1, 0.0);
            self.cand_slot.resize(wrap.max(RANKED - 1) + 1, 0);
        }
        let (cand_d2, cand_slot) = (&mut self.cand_d2[..=wrap], &mut self.cand_slot[..=wrap]);
        // Slices held locally: their bounds stay in registers across
        // the stores below. One length for both (one bounds check per
        // four).
        let lx = &self.lanes[0][..];
        let ly = &self.lanes[1][..lx.len()];
        let (mx, my) = (Vec4::splat(pos.x), Vec4::splat(pos.y));
        let r2v = Vec4::splat(r2);
        let mut m = 0usize;
        for &(lo, hi) in &runs[..n_runs] {
            let (lo, hi) = (lo as usize, hi as usize);
            let mut a = lo;
            while a < hi {
                let (qx, qy) = (
                    Vec4::from_slice(&lx[a..a + 4]),
                    Vec4::from_slice(&ly[a..a + 4]),
                );
                // (me.pos − q.pos)², as the scalar length_squared.
                let (dx, dy) = (mx - qx, my - qy);
                let d2 = dx * dx + dy * dy;
                let inside = d2.cmplt(r2v);
                // In reach, in the run, and not the agent itself (its
                // lane bit, if in these four: the shift saturates to
                // bit 31 otherwise).
                let own = (1u32 << slot.wrapping_sub(a).min(31)) & 0xf;
                let keep = inside.bitmask() & orca::lane_mask(0, hi - a) & !own;
                for (l, d) in d2.to_array().into_iter().enumerate() {
                    // m < total + 4 ≤ wrap + 1: the mask changes nothing.
                    cand_d2[m & wrap] = d;
                    cand_slot[m & wrap] = (a + l) as u32;
                    m += ((keep >> l) & 1) as usize;
                }
                a += 4;
            }
        }
        // Every candidate but the agent itself (its own cell is in
        // the runs once) was examined.
        self.grid.add_checks(total as u64 - 1);
        m
    }

    /// The k nearest of the `m` candidates gathered, nearest first (ties:
    /// grid order, deterministic): below [`RANKED`] of them, by a sorting
    /// network on (d², gather order); beyond, by insertion; the same k, in
    /// the same order, either way. Where `passing`, every neighbour
    /// gathered also tells the keep-right rule `lane` whether it comes the
    /// other way ([`see_gathered`]), as many fours as the ranking's case
    /// allows (one branch on m for both).
    #[inline(always)]
    pub(crate) fn rank(
        &self,
        m: usize,
        k_max: usize,
        passing: bool,
        lane: &mut Passing,
        pos: Vec2,
    ) -> Nearest {
        let gathered = if passing { &self.cand_slot[..m] } else { &[] };
        let mut near = [(0.0f32, 0u32); MAX_NEIGHBOURS];
        let k = m.min(k_max);
        if m <= RANKED {
            // Keys (d² bits, gather order): unique, and ordered as
            // (d², order) since d² ≥ +0 (IEEE bits of non-negative
            // floats order like the floats); past the m gathered, the
            // largest (all RANKED built: no loop exit to mispredict).
            let mut keys = [u64::MAX; RANKED];
            for (a, (key, &d2)) in keys.iter_mut().zip(&self.cand_d2[..RANKED]).enumerate() {
                let built = (u64::from(d2.to_bits()) << 32) | a as u64;
                *key = if a < m { built } else { u64::MAX };
            }
            if m <= 8 {
                sort_network::<8>(&mut keys);
                see_gathered::<2>(lane, &self.peers, gathered, pos);
            } else if m <= 12 {
                sort_network::<12>(&mut keys);
                see_gathered::<3>(lane, &self.peers, gathered, pos);
            } else {
                sort_network::<RANKED>(&mut keys);
                see_gathered::<4>(lane, &self.peers, gathered, pos);
            }
            // All RANKED slots (those past k are not read), not the k
            // nearest: no loop exit to mispredict. A key past the m
            // gathered indexes slot 15 (read, not used).
            const { assert!(RANKED == MAX_NEIGHBOURS && RANKED.is_power_of_two()) };
            let slots = &self.cand_slot[..RANKED];
            for (t, &key) in near.iter_mut().zip(&keys) {
                *t = (
                    f32::from_bits((key >> 32) as u32),
                    slots[key as u32 as usize & (RANKED - 1)],
                );
            }
        } else {
            for some in gathered.chunks(RANKED) {
                see_gathered::<4>(lane, &self.peers, some, pos);
            }
            let mut kk = 0usize;
            for (&d2, &sj) in self.cand_d2[..m].iter().zip(&self.cand_slot[..m]) {
                if kk == k_max && d2 >= near[kk - 1].0 {
                    continue;
                }
                let mut at = if kk < k_max { kk } else { kk - 1 };
                while at > 0 && near[at - 1].0 > d2 {
                    near[at] = near[at - 1];
                    at -= 1;
                }
                near[at] = (d2, sj);
                if kk < k_max {
                    kk += 1;
                }
            }
        }
        Nearest { near, k }
    }
}

/// The k nearest neighbours (squared distance, slot in the records),
/// nearest first; past the k-th, not read.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Nearest {
    pub(crate) near: [(f32, u32); MAX_NEIGHBOURS],
    pub(crate) k: usize,
}

/// Candidates in reach up to which the k nearest are sorted by a sorting
/// network (no branch); beyond (a packed crowd), by insertion.
const RANKED: usize = 16;

/// Sorts the first `N` of [`RANKED`] keys (the others are `u64::MAX`)
/// with Batcher's odd–even merge sort for 16 keys, less the
/// compare–exchanges with a key past `N` (no-ops: the maximum stays
/// put): 63 for `N` = 16, fewer below; the same whatever the keys
/// (constant loop bounds: unrolled into straight code). Insertion's
/// data-dependent branches are mispredicted about once per neighbour.
#[inline]
fn sort_network<const N: usize>(keys: &mut [u64; RANKED]) {
    let mut p = 1;
    while p < RANKED {
        let mut k = p;
        while k >= 1 {
            let mut j = k % p;
            while j + k < RANKED {
                let mut i = 0;
                while i < k && i + j + k < N {
                    if (i + j) / (2 * p) == (i + j + k) / (2 * p) {
                        let (x, y) = (keys[i + j], keys[i + j + k]);
                        keys[i + j] = x.min(y);
                        keys[i + j + k] = x.max(y);
                    }
                    i += 1;
                }
                j += 2 * k;
            }
            k /= 2;
        }
        p *= 2;
    }
}

/// Tells the keep-right rule about the first `4 × FOURS` neighbours
/// gathered (`slots` into `peers`; none when empty), four at a time from
/// their records (the position and heading, transposed), past the last one
/// the last again (the largest ask and "any" mate do not change). About 3
/// fours at 11 neighbours, against every candidate of the nine cells
/// (about 10 fours, two thirds of them out of reach) while gathering; a
/// constant count of fours: no loop exit to mispredict.
#[inline(always)]
fn see_gathered<const FOURS: usize>(lane: &mut Passing, peers: &[Peer], slots: &[u32], at: Vec2) {
    let Some(last) = slots.len().checked_sub(1) else {
        return;
    };
    let record = |c: usize| peers[slots[c.min(last)] as usize].head();
    let (ax, ay) = (Vec4::splat(at.x), Vec4::splat(at.y));
    for f in 0..FOURS {
        let c = 4 * f;
        let t = Mat4::from_cols(record(c), record(c + 1), record(c + 2), record(c + 3)).transpose();
        lane.see4(
            t.x_axis - ax,
            t.y_axis - ay,
            t.z_axis,
            t.w_axis,
            BVec4A::splat(true),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pruned networks sort like a stable sort (ties kept in order),
    /// seeded keys with many ties, every length up to 16.
    #[test]
    fn sort_networks_sort_stably() {
        let mut rng = crate::base::rng::Rng::new(7);
        for trial in 0..3000 {
            let m = trial % (RANKED + 1);
            let d: Vec<f32> = (0..m)
                .map(|_| (rng.range(0.0, 6.0) as u32) as f32 * 0.5)
                .collect();
            let mut keys = [u64::MAX; RANKED];
            for (a, key) in keys.iter_mut().take(m).enumerate() {
                *key = (u64::from(d[a].to_bits()) << 32) | a as u64;
            }
            match m {
                0..=8 => sort_network::<8>(&mut keys),
                9..=12 => sort_network::<12>(&mut keys),
                _ => sort_network::<RANKED>(&mut keys),
            }
            let mut want: Vec<usize> = (0..m).collect();
            want.sort_by(|&a, &b| d[a].total_cmp(&d[b]));
            let got: Vec<usize> = keys[..m].iter().map(|&k| k as u32 as usize).collect();
            assert_eq!(got, want, "{d:?}");
        }
    }
}
