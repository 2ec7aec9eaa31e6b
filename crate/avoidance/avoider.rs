//! One avoidance pass over a world's agents: neighbours through a grid,
//! the method's velocity, and that velocity turned into what a
//! forward-only unicycle can do (paper 000 §7 and 001 §7 name avoidance
//! as the next step).
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
//! ([`crate::base::vehicle::VehicleParams::integrate`]), which clamps them into
//! the admissible set: no limit is ever broken, whatever the avoidance asks.
//!
//! **Who gives way** (without it the corridor and the doorway jam for
//! good: two forward-only agents face to face, or level at a door, each
//! waiting for the other). *Right of way by progress*: of a pair, the
//! agent clearly nearer its current goal ([`PRIORITY_GAP`](crate::avoidance::orca_plan::PRIORITY_GAP); within it, the
//! lower index) keeps only the bodies' clearance plus [`PRIORITY_MARGIN`](crate::avoidance::orca_plan::PRIORITY_MARGIN)
//! from the other, which keeps the whole margin: the pair never overlaps,
//! and where the margins leave no room one of them goes. *Keep right*
//! only against an oncoming neighbour ahead (heading cosine below
//! [`ONCOMING_COS`](crate::avoidance::passing::ONCOMING_COS)): a neighbour going the same way is followed; and
//! *early*, against any oncoming neighbour in reach, not only the nearest
//! ([`crate::avoidance::passing`]: the funnel's velocity turned right, so
//! that two groups meeting head on pass in lanes), and moving ones up to
//! [`crate::avoidance::passing::PASS_REACH`] ahead, read from the grid's
//! cells round a point further along the way; an agent turning into its
//! lane with a mate beside it on that side drops back to half speed and
//! merges behind it (a block as wide as the corridor cannot turn as a
//! block, four abreast). *Walls*:
//! when the funnel's heading runs into a wall (tested at a walking speed,
//! so that a funnel turning on the spot is caught too), the velocity
//! sought points at the goal, not along γ, which turns with the agent's own
//! heading (funnel and avoidance would otherwise take turns for ever at a
//! corner); so it does for an agent at rest, and the keep-right bias never
//! points into a wall ([`crate::avoidance::stalled`]). Finished agents
//! rank last and step aside at up to [`DODGE_SPEED`].
//!
//! **Neighbours** come from the crowd's hashed uniform grid
//! ([`crate::base::grid::NeighbourGrid`], cell = the search
//! distance), the `max_neighbours` nearest kept in a fixed array: the cost
//! per agent is bounded at constant density and nothing is allocated once
//! the buffers have grown. Obstacles are tested one by one (few by design,
//! [`crate::avoidance::config::MAX_OBSTACLES`]).
//!
//! **The pass, phase by phase** ([`Avoider::compute`]): the agents between
//! their plans hold their commands (`hold_commands`); the grid and the
//! agents' records are rebuilt in its bucket order (`index_agents`); the
//! agents due to plan this step are listed (`collect_due`); and each of them
//! plans (`plan`), in bucket order so that consecutive queries hit cached
//! buckets. One plan: the agent as its phases read it (`Agent`: its record,
//! the funnel's ask, the margin its patience leaves it); with ORCA the
//! obstacles' half-planes and the way sought (`seek_around_walls`: the goal's
//! direction when walled or at rest); the candidates in reach gathered
//! (`gather`) and the k nearest ranked, the keep-right rule reading them on
//! the way (`rank`). Then the method: off, the funnel's command;
//! separation, a push away from what is too near (`separation_command`);
//! ORCA (`orca_command`), the keep-right look ahead (`see_ahead`), the turn
//! into the lane (`lane_way`), the neighbours' half-planes
//! (`push_agent_lines`), and either the way sought as it is
//! (`way_admitted`) or the linear program's velocity turned into the
//! unicycle's heading and speed (`solve_keep_right`, [`unicycle`](crate::avoidance::command::unicycle)). The
//! values every plan shares live in a per-pass context (`Pass`). Every
//! phase is inlined into the pass's loop: the compiler sees one body.
//!
//! **Cost.** ORCA's plan costs as much in unpredictable branches as in
//! instructions: which case of a neighbour's half-plane applies, which
//! neighbour has the right of way or asks to keep right, which line bounds
//! a ray flip from neighbour to neighbour, and as branches they would be
//! mispredicted about every other time (scalar `select`s on a compound
//! condition become branches on x86, which has no conditional move for
//! floats). So the per-neighbour work runs four lanes at a time (glam's
//! `Vec4`, SSE2 natively, simd128 or scalar in wasm) with lane masks: the
//! candidates' distances and the keep-right asks
//! ([`crate::avoidance::passing::Passing::see4`]), the agents' half-planes
//! ([`orca::agent_lines4`](crate::avoidance::orca::agent_lines4)), the line set as a structure of arrays read
//! four lines at a time by the linear program and the ray caps
//! ([`orca::ray_cap`](crate::avoidance::orca::ray_cap)). Every lane does the scalar code's operations on the
//! same values (IEEE `+ − × ÷ sqrt`), and folds that the order could change
//! (minima, maxima) are folded in the scalar order: the same bits, which
//! unit tests check lane by lane against the scalar forms. Loops whose
//! length varies from agent to agent are avoided where a constant count
//! does the same work (the ranking's keys and its copy for all `RANKED`
//! slots, the gathered neighbours shown to the keep-right rule in a fixed
//! number of fours): a loop's exit is mispredicted when its length changes.
//! `diagnostics/avoid_icount.rs` counts instructions and simulated
//! mispredictions per agent update under callgrind.
//!
//! The look-ahead scan ([`passing::LOOK_AHEAD`](crate::avoidance::passing::LOOK_AHEAD)) reads only the cells of
//! its 3 × 3 block that meet the box where a neighbour it takes in can be
//! and none within reach was ([`passing::FarBox`](crate::avoidance::passing::FarBox): beyond reach ahead, in
//! the lane), a third fewer candidates, when the grid's table gives every
//! cell near the agent its own bucket (else the whole block): the same
//! neighbours seen, the same bits. It looks for mates only where some may
//! be beyond reach, and it does not run at all when the asks within reach
//! are already larger than any from beyond can be
//! ([`Passing::far_may_ask`]: 0.32 at the default clearance and reach, a
//! neighbour ahead in the lane within about 1.4 m). The keep-right rule
//! reads the neighbours gathered (`see_gathered`, about 3 fours at 11
//! neighbours) rather than every candidate of the nine cells (about 10
//! fours, two thirds out of reach). ORCA's neighbours are read four at a
//! time from their records, transposed, rather than copied lane by lane
//! into arrays first. The unit vectors of the agents' headings, the
//! funnels' and the keep-right turn come from [`trig::sin_cos`], whose
//! quadrant is restored by bit operations, not by a jump whose target
//! flips from agent to agent.
//!
//! **Plans every other step** ([`AvoidanceConfig::replan_every`], default
//! 2: 30 Hz at the default step of 1/60 s, agents taking turns by index).
//! Between its plans an agent keeps its last plan's command (heading and
//! speed), or takes its funnel's when that plan left the funnel's alone;
//! its patience clock, the grid, the neighbours' records and the vehicle
//! model still run every step. Why: what a plan costs is the method itself
//! (the half-planes, the linear program, the unicycle, the keep-right), and
//! one plan costs about three times a whole update without avoidance; the
//! per-step part (grid, records, lanes) is a small fraction of it, so
//! planning every other step nearly halves what the avoidance adds to an
//! agent update. Held
//! for one 1/60 s step, a command is 17 ms old at most: at 1.5 m/s an agent
//! moves 2.5 cm in it, a sixth of the 0.15 m margin. The benchmarks'
//! figures (README) are measured at this default; `replanEvery` 1 plans
//! every step, its own golden hash checked beside the default's.

