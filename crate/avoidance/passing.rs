//! Keep right early: the passing side taken before two groups crossing
//! head on meet (the corridor benchmark, `studies::avoidance`).
//!
//! **Why.** Two groups of 12 in 3 × 4 blocks, 1 m apart, each as wide as
//! the 4 m corridor, meet face to face mid-corridor. An agent that keeps
//! right only against the `max_neighbours` (10) *nearest* sees, inside a
//! block of 12, only its own group mates until the other block is about a
//! metre away: half a second before contact at a closing speed of 2.6 m/s,
//! too late for a forward-only unicycle to make room. The blocks then meet
//! at full width and come to rest interlocked, every agent at the distance
//! ORCA keeps (0.75–0.9 m) from an oncoming one ahead and its own group
//! mates beside and behind, turning on the spot with no admissible
//! forward ray (`diagnostics/avoid_stuck.rs` and `diagnostics/avoid_snap.rs`
//! show such jams).
//!
//! **Rule.** While the grid lists the neighbours in reach (all of them, not
//! only the nearest kept for ORCA), every *oncoming* neighbour ahead
//! (heading cosine with the agent's way below
//! [`ONCOMING_COS`]) that is not already clear on
//! the agent's left (lateral offset within ± the clearance 2(r + margin))
//! asks the agent to move right by its half share ([`LANE_SHARE`]) of the
//! lateral gap that would put it on the left at that clearance; the largest
//! ask, as the tangent of a turn over the distance ahead (at most
//! [`LANE_MAX_TAN`], 45°), turns the funnel's preferred velocity to the
//! right. The ask is seen from both sides of a pair alike (each is on the
//! other's same side), so a pair never chooses opposite sides; a whole
//! group moves to its right half and the two groups pass in lanes. The turn
//! is skipped when the turned velocity would run into a wall (an agent at
//! the wall already keeps as far right as it can) and for walled agents
//! (they seek their goal's direction). The turned velocity then goes
//! through the avoider as the funnel's own would: used as it is when
//! admissible, else ORCA's nearest. It is the funnel's command that turns,
//! not only the velocity ORCA seeks: ORCA's projected speed while an agent
//! turns would starve a group that the funnel's own command keeps moving.
//! The clearance is the avoidance's own: a wider one pushes the outer rows
//! into the walls. No agent in reach oncoming: the funnel's (γ, v_dt)
//! unchanged, the same bits (so Fig. 7-like scenes and every world without
//! avoidance are untouched).
//!
//! **Seen further ahead, and merging.** Within the 3 m reach the ask of a
//! neighbour ahead is at most a few degrees until 1.2 s before contact:
//! an inner-row agent that must cross to its own half is still on the
//! wrong side at full speed a few metres from the other front. And a block
//! as wide as the corridor cannot turn right as a block: an agent asked to
//! move right with a mate level beside it on the right keeps its speed
//! (ORCA's nearest velocity slides along the mate), so the front stays four
//! abreast until it meets the other, and the outer agents at the wall end
//! up behind mates that cut in front of them.
//!
//! **Rules.** (1) The avoider also reads the neighbours round the point
//! [`LOOK_AHEAD`] (5 m) along the agent's way (the grid's 3 × 3 cells
//! round it), and every one within [`PASS_REACH`] (8 m) that moves faster
//! than [`PASS_MOVING`] (a group coming, not a queue) asks as above
//! ([`Passing::see_far4`]); and any oncoming neighbour in the lane asks at
//! least [`LANE_MIN_TAN`] (11°), however far (the ask falls as 1 /
//! distance: 3° at 8 m). The cells round one point ahead, not a longer
//! reach: a longer reach gives ORCA far neighbours too, and a grid cell
//! widened to the passing reach makes every query scan about 7× the
//! candidates. (2) While it turns right with a *mate* (heading
//! cosine above [`MATE_COS`]) beside it on that side (lateral offset
//! within [`MERGE_SIDE`] clearances, from [`MERGE_BACK`] clearances behind
//! to one ahead), an agent keeps [`MERGE_SPEED`] (half) of the funnel's
//! speed: it drops back and merges behind the mate, so the block's front
//! becomes an echelon and then a lane ([`Passing::merge_factor`]). Both
//! rules only change what the early keep-right already turned: no
//! oncoming neighbour, the funnel's (γ, v_dt) unchanged, the same bits.
//!
//! **Chosen on tune seeds** (`steer avoid --seeds 100 --seed 1000` and
//! `--seed 2000`, ORCA, the corridor's deadlocked agents, the doorway's as
//! a check): the constants of this module; the report and held-out seeds'
//! figures are in the README's figures table. One change moves the
//! corridor's counts by half from chaos alone: differences of a few agents
//! are not evidence. The jams these rules leave (agents in the other
//! group's lane against a wall, slow jams packed at the margins) are for
//! [`crate::avoidance::stalled`] and [`crate::avoidance::patience`].

