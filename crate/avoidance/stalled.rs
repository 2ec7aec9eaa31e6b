//! Agents at rest in a jam: what they seek (the corridor benchmark,
//! `studies::avoidance`).
//!
//! **Why.** In a jam that the early keep-right
//! ([`crate::avoidance::passing`]) does not prevent, the agents stand at
//! rest, *turning on the spot*, the command swinging between two headings
//! far apart, because the velocity they seek moves with their own heading:
//! - the funnel's γ is relative to the agent's heading: turning on the
//!   spot, the funnel's heading turns too, and the agent chases it (as an
//!   agent blocked by a wall would, [`crate::avoidance::avoider`]);
//! - at rest the avoider's keep-right bias turns the velocity sought up
//!   to 90° right: at the right-hand wall, into the wall, so the heading
//!   search's nearest admissible rays lie along the wall both ways and the
//!   agent swings between ahead and behind.
//!
//! **Rule.** An unfinished agent at rest (slower than [`STUCK_SPEED`])
//! whose funnel asks to move (v_dt ≥ [`STUCK_SPEED`]) seeks its goal's
//! direction, as a walled agent does: a target that does not turn with it
//! ([`seeks_goal`]); the early keep-right still turns that direction
//! right. An agent the funnel itself turns on the spot (to its
//! orientation, v_dt ≈ 0) keeps the funnel's heading: it turns on purpose,
//! and seeking the goal would undo the turn. And the keep-right
//! bias is not applied when the biased velocity would run into a wall
//! ([`bias_clear_of_walls`]): the agent then seeks its way along the
//! wall. Both are stateless, deterministic, for every scenario (no preset
//! is named); the funnel's own command (γ, v_dt, same bits) is still
//! taken whenever the velocity tested is admissible, so an agent with its
//! way clear arrives as it would without them.
//!
//! An agent at rest may turn round: turning round is how jams clear (an
//! agent that holds while ORCA's velocity points behind it stays jammed).
//! The jams left, both groups packed at the ORCA
//! clearance and boxed in by their own mates, are for
//! [`crate::avoidance::patience`]. Chosen on the tune seeds 1000–1099
//! (`steer avoid --seeds 100 --seed 1000`, ORCA, the corridor's deadlocked
//! agents); the report seeds' figures are in the README's figures table.

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
