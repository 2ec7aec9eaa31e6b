// The funnelling step on the GPU: one invocation updates one agent exactly
// as the core's default world step does (crate/world/world.rs `step_agent`
// with `FunnelConfig::plan_ours` and `seek_step_committed_unicycle`: our
// standard controller on a unicycle, avoidance off, static goals). Every
// function below names the core function it mirrors; the core stays the
// reference (docs/DESIGN.md §20), and web/test/e2e-gpu.mjs checks this file
// against it. The contract: the same operations in f32, in the same order
// where WGSL lets us say it, but a GPU may fuse a multiply-add, sums the 32
// blend corners in its own order and has its own sin/cos below (the core's
// are f64), so results agree to tolerances, not to the bit: one step from
// the same state gives the same mode for >= 99.9 % of agents, positions
// within 1e-4 m and headings within 1e-4 rad; a table read is within 1e-5
// rad of the core's lookup.
//
// Near a static goal a unicycle is approached as the core's short-range
// choice says (crate/funnelling/short_range.rs): funnelling, funnelling
// at a capped speed, or turning first round one side of the disk. The
// choice itself (short_range::decide, which simulates the ways in) stays
// on the CPU: the core makes it for each agent's current goal when the
// world is packed (crate/world/gpu_world.rs), and when this kernel moves
// an agent on to its next goal it marks the choice awaited (flags bit 1);
// the host makes it from the state after that step (Lab.gpuDecide,
// GpuWorld::decide_pending) and uploads it before the next one. A choice
// still awaited when the agent is planned is taken as plain funnelling.
// Every update then follows the choice here (plan_with, turn_first).

const PI: f32 = 3.14159265358979323846;
const TAU: f32 = 6.28318530717958647692;
const HALF_PI: f32 = 1.57079632679489661923;
// crate/funnelling/seek.rs TURN_COMMIT_WINDOW.
const COMMIT_WINDOW: f32 = 10.0 * PI / 180.0;
// Records: crate/world/state_field.rs STATE_STRIDE and its field order.
const STRIDE: u32 = 19u;

// Modes: crate/funnelling/update.rs Mode.
const END_OF_STEERING: u32 = 0u;
const ORIENTATION_ONLY: u32 = 1u;
const POSITION_ONLY: u32 = 2u;
const FUNNELLING: u32 = 3u;

// crate/world/gpu_world.rs GpuWorld (14 words): flags bit 0 the position
// met, bit 1 the short-range choice awaited from the host.
struct Agent {
  x: f32, y: f32, theta: f32, v: f32, omega: f32,
  flags: u32, current: u32, first: u32, count: u32, oriented: u32, mode: u32,
  // Table reads counted over the steps (`counted`).
  pad: u32,
  // goal.rs ShortRange for the current goal: the speed cap (0: none) and
  // the side turned round (0: funnelling).
  cap: f32, side: i32,
}

const MET = 1u;
const PENDING = 2u;

// crate/world/gpu_world.rs GpuWorld (8 words): flags bit 0 halting, bit 1
// the End_of_Steering switch rule.
struct Goal { x: f32, y: f32, beta: f32, d_tol: f32, eps_tol: f32, speed: f32, flags: u32, pad: u32 }

struct Frame { n: u32, records: u32, ring: u32, pad: u32 }

// The settings' indices (crate/world/gpu_world.rs GpuWorld::settings).
const DT = 0u; const V_MAX = 1u; const ACCEL = 2u; const OMEGA_MAX = 3u; const OMEGA_ACCEL = 4u;
const NORMAL_ACCEL = 5u; const KP = 6u; const KD = 7u; const SEMI_IMPLICIT = 8u; const GAIN = 9u;
const SEEK_THRESHOLD = 10u; const BOUND_FACTOR = 11u; const MIN_BOUND_RADIUS = 12u;
const LOOKAHEAD = 13u; const TERMINAL_HEADING = 14u; const TERMINAL_RANGE = 15u; const AIM_ENTRY = 16u;
const SCALE_LENGTH = 17u; const SCALE_SPEED = 18u; const SCALE_TIME = 19u; const REACH_RADIUS = 20u;
const D_ETA = 21u; const VD_MIN = 22u; const RELEASE = 23u;
// Avoidance (GpuWorld::avoidance_settings): separation on, the radius
// avoided with, reach², 1/reach, neighbours kept, the push's weight, the
// planning cadence, the buckets of the grid, the first step's number.
const SEPARATION = 24u; const SEP_R = 25u; const REACH2 = 26u; const INV_CELL = 27u; const K_MAX = 28u;
const SEP_WEIGHT = 29u; const REPLAN = 30u; const BUCKETS = 31u; const STEP0 = 32u;

