//! ORCA's meaning, against the closed form of van den Berg, Guy, Lin and
//! Manocha, "Reciprocal n-body collision avoidance" (ISRR 2011), §4–5:
//!
//! - the velocity obstacle of A induced by B for time horizon τ is the
//!   truncated cone `VO = {v | ∃ t ∈ [0, τ]: t·v ∈ D(p_B − p_A, r_A + r_B)}`:
//!   apex 0, legs tangent to the disc `D((p_B − p_A)/τ, (r_A + r_B)/τ)`,
//!   cut off by that disc's near arc;
//! - `u` is the vector from the relative velocity `v_A − v_B` to the
//!   nearest point of VO's boundary, `n` the boundary's outward normal
//!   there, and `ORCA_A|B = {v | (v − (v_A + ½u))·n ≥ 0}`: each agent takes
//!   half the avoidance;
//! - the new velocity is the one nearest the preferred velocity in the
//!   ORCA half-planes and the speed disc (§5, a linear program).
//!
//! The closed form here is derived from that geometry (nearest point on
//! the arc or on either leg, whichever is nearest), not from the code's
//! case selection. Checked first on the half-planes of
//! `avoidance/orca.rs` (`agent_line`, `agent_lines4`, `obstacle_line`),
//! then on what the avoider commands for two agents and for one agent at
//! a wall with the default settings: a change of the time horizon, of the
//! reciprocal share or of the obstacle horizon moves a line and fails here
//! (a corridor tally could absorb it).

use glam::{BVec4A, Vec2, Vec4};
use steering::avoidance::avoider::Avoider;
use steering::avoidance::config::{AvoidanceConfig, AvoidanceMethod, Obstacle};
use steering::avoidance::orca::{agent_line, agent_lines4, obstacle_line, Line, Pairs4};
use steering::base::trig;
use steering::base::vehicle::{VehicleParams, VehicleState};

/// Rotates `v` by `a` rad counter-clockwise.
fn rot(v: Vec2, a: f32) -> Vec2 {
    Vec2::from_angle(a).rotate(v)
}

/// Which part of VO's boundary is nearest.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Part {
    /// The cut-off arc (or, overlapping, the one-step disc).
    Arc,
    /// The leg counter-clockwise of the cone's axis.
    LeftLeg,
    /// The leg clockwise of it.
    RightLeg,
}

/// The closed form: `(u, n, part)` for relative position `p = p_B − p_A`,
/// relative velocity `x = v_A − v_B`, combined radius `r`, horizon `tau`,
/// step `dt` (overlapping agents, `|p| < r`: the disc `D(p/dt, r/dt)`,
/// leave within one step, as RVO2 does).
fn closed_form(p: Vec2, x: Vec2, r: f32, tau: f32, dt: f32) -> (Vec2, Vec2, Part) {
    let on_circle = |c: Vec2, rho: f32| {
        let e = (x - c).normalize();
        (c + e * rho - x, e)
    };
    if p.length() < r {
        let (u, n) = on_circle(p / dt, r / dt);
        return (u, n, Part::Arc);
    }
    let (c, rho) = (p / tau, r / tau);
    let axis = c.normalize();
    let half = (rho / c.length()).asin();
    let tangent = (c.length_squared() - rho * rho).sqrt();
    let mut best: Option<(f32, Vec2, Vec2, Part)> = None;
    let mut offer = |q: Vec2, n: Vec2, part: Part| {
        let d = (q - x).length();
        if best.is_none_or(|b| d < b.0) {
            best = Some((d, q - x, n, part));
        }
    };
    // The arc: the circle's points nearer the apex than the tangent points
    // (their projection on the axis is at most `tangent²/|c|`).
    let (u, e) = on_circle(c, rho);
    if (x + u).dot(axis) <= tangent * tangent / c.length() {
        offer(x + u, e, Part::Arc);
    }
    // The legs: rays from the tangent points outwards; normals away from
    // the axis.
    for (side, part) in [(1.0f32, Part::LeftLeg), (-1.0, Part::RightLeg)] {
        let l = rot(axis, side * half);
        let q = l * x.dot(l).max(tangent);
        offer(q, rot(l, side * core::f32::consts::FRAC_PI_2), part);
    }
    let (_, u, n, part) = best.expect("three candidates");
    (u, n, part)
}