use glam::{BVec4A, Vec2, Vec4};

/// A neighbour ahead whose heading makes a cosine below this with the
/// funnel's heading is oncoming: only oncoming neighbours call for keeping
/// right (a neighbour going the same way is followed, not overtaken on a
/// side).
pub const ONCOMING_COS: f32 = -0.3;

/// Largest turn of the preferred velocity, as its tangent (1: 45°).
pub const LANE_MAX_TAN: f32 = 1.0;

/// The share of the lateral gap an agent makes up itself (its oncoming
/// neighbour, seeing the same gap, makes up the other half).
pub const LANE_SHARE: f32 = 0.5;

/// The smallest turn, as its tangent, that an oncoming neighbour in the
/// agent's lane asks for, however far ahead (0.2: 11°): the ask of a
/// neighbour 8 m ahead is otherwise 3°, and the lane forms too late.
pub const LANE_MIN_TAN: f32 = 0.2;

/// The avoider also reads the neighbours round the point this far ahead
/// along the agent's way, m (the grid's 3 × 3 cells round it): oncoming
/// neighbours up to about [`PASS_REACH`] ask for a turn, not only those in
/// the avoidance's reach (3 m, 1.2 s before contact at the corridor's
/// closing speed).
pub const LOOK_AHEAD: f32 = 5.0;

/// Oncoming neighbours up to this far, m, ask for a turn.
pub const PASS_REACH: f32 = 8.0;

/// Beyond the avoidance's reach, only neighbours faster than this, m/s,
/// ask (a group coming, not a queue at rest).
pub const PASS_MOVING: f32 = 0.5;

/// A neighbour whose heading makes a cosine above this with the agent's
/// way goes the same way: a mate.
pub const MATE_COS: f32 = 0.7;

/// A mate counts as beside the agent on its right when its lateral
/// offset is within this many clearances.
pub const MERGE_SIDE: f32 = 2.0;

/// … and it is no more than this many clearances behind (up to one
/// ahead).
pub const MERGE_BACK: f32 = 0.25;

/// The share of the funnel's speed an agent keeps while it turns into its
/// lane with a mate beside it on that side: it drops back and merges
/// behind the mate (a block as wide as the corridor becomes a lane).
pub const MERGE_SPEED: f32 = 0.5;

/// [`Passing::far_box`]'s margin, m: more than its corners' and the
/// tests' rounding errors for positions within [`FAR_BOX_LIMIT`].
pub const FAR_BOX_PAD: f32 = 0.01;

/// Up to this far from the origin on either axis, m, an agent's
/// [`Passing::far_box`] holds everything its look-ahead scan takes in
/// (f32's spacing there is 0.001 m).
pub const FAR_BOX_LIMIT: f32 = 1.0e4;

/// Where the neighbours that [`Passing::see_far4`] takes in and
/// [`Passing::see4`] on every neighbour within the avoidance's reach did
/// not lie, in the agent's frame (a rectangle, ahead × aside, by its centre
/// and half sides): an oncoming neighbour asks only up to [`PASS_REACH`]
/// ahead and within ± the clearance aside, and those nearer ahead than
/// `√(reach² − clearance²)` are in reach; a mate is from [`MERGE_BACK`]
/// clearances behind to one ahead and up to [`MERGE_SIDE`] on the right,
/// in reach too unless the clearance is nearly the reach (then the
/// rectangle holds them). Padded against rounding: a thousandth of the
/// reach on its tests, [`FAR_BOX_PAD`] on the corners.
#[derive(Clone, Copy, Debug)]
pub struct FarBox {
    ahead: f32,
    aside: f32,
    half_ahead: f32,
    half_aside: f32,
    pad: Vec2,
    /// Mates may be beyond reach: [`Passing::see_far4`] looks for them.
    mates: bool,
    /// The largest ask of a neighbour beyond reach (∞ when mates may be
    /// there too): it is beyond `√(reach² − clearance²)` ahead and less
    /// than two clearances to the right of one asking to pass on the left.
    max_ask: f32,
}

