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
//! agent clearly nearer its current goal ([`PRIORITY_GAP`]; within it, the
//! lower index) keeps only the bodies' clearance plus [`PRIORITY_MARGIN`]
//! from the other, which keeps the whole margin: the pair never overlaps,
//! and where the margins leave no room one of them goes. *Keep right*
//! only against an oncoming neighbour ahead (heading cosine below
//! [`ONCOMING_COS`]): a neighbour going the same way is followed; and
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
//! unicycle's heading and speed (`solve_keep_right`, [`unicycle`]). The
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
//! ([`orca::agent_lines4`]), the line set as a structure of arrays read
//! four lines at a time by the linear program and the ray caps
//! ([`orca::ray_cap`]). Every lane does the scalar code's operations on the
//! same values (IEEE `+ − × ÷ sqrt`), and folds that the order could change
//! (minima, maxima) are folded in the scalar order: the same bits, which
//! unit tests check lane by lane against the scalar forms. Loops whose
//! length varies from agent to agent are avoided where a constant count
//! does the same work (the ranking's keys and its copy for all `RANKED`
//! slots, the gathered neighbours shown to the keep-right rule in a fixed
//! number of fours): a loop's exit is mispredicted when its length changes.
//! `examples/avoid_icount.rs` counts instructions and simulated
//! mispredictions per agent update under callgrind.
//!
//! The look-ahead scan ([`passing::LOOK_AHEAD`]) reads only the cells of
//! its 3 × 3 block that meet the box where a neighbour it takes in can be
//! and none within reach was ([`passing::FarBox`]: beyond reach ahead, in
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

use glam::{BVec4A, Mat4, Vec2, Vec4};

use crate::avoidance::config::{AvoidanceConfig, AvoidanceMethod, Obstacle};
use crate::avoidance::orca::{self, ray_cap, Lines, MAX_NEIGHBOURS};
use crate::avoidance::passing::{self, Passing, ONCOMING_COS};
use crate::avoidance::patience;
use crate::avoidance::stalled::{self, STUCK_SPEED};
use crate::base::grid::NeighbourGrid;
use crate::base::trig;
use crate::base::vehicle::{VehicleParams, VehicleState};

/// What one agent is told to do this step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Command {
    /// Heading for the seek step, rad.
    pub heading: f32,
    /// Desired speed, m/s.
    pub speed: f32,
    /// True when the avoidance changed the funnel's (γ, v_dt).
    pub active: bool,
    /// An obstacle was in reach: the step keeps the agent's turn near the
    /// ±π seam (`world::avoid_step`'s turn commitment).
    pub walls: bool,
}

/// One agent as the pass reads it, kept in the grid's bucket order: a
/// neighbour's data is one 32-byte record beside its cell-mates', not
/// five arrays in world order read per neighbour.
#[derive(Clone, Copy, Debug, Default)]
#[repr(align(32))]
struct Peer {
    pos: Vec2,
    /// Unit heading.
    fwd: Vec2,
    /// Speed along it, m/s.
    v: f32,
    /// [`Avoider::priority`]'s value; NaN when none is given.
    prio: f32,
    /// Index in the world.
    index: u32,
}

impl Peer {
    /// Position and heading, four lanes (x, y, x, y).
    #[inline]
    fn head(&self) -> Vec4 {
        Vec4::new(self.pos.x, self.pos.y, self.fwd.x, self.fwd.y)
    }
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

/// The avoidance's buffers (reused every step).
#[derive(Clone, Debug, Default)]
pub struct Avoider {
    grid: NeighbourGrid,
    pos: Vec<f32>,
    /// The agents in the grid's bucket order.
    peers: Vec<Peer>,
    /// Their positions' and unit headings' x and y, in the same order,
    /// then four padding lanes: the candidates are read four at a time.
    lanes: [Vec<f32>; 5],
    /// One query's candidates: squared distance, slot in `peers`.
    cand_d2: Vec<f32>,
    cand_slot: Vec<u32>,
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
        self.grid.checks()
    }