/// The ORCA half-plane of A as a directed line (admissible on its left):
/// through `v_A + share·u`, along `n` turned a quarter clockwise.
fn orca_line(v_a: Vec2, u: Vec2, n: Vec2, share: f32) -> Line {
    Line {
        point: v_a + u * share,
        direction: Vec2::new(n.y, -n.x),
    }
}

fn assert_line(got: Line, want: Line, what: &str) {
    // f32 arithmetic in another order: a few ulps of the point's size.
    let tol = 2e-5 * want.point.length().max(1.0);
    let ok =
        (got.point - want.point).length() < tol && (got.direction - want.direction).length() < 2e-5;
    assert!(ok, "{what}: line {got:?}, closed form {want:?}");
}

/// Two-agent cases: (p_A, v_A, p_B, v_B), combined radius 0.9 m (two
/// bodies of 0.3 m with 0.15 m margins, the avoider's default pair).
fn cases() -> Vec<(Vec2, Vec2, Vec2, Vec2)> {
    let v = Vec2::new;
    vec![
        // Crossing, the collision in 1.1 s: inside VO, nearest a leg.
        (v(0.0, 0.0), v(1.3, 0.0), v(2.5, -2.0), v(0.0, 1.2)),
        // B ahead and slower, closing slowly: not within τ (outside VO,
        // between the apex and the cut-off arc), nearest the arc.
        (v(0.0, 0.0), v(1.0, 0.1), v(3.0, 0.0), v(0.6, 0.0)),
        // B ahead, coming slowly: inside the cut-off disc, nearest its arc.
        (v(0.0, 0.0), v(1.0, 0.05), v(3.0, 0.0), v(-0.2, 0.0)),
        // Head-on, B slightly to the left: inside, nearest the right leg.
        (v(0.0, 0.0), v(1.3, 0.0), v(4.0, 0.3), v(-1.3, 0.0)),
        // The mirror image: the left leg.
        (v(0.0, 0.0), v(1.3, 0.0), v(4.0, -0.3), v(-1.3, 0.0)),
        // Diverging: outside VO (u points inwards, the half-plane admits
        // v_A with room to spare).
        (v(0.0, 0.0), v(-1.0, 0.2), v(2.0, 1.0), v(0.5, 0.0)),
        // Overlapping (0.6 m apart, 0.9 m combined): leave in one step.
        (v(0.0, 0.0), v(0.5, 0.0), v(0.6, 0.0), v(0.0, 0.0)),
    ]
}

const R: f32 = 0.9;
const DT: f32 = 1.0 / 60.0;

#[test]
fn default_horizons_are_the_ones_the_closed_forms_below_use() {
    // The avoider's lines use the configured horizons; the closed forms of
    // the avoider's tests below are computed for these values.
    let c = AvoidanceConfig::default();
    assert_eq!((c.horizon, c.obstacle_horizon), (2.0, 1.0));
    assert_eq!((c.radius, c.margin), (0.3, 0.15));
}

#[test]
fn agent_half_plane_is_the_closed_form() {
    let tau = AvoidanceConfig::default().horizon;
    let mut parts = Vec::new();
    for (i, &(pa, va, pb, vb)) in cases().iter().enumerate() {
        let (u, n, part) = closed_form(pb - pa, va - vb, R, tau, DT);
        parts.push(part);
        for share in [0.5, 1.0] {
            let got = agent_line(pa, va, pb, vb, R, tau, DT, share, Vec2::Y, false);
            assert_line(
                got,
                orca_line(va, u, n, share),
                &format!("case {i} ({part:?}), share {share}"),
            );
        }
        // The half-plane's meaning: B keeping the mirror half-plane, any
        // pair of velocities on the two lines is collision-free for τ (the
        // relative velocity lands on VO's boundary: u added in full).
        let v_a = va + u * 0.5;
        let v_b = vb - u * 0.5;
        let rel = v_a - v_b;
        let (u2, _, _) = closed_form(pb - pa, rel, R, tau, DT);
        assert!(u2.length() < 1e-4, "case {i}: {u2}");
    }
    for want in [Part::Arc, Part::LeftLeg, Part::RightLeg] {
        assert!(parts.contains(&want), "{parts:?}");
    }
}