impl FarBox {
    /// The rectangle for a clearance `clear` and the avoidance's `reach`.
    #[must_use]
    pub fn new(clear: f32, reach: f32) -> Self {
        let (c, r2) = (clear, reach * reach);
        let mates = (1.0 + MERGE_SIDE * MERGE_SIDE) * c * c >= 0.999 * r2;
        let (a0, l0) = if mates {
            (-MERGE_BACK * c, -MERGE_SIDE * c)
        } else {
            ((0.999 * r2 - c * c).sqrt(), -c)
        };
        let (a1, l1) = (PASS_REACH, c);
        Self {
            ahead: 0.5 * (a0 + a1),
            aside: 0.5 * (l0 + l1),
            half_ahead: (0.5 * (a1 - a0)).max(0.0),
            half_aside: 0.5 * (l1 - l0),
            pad: Vec2::splat(FAR_BOX_PAD),
            mates,
            max_ask: if mates {
                f32::INFINITY
            } else {
                (2.0 * c * LANE_SHARE / a0 * 1.001).clamp(LANE_MIN_TAN, LANE_MAX_TAN)
            },
        }
    }
}

/// One agent's keep-right turn, accumulated over every neighbour in reach.
#[derive(Clone, Copy, Debug)]
pub struct Passing {
    u: Vec2,
    left: Vec2,
    clear: f32,
    tan: f32,
    /// [`Passing::see4`]'s asks, lane by lane (each ≥ 0).
    tan4: Vec4,
    /// A neighbour going the same way beside the agent on its right.
    mate_right: bool,
}

impl Passing {
    /// An agent going along the unit direction `u`, passing oncoming
    /// neighbours `clear` apart (centre to centre) on its left.
    #[inline]
    #[must_use]
    pub fn new(u: Vec2, clear: f32) -> Self {
        Self {
            u,
            left: Vec2::new(-u.y, u.x),
            clear,
            tan: 0.0,
            tan4: Vec4::ZERO,
            mate_right: false,
        }
    }

    /// A neighbour at `rel` from the agent, heading along the unit `fwd`.
    ///
    /// Without a branch: whether a neighbour asks flips from neighbour to
    /// neighbour (as branches, ~10 mispredictions per agent update at 11
    /// neighbours). The ask is computed whatever the tests say and kept
    /// only when they all pass (the same value as the early returns'
    /// form, NaN cases included).
    // The early returns' tests negated as written (`!(a <= b)`): the same
    // outcome, NaN included.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    #[inline]
    pub fn see(&mut self, rel: Vec2, fwd: Vec2) {
        let ahead = rel.dot(self.u);
        let lat = rel.dot(self.left);
        let along = fwd.dot(self.u);
        // A mate beside on the right: level, or at most MERGE_BACK
        // clearances behind, up to one ahead.
        self.mate_right |= (along > MATE_COS)
            & (lat < 0.0)
            & (lat > -MERGE_SIDE * self.clear)
            & (ahead > -MERGE_BACK * self.clear)
            & (ahead < self.clear);
        let asks = !(ahead <= 0.0)
            & !(along >= ONCOMING_COS)
            & !(lat >= self.clear)
            & !(lat <= -self.clear);
        let ask = ((self.clear - lat) * LANE_SHARE / ahead).max(LANE_MIN_TAN);
        let kept = self.tan.max(ask.min(LANE_MAX_TAN));
        self.tan = if asks { kept } else { self.tan };
    }

    /// [`Passing::see`] for four neighbours at once, lane by lane (those
    /// not in `lanes` are not read): the same tests and ask in every lane,
    /// folded in by their maximum, and the mates by "any". The asks kept
    /// are positive and finite, so the order they are folded in does not
    /// change the largest.
    #[inline]
    pub fn see4(&mut self, rx: Vec4, ry: Vec4, fx: Vec4, fy: Vec4, lanes: BVec4A) {
        self.see4_with(rx, ry, fx, fy, lanes, true);
    }

