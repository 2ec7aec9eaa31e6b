//! Patience: an agent stalled in a jam gives up its margin (the corridor,
//! the doorway and the circle swap of 100, `studies::avoidance`).
//!
//! **Why.** After the early keep-right ([`crate::avoidance::passing`])
//! and the rules for agents at rest ([`crate::avoidance::stalled`]) some
//! jams still hold for more than the deadlock rule's 10 s: the agents
//! stand at the distance the avoidance keeps, two radii plus two margins,
//! from oncoming agents and mates all round, with no admissible forward
//! ray. A forward-only vehicle cannot back out, and ORCA keeps every pair
//! its whole margin even when the bodies themselves would pass.
//!
//! **Rule.** Every agent carries a clock of the time it has been
//! unfinished and slower than [`PATIENCE_SPEED`] (the deadlock rule's
//! speed), reset as soon as it moves or finishes. After [`PATIENCE_AFTER`]
//! seconds its margin shrinks linearly, over [`PATIENCE_RAMP`] seconds, to
//! [`PATIENCE_KEEP`] of itself ([`margin`]), from its neighbours and from
//! the walls alike: the room the margins held opens and the jam's agents
//! slide past each other, or along the wall past the agent ahead. The
//! bodies still keep their radii (and a sliver), and an agent that moves
//! gets its whole margin back at once. Crowd simulators call this
//! *patience* (agents that have waited too long accept a closer pass); it
//! costs one float of state per agent, and no scenario is named.
//!
//! **Why these values.**
//! - The clock runs below 0.05 m/s, not faster: agents crawling through
//!   the doorway would lose their margin there, and the doorway jams.
//! - From the walls too, not only from neighbours: an agent at a wall
//!   behind a mate stalled at the wall has no room otherwise.
//! - A tenth of the margin kept, not none: pairs held at exactly two radii
//!   touch now and then (the unicycle does not track ORCA's velocity
//!   exactly); much more, and the jam has no room to open.
//!
//! Chosen on tune seeds (`steer avoid --seeds 100 --seed 1000` and
//! `--seed 2000`, then `--seeds 1000 --seed 3000`; ORCA, corridor,
//! doorway, circle32) among stall speeds 0.05 and 0.1 m/s, waits of 1–3 s,
//! ramps of 1–6 s and 0–67 % of the margin kept; the report and held-out
//! seeds' figures are in the README's figures table.

/// Below this speed, m/s, an unfinished agent's patience runs down (the
/// deadlock rule's speed, `world::proximity`).
pub const PATIENCE_SPEED: f32 = 0.05;
/// Seconds stalled before the margin starts to shrink.
pub const PATIENCE_AFTER: f32 = 3.0;
/// Seconds over which it shrinks to [`PATIENCE_KEEP`] of itself.
pub const PATIENCE_RAMP: f32 = 1.0;
/// The share of the margin an agent out of patience still keeps: with
/// none, pairs held at exactly two radii touch now and then (the
/// unicycle does not track ORCA's velocity exactly).
pub const PATIENCE_KEEP: f32 = 0.1;

/// The clock after one step of `dt` s: counts while the agent is
/// unfinished and slower than [`PATIENCE_SPEED`], else 0.
#[inline]
#[must_use]
pub fn tick(clock: f32, done: bool, speed: f32, dt: f32) -> f32 {
    if !done && speed < PATIENCE_SPEED {
        clock + dt
    } else {
        0.0
    }
}

/// The margin an agent stalled for `clock` s keeps from its neighbours
/// and from obstacles: the whole `margin` until [`PATIENCE_AFTER`], then
/// linearly less, [`PATIENCE_KEEP`] of it after [`PATIENCE_RAMP`] more.
#[inline]
#[must_use]
pub fn margin(margin: f32, clock: f32) -> f32 {
    let shrink = ((clock - PATIENCE_AFTER) / PATIENCE_RAMP).clamp(0.0, 1.0);
    margin * (1.0 - shrink * (1.0 - PATIENCE_KEEP))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clock_runs_while_stalled_and_resets_on_moving_or_finishing() {
        let dt = 1.0 / 60.0;
        let mut c = 0.0;
        for _ in 0..60 {
            c = tick(c, false, 0.01, dt);
        }
        assert!((c - 1.0).abs() < 1e-4, "{c}");
        assert_eq!(tick(c, false, PATIENCE_SPEED, dt), 0.0);
        assert_eq!(tick(c, true, 0.0, dt), 0.0);
    }

    #[test]
    fn the_margin_is_whole_then_shrinks_to_a_tenth() {
        assert_eq!(margin(0.15, 0.0), 0.15);
        assert_eq!(margin(0.15, PATIENCE_AFTER), 0.15);
        let half = margin(0.15, PATIENCE_AFTER + 0.5 * PATIENCE_RAMP);
        assert!(
            (half - 0.15 * (1.0 + PATIENCE_KEEP) / 2.0).abs() < 1e-6,
            "{half}"
        );
        let least = 0.15 * PATIENCE_KEEP;
        assert!((margin(0.15, PATIENCE_AFTER + PATIENCE_RAMP) - least).abs() < 1e-7);
        assert!((margin(0.15, 1e9) - least).abs() < 1e-7);
    }
}