@group(0) @binding(0) var<storage, read> settings: array<f32>;
@group(0) @binding(1) var<storage, read> tmeta: array<u32>;
@group(0) @binding(2) var<storage, read> axes: array<f32>;
@group(0) @binding(3) var<storage, read> cells: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> agents: array<Agent>;
@group(0) @binding(5) var<storage, read> goals: array<Goal>;
@group(0) @binding(6) var<storage, read_write> records: array<f32>;
@group(0) @binding(7) var<uniform> frame: Frame;

fn S(i: u32) -> f32 { return settings[i]; }

// What this invocation read from the table, counted for the cost report
// (kernel.ts countedCost): one per blend of 32 cells, 65536 per axis
// located; added to the agent's last word each step.
var<private> counted: u32;

// ---- angles and trigonometry (crate/base/angle.rs, crate/base/trig.rs)

// angle::wrap: into (-π, π], one exact subtraction for one turn off.
fn wrap(a: f32) -> f32 {
  if (a > -PI && a <= PI) { return a; }
  var b = a + TAU;
  if (a > PI) { b = a - TAU; }
  if (b > -PI && b <= PI) { return b; }
  let s = a + PI;
  let r = s - TAU * floor(s / TAU) - PI;
  if (r <= -PI) { return r + TAU; }
  return r;
}

// trig::atan2: the same polynomial, the same f32 operations.
fn atan2c(y: f32, x: f32) -> f32 {
  let ax = abs(x);
  let ay = abs(y);
  let steep = ay > ax;
  let n = select(ay, ax, steep);
  let d = select(ax, ay, steep);
  if (d == 0.0) { return 0.0; }
  let t = n / d;
  let u = t * t;
  let u2 = u * u;
  let u4 = u2 * u2;
  let p = (0.99999934 + -0.3332986 * u) + u2 * (0.1994656 + -0.13908604 * u);
  let q = (0.09642133 + -0.055911474 * u) + u2 * (0.021862382 + -0.004054412 * u);
  var a = t * (p + u4 * q);
  if (steep) { a = HALF_PI - a; }
  if (x < 0.0) { a = PI - a; }
  if (y < 0.0) { a = -a; }
  return a;
}

// trig::sin_cos, in f32 (WGSL has no f64, and its own sin/cos may be off
// by 2^-11): the nearest quadrant, a three-part Cody-Waite reduction by
// π/2 and minimax polynomials on |r| <= π/4, about 1e-7 absolute for the
// angles a step meets. Returns (sin, cos).
fn sincos(x: f32) -> vec2<f32> {
  let k = round(x * 0.636619772367581343);
  let r = ((x - k * 1.5703125) - k * 4.837512969970703125e-4) - k * 7.54978995489188216e-8;
  let z = r * r;
  let s = r + r * z * (-1.6666654611e-1 + z * (8.3321608736e-3 + z * -1.9515295891e-4));
  let c = 1.0 - 0.5 * z + z * z * (4.166664568298827e-2 + z * (-1.388731625493765e-3 + z * 2.443315711809948e-5));
  let q = u32(i32(k)) & 3u;
  if (q == 0u) { return vec2<f32>(s, c); }
  if (q == 1u) { return vec2<f32>(c, -s); }
  if (q == 2u) { return vec2<f32>(-s, -c); }
  return vec2<f32>(-c, s);
}

// ---- the vehicle (crate/base/vehicle.rs, unicycle: r_min = 0)

// VehicleParams::omega_limit.
fn omega_limit(v: f32) -> f32 {
  if (v * S(OMEGA_MAX) > S(NORMAL_ACCEL)) { return S(NORMAL_ACCEL) / v; }
  return S(OMEGA_MAX);
}