use glam::Vec2;

use crate::avoidance::command::Command;
use crate::avoidance::config::{AvoidanceConfig, AvoidanceMethod, Obstacle};
use crate::avoidance::neighbours::Neighbours;
use crate::avoidance::orca::Lines;
use crate::avoidance::orca_plan::push_obstacle_lines;
use crate::avoidance::passing::Passing;
use crate::avoidance::patience;
use crate::avoidance::planning::{Agent, Pass, Way, DODGE_SPEED};
use crate::avoidance::stalled;
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};

/// The avoidance's buffers (reused every step).
#[derive(Clone, Debug, Default)]
pub struct Avoider {
    /// The grid, the agents' records and one query's candidates.
    neighbours: Neighbours,
    /// This step's commands, one per agent.
    pub commands: Vec<Command>,
    /// Per agent, its rank for right of way (smaller goes first: the
    /// distance left to its current goal; ∞ once finished), filled by the
    /// world before [`Avoider::compute`]; empty: nobody has priority.
    pub priority: Vec<f32>,
    /// Per agent, the position of its current goal, filled with
    /// [`Avoider::priority`]: when a wall blocks the funnel's way, the
    /// velocity sought points at it (the funnel's heading γ depends on the
    /// agent's own heading, and turning on the spot against a wall the two
    /// chased each other for ever); empty: the funnel's heading.
    pub goals: Vec<Vec2>,
    /// Per agent, its patience clock ([`crate::avoidance::patience`]): s
    /// unfinished and at rest, kept from step to step by the world; its
    /// margin from neighbours shrinks once it runs past
    /// [`patience::PATIENCE_AFTER`]. Empty: every agent keeps its margin.
    pub stalled: Vec<f32>,
    /// Steps computed so far: with [`AvoidanceConfig::replan_every`] = e,
    /// agent i plans on the steps where `(step + i) % e == 0`.
    step: u32,
    /// This step's planning agents, slots in `peers` (bucket order).
    due: Vec<u32>,
}

