//! Agents at rest in a jam: what they seek (issue 18's deadlock target,
//! the corridor).
//!
//! **Problem.** After the early keep-right ([`crate::avoidance::passing`])
//! the corridor still had deadlocked agents (unfinished, < 0.05 m/s for
//! 10 s) in about half the runs. Classified on the tune seeds 1000–1099
//! (`examples/avoid_kinds.rs`, 100 agents in 48 runs): 44 at a wall *in
//! their own lane*, 43 in a jam mid-corridor, 8 beyond the corridor near
//! their goals, 3 at a wall in the other group's lane, 2 beside an arrived
//! agent; 84 of the 100 finished later (jams that take more than 10 s to
//! clear), and 17 of them never did. Traced, nearly all were at rest,
//! *turning on the spot* (median 170° in their 10 s, a quarter more than
//! 310°), the command swinging between two headings far apart, because
//! the velocity they sought moved with their own heading:
//! - the funnel's γ is relative to the agent's heading: turning on the
//!   spot, the funnel's heading turns too, and the agent chases it (the
//!   fault the avoider already fixed for agents blocked by a wall);
//! - at rest the avoider's keep-right bias turns the velocity sought up
//!   to 90° right: at the right-hand wall, into the wall, so the heading
//!   search's nearest admissible rays lie along the wall both ways and the
//!   agent swung between ahead and behind (seed 1001, agent 15).
//!
//! **Rule.** An unfinished agent at rest (slower than [`STUCK_SPEED`])
//! whose funnel asks to move (v_dt ≥ [`STUCK_SPEED`]) seeks its goal's
//! direction, as a walled agent does: a target that does not turn with it
//! ([`seeks_goal`]); the early keep-right still turns that direction
//! right. An agent the funnel itself turns on the spot (to its
//! orientation, v_dt ≈ 0) keeps the funnel's heading. And the keep-right
//! bias is not applied when the biased velocity would run into a wall
//! ([`bias_clear_of_walls`]): the agent then seeks its way along the
//! wall. Both are stateless, deterministic, for every scenario (no preset
//! is named); the funnel's own command (γ, v_dt, same bits) is still
//! taken whenever the velocity tested is admissible, so an agent with its
//! way clear arrives as before.
//!
//! **Measured**, tune seeds 1000–1099 (`steer avoid --seeds 100 --seed
//! 1000`, ORCA, corridor: deadlocked agents (runs), reach, runs whole):
//! before 100 (48), 99.08 %, 87; the wall check alone 72 (38), 99.00 %;
//! the goal's direction at rest alone 91 (41), 99.21 %; both 60 (28),
//! 99.42 %, 87; **both, without the goal's direction for agents the
//! funnel turns on the spot: 60 (28), 99.88 %, 98** (kept; chosen on
//! these seeds after the first version's report seeds had been read, so
//! its held-out set is 400–499). By kind after: 32 mid-corridor, 27 at a
//! wall in their own lane, 1 in the other's, none beyond the corridor or
//! beside an arrived agent; 58 of the 60 finish later. Doorway 0
//! deadlocks before and after; circles 0 overlaps; Fig. 8 oriented
//! entries 69 → 66 of 80. Report seeds: the README's figures table.
//! A single change moves these counts by ±15 agents from chaos alone, so
//! smaller differences below are not evidence.
//!
//! **Tried and not kept** (tune seeds, corridor, with both rules of the
//! first version unless said): a *waiting rule* (after 3 s at rest, an
//! agent with an oncoming or obstructed neighbour that has the right of
//! way backs off for 2 s at 0.5 m/s, through ORCA): 72 (27); backing off to its right 60 (29),
//! towards its goal 84 (31), after 5 s 72 (28), with any stall 81 (30);
//! without the goal's direction 88 (39), with oncoming blockers only and
//! no wall check 106 (52). *Priority by progress with a wider gap* (1 /
//! 3 / 100 m: nearly by index): 53 (28) but the doorway 39 deadlocked
//! agents, 158 (49), 112 (36). *No turning back at rest* (hold when ORCA's
//! velocity points behind, below 0.3 / 0.6 / 1.5 m/s): 271 (73), 507
//! (85), 1,544 (100) — turning round is how jams clear. *Resting pairs at
//! the right of way's clearance*: 83 (47), doorway 324. The rest
//! threshold 0.05 / 0.2 / 0.4 m/s: 83 (34), 71 (31), 76 (30). No
//! keep-right turn at rest: 163 (38). Finished agents that step aside: not
//! built, after the two rules no deadlock was beside an arrived agent.
//!
//! **Not reached: 0 deadlocks.** What is left are jams where both groups
//! stand packed at the ORCA clearance, boxed in by their own mates, each
//! agent turning on the spot; most clear, in more than 10 s, but on the
//! report seeds 0–99 and 400–499 more agents than before never finish
//! (reach 98.54 → 98.21 % and 98.67 → 98.25 %, while runs whole rose 84 →
//! 94 and 84 → 93).

use glam::Vec2;

use crate::avoidance::orca::Lines;

/// Below this speed, m/s, an agent is at rest: the avoider searches the
/// headings instead of following ORCA's velocity ([`crate::avoidance::avoider`]),
/// and an unfinished agent at rest seeks its goal's direction.
pub const STUCK_SPEED: f32 = 0.1;

/// True when an unfinished agent at speed `v`, whose funnel asks for
/// `v_dt`, seeks its goal's direction instead of the funnel's heading γ:
/// at rest, γ turns with it. Not when the funnel itself asks for no speed
/// (it turns the agent on the spot on purpose, to its orientation).
#[inline]
#[must_use]
pub fn seeks_goal(unfinished: bool, v: f32, v_dt: f32) -> bool {
    unfinished && v < STUCK_SPEED && v_dt >= STUCK_SPEED
}

/// The keep-right `biased` velocity when an agent may walk along it
/// (tested at `probe` m/s) without running into an obstacle; else the
/// unbiased `v_pref`.
#[inline]
#[must_use]
pub fn bias_clear_of_walls(lines: &Lines, v_pref: Vec2, biased: Vec2, probe: f32) -> Vec2 {
    if lines.obstacles_admit(biased.normalize_or_zero() * probe, 0.0) {
        biased
    } else {
        v_pref
    }
}