// VehicleParams::speed_limit.
fn speed_limit(omega: f32) -> f32 {
  let w = abs(omega);
  if (w * S(V_MAX) > S(NORMAL_ACCEL)) { return S(NORMAL_ACCEL) / w; }
  return S(V_MAX);
}

// VehicleParams::min_turn_radius.
fn min_turn_radius(v_in: f32) -> f32 {
  let v = clamp(v_in, 1e-3, S(V_MAX));
  return v / omega_limit(v);
}

// VehicleParams::integrate_unicycle (new_speeds_as, integrate_as): every
// limit clamped, then the explicit Euler pose (the speeds of the step's
// start, the paper's) or the semi-implicit one.
fn integrate(a: ptr<function, Agent>, ang_acc: f32, v_des: f32) {
  let dt = S(DT);
  let v0 = (*a).v;
  let w0 = (*a).omega;
  let acc = clamp(ang_acc, -S(OMEGA_ACCEL), S(OMEGA_ACCEL));
  let wl = omega_limit(v0);
  let w1 = clamp(w0 + acc * dt, -wl, wl);
  let dv = S(ACCEL) * dt;
  let vcap = speed_limit(w1);
  let v1 = max(min(clamp(v_des, v0 - dv, v0 + dv), vcap), 0.0);
  if (S(SEMI_IMPLICIT) == 0.0) {
    let u = sincos((*a).theta);
    (*a).x = (*a).x + u.y * (v0 * dt);
    (*a).y = (*a).y + u.x * (v0 * dt);
    (*a).theta = wrap((*a).theta + w0 * dt);
  } else {
    (*a).theta = wrap((*a).theta + w1 * dt);
    let u = sincos((*a).theta);
    (*a).x = (*a).x + u.y * (v1 * dt);
    (*a).y = (*a).y + u.x * (v1 * dt);
  }
  (*a).v = v1;
  (*a).omega = w1;
}

// seek::committed_error: keep the turn direction near the ±π seam.
fn committed_error(e: f32, omega: f32) -> f32 {
  if (abs(e) > PI - COMMIT_WINDOW && e * omega < 0.0) {
    return e + select(TAU, -TAU, omega < 0.0);
  }
  return e;
}

// seek::seek_step_committed_unicycle: the PD law on the committed error.
fn seek_committed(a: ptr<function, Agent>, heading: f32, speed: f32) {
  let e = committed_error(wrap(heading - (*a).theta), (*a).omega);
  integrate(a, S(KP) * e - S(KD) * (*a).omega, speed);
}

// ---- the η table (crate/funnelling/table/lookup.rs, grid.rs)

struct Pos { i0: u32, i1: u32, t: f32 }

// grid::Axis::locate_linear (and locate for the periodic α axis): the
// interval holding the clamped coordinate, found by a search over the
// samples (the core's bucket grid finds the same one: the samples not
// above it, less one), weighted with the core's reciprocal widths.
fn locate(k: u32, v_in: f32) -> Pos {
  counted += 65536u;
  let n = tmeta[k];
  let xo = tmeta[10u + k];
  let io = tmeta[15u + k];
  let m = tmeta[20u + k];
  let lo = axes[xo];
  let hi = axes[xo + m];
  var v = v_in;
  if (k == 1u && v < lo) { v = v + TAU; }
  var c = lo;
  if (v >= lo) { c = select(hi, v, v <= hi); }
  var a = 0u;
  var b = m;
  loop {
    if (a >= b) { break; }
    let mid = (a + b + 1u) / 2u;
    if (axes[xo + mid] <= c) { a = mid; } else { b = mid - 1u; }
  }
  let i = min(a, m - 1u);
  var t = 1.0;
  if (c < hi) { t = min((c - axes[xo + i]) * axes[io + i], 1.0); }
  var i1 = i + 1u;
  if (i1 == n) { i1 = 0u; }
  return Pos(i, i1, t);
}

// EtaTable::omega_fraction.
fn omega_fraction(omega: f32, v: f32) -> f32 {
  return omega / omega_limit(max(v, 0.0));
}

