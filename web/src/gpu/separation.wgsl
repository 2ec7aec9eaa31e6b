// Separation between agents on the GPU (paper 003's Parker separation):
// the core's Avoider::compute with AvoidanceMethod::Separation and no
// obstacles (crate/avoidance/avoider.rs, neighbours.rs, separation.rs,
// command.rs). Compiled after funnel.wgsl and grid.wgsl (kernel.ts joins
// the sources). The step with separation (crate/world/avoid_step.rs) is
// three passes over agents here round the grid's: every funnel plans
// (plan_agents, into `plans`), the grid is built (grid.wgsl: `starts`,
// `order`), each agent's command is made (separate, into `commands`), and
// every agent steps with it (move_agents). In `separate`, one invocation
// per agent:
// - the step's number is ctl[0] (Avoider::next_step); agent i plans when
//   (step + i) % every == 0 (collect_due); an agent not due keeps its
//   last plan's command when that plan changed the funnel's (active),
//   else takes this step's funnel command (hold_commands);
// - an agent due gathers the candidates within reach from the 3 × 3 cells
//   round its own (NeighbourGrid::candidate_runs: row by row, each row's
//   buckets as one or two runs, within a bucket by index; the agent itself
//   left out), from the states at the start of the step (the agent buffer:
//   no agent has moved yet), and keeps the k nearest, ties in gather order
//   (Neighbours::rank: a stable sort by the squared distance, done here by
//   insertion as the core does past 16 candidates);
// - then separation_command: a push away from each of those closer than
//   two radii (equal positions: along -x for the lower index, +x for the
//   higher), none: the funnel's own command; else the funnel's velocity
//   plus push·weight, clamped to v_max, turned into the unicycle's
//   command (command::unicycle with no half-plane).
// A finished agent takes part as any other: its funnel's command holds
// its heading at its cruise speed, and it is pushed.

// A plan as the move reads it when avoidance sits between them
// (plan_agents, then separate, then move_agents): the funnel's
// Internals, whether the position is met after the plan, the table
// reads counted.
struct Plan { out: Out, met: u32, counted: u32 }

// The command an agent steps with (crate/avoidance/command.rs Command):
// heading, speed, on (1: the avoidance changed the funnel's: Command::active).
struct Command { heading: f32, speed: f32, on: u32, pad: u32 }

@group(0) @binding(10) var<storage, read_write> plans: array<Plan>;
@group(0) @binding(11) var<storage, read_write> commands: array<Command>;
// The avoider's next step number (crate/avoidance/avoider.rs Avoider::next_step).
@group(0) @binding(12) var<storage, read_write> ctl: array<u32>;

// avoidance/stalled.rs STUCK_SPEED; command.rs HEADING_SAMPLES.
const STUCK_SPEED: f32 = 0.1;
const HEADING_SAMPLES: u32 = 12u;
// orca.rs MAX_NEIGHBOURS.
const MAX_NEIGHBOURS: u32 = 16u;

// trig::unit: (cos a, sin a).
fn unit(a: f32) -> vec2<f32> {
  let sc = sincos(a);
  return vec2<f32>(sc.y, sc.x);
}

// glam's Vec2::rotate: `r` rotated by the angle of unit `by`.
fn rotate(by: vec2<f32>, r: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(by.x * r.x - by.y * r.y, by.y * r.x + by.x * r.y);
}

struct Best { cost: f32, turn: f32, heading: f32, speed: f32 }

// command.rs unicycle's `consider` with no half-plane (every ray's cap is
// v_max): the candidate nearest v_seek wins, ties the smaller turn.
fn consider(best: ptr<function, Best>, v: vec2<f32>, h: f32, u: vec2<f32>, turn: f32, vmax: f32) {
  // A ray facing away from v_seek gets speed 0 whatever its cap.
  let d = dot(v, u);
  let sp = clamp(d, 0.0, vmax);
  let e = u * sp - v;
  let cost = dot(e, e);
  if (cost < (*best).cost - 1e-9 || (cost <= (*best).cost + 1e-9 && turn < (*best).turn)) {
    *best = Best(cost, turn, h, sp);
  }
}

// command::unicycle(s, forward, h_pref, v, v, no lines, v_max).
fn unicycle(a: Agent, fwd: vec2<f32>, h_pref: f32, v: vec2<f32>, vmax: f32) -> Command {
  let along = vmax;
  if (length(v) >= STUCK_SPEED) {
    return Command(atan2c(v.y, v.x), min(max(dot(v, fwd), 0.0), along), 1u, 0u);
  }
  if (dot(v, v) < 1e-6) { return Command(h_pref, 0.0, 1u, 0u); }
  let step = 15.0 * (PI / 180.0);
  let turn_step = unit(step);
  // The core starts from an infinite cost: any candidate's is below this.
  var best = Best(3.0e38, 0.0, a.theta, 0.0);
  if (dot(v, v) > 1e-6) {
    let h = atan2c(v.y, v.x);
    consider(&best, v, h, v * (1.0 / length(v)), abs(wrap(h - a.theta)), vmax);
  }
  consider(&best, v, a.theta, fwd, 0.0, vmax);
  var left = fwd;
  var right = fwd;
  for (var k = 1u; k <= HEADING_SAMPLES; k++) {
    let d = step * f32(k);
    left = rotate(turn_step, left);
    right = rotate(vec2<f32>(turn_step.x, -turn_step.y), right);
    consider(&best, v, wrap(a.theta + d), left, d, vmax);
    consider(&best, v, wrap(a.theta - d), right, d, vmax);
  }
  return Command(best.heading, min(best.speed * max(sincos(best.turn).y, 0.0), along), 1u, 0u);
}