/// Scratch buffers carry no state worth comparing: two worlds are equal
/// whatever their avoiders hold, but for the state kept from step to step
/// (the patience clocks, the step count and the commands that agents
/// between plans keep).
impl PartialEq for Avoider {
    fn eq(&self, other: &Self) -> bool {
        self.stalled == other.stalled && self.step == other.step && self.commands == other.commands
    }
}

impl Avoider {
    /// Candidate pairs the grid examined since the last reset (tests prove
    /// the search is not quadratic with it).
    #[must_use]
    pub fn checks(&self) -> u64 {
        self.neighbours.grid.checks()
    }

    /// Resets [`Avoider::checks`].
    pub fn reset_checks(&mut self) {
        self.neighbours.grid.reset_checks();
    }

    /// The next step's number: with [`AvoidanceConfig::replan_every`] = e,
    /// agent i plans at it when `(step + i) % e == 0` (a copy of the
    /// avoidance stepped elsewhere, the GPU kernel, starts from it).
    #[must_use]
    pub fn next_step(&self) -> u32 {
        self.step
    }

    /// Fills [`Avoider::commands`] for agents in `states` whose funnels
    /// asked for `preferred[i] = (heading, speed)`: the agents not due to
    /// plan hold their commands, the grid and the records are rebuilt, and
    /// each agent due plans (`plan`).
    pub fn compute(
        &mut self,
        p: &VehicleParams,
        cfg: &AvoidanceConfig,
        obstacles: &[Obstacle],
        states: &[VehicleState],
        preferred: &[(f32, f32)],
    ) {
        let every = cfg.replan_every.max(1);
        let step = self.hold_commands(states.len(), every, preferred);
        self.neighbours
            .index_agents(states, cfg.reach, &self.priority);
        let pass = Pass::new(p, cfg, obstacles, &self.neighbours.grid);
        let n_due = self.collect_due(step, every);
        let mut lines = Lines::default();
        // Agents in the grid's bucket order: consecutive neighbour queries
        // hit the same, already cached buckets (each agent's answer does
        // not depend on the order).
        for d in 0..n_due {
            let slot = self.due[d] as usize;
            let i = self.neighbours.peers[slot].index as usize;
            self.commands[i] = self.plan(&pass, slot, states, preferred, &mut lines);
        }
    }

    /// Advances the step count and gives every agent its command until it
    /// plans: between its plans an agent keeps its last plan's command, or
    /// takes its funnel's when that plan left the funnel's alone. Returns
    /// this step's number (agent i plans when `(step + i) % every == 0`).
    fn hold_commands(&mut self, n: usize, every: u32, preferred: &[(f32, f32)]) -> u32 {
        let step = self.step;
        self.step = (step + 1) % every;
        if self.commands.len() != n {
            // Agents came or went: no plan is kept (each takes its
            // funnel's command until it plans).
            self.commands.clear();
        }
        self.commands.resize(n, Command::default());
        for (c, &(heading, speed)) in self.commands.iter_mut().zip(preferred) {
            if !c.active {
                *c = Command {
                    heading,
                    speed,
                    active: false,
                    walls: false,
                };
            }
        }
        step
    }

    /// Lists this step's planning agents in [`Avoider::due`], slots in the
    /// grid's bucket order, and returns how many: compacted without a
    /// branch (whether an agent is due flips from slot to slot).
    fn collect_due(&mut self, step: u32, every: u32) -> usize {
        self.due.resize(self.neighbours.peers.len() + 1, 0);
        let mut n_due = 0usize;
        for (slot, q) in self.neighbours.peers.iter().enumerate() {
            self.due[n_due] = slot as u32;
            n_due += usize::from((q.index + step) % every == 0);
        }
        n_due
    }

