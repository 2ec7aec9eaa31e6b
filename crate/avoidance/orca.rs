//! ORCA, optimal reciprocal collision avoidance (van den Berg, Guy, Lin,
//! Manocha, "Reciprocal n-body collision avoidance", ISRR 2011; the RVO2
//! library's algorithm): each neighbour contributes a half-plane of
//! velocities that cannot collide with it within the time horizon (each of
//! the two taking half the avoidance), each obstacle a half-plane that keeps
//! the agent off it; the new velocity is the one nearest the preferred
//! velocity inside all half-planes and the speed disc (a 2D linear program,
//! randomisation-free incremental form), or, when they have no common point,
//! the one that least violates the agents' half-planes while keeping the
//! obstacles' (a 3D linear program).
//!
//! Why not the `dodgy_2d` crate (0.5.5, which implements the same paper):
//! it does not build for `wasm32-unknown-unknown` (it depends on `rand`
//! 0.9, whose `getrandom` 0.3 refuses that target without a `--cfg
//! getrandom_backend` flag), it draws an *unseeded* random direction when
//! two agents coincide (our trajectories must be the same bits on every
//! run and target), it allocates two `Vec`s per agent per step and wants
//! its neighbours as a slice of `Cow<Agent>`, and it depends on glam 0.29
//! (we are on 0.34). Its obstacles are polygons; ours are discs and
//! segments. This module holds the agents' half-planes and the
//! linear programs, written after the paper, in fixed-size arrays (no
//! allocation), with a deterministic choice where RVO2 divides by zero.
//!
//! Obstacles: RVO2 builds velocity obstacles for polygon edges. For a disc
//! or a segment we use the tangent half-plane at the nearest point,
//! `v·n ≥ −(dist − r)/τ_o` (n the unit normal away from the obstacle, τ_o
//! the obstacle horizon): exact for a straight wall, conservative round a
//! disc; it lets the distance shrink at most exponentially, never to zero
//! in continuous time. Inside (dist < r) it asks to get out within one step.
//!
//! Arithmetic: only `+ − × ÷` and `sqrt` (all IEEE-exact), so the result is
//! the same bits natively and in wasm.

use glam::{BVec4A, Vec2, Vec4};

/// Most agent half-planes per agent ([`crate::avoidance::config::AvoidanceConfig::max_neighbours`] ≤ this).
pub const MAX_NEIGHBOURS: usize = 16;
/// Most obstacle half-planes per agent (the nearest obstacles in reach).
pub const MAX_OBSTACLE_LINES: usize = 16;
/// Capacity of a line set.
pub const MAX_LINES: usize = MAX_NEIGHBOURS + MAX_OBSTACLE_LINES;

const EPS: f32 = 1e-5;

/// A directed line; the admissible half-plane is on its left:
/// `det(direction, v − point) ≥ 0`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Line {
    /// A point on the line.
    pub point: Vec2,
    /// Unit direction.
    pub direction: Vec2,
}

impl Line {
    /// True when `v` is on the admissible side (within `slack`).
    #[inline]
    #[must_use]
    pub fn admits(&self, v: Vec2, slack: f32) -> bool {
        det(self.direction, self.point - v) <= slack
    }
}

/// A fixed-capacity set of half-planes: obstacles first, then agents.
///
/// Kept as a structure of arrays (points' x and y, directions' x and y):
/// the linear program and the ray caps read four lines at a time.
#[derive(Clone, Copy, Debug)]
pub struct Lines {
    px: [f32; MAX_LINES],
    py: [f32; MAX_LINES],
    dx: [f32; MAX_LINES],
    dy: [f32; MAX_LINES],
    len: usize,
    obstacles: usize,
}

impl Default for Lines {
    fn default() -> Self {
        Self {
            px: [0.0; MAX_LINES],
            py: [0.0; MAX_LINES],
            dx: [0.0; MAX_LINES],
            dy: [0.0; MAX_LINES],
            len: 0,
            obstacles: 0,
        }
    }
}

impl Lines {
    /// Empties the set.
    #[inline]
    pub fn clear(&mut self) {
        self.len = 0;
        self.obstacles = 0;
    }

    #[inline]
    fn put(&mut self, at: usize, l: Line) {
        self.px[at] = l.point.x;
        self.py[at] = l.point.y;
        self.dx[at] = l.direction.x;
        self.dy[at] = l.direction.y;
    }

    /// Adds an obstacle half-plane (call before any agent's); ignored when
    /// [`MAX_OBSTACLE_LINES`] are already in.
    #[inline]
    pub fn push_obstacle(&mut self, l: Line) {
        debug_assert_eq!(self.len, self.obstacles, "obstacles first");
        if self.obstacles < MAX_OBSTACLE_LINES {
            self.put(self.len, l);
            self.len += 1;
            self.obstacles += 1;
        }
    }