#[test]
fn four_lanes_build_the_same_half_planes() {
    let tau = AvoidanceConfig::default().horizon;
    let cs = cases();
    for chunk in cs.chunks(4) {
        let (pa, va) = (chunk[0].0, chunk[0].1);
        let lane = |k: usize| chunk[k.min(chunk.len() - 1)];
        let pick = |f: &dyn Fn(usize) -> f32| Vec4::new(f(0), f(1), f(2), f(3));
        // The same agent A (each case's A is at the origin, but velocities
        // differ: lanes take A's velocity from the first case, so B's are
        // shifted to keep each case's relative velocity).
        let vb = |k: usize| lane(k).3 + (va - lane(k).1);
        let q = Pairs4 {
            pn: (pick(&|k| lane(k).2.x), pick(&|k| lane(k).2.y)),
            vn: (pick(&|k| vb(k).x), pick(&|k| vb(k).y)),
            r: Vec4::splat(R),
            share: Vec4::new(0.5, 1.0, 0.5, 1.0),
            tie: (Vec4::ZERO, Vec4::ONE),
            keep_right: BVec4A::FALSE,
        };
        let [px, py, dx, dy] = agent_lines4(pa, va, &q, 1.0 / tau, 1.0 / DT);
        for k in 0..chunk.len() {
            let (u, n, _) = closed_form(lane(k).2 - pa, va - vb(k), R, tau, DT);
            let share = q.share.to_array()[k];
            let got = Line {
                point: Vec2::new(px.to_array()[k], py.to_array()[k]),
                direction: Vec2::new(dx.to_array()[k], dy.to_array()[k]),
            };
            assert_line(got, orca_line(va, u, n, share), &format!("lane {k}"));
        }
    }
}

#[test]
fn obstacle_half_plane_keeps_the_radius_within_the_obstacle_horizon() {
    // A wall's tangent: v·n ≥ −(dist − r)/τ_o; inside, out within a step.
    let tau_o = AvoidanceConfig::default().obstacle_horizon;
    let n = Vec2::new(-0.6, 0.8);
    for (dist, want_c) in [(1.45, -(1.45 - 0.45) / tau_o), (0.3, (0.45 - 0.3) / DT)] {
        let l = obstacle_line(n, dist, 0.45, tau_o, DT);
        // The boundary: v·n = want_c, admissible side along n.
        assert!((l.point.dot(n) - want_c).abs() < 1e-5, "{l:?}");
        assert!(l.direction.dot(n).abs() < 1e-6);
        assert!(l.admits(n * (want_c + 0.1), 0.0) && !l.admits(n * (want_c - 0.1), 0.0));
    }
}

/// The 2D linear program for one half-plane and the speed disc, closed
/// form: `pref` if admitted, else its projection on the line, or where the
/// line meets the disc nearest that projection.
fn lp_one_line(l: Line, cap: f32, pref: Vec2) -> Vec2 {
    if l.admits(pref, 0.0) && pref.length() <= cap {
        return pref;
    }
    let t = (pref - l.point).dot(l.direction);
    let q = l.point + l.direction * t;
    if q.length() <= cap {
        return q;
    }
    let b = l.point.dot(l.direction);
    let disc = (b * b - l.point.length_squared() + cap * cap).sqrt();
    l.point + l.direction * t.clamp(-b - disc, -b + disc)
}

/// What the avoider's forward-only vehicle is told for ORCA velocity `v`:
/// its heading, and its projection on the present heading `f`, no more
/// than the line admits along `f` (`orca::ray_cap` for one line).
fn command_of(v: Vec2, f: Vec2, l: Line, cap: f32) -> (f32, f32) {
    let det = |a: Vec2, b: Vec2| a.x * b.y - a.y * b.x;
    let a = det(l.direction, f);
    let along = if a < -1e-6 {
        (det(l.direction, l.point) / a).min(cap).max(0.0)
    } else {
        cap
    };
    (v.y.atan2(v.x), v.dot(f).max(0.0).min(along))
}

fn orca_config() -> AvoidanceConfig {
    AvoidanceConfig {
        method: AvoidanceMethod::Orca,
        // Every agent plans every step (the default plans every other).
        replan_every: 1,
        ..AvoidanceConfig::default()
    }
}

