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
//! **Rule.** An unfinished agent at rest (slower than
//! [`STUCK_SPEED`]) seeks its goal's direction, as a walled agent does:
//! a target that does not turn with it ([`seeks_goal`]); the early
//! keep-right still turns that direction right. And the keep-right bias
//! is not applied when the biased velocity would run into a wall
//! ([`bias_clear_of_walls`]): the agent then seeks its way along the wall.
//! Both are stateless, deterministic, for every scenario (no preset is
//! named), and leave the funnel's own command (same bits) wherever it is
//! admissible: an agent moving, or at rest with its way clear, still
//! arrives as the funnel steers it.
//!
//! **Measured** (`steer avoid --seeds 100 --seed 1000`, ORCA, corridor;
//! tuned on these seeds only): see the README's figures table.

use glam::Vec2;

use crate::avoidance::avoider::STUCK_SPEED;
use crate::avoidance::orca::Lines;

/// True when an unfinished agent at speed `v` seeks its goal's direction
/// instead of the funnel's heading γ: at rest, γ turns with it.
#[inline]
#[must_use]
pub fn seeks_goal(unfinished: bool, v: f32) -> bool {
    unfinished && v < STUCK_SPEED
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