    /// Adds an agent half-plane; ignored when full.
    #[inline]
    pub fn push_agent(&mut self, l: Line) {
        if self.len < MAX_LINES {
            self.put(self.len, l);
            self.len += 1;
        }
    }

    /// Adds the first `n` (≤ 4) of four agent half-planes given lane by
    /// lane as [`agent_lines4`] returns them (points' x and y, directions'
    /// x and y); those past the capacity are ignored.
    #[inline]
    pub fn push_agents4(&mut self, l: &[Vec4; 4], n: usize) {
        let at = self.len;
        if at + 4 <= MAX_LINES {
            // All four lanes written at once; only `n` counted.
            l[0].write_to_slice(&mut self.px[at..at + 4]);
            l[1].write_to_slice(&mut self.py[at..at + 4]);
            l[2].write_to_slice(&mut self.dx[at..at + 4]);
            l[3].write_to_slice(&mut self.dy[at..at + 4]);
            self.len += n.min(4);
        } else {
            let [px, py, dx, dy] = l.map(|x| x.to_array());
            for (((&x, &y), &ux), &uy) in px.iter().zip(&py).zip(&dx).zip(&dy).take(n) {
                self.push_agent(Line {
                    point: Vec2::new(x, y),
                    direction: Vec2::new(ux, uy),
                });
            }
        }
    }

    /// Lines in the set.
    #[inline]
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when the set has no line.
    #[inline]
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Line `i` (< [`Lines::len`]).
    #[inline]
    #[must_use]
    pub fn get(&self, i: usize) -> Line {
        Line {
            point: Vec2::new(self.px[i], self.py[i]),
            direction: Vec2::new(self.dx[i], self.dy[i]),
        }
    }

    /// The lines, in order.
    pub fn iter(&self) -> impl Iterator<Item = Line> + '_ {
        (0..self.len).map(|i| self.get(i))
    }

    /// Lines `at..at + 4` lane by lane (points' x and y, directions' x
    /// and y), `at` a multiple of 4; lanes past [`Lines::len`] hold
    /// whatever an earlier set left (callers mask them).
    #[inline]
    fn four(&self, at: usize) -> [Vec4; 4] {
        [
            Vec4::from_slice(&self.px[at..at + 4]),
            Vec4::from_slice(&self.py[at..at + 4]),
            Vec4::from_slice(&self.dx[at..at + 4]),
            Vec4::from_slice(&self.dy[at..at + 4]),
        ]
    }

    /// Obstacle half-planes in the set.
    #[inline]
    #[must_use]
    pub fn obstacle_count(&self) -> usize {
        self.obstacles
    }

    /// True when `v` satisfies every obstacle line (within `slack`).
    #[must_use]
    pub fn obstacles_admit(&self, v: Vec2, slack: f32) -> bool {
        (0..self.obstacles).all(|i| self.get(i).admits(v, slack))
    }

    /// True when `v` satisfies every line (within `slack`).
    #[must_use]
    pub fn admits(&self, v: Vec2, slack: f32) -> bool {
        self.iter().all(|l| l.admits(v, slack))
    }

    /// The first line from `from` on that `v` violates (`det(direction,
    /// point − v) > 0`), four lines tested at a time.
    #[inline]
    fn first_violated(&self, from: usize, v: Vec2) -> Option<usize> {
        let (vx, vy) = (Vec4::splat(v.x), Vec4::splat(v.y));
        let mut at = from & !3;
        while at < self.len {
            let [px, py, dx, dy] = self.four(at);
            let bad = (dx * (py - vy) - dy * (px - vx)).cmpgt(Vec4::ZERO);
            // Lanes before `from` or past the end do not count.
            let lanes = lane_mask(from.saturating_sub(at), self.len - at);
            let hits = bad.bitmask() & lanes;
            if hits != 0 {
                return Some(at + hits.trailing_zeros() as usize);
            }
            at += 4;
        }
        None
    }
}

/// The lanes below `n` (all four from 4 on).
#[inline]
fn lanes_below(n: usize) -> BVec4A {
    Vec4::new(0.0, 1.0, 2.0, 3.0).cmplt(Vec4::splat(n.min(4) as f32))
}

/// Bits `lo..hi` of a 4-lane mask (`hi` clamped to 4).
#[inline]
#[must_use]
pub fn lane_mask(lo: usize, hi: usize) -> u32 {
    (0xf_u32 >> (4 - hi.min(4))) & !((1_u32 << lo.min(4)) - 1)
}