#[test]
fn avoider_commands_the_orca_velocity_of_two_crossing_agents() {
    // Two agents crossing at right angles 2.6 m apart (within the 3 m
    // reach), each asking to go straight on at its speed; no priorities (no right of way, no keep-right rule),
    // no obstacles. Each takes half the avoidance: its command is the
    // closed-form ORCA velocity for the default horizon of 2 s.
    let p = VehicleParams::default();
    let cfg = orca_config();
    let states = [
        VehicleState::new(Vec2::new(0.0, 0.0), 0.0, 1.3, 0.0),
        VehicleState::new(Vec2::new(2.0, -1.6), core::f32::consts::FRAC_PI_2, 1.2, 0.0),
    ];
    let preferred = [(0.0, 1.3), (core::f32::consts::FRAC_PI_2, 1.2)];
    let mut av = Avoider::default();
    av.compute(&p, &cfg, &[], &states, &preferred);
    for (a, b) in [(0usize, 1usize), (1, 0)] {
        let (sa, sb) = (&states[a], &states[b]);
        let (va, vb) = (sa.forward() * sa.v, sb.forward() * sb.v);
        let (u, n, part) = closed_form(sb.pos - sa.pos, va - vb, R, 2.0, p.dt);
        let line = orca_line(va, u, n, 0.5);
        let pref = trig::unit(preferred[a].0) * preferred[a].1;
        assert!(
            !line.admits(pref, 0.0),
            "agent {a}: the preferred velocity collides"
        );
        let v = lp_one_line(line, preferred[a].1, pref);
        let (heading, speed) = command_of(v, sa.forward(), line, preferred[a].1);
        let c = av.commands[a];
        println!(
            "agent {a}: nearest {part:?}; u ({:.4}, {:.4}); ORCA velocity ({:.4}, {:.4}); command heading {:.4} rad, speed {:.4} m/s (closed form {heading:.4}, {speed:.4})",
            u.x, u.y, v.x, v.y, c.heading, c.speed
        );
        assert!(c.active, "agent {a}: {c:?}");
        assert!(
            (c.heading - heading).abs() < 1e-4 && (c.speed - speed).abs() < 1e-4,
            "agent {a}: command heading {} speed {}, closed form {heading} / {speed}",
            c.heading,
            c.speed
        );
    }
}

#[test]
fn avoider_keeps_an_agent_off_a_wall_within_the_obstacle_horizon() {
    // One agent 1 m from a wall, asking to walk into it at 30°: the
    // command is its preferred velocity projected on the wall's half-plane
    // v·n ≥ −(dist − r)/τ_o, τ_o the default 1 s, r = 0.3 + 0.15 m.
    let p = VehicleParams::default();
    let cfg = orca_config();
    let h = 30f32.to_radians();
    let states = [VehicleState::new(Vec2::ZERO, h, 1.3, 0.0)];
    let wall = Obstacle::Segment {
        x1: 1.0,
        y1: -5.0,
        x2: 1.0,
        y2: 5.0,
    };
    let mut av = Avoider::default();
    av.compute(&p, &cfg, &[wall], &states, &[(h, 1.3)]);
    let n = Vec2::new(-1.0, 0.0);
    let c0 = -(1.0 - 0.45) / 1.0;
    let line = Line {
        point: n * c0,
        direction: Vec2::new(n.y, -n.x),
    };
    let pref = trig::unit(h) * 1.3;
    let v = lp_one_line(line, 1.3, pref);
    assert!((v.x - 0.55).abs() < 1e-5, "{v}");
    let (heading, speed) = command_of(v, states[0].forward(), line, 1.3);
    let c = av.commands[0];
    println!(
        "wall: ORCA velocity ({:.4}, {:.4}); command heading {:.4} rad, speed {:.4} m/s (closed form {heading:.4}, {speed:.4})",
        v.x, v.y, c.heading, c.speed
    );
    assert!(c.active && c.walls, "{c:?}");
    assert!(
        (c.heading - heading).abs() < 1e-4 && (c.speed - speed).abs() < 1e-4,
        "command heading {} speed {}, closed form {heading} / {speed}",
        c.heading,
        c.speed
    );
}