    /// [`Passing::see4`], the mates looked for only when `mates`.
    #[inline]
    fn see4_with(&mut self, rx: Vec4, ry: Vec4, fx: Vec4, fy: Vec4, lanes: BVec4A, mates: bool) {
        let (ux, uy) = (Vec4::splat(self.u.x), Vec4::splat(self.u.y));
        let (lx, ly) = (Vec4::splat(self.left.x), Vec4::splat(self.left.y));
        let clear = Vec4::splat(self.clear);
        let ahead = rx * ux + ry * uy;
        let lat = rx * lx + ry * ly;
        let along = fx * ux + fy * uy;
        if mates {
            let mates = lanes
                & along.cmpgt(Vec4::splat(MATE_COS))
                & lat.cmplt(Vec4::ZERO)
                & lat.cmpgt(Vec4::splat(-MERGE_SIDE * self.clear))
                & ahead.cmpgt(Vec4::splat(-MERGE_BACK * self.clear))
                & ahead.cmplt(clear);
            self.mate_right |= mates.any();
        }
        let asks = lanes
            & !ahead.cmple(Vec4::ZERO)
            & !along.cmpge(Vec4::splat(ONCOMING_COS))
            & !lat.cmpge(clear)
            & !lat.cmple(-clear);
        let ask = ((clear - lat) * Vec4::splat(LANE_SHARE) / ahead).max(Vec4::splat(LANE_MIN_TAN));
        let kept = Vec4::select(asks, ask.min(Vec4::splat(LANE_MAX_TAN)), Vec4::ZERO);
        // Lane by lane until read ([`Passing::settle`]).
        self.tan4 = self.tan4.max(kept);
    }

    /// Folds the asks [`Passing::see4`] kept lane by lane into the
    /// largest (call before [`Passing::active`] or [`Passing::turn`]).
    #[inline]
    pub fn settle(&mut self) {
        self.tan = self.tan.max(self.tan4.max_element());
        self.tan4 = Vec4::ZERO;
    }

