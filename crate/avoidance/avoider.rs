//! One avoidance pass over a world's agents: neighbours through a grid,
//! the method's velocity, and that velocity turned into what a
//! forward-only unicycle can do (issue 18; paper 000 §7 and 001 §7 name
//! avoidance as the next step).
//!
//! **Combined with funnelling.** Every agent's funnel plans first; its
//! modulated heading γ and desired speed v_dt give the *preferred
//! velocity* `v_dt·(cos γ, sin γ)`. When that velocity is admissible
//! (no neighbour or obstacle constrains it) the agent steps with exactly
//! (γ, v_dt), the same bits as without avoidance: so once the way is clear
//! it funnels and arrives oriented as it would have.
//!
//! **Adapted to the unicycle.** Otherwise the method gives a velocity v*
//! (ORCA: nearest the preferred one outside every velocity obstacle). A
//! forward-only vehicle moves along its heading θ, not along v*; so the
//! heading command is v*'s direction (the PD turns towards it within ω_max
//! and the angular acceleration), and the speed command is the largest
//! speed along θ, at most v*'s projection on θ (≥ 0: it slows down while it
//! turns, and never reverses), that every half-plane admits. If even
//! braking is not admissible, it brakes (the reciprocal neighbour takes its
//! share). The commands go through the vehicle model
//! ([`crate::vehicle::VehicleParams::integrate`]), which clamps them into
//! the admissible set: no limit is ever broken, whatever the avoidance asks.
//!
//! **Neighbours** come from the crowd's hashed uniform grid
//! ([`crate::crowd::separation::NeighbourGrid`], cell = the search
//! distance), the `max_neighbours` nearest kept in a fixed array: the cost
//! per agent is bounded at constant density and nothing is allocated once
//! the buffers have grown. Obstacles are tested one by one (few by design,
//! [`crate::avoidance::config::MAX_OBSTACLES`]).

use glam::Vec2;

use crate::avoidance::config::{AvoidanceConfig, AvoidanceMethod, Obstacle};
use crate::avoidance::orca::{self, Lines, MAX_NEIGHBOURS};
use crate::crowd::separation::NeighbourGrid;
use crate::trig;
use crate::vehicle::{VehicleParams, VehicleState};

/// What one agent is told to do this step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Command {
    /// Heading for the seek step, rad.
    pub heading: f32,
    /// Desired speed, m/s.
    pub speed: f32,
    /// True when the avoidance changed the funnel's (γ, v_dt).
    pub active: bool,
}

/// The avoidance's buffers (reused every step).
#[derive(Clone, Debug, Default)]
pub struct Avoider {
    grid: NeighbourGrid,
    pos: Vec<f32>,
    vel: Vec<Vec2>,
    /// This step's commands, one per agent.
    pub commands: Vec<Command>,
}

/// Scratch buffers carry no state worth comparing: two worlds are equal
/// whatever their avoiders hold.
impl PartialEq for Avoider {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Avoider {
    /// Candidate pairs the grid examined since the last reset (tests prove
    /// the search is not quadratic with it).
    #[must_use]
    pub fn checks(&self) -> u64 {
        self.grid.checks()
    }

    /// Resets [`Avoider::checks`].
    pub fn reset_checks(&mut self) {
        self.grid.reset_checks();
    }