// Neighbours::gather and rank: the k nearest within reach of agent i at
// `me`, squared distances and indices, nearest first (ties: gather order).
struct Nearest { d2: array<f32, MAX_NEIGHBOURS>, j: array<u32, MAX_NEIGHBOURS>, k: u32 }

fn take_run(near: ptr<function, Nearest>, i: u32, me: vec2<f32>, lo: u32, hi: u32, kmax: u32) {
  let r2 = S(REACH2);
  for (var s = starts[lo]; s < starts[hi]; s++) {
    let j = order[s];
    if (j == i) { continue; }
    let dx = me.x - agents[j].x;
    let dy = me.y - agents[j].y;
    let d2 = dx * dx + dy * dy;
    if (!(d2 < r2)) { continue; }
    let k = (*near).k;
    if (k == kmax && d2 >= (*near).d2[k - 1u]) { continue; }
    var at = select(k - 1u, k, k < kmax);
    loop {
      if (at == 0u || !((*near).d2[at - 1u] > d2)) { break; }
      (*near).d2[at] = (*near).d2[at - 1u];
      (*near).j[at] = (*near).j[at - 1u];
      at -= 1u;
    }
    (*near).d2[at] = d2;
    (*near).j[at] = j;
    if (k < kmax) { (*near).k = k + 1u; }
  }
}

fn nearest(i: u32, me: vec2<f32>) -> Nearest {
  var near: Nearest;
  near.k = 0u;
  let kmax = min(u32(S(K_MAX)), MAX_NEIGHBOURS);
  if (kmax == 0u) { return near; }
  let nb = bucket_count();
  let ix = cell_coord(me.x) - 1;
  let iy = cell_coord(me.y) - 1;
  for (var dy = 0; dy < 3; dy++) {
    let b = bucket_of_cell(ix, iy + dy);
    if (b + 3u <= nb) {
      take_run(&near, i, me, b, b + 3u, kmax);
    } else {
      take_run(&near, i, me, b, nb, kmax);
      take_run(&near, i, me, 0u, b + 3u - nb, kmax);
    }
  }
  return near;
}

// Neighbours::separation_command for agent i, whose funnel asks for
// (h_pref, s_pref).
fn separation_command(i: u32, a: Agent, h_pref: f32, s_pref: f32) -> Command {
  let r = S(SEP_R);
  let me = vec2<f32>(a.x, a.y);
  let near = nearest(i, me);
  var push = vec2<f32>(0.0, 0.0);
  for (var t = 0u; t < near.k; t++) {
    let d = sqrt(near.d2[t]);
    if (d < 2.0 * r) {
      let j = near.j[t];
      var dir = vec2<f32>(1.0, 0.0);
      if (d > 1e-9) {
        dir = (me - vec2<f32>(agents[j].x, agents[j].y)) / d;
      } else if (i < j) {
        dir = vec2<f32>(-1.0, 0.0);
      }
      push += dir * (2.0 * r - d);
    }
  }
  if (push.x == 0.0 && push.y == 0.0) { return Command(h_pref, s_pref, 0u, 0u); }
  let vmax = S(V_MAX);
  var v = unit(h_pref) * s_pref + push * S(SEP_WEIGHT);
  let l2 = dot(v, v);
  if (l2 > vmax * vmax) { v = vmax * (v / sqrt(l2)); }
  return unicycle(a, unit(a.theta), h_pref, v, vmax);
}

@compute @workgroup_size(64)
fn separate(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= frame.n) { return; }
  let pref = plans[i].out;
  let due = (ctl[0] + i) % u32(S(REPLAN)) == 0u;
  if (!due) {
    if (commands[i].on == 0u) { commands[i] = Command(pref.gamma, pref.v_dt, 0u, 0u); }
    return;
  }
  commands[i] = separation_command(i, agents[i], pref.gamma, pref.v_dt);
}

// avoid_step.rs step 1: every agent's plan, from the states at the start
// of the step (the agents are not written: separation reads them).
@compute @workgroup_size(64)
fn plan_agents(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= frame.n) { return; }
  var a = agents[i];
  var met = false;
  let out = plan_agent(&a, &met);
  plans[i] = Plan(out, select(0u, 1u, met), counted);
}

// avoid_step.rs step 3: every agent steps with its command (commands,
// from separation.wgsl); the avoider's step number advances (Avoider's
// hold_commands), once.
@compute @workgroup_size(64)
fn move_agents(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= frame.n) { return; }
  if (i == 0u) { ctl[0] = (ctl[0] + 1u) % u32(S(REPLAN)); }
  var a = agents[i];
  drop_awaited_choice(&a);
  let p = plans[i];
  let c = commands[i];
  counted = p.counted;
  move_agent(i, a, p.out, p.met == 1u, c.heading, c.speed);
}