// EtaTable::blend over the 32 corners, of the blend cells (fallback =
// false: lookup.rs Cell::new) or of the stored fallback η's (Cell::fallback).
fn blend(at: array<Pos, 5>, fallback: bool) -> vec4<f32> {
  var p = at;
  counted += 1u;
  var acc = vec4<f32>(0.0);
  for (var corner = 0u; corner < 32u; corner++) {
    var idx = 0u;
    var w = 1.0;
    for (var k = 0u; k < 5u; k++) {
      let up = ((corner >> (4u - k)) & 1u) == 1u;
      idx += select(p[k].i0, p[k].i1, up) * tmeta[5u + k];
      w *= select(1.0 - p[k].t, p[k].t, up);
    }
    let e = cells[idx];
    var cell: vec4<f32>;
    if (fallback) {
      cell = select(vec4<f32>(0.0), vec4<f32>(e.x, e.y, 1.0, 0.0), e.z == 2.0);
    } else {
      cell = select(vec4<f32>(0.0, 0.0, 0.0, e.w), vec4<f32>(e.x, e.y, 1.0, 0.0), e.z == 1.0);
    }
    acc += cell * w;
  }
  return acc;
}

// EtaTable::eta_at: η of the reachable corners, else of the stored
// fallback η's; valid = false when neither has weight.
fn eta_at(p: array<Pos, 5>, b: vec4<f32>) -> vec2<f32> {
  if (b.z > 1e-6) { return vec2<f32>(atan2c(b.y, b.x), 1.0); }
  let fb = blend(p, true);
  if (fb.z > 1e-6) { return vec2<f32>(atan2c(fb.y, fb.x), 1.0); }
  return vec2<f32>(0.0, 0.0);
}

// lookup.rs Lookup: eta, reachable, v_dt, eta_valid.
struct Lk { eta: f32, reachable: bool, v_dt: f32, valid: bool }

// EtaTable::lookup: the weighted vote of reachability, the proactive
// fallback speed v_dt and η there (a second blend) when unreachable.
fn lookup(d: f32, alpha: f32, omega: f32, v_c: f32, v_d: f32) -> Lk {
  var p = array<Pos, 5>(
    locate(0u, d), locate(1u, wrap(alpha)), locate(2u, omega_fraction(omega, v_c)),
    locate(3u, v_c), locate(4u, v_d));
  let b = blend(p, false);
  if (b.z >= 0.5) {
    let e = eta_at(p, b);
    return Lk(e.x, true, v_d, e.y == 1.0);
  }
  let v_dt = max(min(b.z * v_d + b.w, v_d), 0.0);
  if (v_dt > 0.0) {
    p[4] = locate(4u, v_dt);
    let e = eta_at(p, blend(p, false));
    return Lk(e.x, false, v_dt, e.y == 1.0);
  }
  return Lk(0.0, false, v_dt, false);
}

// ---- one plan (crate/funnelling/funnel.rs, approach.rs, config.rs)

// update.rs Internals (those the records carry).
struct Out { mode: u32, d: f32, alpha: f32, eta: f32, delta_eta: f32, mu: f32, gamma: f32, reachable: f32, v_dt: f32 }

// approach::seen_from: distance, world bearing and α of a point.
fn seen(a: Agent, px: f32, py: f32) -> vec3<f32> {
  let rx = px - a.x;
  let ry = py - a.y;
  let d = sqrt(rx * rx + ry * ry);
  var bearing = a.theta;
  if (d > 1e-6) { bearing = atan2c(ry, rx); }
  return vec3<f32>(d, bearing, wrap(bearing - a.theta));
}

// approach::rest_rotation: the heading change while ω decays to rest.
fn rest_rotation(omega: f32) -> f32 {
  let w = abs(omega);
  let w1 = min(w, S(OMEGA_ACCEL) / S(KD));
  let turn = (w * w - w1 * w1) / (2.0 * S(OMEGA_ACCEL)) + w1 / S(KD) + 0.5 * w * S(DT);
  return select(turn, -turn, omega < 0.0);
}