    /// One agent's plan, the agent at `slot` in the grid's bucket order:
    /// the obstacles' half-planes and the way it seeks (ORCA), its
    /// neighbours gathered and ranked, then the method's command.
    /// Inlined, as every phase below: the pass's loop is one body.
    #[inline(always)]
    fn plan(
        &mut self,
        pass: &Pass,
        slot: usize,
        states: &[VehicleState],
        preferred: &[(f32, f32)],
        lines: &mut Lines,
    ) -> Command {
        let orca = pass.cfg.method == AvoidanceMethod::Orca;
        let mut a = self.agent(pass, slot, states, preferred);
        // ORCA's view before the neighbours (none of it reads them): the
        // obstacles' half-planes, a way blocked by a wall, and the way
        // sought, along which the keep-right rule reads every neighbour in
        // reach while they are gathered.
        lines.clear();
        if orca {
            push_obstacle_lines(pass, a.state.pos, a.margin, lines);
            self.seek_around_walls(&mut a, lines);
        }
        // Keep right early ([`crate::avoidance::passing`]): read only where
        // the turn can apply (ORCA, an unfinished agent not blocked by a
        // wall).
        let mut lane = Passing::new(a.seek.u, 2.0 * pass.r);
        a.passing = orca && a.unfinished && !a.walled;
        let m = self.neighbours.gather(slot, a.peer.pos, pass.r2);
        let near = self
            .neighbours
            .rank(m, pass.k_max, a.passing, &mut lane, a.peer.pos);
        match pass.cfg.method {
            AvoidanceMethod::Off => a.funnel_command(),
            AvoidanceMethod::Orca => self
                .neighbours
                .orca_command(pass, &a, &mut lane, &near, lines),
            AvoidanceMethod::Separation => {
                self.neighbours.separation_command(pass, &a, &near, states)
            }
        }
    }

    /// The agent at `slot` as its plan starts: its record, its state, the
    /// funnel's ask and the margin its patience leaves it; the way sought
    /// is the funnel's.
    #[inline(always)]
    fn agent<'s>(
        &self,
        pass: &Pass,
        slot: usize,
        states: &'s [VehicleState],
        preferred: &[(f32, f32)],
    ) -> Agent<'s> {
        let peer = self.neighbours.peers[slot];
        let i = peer.index as usize;
        let (h_pref, s_pref) = preferred[i];
        let u_pref = trig::unit(h_pref);
        let v_pref = u_pref * s_pref;
        Agent {
            peer,
            state: &states[i],
            h_pref,
            s_pref,
            u_pref,
            v_pref,
            // Less once the agent has waited too long ([`patience`]).
            margin: patience::margin(pass.cfg.margin, self.stalled.get(i).copied().unwrap_or(0.0)),
            unfinished: peer.prio.is_finite(),
            walled: false,
            seek: Way {
                heading: h_pref,
                speed: s_pref,
                u: u_pref,
                v: v_pref,
            },
            passing: false,
        }
    }

    /// The way an agent seeks once the obstacles' half-planes are in
    /// `lines`. An unfinished agent whose funnel turns it in place
    /// (v_dt ≈ 0) towards a wall is blocked too: the funnel's heading is
    /// tested against the walls at a walking speed, or the funnel and the
    /// avoidance take turns for ever at a wall's corner. Blocked by a wall,
    /// or at rest ([`crate::avoidance::stalled`]), it seeks its goal's
    /// direction: the funnel's γ turns with the agent's own heading.
    #[inline(always)]
    fn seek_around_walls(&self, a: &mut Agent, lines: &Lines) {
        a.walled =
            a.unfinished && !lines.obstacles_admit(a.u_pref * a.s_pref.max(DODGE_SPEED), 0.0);
        let to_goal = a.walled || stalled::seeks_goal(a.unfinished, a.peer.v, a.s_pref);
        if let Some(&g) = self.goals.get(a.peer.index as usize) {
            let pos = a.state.pos;
            if to_goal && (g - pos).length_squared() > 1e-6 {
                a.seek.u = (g - pos).normalize();
                a.seek.v = a.seek.u * a.s_pref.max(DODGE_SPEED);
            }
        }
    }
}