    /// Resets [`Avoider::checks`].
    pub fn reset_checks(&mut self) {
        self.grid.reset_checks();
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
        self.index_agents(states, cfg.reach);
        let pass = Pass::new(p, cfg, obstacles, &self.grid);
        let n_due = self.collect_due(step, every);
        let mut lines = Lines::default();
        // Agents in the grid's bucket order: consecutive neighbour queries
        // hit the same, already cached buckets (each agent's answer does
        // not depend on the order).
        for d in 0..n_due {
            let slot = self.due[d] as usize;
            let i = self.peers[slot].index as usize;
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

    /// Rebuilds the grid (cell = `reach`) over the agents' positions, and
    /// their records in its bucket order: one [`Peer`] each, and the
    /// same positions, headings and speeds as lanes read four at a time.
    fn index_agents(&mut self, states: &[VehicleState], reach: f32) {
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
                prio: self.priority.get(i).copied().unwrap_or(f32::NAN),
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

    /// Lists this step's planning agents in [`Avoider::due`], slots in the
    /// grid's bucket order, and returns how many: compacted without a
    /// branch (whether an agent is due flips from slot to slot).
    fn collect_due(&mut self, step: u32, every: u32) -> usize {
        self.due.resize(self.peers.len() + 1, 0);
        let mut n_due = 0usize;
        for (slot, q) in self.peers.iter().enumerate() {
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
        let m = self.gather(slot, a.peer.pos, pass.r2);
        let near = self.rank(m, pass.k_max, a.passing, &mut lane, a.peer.pos);
        match pass.cfg.method {
            AvoidanceMethod::Off => a.funnel_command(),
            AvoidanceMethod::Orca => self.orca_command(pass, &a, &mut lane, &near, lines),
            AvoidanceMethod::Separation => self.separation_command(pass, &a, &near, states),
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
        let peer = self.peers[slot];
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

    /// Gathers the candidates in reach of the agent at `slot` (at `pos`)
    /// from the grid's nine cells round it into [`Avoider::cand_d2`] and
    /// [`Avoider::cand_slot`], in grid order, without a branch: four at a
    /// time, each written and the count advanced by its lane's "in reach"
    /// bit. Returns how many.
    #[inline(always)]
    fn gather(&mut self, slot: usize, pos: Vec2, r2: f32) -> usize {
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
    fn rank(
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

    /// ORCA's command: the keep-right rule completed (the look-ahead scan,
    /// the turn into the lane), the neighbours' half-planes added, then
    /// the way sought taken as it is when every half-plane admits it, or
    /// else the linear program's velocity turned into the unicycle's
    /// heading and speed.
    #[inline(always)]
    fn orca_command(
        &self,
        pass: &Pass,
        a: &Agent,
        lane: &mut Passing,
        near: &Nearest,
        lines: &mut Lines,
    ) -> Command {
        if a.passing && lane.far_may_ask(&pass.far_box) {
            self.see_ahead(pass, a, lane);
        }
        let (way, turned) = lane_way(a, lane, lines);
        let oncoming = self.push_agent_lines(pass, a, way.u, near, lines);
        if way_admitted(pass, a, &way, oncoming, lines) {
            Command {
                heading: way.heading,
                speed: way.speed,
                active: turned,
                walls: false,
            }
        } else {
            solve_keep_right(pass, a, &way, oncoming, lines)
        }
    }

    /// The keep-right rule's look ahead beyond reach
    /// ([`passing::LOOK_AHEAD`]): the cells round a point further along
    /// the way, so that lanes form before the groups meet. Four at a time
    /// from the lanes (the asks fold by their maximum and the mates by
    /// "any": the order does not matter; the agent itself, at distance 0,
    /// asks nothing and is no mate, [`Passing::see4`]): scalar, one peer at
    /// a time, this scan costs more than the rest of the keep-right rule.
    /// Only the cells that meet the agent's far box ([`Passing::far_box`]:
    /// about 6 of the 9), when no other cell shares their buckets: the
    /// same neighbours seen.
    #[inline(always)]
    fn see_ahead(&self, pass: &Pass, a: &Agent, lane: &mut Passing) {
        let pos = a.peer.pos;
        let at = pos + a.seek.u * passing::LOOK_AHEAD;
        let (far, n_far) = if pass.far_trim && pos.abs().max_element() < passing::FAR_BOX_LIMIT {
            let [fx, fy] = self.grid.cell_of(at);
            let (lo, hi) = lane.far_box(pos, &pass.far_box);
            let ([x0, y0], [x1, y1]) = (self.grid.cell_of(lo), self.grid.cell_of(hi));
            let (x0, y0) = (x0.max(fx - 1), y0.max(fy - 1));
            let (x1, y1) = (x1.min(fx + 1), y1.min(fy + 1));
            self.grid.cell_runs(
                [x0, y0],
                (x1 - x0 + 1).max(0) as u32,
                (y1 - y0 + 1).max(0) as u32,
            )
        } else {
            self.grid.candidate_runs(at)
        };
        let (mx, my) = (Vec4::splat(pos.x), Vec4::splat(pos.y));
        // One length for the five (one bounds check).
        let n4 = self.lanes[0].len();
        let [lx, ly, lfx, lfy, lv] = self.lanes.each_ref().map(|l| &l[..n4]);
        for &(lo, hi) in &far[..n_far] {
            let (lo, hi) = (lo as usize, hi as usize);
            let mut c = lo;
            while c < hi {
                let in_run = Vec4::new(0.0, 1.0, 2.0, 3.0).cmplt(Vec4::splat((hi - c) as f32));
                lane.see_far4(
                    Vec4::from_slice(&lx[c..c + 4]) - mx,
                    Vec4::from_slice(&ly[c..c + 4]) - my,
                    Vec4::from_slice(&lfx[c..c + 4]),
                    Vec4::from_slice(&lfy[c..c + 4]),
                    Vec4::from_slice(&lv[c..c + 4]),
                    in_run,
                    &pass.far_box,
                );
                c += 4;
            }
        }
    }

    /// Adds the half-planes of the k nearest neighbours to `lines`, four
    /// at a time, every test a lane mask (their outcomes flip from
    /// neighbour to neighbour: as branches they are mispredicted about
    /// every other time). Read from their records (positions and headings
    /// transposed), past the k-th the k-th again (masked). Returns whether
    /// one of them is oncoming ahead along `u_seek`, the way the agent
    /// seeks.
    #[inline(always)]
    fn push_agent_lines(
        &self,
        pass: &Pass,
        a: &Agent,
        u_seek: Vec2,
        near: &Nearest,
        lines: &mut Lines,
    ) -> bool {
        let (cfg, me, pos) = (pass.cfg, &a.peer, a.state.pos);
        let (near, k) = (&near.near, near.k);
        let record = |c: usize| &self.peers[near[c.min(k - 1)].1 as usize];
        let mut oncoming = BVec4A::FALSE;
        let v_me = me.fwd * me.v;
        // A pair's combined reach: with the right of way, the bodies'
        // clearance plus a sliver; otherwise the whole margin (both less
        // for an agent out of patience).
        let reach_ahead = 2.0 * cfg.radius + PRIORITY_MARGIN.min(2.0 * a.margin);
        let reach_yield = 2.0 * (cfg.radius + a.margin);
        let (inv_h, inv_dt) = (1.0 / cfg.horizon, 1.0 / pass.p.dt);
        let splat = Vec4::splat;
        let moving = BVec4A::splat(me.v >= STUCK_SPEED);
        let mut c = 0;
        while c < k {
            let q = [record(c), record(c + 1), record(c + 2), record(c + 3)];
            let t = Mat4::from_cols(q[0].head(), q[1].head(), q[2].head(), q[3].head()).transpose();
            let (qx, qy, fx, fy) = (t.x_axis, t.y_axis, t.z_axis, t.w_axis);
            let qv = Vec4::new(q[0].v, q[1].v, q[2].v, q[3].v);
            let prio = Vec4::new(q[0].prio, q[1].prio, q[2].prio, q[3].prio);
            // The tie direction, +y when i < j, else −y (the scalar
            // `-Vec2::Y`: x is −0), by its sign bit.
            let after = q.map(|q| u32::from(q.index <= me.index) << 31);
            let tie_x = Vec4::from_array(after.map(f32::from_bits));
            let tie_y = Vec4::from_array(after.map(|a| f32::from_bits(0x3f80_0000 | a)));
            let valid = (splat(c as f32) + Vec4::new(0.0, 1.0, 2.0, 3.0)).cmplt(splat(k as f32));
            let (rx, ry) = (qx - splat(pos.x), qy - splat(pos.y));
            // Oncoming and ahead along the way the agent will seek (its
            // goal's direction when walled, not the funnel's γ it then
            // ignores: judged along γ, a neighbour beside the way flips in
            // and out of "ahead" step after step at a doorway's wall end,
            // and the keep-right turn with it, so that at rest the velocity
            // sought swings between the gap and the wall).
            let opposed = (fx * splat(u_seek.x) + fy * splat(u_seek.y)).cmplt(splat(ONCOMING_COS));
            oncoming |=
                valid & opposed & (rx * splat(u_seek.x) + ry * splat(u_seek.y)).cmpgt(Vec4::ZERO);
            let opposed = (fx * splat(me.fwd.x) + fy * splat(me.fwd.y)).cmplt(splat(ONCOMING_COS));
            let before = tie_y.cmpgt(Vec4::ZERO);
            // Reciprocity assumes the neighbour takes half the avoidance;
            // a forward-only neighbour at rest cannot step back, so an
            // agent closing on it takes all.
            let share = Vec4::select(qv.cmplt(splat(STUCK_SPEED)) & moving, Vec4::ONE, splat(0.5));
            // Right of way: the agent clearly nearer its goal keeps only
            // the bodies' distance (plus a sliver) from the other, which
            // keeps the whole margin; the pair still never overlaps, and
            // where the margins leave no room (a doorway, a jam) the one
            // ahead gets through instead of both waiting. Within the gap
            // (two agents level at a doorway, both waiting for the other)
            // the lower index goes first. No priority given (NaN): nobody
            // is ahead.
            let pa = me.prio;
            let ahead = splat(pa + PRIORITY_GAP).cmplt(prio)
                | (before & splat(pa).cmple(prio + splat(PRIORITY_GAP)));
            let keep_right = opposed
                & (rx * splat(me.fwd.x) + ry * splat(me.fwd.y)).cmpgt(Vec4::ZERO)
                & ((splat(pos.x) - qx) * fx + (splat(pos.y) - qy) * fy).cmpgt(Vec4::ZERO);
            let pairs = orca::Pairs4 {
                pn: (qx, qy),
                vn: (fx * qv, fy * qv),
                r: Vec4::select(ahead, splat(reach_ahead), splat(reach_yield)),
                share,
                tie: (tie_x, tie_y),
                keep_right,
            };
            lines.push_agents4(&orca::agent_lines4(pos, v_me, &pairs, inv_h, inv_dt), k - c);
            c += 4;
        }
        oncoming.any()
    }

    /// Separation's command: a push away from every neighbour closer than
    /// two radii and from every obstacle closer than one, added to the
    /// funnel's velocity; the funnel's own command when nothing pushes.
    #[inline(always)]
    fn separation_command(
        &self,
        pass: &Pass,
        a: &Agent,
        near: &Nearest,
        states: &[VehicleState],
    ) -> Command {
        let (r, s, i) = (pass.r, a.state, a.peer.index as usize);
        let mut push = Vec2::ZERO;
        for &(d2, sj) in &near.near[..near.k] {
            let d = d2.sqrt();
            if d < 2.0 * r {
                let j = self.peers[sj as usize].index as usize;
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
        for o in pass.obstacles {
            let (dist, nrm) = o.distance_normal(s.pos);
            if dist < r {
                push += nrm * (r - dist);
            }
        }
        if push == Vec2::ZERO {
            return a.funnel_command();
        }
        let v = (a.v_pref + push * pass.cfg.separation_weight).clamp_length_max(pass.p.v_max);
        unicycle(s, a.peer.fwd, a.h_pref, v, v, &pass.no_lines, pass.p.v_max)
    }
}

/// What every planning agent of a pass reads: the settings, and what
/// follows from them once per step.
struct Pass<'a> {
    p: &'a VehicleParams,
    cfg: &'a AvoidanceConfig,
    obstacles: &'a [Obstacle],
    /// The radius avoided with: the body's plus the margin, m.
    r: f32,
    /// The neighbour reach, squared, m².
    r2: f32,
    /// Neighbours kept per agent.
    k_max: usize,
    /// The look-ahead scan may skip the cells of its block that no
    /// neighbour it would take in lies in ([`passing::FarBox`]).
    far_trim: bool,
    far_box: passing::FarBox,
    /// No half-plane: the separation's unicycle reads no line.
    no_lines: Lines,
}

impl<'a> Pass<'a> {
    fn new(
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
/// γ), and the keep-right rule turns it ([`lane_way`]).
#[derive(Clone, Copy, Debug)]
struct Way {
    heading: f32,
    speed: f32,
    u: Vec2,
    v: Vec2,
}

/// One planning agent, as its plan's phases read it.
#[derive(Clone, Copy, Debug)]
struct Agent<'s> {
    /// Its record (position, unit heading, speed, priority, index).
    peer: Peer,
    state: &'s VehicleState,
    /// The funnel's heading γ and speed v_dt, and its velocity.
    h_pref: f32,
    s_pref: f32,
    u_pref: Vec2,
    v_pref: Vec2,
    /// The margin it keeps from neighbours and obstacles ([`patience`]).
    margin: f32,
    /// It has a goal left ([`Avoider::priority`] finite).
    unfinished: bool,
    /// ORCA: the funnel's way runs into a wall.
    walled: bool,
    /// The way it seeks.
    seek: Way,
    /// The keep-right rule applies: ORCA, unfinished, not walled.
    passing: bool,
}

impl Agent<'_> {
    /// The funnel's own command, untouched.
    #[inline(always)]
    fn funnel_command(&self) -> Command {
        Command {
            heading: self.h_pref,
            speed: self.s_pref,
            active: false,
            walls: false,
        }
    }
}

/// The k nearest neighbours (squared distance, slot in the records),
/// nearest first; past the k-th, not read.
#[derive(Clone, Copy, Debug)]
struct Nearest {
    near: [(f32, u32); MAX_NEIGHBOURS],
    k: usize,
}

/// Adds the half-planes of the obstacles in reach of an agent at `pos`
/// keeping `margin` to `lines`.
#[inline(always)]
fn push_obstacle_lines(pass: &Pass, pos: Vec2, margin: f32, lines: &mut Lines) {
    let cfg = pass.cfg;
    for o in pass.obstacles {
        let (dist, nrm) = o.distance_normal(pos);
        if dist - pass.r < cfg.reach {
            lines.push_obstacle(orca::obstacle_line(
                nrm,
                dist,
                cfg.radius + margin,
                cfg.obstacle_horizon,
                pass.p.dt,
            ));
        }
    }
}

/// The way sought after the keep-right turn, and whether it turned: the
/// asks folded ([`Passing::settle`]), the way turned right where an
/// unfinished agent not walled is asked to and the turned way is clear of
/// walls; turning into its lane with a mate beside it on that side, it
/// drops back to merge behind it ([`Passing::merge_factor`]).
#[inline(always)]
fn lane_way(a: &Agent, lane: &mut Passing, lines: &Lines) -> (Way, bool) {
    lane.settle();
    let u_lane = lane.turn(a.seek.u);
    let turned = a.unfinished
        && !a.walled
        && lane.active()
        && lines.obstacles_admit(u_lane * a.s_pref.max(DODGE_SPEED), 0.0);
    if !turned {
        return (a.seek, false);
    }
    let f = lane.merge_factor();
    let way = Way {
        heading: trig::atan2(u_lane.y, u_lane.x),
        speed: a.s_pref * f,
        u: u_lane,
        v: lane.turn(a.seek.v) * f,
    };
    (way, true)
}

/// True when the agent takes the way sought as it is: not walled, no
/// oncoming neighbour ahead (then it keeps right at once, before the pair
/// is blocked, so that lanes form before a jam does), within the vehicle's
/// speed, admitted by every half-plane, and its present heading clear of
/// walls at that speed ([`present_heading_clear`]).
#[inline(always)]
fn way_admitted(pass: &Pass, a: &Agent, way: &Way, oncoming: bool, lines: &Lines) -> bool {
    !a.walled
        && !oncoming
        && way.speed <= pass.p.v_max
        && lines.admits(way.v, 0.0)
        && present_heading_clear(lines, a.peer.fwd, way.speed)
}

/// ORCA's velocity for a way not admitted, as the unicycle's command: the
/// velocity sought turned right by an oncoming neighbour ahead (at least
/// [`LANE_BIAS`] of [`AvoidanceConfig::bias_deg`], the more the slower the
/// agent goes than its way asks: none at full speed), unless that runs
/// into a wall; the linear program's nearest admissible velocity, no
/// faster than the way asks; then [`unicycle`].
#[inline(always)]
fn solve_keep_right(pass: &Pass, a: &Agent, way: &Way, oncoming: bool, lines: &Lines) -> Command {
    let slow = if oncoming {
        (1.0 - a.state.v / way.speed.max(0.1)).clamp(LANE_BIAS, 1.0)
    } else {
        0.0
    };
    let v_seek = if slow > 0.0 {
        // Not into a wall ([`crate::avoidance::stalled`]).
        stalled::bias_clear_of_walls(
            lines,
            way.v,
            way.v
                .rotate(trig::unit(-pass.cfg.bias_deg.to_radians() * slow)),
            DODGE_SPEED,
        )
    } else {
        way.v
    };
    // Never faster than the way asks (at least DODGE_SPEED, so an agent
    // at rest can step aside): a vehicle that must brake within its
    // acceleration limit cannot afford ORCA's habit of speeding up to pass
    // in front.
    let cap = way.speed.max(DODGE_SPEED).min(pass.p.v_max);
    let v = orca::solve(lines, cap, v_seek);
    Command {
        walls: lines.obstacle_count() > 0,
        ..unicycle(a.state, a.peer.fwd, way.heading, way.v, v, lines, cap)
    }
}

/// True when the vehicle, still moving along its present heading `forward`
/// while it turns to the funnel's, may speed up to `speed` without running
/// into an obstacle. The funnel's own command sets a heading to turn to and
/// a speed, not a velocity: an agent facing a wall whose funnel asks to
/// turn round at full speed would accelerate into the wall while it
/// turns, closer than its radius. Without obstacles in reach: always (the
/// same bits).
#[inline]
fn present_heading_clear(lines: &Lines, forward: Vec2, speed: f32) -> bool {
    lines.obstacle_count() == 0 || lines.obstacles_admit(forward * speed, 0.0)
}

/// Speed up to which an agent whose funnel asks for less (at rest on its
/// goal) may move to let others pass, m/s.
pub const DODGE_SPEED: f32 = 0.5;

/// How much nearer its goal an agent must be than a neighbour, m, to have
/// the right of way over it. Much wider, the right of way goes nearly by
/// index, and agents level at the doorway jam.
pub const PRIORITY_GAP: f32 = 0.25;

/// The clearance, m, beyond the two bodies that an agent with the right of
/// way keeps from the neighbour yielding to it.
pub const PRIORITY_MARGIN: f32 = 0.15;

/// The share of [`AvoidanceConfig::bias_deg`] an agent keeps right by, at
/// least, while an oncoming neighbour is ahead (the full bias once it has
/// slowed to a stop).
pub const LANE_BIAS: f32 = 0.2;

/// Headings sampled each side of the current one by [`unicycle`].
pub const HEADING_SAMPLES: usize = 12;

/// The forward-only unicycle's answer: it chooses among the admissible
/// headings and speeds. When ORCA's velocity `v_orca` is at least
/// [`STUCK_SPEED`], the heading command is its direction and the speed its
/// projection on the present heading, no more than that ray admits.
/// Otherwise (a crowd packed at the contact distance leaves ORCA nearly no
/// velocity) the headings are searched: candidates are the ORCA velocity's direction
/// (`v_orca`), the current heading and [`HEADING_SAMPLES`] headings every
/// 15° each side of it; along each, the speed nearest the sought velocity
/// `v_seek` that every half-plane admits (a 1D linear program). The
/// candidate nearest `v_seek` wins (ties: the smaller turn). It contains
/// ORCA's own answer, so it is never worse than ORCA's velocity; it still
/// finds a way out where ORCA's velocity is nearly zero (a crowd packed at
/// the contact distance) and a ray away from the packing is free.
///
/// The heading command is the winner's; the speed command is the speed the
/// winner asks for, scaled by the cosine of the turn still to make, and no
/// more than the current heading's own ray admits: the vehicle moves along
/// its present heading while it turns.
#[must_use]
pub fn unicycle(
    s: &VehicleState,
    forward: Vec2,
    h_pref: f32,
    v_seek: Vec2,
    v_orca: Vec2,
    lines: &Lines,
    v_max: f32,
) -> Command {
    let along = ray_cap(lines, forward, v_max);
    if v_orca.length() >= STUCK_SPEED {
        // ORCA found a way: turn to it, move along the present heading at
        // its projection, as far as that ray is admissible.
        return Command {
            heading: trig::atan2(v_orca.y, v_orca.x),
            speed: v_orca.dot(forward).max(0.0).min(along),
            active: true,
            walls: false,
        };
    }
    if v_seek.length_squared() < 1e-6 {
        // Nothing sought (the funnel turns the agent in place, or it rests):
        // turning on the spot is always admissible.
        return Command {
            heading: h_pref,
            speed: 0.0,
            active: true,
            walls: false,
        };
    }
    let step = 15f32.to_radians();
    let turn_step = trig::unit(step);
    let mut best = (f32::INFINITY, 0.0f32, s.theta, 0.0f32); // cost, |turn|, heading, speed
    let mut consider = |h: f32, u: Vec2, turn: f32, along: Option<f32>| {
        // A ray facing away from `v_seek` gets speed 0 whatever its cap
        // (the clamp's lower bound): its lines are not read.
        let d = v_seek.dot(u);
        let cap = if d > 0.0 {
            along.unwrap_or_else(|| ray_cap(lines, u, v_max))
        } else {
            f32::INFINITY
        };
        let sp = d.clamp(0.0, cap);
        let cost = (u * sp - v_seek).length_squared();
        if cost < best.0 - 1e-9 || (cost <= best.0 + 1e-9 && turn < best.1) {
            best = (cost, turn, h, sp);
        }
    };
    if v_orca.length_squared() > 1e-6 {
        let h = trig::atan2(v_orca.y, v_orca.x);
        consider(
            h,
            v_orca.normalize(),
            crate::base::angle::diff(h, s.theta).abs(),
            None,
        );
    }
    consider(s.theta, forward, 0.0, Some(along));
    // The samples by successive rotations of the present heading (no
    // sine or cosine per sample).
    let (mut left, mut right) = (forward, forward);
    for k in 1..=HEADING_SAMPLES {
        let d = step * k as f32;
        left = turn_step.rotate(left);
        right = Vec2::new(turn_step.x, -turn_step.y).rotate(right);
        consider(crate::base::angle::wrap(s.theta + d), left, d, None);
        consider(crate::base::angle::wrap(s.theta - d), right, d, None);
    }
    let (_, turn, heading, sp) = best;
    if !best.0.is_finite() {
        // No ray is admissible: brake, turning to the funnel's heading.
        return Command {
            heading: h_pref,
            speed: 0.0,
            active: true,
            walls: false,
        };
    }
    Command {
        heading,
        // `trig`, not `f32::cos` (the platform's libm): the same bits
        // natively and in wasm.
        speed: (sp * trig::sin_cos(turn).1.max(0.0)).min(along),
        active: true,
        walls: false,
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