// approach::tolerance_phase for a static goal (the latched phase):
// latches the position, and once met settles End_of_Steering or
// Orientation_only. Returns true when settled (`out` final).
fn tolerance_phase(a: Agent, g: Goal, met: ptr<function, bool>, d: f32, out: ptr<function, Out>) -> bool {
  let halting = (g.flags & 1u) == 1u;
  var entered = d < g.d_tol;
  if (halting) {
    // approach::braking_distance
    entered = d + (a.v * a.v / (2.0 * S(ACCEL)) + a.v * S(DT)) < g.d_tol;
  }
  if (entered) {
    *met = true;
  } else if (*met && d > 2.0 * g.d_tol + S(RELEASE)) {
    *met = false;
  }
  if (!*met) { return false; }
  let he = wrap(g.beta - a.theta);
  (*out).delta_eta = he;
  let oriented = abs(he) < g.eps_tol && (!halting || abs(wrap(he - rest_rotation(a.omega))) < g.eps_tol);
  if (oriented && !halting && d >= g.d_tol) {
    *met = false;
    return false;
  }
  if (oriented) {
    (*out).mode = END_OF_STEERING;
    (*out).gamma = a.theta;
    (*out).v_dt = select(g.speed, 0.0, halting);
  } else {
    (*out).mode = ORIENTATION_ONLY;
    (*out).gamma = g.beta;
    (*out).v_dt = 0.0;
  }
  return true;
}

// config::Terminal::look: the carrot distance.
fn carrot(a: Agent, g: Goal) -> f32 {
  return S(LOOKAHEAD) * S(SCALE_TIME) * max(max(a.v, g.speed), 0.5 * S(SCALE_SPEED));
}

// Approach::terminal: the line pursuit behind the disk along β. Returns
// true when it steers (`out` final).
fn terminal(a: Agent, g: Goal, bearing: f32, out: ptr<function, Out>) -> bool {
  let he = wrap(g.beta - a.theta);
  if (abs(he) >= S(TERMINAL_HEADING)) { return false; }
  let u = sincos(g.beta);
  let rx = a.x - g.x;
  let ry = a.y - g.y;
  let along = rx * u.y + ry * u.x;
  let lateral = rx * u.x - ry * u.y;
  let look = carrot(a, g);
  if (along >= 0.0 || -along - g.d_tol >= S(TERMINAL_RANGE) * look || abs(lateral) >= 0.5 * max(-along, g.d_tol)) {
    return false;
  }
  let b = seen(a, g.x + u.y * (along + look), g.y + u.x * (along + look)).y;
  (*out).mode = FUNNELLING;
  (*out).gamma = b;
  (*out).mu = wrap(b - bearing);
  (*out).delta_eta = he;
  return true;
}

// funnel::orbit_free_speed: the largest speed whose turning circle still
// passes through the aim point.
fn orbit_free_speed(d: f32, alpha: f32) -> f32 {
  let r = d / max(2.0 * abs(sincos(alpha).x), 1e-3);
  return min(S(OMEGA_MAX) * r, sqrt(S(NORMAL_ACCEL) * r));
}