/// `a` when `c`, else `b`, through bit masks: a choice whose outcome
/// flips from neighbour to neighbour, which the compiler would otherwise
/// often turn into a branch (a select whose condition compares a loaded
/// value becomes one on x86), mispredicted about every other time.
#[inline(always)]
#[must_use]
pub fn pick(c: bool, a: f32, b: f32) -> f32 {
    let m = u32::from(c).wrapping_neg();
    f32::from_bits((a.to_bits() & m) | (b.to_bits() & !m))
}

/// [`pick`] for vectors.
#[inline(always)]
#[must_use]
pub fn pick2(c: bool, a: Vec2, b: Vec2) -> Vec2 {
    Vec2::new(pick(c, a.x, b.x), pick(c, a.y, b.y))
}

#[inline]
fn det(a: Vec2, b: Vec2) -> f32 {
    a.x * b.y - a.y * b.x
}

/// The half-plane that `me` (position `p`, velocity `v`) must keep to so as
/// not to collide with a neighbour (`pn`, `vn`) within `horizon` (sum of
/// radii `r`), taking `share` of the avoidance (½ reciprocal). `dt` is the
/// step, used when already overlapping; `tie` is a deterministic unit
/// direction used where RVO2 would divide by zero (coincident agents).
///
/// Without a branch: which of the three cases applies (the cut-off
/// circle, a leg of the cone, already overlapping) flips from neighbour to
/// neighbour, so every case is computed and the answer selected (the same
/// operations on the same values as a branch per case: the same bits).
/// The cut-off circle and the overlap differ only in the inverse time
/// (1/horizon, 1/dt) and the threshold below which `tie` replaces the
/// unit vector (0, 1e-9), and share their arithmetic.
// `!(a > b)`, not `a <= b`: the same outcome as the branch it replaces,
// NaN included.
#[allow(clippy::too_many_arguments, clippy::neg_cmp_op_on_partial_ord)]
#[inline]
#[must_use]
pub fn agent_line(
    p: Vec2,
    v: Vec2,
    pn: Vec2,
    vn: Vec2,
    r: f32,
    horizon: f32,
    dt: f32,
    share: f32,
    tie: Vec2,
    keep_right: bool,
) -> Line {
    let rel_pos = pn - p;
    let rel_vel = v - vn;
    let dist_sq = rel_pos.length_squared();
    let r_sq = r * r;
    let overlap = !(dist_sq > r_sq);
    // Both inverse times, whatever the case (loop-invariant for a caller
    // running over its neighbours).
    let (inv_h, inv_dt) = (1.0 / horizon, 1.0 / dt);
    let inv = pick(overlap, inv_dt, inv_h);
    // Vector from the cut-off circle's centre to the relative velocity
    // (overlapping: from the circle one step away).
    let w = rel_vel - rel_pos * inv;
    let w_len_sq = w.length_squared();
    let dot1 = w.dot(rel_pos);
    let cut = overlap | ((dot1 < 0.0) & (dot1 * dot1 > r_sq * w_len_sq));
    // Project on the cut-off circle (overlapping: leave within one step).
    let w_len = w_len_sq.sqrt();
    let min_len = pick(overlap, 1e-9, 0.0);
    let unit_w = pick2(w_len > min_len, w / w_len, tie);
    let dir_cut = Vec2::new(unit_w.y, -unit_w.x);
    let u_cut = unit_w * (r * inv - w_len);
    // Project on a leg of the cone (NaN when overlapping: not selected).
    let leg = (dist_sq - r_sq).sqrt();
    // Left leg: pass with the neighbour on one's right; a pair meeting
    // head-on both keep right instead (the same choice seen from either
    // side: det is symmetric under the swap).
    let left = Vec2::new(
        rel_pos.x * leg - rel_pos.y * r,
        rel_pos.x * r + rel_pos.y * leg,
    ) / dist_sq;
    let right = -Vec2::new(
        rel_pos.x * leg + rel_pos.y * r,
        -rel_pos.x * r + rel_pos.y * leg,
    ) / dist_sq;
    let dir_leg = pick2((det(rel_pos, w) > 0.0) & !keep_right, left, right);
    let u_leg = dir_leg * rel_vel.dot(dir_leg) - rel_vel;
    let direction = pick2(cut, dir_cut, dir_leg);
    let u = pick2(cut, u_cut, u_leg);
    Line {
        point: v + u * share,
        direction,
    }
}

/// Four neighbours' inputs to [`agent_lines4`], one per lane: positions,
/// velocities, the combined radius, the share, the tie direction and
/// whether the pair keeps right.
#[derive(Clone, Copy, Debug)]
pub struct Pairs4 {
    /// Neighbour positions.
    pub pn: (Vec4, Vec4),
    /// Neighbour velocities.
    pub vn: (Vec4, Vec4),
    /// Sum of radii.
    pub r: Vec4,
    /// Share of the avoidance.
    pub share: Vec4,
    /// Tie directions.
    pub tie: (Vec4, Vec4),
    /// Keep right (head on).
    pub keep_right: BVec4A,
}