    /// Fills [`Avoider::commands`] for agents in `states` whose funnels
    /// asked for `preferred[i] = (heading, speed)`.
    pub fn compute(
        &mut self,
        p: &VehicleParams,
        cfg: &AvoidanceConfig,
        obstacles: &[Obstacle],
        states: &[VehicleState],
        preferred: &[(f32, f32)],
    ) {
        let n = states.len();
        self.pos.clear();
        self.vel.clear();
        for s in states {
            self.pos.push(s.pos.x);
            self.pos.push(s.pos.y);
            self.vel.push(s.forward() * s.v);
        }
        self.commands.resize(n, Command::default());
        self.grid.rebuild(&self.pos, cfg.reach);
        let r = cfg.radius + cfg.margin;
        let k_max = (cfg.max_neighbours as usize).min(MAX_NEIGHBOURS);
        let keep_right = trig::unit(-cfg.bias_deg.to_radians());
        for i in 0..n {
            let (h_pref, s_pref) = preferred[i];
            let s = &states[i];
            let v_pref = trig::unit(h_pref) * s_pref;
            // The k nearest neighbours, nearest first (ties: grid order,
            // deterministic).
            let mut near = [(0.0f32, 0u32); MAX_NEIGHBOURS];
            let mut k = 0usize;
            self.grid
                .for_each_neighbour(&self.pos, i, cfg.reach, |j, _, d2| {
                    if k == k_max && d2 >= near[k - 1].0 {
                        return;
                    }
                    let mut at = if k < k_max { k } else { k - 1 };
                    while at > 0 && near[at - 1].0 > d2 {
                        near[at] = near[at - 1];
                        at -= 1;
                    }
                    near[at] = (d2, j as u32);
                    if k < k_max {
                        k += 1;
                    }
                });
            let cmd = match cfg.method {
                AvoidanceMethod::Off => Command {
                    heading: h_pref,
                    speed: s_pref,
                    active: false,
                },
                AvoidanceMethod::Orca => {
                    let mut lines = Lines::default();
                    for o in obstacles {
                        let (dist, nrm) = o.distance_normal(s.pos);
                        if dist - r < cfg.reach {
                            lines.push_obstacle(orca::obstacle_line(
                                nrm,
                                dist,
                                r,
                                cfg.obstacle_horizon,
                                p.dt,
                            ));
                        }
                    }
                    for &(_, j) in &near[..k] {
                        let j = j as usize;
                        let tie = if i < j { Vec2::Y } else { -Vec2::Y };
                        lines.push_agent(orca::agent_line(
                            s.pos,
                            self.vel[i],
                            states[j].pos,
                            self.vel[j],
                            2.0 * r,
                            cfg.horizon,
                            p.dt,
                            0.5,
                            tie,
                        ));
                    }
                    if s_pref <= p.v_max && lines.admits(v_pref, 0.0) {
                        Command {
                            heading: h_pref,
                            speed: s_pref,
                            active: false,
                        }
                    } else {
                        let v = orca::solve(&lines, p.v_max, v_pref.rotate(keep_right));
                        unicycle(s, h_pref, v, &lines)
                    }
                }
                AvoidanceMethod::Separation => {
                    let mut push = Vec2::ZERO;
                    for &(d2, j) in &near[..k] {
                        let d = d2.sqrt();
                        if d < 2.0 * r {
                            let j = j as usize;
                            let dir = if d > 1e-9 {
                                (s.pos - states[j].pos) / d
                            } else if i < j {
                                -Vec2::X
                            } else {
                                Vec2::X
                            };
                            push += dir * (2.0 * r - d);
                        }
                    }
                    for o in obstacles {
                        let (dist, nrm) = o.distance_normal(s.pos);
                        if dist < r {
                            push += nrm * (r - dist);
                        }
                    }
                    if push == Vec2::ZERO {
                        Command {
                            heading: h_pref,
                            speed: s_pref,
                            active: false,
                        }
                    } else {
                        let v = (v_pref + push * cfg.separation_weight).clamp_length_max(p.v_max);
                        unicycle(s, h_pref, v, &Lines::default())
                    }
                }
            };
            self.commands[i] = cmd;
        }
    }
}

/// The forward-only unicycle's answer to the velocity `v`: turn towards
/// `v` (towards the funnel's heading `h_pref` when `v` is nearly zero),
/// and go along the current heading at the largest speed up to `v`'s
/// projection on it that every line admits (0 if none).
#[must_use]
pub fn unicycle(s: &VehicleState, h_pref: f32, v: Vec2, lines: &Lines) -> Command {
    let heading = if v.length_squared() > 1e-6 {
        trig::atan2(v.y, v.x)
    } else {
        h_pref
    };
    let u = s.forward();
    let mut hi = v.dot(u).max(0.0);
    for l in lines.as_slice() {
        // v = σ·u admitted ⇔ σ·det(d, u) ≥ det(d, point).
        let a = l.direction.x * u.y - l.direction.y * u.x;
        let b = l.direction.x * l.point.y - l.direction.y * l.point.x;
        if a < -1e-6 {
            hi = hi.min(b / a);
        }
    }
    Command {
        heading,
        speed: hi.max(0.0),
        active: true,
    }
}