// FunnelConfig::plan_begun (from plan_ours): Approach::begin (D, α, the
// halting cap, the tolerance phase; static goals need no lead and count no
// laps), then turning first round side `side` when the short-range choice
// says so (short_range::turn_first), else aim_and_funnel: the terminal
// pursuit, the entry aim, one lookup there (Approach::look), Δη,
// Position_only near or when no correction is needed, else the bounded
// modulation (Approach::funnel, config::mu_max with MuBound::TurningRadius,
// config::modulation).
fn plan(a: Agent, g: Goal, met: ptr<function, bool>, side: i32) -> Out {
  let c = seen(a, g.x, g.y);
  let halting = (g.flags & 1u) == 1u;
  var v_d = g.speed;
  if (halting) {
    // approach::halting_speed
    v_d = min(v_d, sqrt(2.0 * 0.8 * S(ACCEL) * max(c.x - 0.9 * g.d_tol, 0.0)));
  }
  var out = Out(FUNNELLING, c.x, c.z, 0.0, 0.0, 0.0, c.y, 1.0, v_d);
  if (tolerance_phase(a, g, met, c.x, &out)) { return out; }
  if (side != 0) { return turn_first(a, g, side, c.x, c.y, v_d, out); }
  if (S(TERMINAL_HEADING) >= 0.0 && terminal(a, g, c.y, &out)) { return out; }
  // Approach::seen_aim / entry_depth: the entry point d_tol − r_reach
  // before the centre along β, the centre itself for a small disk.
  var aim = c;
  let depth = max(g.d_tol - S(REACH_RADIUS), 0.0);
  if (S(AIM_ENTRY) == 1.0 && depth != 0.0) {
    let u = sincos(g.beta);
    aim = seen(a, g.x - u.y * depth, g.y - u.x * depth);
  }
  out.gamma = aim.y;
  // Approach::look
  let v_query = max(v_d, S(VD_MIN));
  let lk = lookup(aim.x, aim.z, a.omega, a.v, v_query);
  out.reachable = select(0.0, 1.0, lk.reachable);
  out.v_dt = select(lk.v_dt, v_d, lk.reachable);
  out.eta = lk.eta;
  out.delta_eta = wrap(g.beta - (a.theta + aim.z + lk.eta));
  if (aim.x < S(D_ETA)) {
    out.v_dt = min(out.v_dt, orbit_free_speed(aim.x, aim.z));
    out.mode = POSITION_ONLY;
    return out;
  }
  if (abs(out.delta_eta) < S(SEEK_THRESHOLD) * g.eps_tol || !lk.valid) {
    out.mode = POSITION_ONLY;
    return out;
  }
  let bound_floor = S(MIN_BOUND_RADIUS) * S(SCALE_LENGTH);
  let r = S(BOUND_FACTOR) * max(min_turn_radius(max(lk.v_dt, a.v)), bound_floor);
  let mu_max = min(atan2c(r, aim.x), HALF_PI);
  out.mode = FUNNELLING;
  out.mu = clamp(-S(GAIN) * out.delta_eta, -mu_max, mu_max);
  out.gamma = wrap(aim.y + out.mu);
  return out;
}

// ---- short range (crate/funnelling/short_range.rs)

// short_range::CLEARANCE, CORE, AIM_SHARE, GO_SHARE, WALK_ERR, COS_PI_8.
const SR_CLEARANCE: f32 = 0.3;
const SR_CORE: f32 = 0.6;
const SR_AIM_SHARE: f32 = 0.4;
const SR_GO_SHARE: f32 = 0.5;
const SR_WALK_ERR: f32 = 0.5;
const COS_PI_8: f32 = 0.9238795;
const FRAC_1_SQRT_2: f32 = 0.70710678118654752440;

// short_range::final_heading: a heading within AIM_SHARE·ε_tol of β whose
// ray passes within CORE·D_tol of the centre, the nearest to β; `y` is 1
// when there is one.
fn final_heading(a: Agent, g: Goal, d: f32) -> vec2<f32> {
  let core = SR_CORE * g.d_tol;
  if (d <= core) { return vec2<f32>(g.beta, 1.0); }
  let bearing = atan2c(g.y - a.y, g.x - a.x);
  let half = atan2c(core, sqrt(max(d * d - core * core, 0.0)));
  let h = wrap(bearing + clamp(wrap(g.beta - bearing), -half, half));
  return vec2<f32>(h, select(0.0, 1.0, abs(wrap(h - g.beta)) <= SR_AIM_SHARE * g.eps_tol));
}

// short_range::clear: the segment from a to b stays at least r from c.
fn clear_of(a: vec2<f32>, b: vec2<f32>, c: vec2<f32>, r: f32) -> bool {
  let ab = b - a;
  let ac = c - a;
  let t = clamp((ac.x * ab.x + ac.y * ab.y) / max(ab.x * ab.x + ab.y * ab.y, 1e-12), 0.0, 1.0);
  let q = a + ab * t - c;
  return sqrt(q.x * q.x + q.y * q.y) >= r;
}