/// [`agent_line`] for four neighbours at once, lane by lane (SIMD where
/// the target has it): the same operations on the same values in every
/// lane, so the same bits as four calls, and every choice a lane mask (no
/// branch). `inv_h` and `inv_dt` are `1 / horizon` and `1 / dt`. Returns
/// the lines' points and directions, `(px, py, dx, dy)`.
#[inline]
#[must_use]
pub fn agent_lines4(p: Vec2, v: Vec2, q: &Pairs4, inv_h: f32, inv_dt: f32) -> [Vec4; 4] {
    let (rx, ry) = (q.pn.0 - Vec4::splat(p.x), q.pn.1 - Vec4::splat(p.y));
    let (vx, vy) = (Vec4::splat(v.x) - q.vn.0, Vec4::splat(v.y) - q.vn.1);
    let r = q.r;
    let dist_sq = rx * rx + ry * ry;
    let r_sq = r * r;
    let overlap = !dist_sq.cmpgt(r_sq);
    let inv = Vec4::select(overlap, Vec4::splat(inv_dt), Vec4::splat(inv_h));
    let (wx, wy) = (vx - rx * inv, vy - ry * inv);
    let w_len_sq = wx * wx + wy * wy;
    let dot1 = wx * rx + wy * ry;
    let cut = overlap | (dot1.cmplt(Vec4::ZERO) & (dot1 * dot1).cmpgt(r_sq * w_len_sq));
    let w_len = w_len_sq.sqrt();
    let min_len = Vec4::select(overlap, Vec4::splat(1e-9), Vec4::ZERO);
    let unit = w_len.cmpgt(min_len);
    let ux = Vec4::select(unit, wx / w_len, q.tie.0);
    let uy = Vec4::select(unit, wy / w_len, q.tie.1);
    let c = r * inv - w_len;
    let leg = (dist_sq - r_sq).sqrt();
    let left_x = (rx * leg - ry * r) / dist_sq;
    let left_y = (rx * r + ry * leg) / dist_sq;
    let right_x = -(rx * leg + ry * r) / dist_sq;
    let right_y = -(-rx * r + ry * leg) / dist_sq;
    let to_left = (rx * wy - ry * wx).cmpgt(Vec4::ZERO) & !q.keep_right;
    let lx = Vec4::select(to_left, left_x, right_x);
    let ly = Vec4::select(to_left, left_y, right_y);
    let d = vx * lx + vy * ly;
    let dx = Vec4::select(cut, uy, lx);
    let dy = Vec4::select(cut, -ux, ly);
    let u_x = Vec4::select(cut, ux * c, lx * d - vx);
    let u_y = Vec4::select(cut, uy * c, ly * d - vy);
    [
        Vec4::splat(v.x) + u_x * q.share,
        Vec4::splat(v.y) + u_y * q.share,
        dx,
        dy,
    ]
}

/// The half-plane that keeps an agent at signed distance `dist` from an
/// obstacle's surface (unit normal `n` from the obstacle to the agent) at
/// least `r` from it, a wall's tangent: `v·n ≥ −(dist − r)/τ`; inside
/// (`dist < r`), `v·n ≥ (r − dist)/dt`, out within one step.
#[inline]
#[must_use]
pub fn obstacle_line(n: Vec2, dist: f32, r: f32, horizon: f32, dt: f32) -> Line {
    let c = if dist >= r {
        -(dist - r) / horizon
    } else {
        (r - dist) / dt
    };
    Line {
        point: n * c,
        direction: Vec2::new(n.y, -n.x),
    }
}

