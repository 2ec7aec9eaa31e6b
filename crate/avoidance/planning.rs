//! What one agent's plan reads, phase by phase: the pass's settings and
//! what follows from them once per step, the planning agent itself (its
//! record, the funnel's ask, its margin) and the way it seeks; and the
//! speed up to which an agent may step aside ([`DODGE_SPEED`]).

use glam::Vec2;

use crate::avoidance::command::Command;
use crate::avoidance::config::{AvoidanceConfig, Obstacle};
use crate::avoidance::neighbours::Peer;
use crate::avoidance::orca::{Lines, MAX_NEIGHBOURS};
use crate::avoidance::passing::{self, Passing};
use crate::base::grid::NeighbourGrid;
use crate::base::vehicle::{VehicleParams, VehicleState};

/// Speed up to which an agent whose funnel asks for less (at rest on its
/// goal) may move to let others pass, m/s.
pub const DODGE_SPEED: f32 = 0.5;

/// What every planning agent of a pass reads: the settings, and what
/// follows from them once per step.
pub(crate) struct Pass<'a> {
    pub(crate) p: &'a VehicleParams,
    pub(crate) cfg: &'a AvoidanceConfig,
    pub(crate) obstacles: &'a [Obstacle],
    /// The radius avoided with: the body's plus the margin, m.
    pub(crate) r: f32,
    /// The neighbour reach, squared, m².
    pub(crate) r2: f32,
    /// Neighbours kept per agent.
    pub(crate) k_max: usize,
    /// The look-ahead scan may skip the cells of its block that no
    /// neighbour it would take in lies in ([`passing::FarBox`]).
    pub(crate) far_trim: bool,
    pub(crate) far_box: passing::FarBox,
    /// No half-plane: the separation's unicycle reads no line.
    pub(crate) no_lines: Lines,
}

impl<'a> Pass<'a> {
    pub(crate) fn new(
        p: &'a VehicleParams,
        cfg: &'a AvoidanceConfig,
        obstacles: &'a [Obstacle],
        grid: &NeighbourGrid,
    ) -> Self {
        let r = cfg.radius + cfg.margin;
        // The look-ahead scan may skip cells only when every cell it could
        // read has a bucket of its own: the block's cells lie within one of
        // the point ahead, those the far box meets within the box's size
        // of the agent, LOOK_AHEAD from that point.
        let far_cells =
            ((passing::LOOK_AHEAD + Passing::far_box_size(2.0 * r)) / cfg.reach).ceil() + 2.0;
        Self {
            p,
            cfg,
            obstacles,
            r,
            r2: cfg.reach * cfg.reach,
            k_max: (cfg.max_neighbours as usize).min(MAX_NEIGHBOURS),
            far_trim: far_cells <= 32.0 && grid.buckets_distinct_within(far_cells as i32),
            far_box: passing::FarBox::new(2.0 * r, cfg.reach),
            no_lines: Lines::default(),
        }
    }
}

/// The way an agent seeks: the command (`heading`, `speed`) it takes when
/// the velocity `v` (along the unit `u`) is admissible. The funnel's
/// (γ, v_dt) at first; ORCA seeks the goal's direction instead when the
/// funnel's runs into a wall or the agent is at rest (the heading stays
/// γ), and the keep-right rule turns it ([`lane_way`](crate::avoidance::keep_right::lane_way)).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Way {
    pub(crate) heading: f32,
    pub(crate) speed: f32,
    pub(crate) u: Vec2,
    pub(crate) v: Vec2,
}

/// One planning agent, as its plan's phases read it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Agent<'s> {
    /// Its record (position, unit heading, speed, priority, index).
    pub(crate) peer: Peer,
    pub(crate) state: &'s VehicleState,
    /// The funnel's heading γ and speed v_dt, and its velocity.
    pub(crate) h_pref: f32,
    pub(crate) s_pref: f32,
    pub(crate) u_pref: Vec2,
    pub(crate) v_pref: Vec2,
    /// The margin it keeps from neighbours and obstacles ([`patience`](crate::avoidance::patience)).
    pub(crate) margin: f32,
    /// It has a goal left ([`Avoider::priority`](crate::avoidance::avoider::Avoider::priority) finite).
    pub(crate) unfinished: bool,
    /// ORCA: the funnel's way runs into a wall.
    pub(crate) walled: bool,
    /// The way it seeks.
    pub(crate) seek: Way,
    /// The keep-right rule applies: ORCA, unfinished, not walled.
    pub(crate) passing: bool,
}

impl Agent<'_> {
    /// The funnel's own command, untouched.
    #[inline(always)]
    pub(crate) fn funnel_command(&self) -> Command {
        Command {
            heading: self.h_pref,
            speed: self.s_pref,
            active: false,
            walls: false,
        }
    }
}