// short_range::corner: of the octagon's corners (k·π/4, CORNERS), ordered
// from the one behind the disk round side `side` to the front, the first
// in sight; `z` is 1 when one is.
fn corner(a: Agent, g: Goal, u: vec2<f32>, side: f32, m: f32, d: f32) -> vec3<f32> {
  let n = vec2<f32>(-u.y, u.x) * side;
  let rho = (g.d_tol + m) / COS_PI_8;
  let r_clear = min(g.d_tol + 0.5 * m, 0.5 * (d + g.d_tol));
  let cs = array<vec2<f32>, 8>(
    vec2<f32>(1.0, 0.0), vec2<f32>(FRAC_1_SQRT_2, FRAC_1_SQRT_2), vec2<f32>(0.0, 1.0),
    vec2<f32>(-FRAC_1_SQRT_2, FRAC_1_SQRT_2), vec2<f32>(-1.0, 0.0), vec2<f32>(-FRAC_1_SQRT_2, -FRAC_1_SQRT_2),
    vec2<f32>(0.0, -1.0), vec2<f32>(FRAC_1_SQRT_2, -FRAC_1_SQRT_2));
  let pos = vec2<f32>(a.x, a.y);
  let centre = vec2<f32>(g.x, g.y);
  for (var k = 0u; k < 8u; k++) {
    let at = centre + (-u * cs[k].x + n * cs[k].y) * rho;
    if (clear_of(pos, at, centre, r_clear)) { return vec3<f32>(at, 1.0); }
  }
  return vec3<f32>(0.0, 0.0, 0.0);
}

// short_range::room_ahead, as the speed it allows (min(v, sqrt(2·0.8·A·room))
// in turn_first): `v` itself when the line ahead misses the disk.
fn room_speed(a: Agent, g: Goal, v: f32) -> f32 {
  let f = sincos(a.theta);
  let tx = g.x - a.x;
  let ty = g.y - a.y;
  let along = tx * f.y + ty * f.x;
  let off2 = (tx * tx + ty * ty) - along * along;
  let r2 = g.d_tol * g.d_tol;
  if (along <= 0.0 || off2 >= r2) { return v; }
  let room = max(along - sqrt(r2 - off2), 0.0);
  return min(v, sqrt(2.0 * 0.8 * S(ACCEL) * room));
}

// short_range::turn_first, once the tolerance phase has let the update
// through: the walk in along final_heading (the speed zero at GO_SHARE·ε_tol
// of heading error), else the walk round the disk to the corner in sight
// (away from the disk when none is), within braking distance of the disk
// ahead and zero at WALK_ERR of heading error; Orientation_only below a
// tenth of the desired speed, Position_only above.
fn turn_first(a: Agent, g: Goal, side: i32, d: f32, bearing: f32, v_d: f32, out_in: Out) -> Out {
  var out = out_in;
  let b = sincos(g.beta);
  let u = vec2<f32>(b.y, b.x);
  let fh = final_heading(a, g, d);
  var heading = fh.x;
  var v = 0.0;
  if (fh.y == 1.0) {
    let e = abs(wrap(heading - a.theta));
    v = v_d * max(1.0 - e / (SR_GO_SHARE * g.eps_tol), 0.0);
  } else {
    // short_range::clearance
    let m = SR_CLEARANCE * S(SCALE_LENGTH) + 0.25 * g.d_tol;
    let c = corner(a, g, u, f32(side), m, d);
    if (c.z == 1.0) {
      heading = atan2c(c.y - a.y, c.x - a.x);
    } else {
      heading = wrap(bearing + PI);
    }
    let e = abs(wrap(heading - a.theta));
    v = room_speed(a, g, v_d) * max(1.0 - e / SR_WALK_ERR, 0.0);
  }
  out.mode = select(POSITION_ONLY, ORIENTATION_ONLY, v < 0.1 * v_d);
  out.gamma = heading;
  out.mu = wrap(heading - bearing);
  out.delta_eta = wrap(g.beta - a.theta);
  out.v_dt = v;
  return out;
}

fn write_record(at: u32, a: Agent, o: Out, g: Goal) {
  var r = array<f32, 19>(a.x, a.y, a.theta, a.v, a.omega, f32(o.mode), o.d, o.alpha, o.eta,
    o.delta_eta, o.mu, o.gamma, o.reachable, o.v_dt, g.x, g.y, g.beta, g.d_tol, g.eps_tol);
  for (var k = 0u; k < STRIDE; k++) { records[at * STRIDE + k] = r[k]; }
}

// The current goal (a default one for an agent without goals).
fn current_goal(a: Agent) -> Goal {
  if (a.count > 0u) { return goals[a.first + min(a.current, a.count - 1u)]; }
  return Goal(0.0, 0.0, 0.0, 0.25, 0.0872664626, 1.3, 0u, 0u);
}