/// Linear program on line `i`: the point of line `i` admitted by lines
/// `0..i` and the disc of radius `radius` that is nearest `opt` (or
/// farthest along `opt` when `direction_opt`). `None` if there is none.
///
/// RVO2's loop over the lines before `i`, four at a time: each line's
/// bound on the parameter along line `i` is computed lane by lane, and the
/// bounds are folded into the interval in the lines' order (the same
/// min/max sequence, so the same bits; a line that bounds nothing folds
/// in ±∞, which changes no finite bound). The early `None` of a line that
/// empties the interval is taken at the end instead: the interval only
/// shrinks, so it is empty at the end if it ever was.
fn lp1(lines: &Lines, i: usize, radius: f32, opt: Vec2, direction_opt: bool) -> Option<Vec2> {
    let li = lines.get(i);
    let (mut t_left, mut t_right) = disc_interval(li, radius)?;
    let (ldx, ldy) = (Vec4::splat(li.direction.x), Vec4::splat(li.direction.y));
    let (lpx, lpy) = (Vec4::splat(li.point.x), Vec4::splat(li.point.y));
    let mut at = 0;
    while at < i {
        let [px, py, dx, dy] = lines.four(at);
        // det(li.direction, lj.direction), det(lj.direction, li.point − lj.point).
        let denom = ldx * dy - ldy * dx;
        let numer = dx * (lpy - py) - dy * (lpx - px);
        let parallel = denom.abs().cmple(Vec4::splat(EPS));
        let lanes = lane_mask(0, i - at);
        if (parallel & numer.cmplt(Vec4::ZERO)).bitmask() & lanes != 0 {
            return None;
        }
        let t = numer / denom;
        let right = denom.cmpge(Vec4::ZERO);
        // Lanes past line i − 1 fold in ±∞ too: all four folded, always
        // (no loop whose length varies, mispredicted at its end).
        let bounds = !parallel & lanes_below(i - at);
        let t_r = Vec4::select(bounds & right, t, Vec4::INFINITY).to_array();
        let t_l = Vec4::select(bounds & !right, t, Vec4::NEG_INFINITY).to_array();
        for k in 0..4 {
            t_right = t_right.min(t_r[k]);
            t_left = t_left.max(t_l[k]);
        }
        at += 4;
    }
    if t_left > t_right {
        return None;
    }
    Some(pick_on_line(li, opt, direction_opt, t_left, t_right))
}

/// The parameter interval of line `li` inside the disc of radius `radius`
/// (`None`: the line misses it); [`lp1`]'s start.
#[inline]
fn disc_interval(li: Line, radius: f32) -> Option<(f32, f32)> {
    let dot = li.point.dot(li.direction);
    let disc = dot * dot + radius * radius - li.point.length_squared();
    if disc < 0.0 {
        return None;
    }
    let sq = disc.sqrt();
    Some((-dot - sq, -dot + sq))
}

/// [`lp1`]'s answer on line `li` within `[t_left, t_right]`: the end
/// farthest along `opt` when `direction_opt`, else the point nearest `opt`.
#[inline]
fn pick_on_line(li: Line, opt: Vec2, direction_opt: bool, t_left: f32, t_right: f32) -> Vec2 {
    let t = if direction_opt {
        if opt.dot(li.direction) > 0.0 {
            t_right
        } else {
            t_left
        }
    } else {
        li.direction.dot(opt - li.point).clamp(t_left, t_right)
    };
    li.point + li.direction * t
}

/// [`lp2`]'s first guess: `opt` scaled to the disc when `direction_opt`,
/// else `opt` brought inside it.
#[inline]
fn lp2_start(opt: Vec2, radius: f32, direction_opt: bool) -> Vec2 {
    if direction_opt {
        opt * radius
    } else if opt.length_squared() > radius * radius {
        opt.normalize_or_zero() * radius
    } else {
        opt
    }
}

/// A 2D linear program as [`lp2`] (the tests pass the scalar reference
/// to [`solve_with`]).
type Lp2 = fn(&Lines, f32, Vec2, bool) -> (Vec2, usize);

/// Linear program in 2D: the velocity in the disc nearest `opt` that every
/// line admits. Returns `(result, n)`: `n == lines.len()` on success, else
/// the index of the first line that could not be met (`result` then meets
/// lines `0..n`). The lines the result already meets are skipped four at
/// a time ([`Lines::first_violated`]).
fn lp2(lines: &Lines, radius: f32, opt: Vec2, direction_opt: bool) -> (Vec2, usize) {
    let mut result = lp2_start(opt, radius, direction_opt);
    let mut from = 0;
    while let Some(i) = lines.first_violated(from, result) {
        match lp1(lines, i, radius, opt, direction_opt) {
            Some(r) => result = r,
            None => return (result, i),
        }
        from = i + 1;
    }
    (result, lines.len())
}

/// Linear program in 3D, when the 2D one is infeasible: keeps the obstacle
/// lines (the first `n_obstacles`) and minimises the largest violation of
/// the others, from line `begin` on.
fn lp3(lines: &Lines, n_obstacles: usize, begin: usize, radius: f32, result: &mut Vec2, lp2: Lp2) {
    let mut distance = 0.0f32;
    let mut proj = Lines::default();
    for i in begin..lines.len() {
        let li = lines.get(i);
        if det(li.direction, li.point - *result) > distance {
            proj.clear();
            for j in 0..n_obstacles {
                proj.push_agent(lines.get(j));
            }
            for j in n_obstacles..i {
                let lj = lines.get(j);
                let d = det(li.direction, lj.direction);
                let point = if d.abs() <= EPS {
                    if li.direction.dot(lj.direction) > 0.0 {
                        continue; // parallel, same direction
                    }
                    (li.point + lj.point) * 0.5
                } else {
                    li.point + li.direction * (det(lj.direction, li.point - lj.point) / d)
                };
                let direction = (lj.direction - li.direction).normalize_or_zero();
                proj.push_agent(Line { point, direction });
            }
            let temp = *result;
            let (r, k) = lp2(
                &proj,
                radius,
                Vec2::new(-li.direction.y, li.direction.x),
                true,
            );
            *result = if k < proj.len() { temp } else { r };
            distance = det(li.direction, li.point - *result);
        }
    }
}

