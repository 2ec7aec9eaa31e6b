//! Patience: an agent stalled in a jam gives up its margin (issue 18's
//! deadlock target: the corridor and the doorway, and the circle swap of
//! 100).
//!
//! **Problem.** After the early keep-right ([`crate::avoidance::passing`])
//! and the rules for agents at rest ([`crate::avoidance::stalled`]) the
//! corridor still had 7 deadlocked agents (unfinished, < 0.05 m/s for
//! 10 s) in 5 of the tune runs 1000–1099 and 5 in 4 of 2000–2099, and the
//! circle swap of 100 had 113 in 40 (all of them finished in the end, up
//! to 99.81 %). They stood at the distance the avoidance keeps, two
//! radii plus two margins, from oncoming agents and mates all round, with
//! no admissible forward ray: a forward-only vehicle cannot back out, and
//! ORCA keeps every pair its whole margin even when the bodies themselves
//! would pass.
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
//! **Chosen on tune seeds** (`steer avoid --seeds 100 --seed 1000` and
//! `--seed 2000`, then `--seeds 1000 --seed 3000`; ORCA, corridor,
//! doorway, circle32): stall speed 0.05 or 0.1 m/s × wait 1, 2 or 3 s ×
//! ramp 1, 3 or 6 s; margin kept 0, 10, 20, 33 or 67 %; from neighbours
//! only or from walls too.
//! - At 0.1 m/s the doorway jammed (33–265 deadlocked agents, and
//!   overlaps): agents crawling through the door lost their margin.
//! - From neighbours only (0.05 m/s, 3 s, 1 s, none kept): 0 deadlocks on
//!   1000–1099 and 2000–2099, but 10 (7) corridor runs in 3000–3999, agents
//!   at a wall behind a mate stalled at the wall.
//! - From walls too: 0 in 3000–3999, but one run with an overlap (55
//!   pair-steps, 0.543 m; pairs held at exactly two radii); keeping 10 %
//!   of the margin: 2 (2) in the corridor, none in the doorway, no
//!   overlap; 20 % had an overlap again, 33 % 8 (6).
//! - **Kept: 0.05 m/s, 3 s, 1 s, 10 %, neighbours and walls.** Tune seeds
//!   1000–1099, ORCA, deadlocked agents (runs) before → after: corridor
//!   7 (5) → 0 (0), reach 99.96 → 99.88 % (unfinished agents still moving
//!   at the end); circle100 113 (40) → 0 (0), reach 99.81 → 100 %,
//!   oriented entries 99.2 → 99.2 %; doorway, circle8 and circle32 0 → 0;
//!   no overlap anywhere. 2000–2099: corridor 5 (4) → 0 (0).
//!   Report seeds (0–99 and held-out): README, issue 18's figures.

/// Below this speed, m/s, an unfinished agent's patience runs down (the
/// deadlock rule's speed, `avoidance::proximity`).
pub const PATIENCE_SPEED: f32 = 0.05;
/// Seconds stalled before the margin starts to shrink.
pub const PATIENCE_AFTER: f32 = 3.0;
/// Seconds over which it shrinks to [`PATIENCE_KEEP`] of itself.
pub const PATIENCE_RAMP: f32 = 1.0;
/// The share of the margin an agent out of patience still keeps: with
/// none, pairs held at exactly two radii touched now and then (the
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