// A short-range choice awaited from the host and not made: plain funnelling.
fn drop_awaited_choice(a: ptr<function, Agent>) {
  if (((*a).flags & PENDING) == PENDING) {
    (*a).cap = 0.0;
    (*a).side = 0;
  }
}

// world.rs step_agent's plan (and avoid_step.rs's step 1): a done agent
// holds its heading at its cruise speed (Agent::cruise_speed, Agent::hold);
// another plans towards its current goal following the short-range choice
// as FunnelConfig::plan_with does: with a speed cap, funnelling towards
// the goal slowed to it; with a side, turning first; a choice still
// awaited, plain funnelling. `met` is the position met after the plan.
fn plan_agent(a: ptr<function, Agent>, met: ptr<function, bool>) -> Out {
  var out = Out(END_OF_STEERING, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  let g = current_goal(*a);
  if ((*a).current >= (*a).count) {
    var speed = 0.0;
    if ((*a).count > 0u && (g.flags & 1u) == 0u) { speed = g.speed; }
    out.v_dt = speed;
    out.gamma = (*a).theta;
    return out;
  }
  *met = ((*a).flags & MET) == MET;
  drop_awaited_choice(a);
  var towards = g;
  var side = (*a).side;
  if ((*a).cap > 0.0) {
    towards.speed = min(g.speed, (*a).cap);
    side = 0;
  }
  return plan(*a, towards, met, side);
}

// world.rs step_agent's move (and avoid_step.rs's step 3): the committed
// seek step to (heading, speed) — the plan's (γ, v_dt), or the avoidance's
// command —, then for an agent not done the queue's advance (planner.rs
// advance_queue), counting an entry as oriented when the heading after
// the step is within ε_tol of β (crate/world/entry_judge.rs); moving on
// to the next goal starts its memory afresh (GoalSpec::fresh_memory) with
// its choice awaited. A done agent's γ is its heading after the step.
fn move_agent(i: u32, a_in: Agent, plan_out: Out, met_in: bool, heading: f32, speed: f32) {
  var a = a_in;
  var out = plan_out;
  var met = met_in;
  let g = current_goal(a);
  let done = a.current >= a.count;
  seek_committed(&a, heading, speed);
  if (done) {
    out.gamma = a.theta;
  } else {
    var pending = false;
    var switch_now = met;
    if ((g.flags & 2u) == 2u) { switch_now = out.mode == END_OF_STEERING; }
    if (switch_now) {
      a.current += 1u;
      met = false;
      if (abs(wrap(g.beta - a.theta)) < g.eps_tol) { a.oriented += 1u; }
      a.cap = 0.0;
      a.side = 0;
      pending = a.current < a.count;
    }
    a.flags = select(0u, MET, met) | select(0u, PENDING, pending);
  }
  a.mode = out.mode;
  a.pad += counted;
  agents[i] = a;
  if (frame.records == 1u) {
    write_record(i, a, out, g);
  } else if (i == frame.ring) {
    write_record(0u, a, out, g);
  }
}

// world.rs step_agent, avoidance off: plan and move in one invocation.
@compute @workgroup_size(64)
fn step_agents(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= frame.n) { return; }
  var a = agents[i];
  var met = false;
  let out = plan_agent(&a, &met);
  move_agent(i, a, out, met, out.gamma, out.v_dt);
}

// ---- table probes: the lookup alone, for the parity checks

@group(0) @binding(8) var<storage, read> probes: array<f32>;
@group(0) @binding(9) var<storage, read_write> answers: array<vec4<f32>>;

// EtaTable::lookup at probe i (D, α, ω, v_c, v_d): η, reachable, v_dt, η valid.
@compute @workgroup_size(64)
fn probe_table(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= frame.n) { return; }
  let q = i * 5u;
  let lk = lookup(probes[q], probes[q + 1u], probes[q + 2u], probes[q + 3u], probes[q + 4u]);
  answers[i] = vec4<f32>(lk.eta, select(0.0, 1.0, lk.reachable), lk.v_dt, select(0.0, 1.0, lk.valid));
}