/// The ORCA velocity: nearest `preferred` within speed `max_speed` that
/// every line of `lines` admits; if none does, the obstacle lines are kept
/// and the largest violation of the agents' is minimised.
#[must_use]
pub fn solve(lines: &Lines, max_speed: f32, preferred: Vec2) -> Vec2 {
    solve_with(lines, max_speed, preferred, lp2)
}

/// [`solve`] with the 2D linear program `lp2`.
#[inline]
fn solve_with(lines: &Lines, max_speed: f32, preferred: Vec2, lp2: Lp2) -> Vec2 {
    let (mut result, k) = lp2(lines, max_speed, preferred, false);
    if k < lines.obstacles {
        // The obstacles' own half-planes have no common point (an agent
        // wedged in a corner deeper than its radius): all become soft.
        lp3(lines, 0, k, max_speed, &mut result, lp2);
    } else if k < lines.len() {
        lp3(lines, lines.obstacles, k, max_speed, &mut result, lp2);
    }
    result
}

/// The largest speed along the unit direction `u`, up to `cap`, that the
/// upper bounds of every line admit (the lower ones, a neighbour closing
/// from behind, are that neighbour's to meet): four lines at a time, each
/// bounding line's cap `det(d, p) / det(d, u)` (`det(d, u) < −1e-6`) lane
/// by lane, folded into the minimum in the lines' order. A line that does
/// not bound the ray folds in −∞ / −1 = +∞.
#[must_use]
pub fn ray_cap(lines: &Lines, u: Vec2, cap: f32) -> f32 {
    let (ux, uy) = (Vec4::splat(u.x), Vec4::splat(u.y));
    let mut hi = cap;
    let mut at = 0;
    while at < lines.len() {
        let [px, py, dx, dy] = lines.four(at);
        let a = dx * uy - dy * ux;
        let b = dx * py - dy * px;
        // Lanes past the last line bound nothing either: all four folded,
        // always.
        let bounds = a.cmplt(Vec4::splat(-1e-6)) & lanes_below(lines.len() - at);
        let q = (Vec4::select(bounds, b, Vec4::NEG_INFINITY)
            / Vec4::select(bounds, a, Vec4::NEG_ONE))
        .to_array();
        for x in q {
            hi = hi.min(x);
        }
        at += 4;
    }
    hi.max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 2D linear program and ray cap in their scalar form (one line
    /// at a time, branches, as RVO2 writes them): the reference the
    /// four-lane ones must match bit for bit. Their start and end
    /// ([`disc_interval`], [`pick_on_line`], [`lp2_start`]) and the 3D
    /// program round them ([`solve_with`]) are shared, not under test.
    mod reference {
        use super::super::{
            det, disc_interval, lp2_start, pick_on_line, solve_with, Line, Lines, EPS,
        };
        use glam::Vec2;

        /// Linear program on line `i`, one line before it at a time.
        fn lp1(
            lines: &Lines,
            i: usize,
            radius: f32,
            opt: Vec2,
            direction_opt: bool,
        ) -> Option<Vec2> {
            let li = lines.get(i);
            let (mut t_left, mut t_right) = disc_interval(li, radius)?;
            for j in 0..i {
                let lj = lines.get(j);
                let denom = det(li.direction, lj.direction);
                let numer = det(lj.direction, li.point - lj.point);
                if denom.abs() <= EPS {
                    if numer < 0.0 {
                        return None;
                    }
                    continue;
                }
                let t = numer / denom;
                if denom >= 0.0 {
                    t_right = t_right.min(t);
                } else {
                    t_left = t_left.max(t);
                }
                if t_left > t_right {
                    return None;
                }
            }
            Some(pick_on_line(li, opt, direction_opt, t_left, t_right))
        }

        /// Linear program in 2D, every line tested in turn.
        fn lp2(lines: &Lines, radius: f32, opt: Vec2, direction_opt: bool) -> (Vec2, usize) {
            let mut result = lp2_start(opt, radius, direction_opt);
            for i in 0..lines.len() {
                let li = lines.get(i);
                if det(li.direction, li.point - result) > 0.0 {
                    match lp1(lines, i, radius, opt, direction_opt) {
                        Some(r) => result = r,
                        None => return (result, i),
                    }
                }
            }
            (result, lines.len())
        }

        /// `solve` with the scalar 2D program inside the same 3D one.
        pub fn solve_ref(lines: &Lines, max_speed: f32, preferred: Vec2) -> Vec2 {
            solve_with(lines, max_speed, preferred, lp2)
        }

        /// The scalar ray cap.
        pub fn ray_cap_ref(ls: &[Line], u: Vec2, cap: f32) -> f32 {
            let mut hi = cap;
            for l in ls {
                let a = l.direction.x * u.y - l.direction.y * u.x;
                let b = l.direction.x * l.point.y - l.direction.y * l.point.x;
                let bounds = a < -1e-6;
                let q = if bounds { b } else { f32::NEG_INFINITY } / if bounds { a } else { -1.0 };
                hi = hi.min(q);
            }
            hi.max(0.0)
        }
    }

    /// The four-lane lines are the scalar ones, bit for bit: seeded
    /// pairs far, near, overlapping and coincident, with and without
    /// keeping right.
    #[test]
    fn four_lanes_give_the_scalar_lines_bit_for_bit() {
        let mut rng = crate::base::rng::Rng::new(18);
        let (horizon, dt) = (2.0f32, 0.1f32);
        for trial in 0..20_000 {
            let p = Vec2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
            let v = Vec2::new(rng.range(-1.5, 1.5), rng.range(-1.5, 1.5));
            let mut lanes = [(Vec2::ZERO, Vec2::ZERO, 0.0, 0.0, Vec2::ZERO, false); 4];
            for (l, lane) in lanes.iter_mut().enumerate() {
                let spread = [3.0, 1.0, 0.5, 0.0][(trial + l) % 4];
                let pn = p + Vec2::new(rng.range(-spread, spread), rng.range(-spread, spread));
                let vn = if rng.range(0.0, 1.0) < 0.2 {
                    v
                } else {
                    Vec2::new(rng.range(-1.5, 1.5), rng.range(-1.5, 1.5))
                };
                let r = [0.6, 0.9][l % 2];
                let share = [0.5, 1.0][(trial / 2 + l) % 2];
                let tie = if rng.range(0.0, 1.0) < 0.5 {
                    Vec2::Y
                } else {
                    -Vec2::Y
                };
                *lane = (pn, vn, r, share, tie, rng.range(0.0, 1.0) < 0.3);
            }
            let col = |f: &dyn Fn(usize) -> f32| Vec4::new(f(0), f(1), f(2), f(3));
            let q = Pairs4 {
                pn: (col(&|l| lanes[l].0.x), col(&|l| lanes[l].0.y)),
                vn: (col(&|l| lanes[l].1.x), col(&|l| lanes[l].1.y)),
                r: col(&|l| lanes[l].2),
                share: col(&|l| lanes[l].3),
                tie: (col(&|l| lanes[l].4.x), col(&|l| lanes[l].4.y)),
                keep_right: BVec4A::new(lanes[0].5, lanes[1].5, lanes[2].5, lanes[3].5),
            };
            let got = agent_lines4(p, v, &q, 1.0 / horizon, 1.0 / dt).map(|x| x.to_array());
            for (l, &(pn, vn, r, share, tie, keep)) in lanes.iter().enumerate() {
                let want = agent_line(p, v, pn, vn, r, horizon, dt, share, tie, keep);
                let bits = |x: f32| x.to_bits();
                assert_eq!(
                    [got[0][l], got[1][l], got[2][l], got[3][l]].map(bits),
                    [
                        want.point.x,
                        want.point.y,
                        want.direction.x,
                        want.direction.y
                    ]
                    .map(bits),
                    "trial {trial} lane {l}"
                );
            }
        }
    }

    /// The linear programs and the ray cap, four lines at a time, give the
    /// scalar reference's bits: seeded line sets of every size, with obstacle
    /// lines, feasible and not (the 3D program too), parallel lines
    /// included.
    #[test]
    fn four_line_programs_give_the_former_bits() {
        let mut rng = crate::base::rng::Rng::new(3);
        let mut lp3_runs = 0;
        for trial in 0..30_000 {
            let n_obs = [0, 0, 1, 3][trial % 4];
            let n = n_obs + (trial / 4) % (MAX_NEIGHBOURS + 1);
            let mut set = Lines::default();
            let mut flat = Vec::new();
            for k in 0..n {
                let a = rng.range(-3.2, 3.2);
                // Some directions repeated exactly (parallel lines).
                let a = if k > 0 && rng.range(0.0, 1.0) < 0.1 {
                    flat.last()
                        .map_or(a, |l: &Line| l.direction.y.atan2(l.direction.x))
                } else {
                    a
                };
                let l = Line {
                    point: Vec2::new(rng.range(-1.5, 1.5), rng.range(-1.5, 1.5)),
                    direction: Vec2::new(a.cos(), a.sin()),
                };
                if k < n_obs {
                    set.push_obstacle(l);
                } else {
                    set.push_agent(l);
                }
                flat.push(l);
            }
            let pref = Vec2::new(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
            let cap = rng.range(0.5, 2.0);
            let got = solve(&set, cap, pref);
            let want = reference::solve_ref(&set, cap, pref);
            assert_eq!(
                (got.x.to_bits(), got.y.to_bits()),
                (want.x.to_bits(), want.y.to_bits()),
                "trial {trial}: {got} vs {want}"
            );
            if !set.admits(got, 1e-4) {
                lp3_runs += 1;
            }
            let u = Vec2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)).normalize_or_zero();
            assert_eq!(
                ray_cap(&set, u, cap).to_bits(),
                reference::ray_cap_ref(&flat, u, cap).to_bits(),
                "trial {trial}"
            );
        }
        assert!(lp3_runs > 1000, "{lp3_runs} infeasible sets");
    }

    #[test]
    fn no_lines_gives_the_preferred_velocity_within_the_disc() {
        let l = Lines::default();
        assert_eq!(solve(&l, 2.0, Vec2::new(1.0, 0.5)), Vec2::new(1.0, 0.5));
        let v = solve(&l, 1.0, Vec2::new(3.0, 4.0));
        assert!((v - Vec2::new(0.6, 0.8)).length() < 1e-6);
    }

    #[test]
    fn head_on_agents_turn_aside_and_their_choices_do_not_collide() {
        // Two agents 4 m apart, face to face at 1 m/s: each keeps out of
        // the other's velocity obstacle with half the avoidance.
        let (pa, pb) = (Vec2::ZERO, Vec2::new(4.0, 0.01));
        let (va, vb) = (Vec2::X, -Vec2::X);
        let mut la = Lines::default();
        la.push_agent(agent_line(
            pa,
            va,
            pb,
            vb,
            0.6,
            5.0,
            0.1,
            0.5,
            Vec2::Y,
            false,
        ));
        let mut lb = Lines::default();
        lb.push_agent(agent_line(
            pb,
            vb,
            pa,
            va,
            0.6,
            5.0,
            0.1,
            0.5,
            -Vec2::Y,
            false,
        ));
        let na = solve(&la, 2.0, va);
        let nb = solve(&lb, 2.0, vb);
        assert!(na.y.abs() > 0.01 && nb.y.abs() > 0.01, "{na} {nb}");
        // Relative motion over the horizon stays clear of the 0.6 m disc.
        let rel_p = pb - pa;
        let rel_v = nb - na;
        let mut min = f32::MAX;
        for k in 0..=500 {
            let t = k as f32 * 0.01;
            min = min.min((rel_p + rel_v * t).length());
        }
        assert!(min >= 0.6 - 1e-3, "closest {min}");
    }

    #[test]
    fn a_wall_line_stops_the_approach_but_allows_sliding() {
        // Wall along y = 0, agent at y = 0.5, radius 0.3, horizon 1 s.
        let p = Vec2::new(0.0, 0.5);
        let l = obstacle_line(Vec2::Y, p.y, 0.3, 1.0, 0.1);
        let mut ls = Lines::default();
        ls.push_obstacle(l);
        let v = solve(&ls, 2.0, Vec2::new(1.0, -1.0));
        assert!(
            (v.y - (-0.2)).abs() < 1e-5 && (v.x - 1.0).abs() < 1e-5,
            "{v}"
        );
    }

    #[test]
    fn infeasible_agents_keep_the_obstacles() {
        let p = Vec2::ZERO;
        let mut ls = Lines::default();
        ls.push_obstacle(obstacle_line(Vec2::Y, 0.4, 0.3, 1.0, 0.1));
        // Neighbours overlapping from both sides along x.
        ls.push_agent(agent_line(
            p,
            Vec2::ZERO,
            Vec2::new(0.3, 0.0),
            Vec2::ZERO,
            0.6,
            2.0,
            0.1,
            0.5,
            Vec2::Y,
            false,
        ));
        ls.push_agent(agent_line(
            p,
            Vec2::ZERO,
            Vec2::new(-0.3, 0.0),
            Vec2::ZERO,
            0.6,
            2.0,
            0.1,
            0.5,
            Vec2::Y,
            false,
        ));
        let v = solve(&ls, 2.0, Vec2::X);
        assert!(v.is_finite());
        assert!(ls.get(0).admits(v, 1e-4), "{v}");
    }
}