    /// Four neighbours found beyond reach, ahead ([`LOOK_AHEAD`]), at
    /// `(rx, ry)` heading along `(fx, fy)` at `v` m/s: seen as
    /// [`Passing::see4`] does those within [`PASS_REACH`] and moving
    /// (faster than [`PASS_MOVING`]: a group coming the other way, not one
    /// standing in a queue). Lanes not in `lanes` are not read. The mates
    /// are looked for only where `b` says some may be beyond reach (they
    /// are within a little over two clearances: in reach, the scan within
    /// it saw them).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn see_far4(
        &mut self,
        rx: Vec4,
        ry: Vec4,
        fx: Vec4,
        fy: Vec4,
        v: Vec4,
        lanes: BVec4A,
        b: &FarBox,
    ) {
        let seen = lanes
            & v.cmpgt(Vec4::splat(PASS_MOVING))
            & (rx * rx + ry * ry).cmplt(Vec4::splat(PASS_REACH * PASS_REACH));
        self.see4_with(rx, ry, fx, fy, seen, b.mates);
    }

    /// The box (lower, upper corner) round an agent at `pos` outside which
    /// [`Passing::see_far4`] takes in nothing that the scan within reach
    /// did not ([`FarBox`]). The look-ahead scan reads only the grid's
    /// cells that meet it.
    #[inline]
    #[must_use]
    pub fn far_box(&self, pos: Vec2, b: &FarBox) -> (Vec2, Vec2) {
        let centre = pos + self.u * b.ahead + self.left * b.aside;
        let half = self.u.abs() * b.half_ahead + self.left.abs() * b.half_aside + b.pad;
        (centre - half, centre + half)
    }

    /// No point of [`Passing::far_box`] is further than this, m, on
    /// either axis from the agent, for a clearance `clear`.
    #[must_use]
    pub fn far_box_size(clear: f32) -> f32 {
        PASS_REACH + (1.0 + MERGE_BACK + MERGE_SIDE) * clear + FAR_BOX_PAD
    }

    /// Folds the asks so far ([`Passing::settle`]); true when a neighbour
    /// beyond reach may still change the turn: its ask may be larger than
    /// the largest so far ([`FarBox`]), or a mate may be there. Otherwise
    /// the look-ahead scan would change nothing.
    #[inline]
    pub fn far_may_ask(&mut self, b: &FarBox) -> bool {
        self.settle();
        self.tan < b.max_ask
    }

    /// True when an oncoming neighbour asks for a turn.
    #[inline]
    #[must_use]
    pub fn active(&self) -> bool {
        self.tan > 0.0
    }

    /// The share of its speed an agent keeps while it turns right with a
    /// mate beside it on that side: it drops back to merge behind it.
    #[inline]
    #[must_use]
    pub fn merge_factor(&self) -> f32 {
        if self.tan > 0.0 && self.mate_right {
            MERGE_SPEED
        } else {
            1.0
        }
    }

    /// `v` (along the agent's direction) turned right by the largest turn
    /// asked, its length kept.
    #[inline]
    #[must_use]
    pub fn turn(&self, v: Vec2) -> Vec2 {
        if self.tan <= 0.0 {
            return v;
        }
        (self.u - self.left * self.tan).normalize() * v.length()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every neighbour that [`Passing::see_far4`] takes in (an ask or a
    /// mate) and [`Passing::see4`] within reach does not lies in the far
    /// box, and asks no more than its bound: seeded agents and neighbours round the box's edges, for the
    /// default clearance and reach, a clearance nearly the reach, a short
    /// and a long reach.
    #[test]
    fn the_far_box_holds_what_only_the_look_ahead_sees() {
        let mut rng = crate::base::rng::Rng::new(5);
        for (clear, reach) in [(0.9, 3.0), (0.9, 1.0), (0.5, 2.0), (0.9, 6.0)] {
            let fb = FarBox::new(clear, reach);
            let mut taken = 0;
            for _ in 0..200_000 {
                let pos = Vec2::new(rng.range(-50.0, 50.0), rng.range(-50.0, 50.0));
                let u = crate::base::trig::unit(rng.range(-3.2, 3.2));
                let rel = Vec2::new(rng.range(-9.0, 9.0), rng.range(-9.0, 9.0));
                let fwd = crate::base::trig::unit(rng.range(-3.2, 3.2));
                let q = pos + rel;
                let (rx, ry) = (Vec4::splat(q.x - pos.x), Vec4::splat(q.y - pos.y));
                let (fx, fy) = (Vec4::splat(fwd.x), Vec4::splat(fwd.y));
                // The look-ahead's tests with the mates always looked for.
                let d2 = (pos - q).length_squared();
                let mut far = Passing::new(u, clear);
                far.see4(rx, ry, fx, fy, BVec4A::splat(d2 < PASS_REACH * PASS_REACH));
                far.settle();
                let mut near = Passing::new(u, clear);
                near.see4(rx, ry, fx, fy, BVec4A::splat(d2 < reach * reach));
                near.settle();
                let far_mate = far.mate_right && !near.mate_right;
                if far.active() && !near.active() || far_mate {
                    taken += 1;
                    let (lo, hi) = far.far_box(pos, &fb);
                    assert!(
                        q.cmpge(lo).all() && q.cmple(hi).all() && (fb.mates || !far_mate),
                        "{clear} {reach} {pos} {u} {q} {lo} {hi}"
                    );
                    // Its ask is at most the bound beyond reach.
                    assert!(
                        near.active() || far.tan <= fb.max_ask,
                        "{} {}",
                        far.tan,
                        fb.max_ask
                    );
                }
                // And see_far4 asks the same.
                let mut look = Passing::new(u, clear);
                look.see_far4(rx, ry, fx, fy, Vec4::ONE, BVec4A::splat(true), &fb);
                look.settle();
                assert_eq!(look.tan, far.tan);
            }
            assert!(taken > 300, "{clear} {reach} {taken}");
        }
    }

    #[test]
    fn a_head_on_pair_both_turn_right_by_the_same_angle() {
        // A at the origin going +x, B 2 m ahead and 0.1 m to A's left
        // going −x: each sees the other on its left within the clearance.
        let (pa, pb) = (Vec2::ZERO, Vec2::new(2.0, 0.1));
        let mut a = Passing::new(Vec2::X, 0.9);
        a.see(pb - pa, -Vec2::X);
        let mut b = Passing::new(-Vec2::X, 0.9);
        b.see(pa - pb, Vec2::X);
        let (ta, tb) = (a.turn(Vec2::X), b.turn(-Vec2::X));
        assert!(ta.y < 0.0 && tb.y > 0.0, "{ta} {tb}");
        assert!((ta.y + tb.y).abs() < 1e-6 && (ta.length() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn followers_neighbours_behind_and_clear_ones_ask_nothing() {
        let mut p = Passing::new(Vec2::X, 0.9);
        p.see(Vec2::new(1.0, 0.0), Vec2::X); // same way
        p.see(Vec2::new(-1.0, 0.0), -Vec2::X); // behind
        p.see(Vec2::new(2.0, 1.0), -Vec2::X); // already clear on the left
        p.see(Vec2::new(2.0, -1.0), -Vec2::X); // clear on the right
        assert!(!p.active());
        assert_eq!(p.turn(Vec2::X), Vec2::X);
        p.see(Vec2::new(0.1, 0.0), -Vec2::X); // close ahead: at most 45°
        let t = p.turn(Vec2::X);
        assert!((t.x + t.y).abs() < 1e-6 && t.y < 0.0, "{t}");
    }
}
