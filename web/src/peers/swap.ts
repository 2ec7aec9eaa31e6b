// The antipodal circle swaps (scenarios/avoid_circle*.json) for the crowd
// rows: our core loads the scenario as the lab's preset does (ORCA, its
// radius and settings); DetourCrowd gets the same starts, goals, body
// radius, cruise speed (the goal's speed as Detour's maxSpeed) and
// acceleration. Both are measured the same way from their positions after
// every step over the scenario's duration: pairs of bodies overlapping
// (closer than two radii), agents at rest inside D_tol at the end (as
// meter.ts: for HOLD_S at least), when the last came to rest, and the
// heading error they stand with.

import { Crowd, type NavMesh } from "@recast-navigation/core";
import { Lab, StateField } from "../core/wasm";
import { HOLD_S, REST_SPEED, VEHICLE, wrap } from "./cases";
import { quantile } from "./meter";
import { BODY_RADIUS, Heading } from "./detourside";

interface ScenarioGoal { x: number; y: number; betaDeg: number; dTol: number; epsTolDeg: number; speed: number }
interface ScenarioAgent { x: number; y: number; thetaDeg: number; goals: ScenarioGoal[] }
/** The fields of a scenario file the swap reads. */
export interface SwapScenario { name: string; duration: number; avoidance: { radius: number }; agents: ScenarioAgent[] }

export interface SwapResult {
  agents: number;
  /** The most pairs overlapping after one step, and the steps with any. */
  worstOverlaps: number;
  overlapSteps: number;
  /** Agents at rest inside D_tol at the end (for HOLD_S at least). */
  arrived: number;
  /** When the last of them came to rest, s; NaN unless every agent did. */
  allArrivedTime: number;
  /** Heading error at rest at the end, median and largest, °. */
  restHeadingP50: number;
  restHeadingMax: number;
  /** The agents not at rest at the end: index, distance to the goal (m), speed (m/s). */
  unsettled: Array<{ i: number; d: number; v: number }>;
}

const DEG = Math.PI / 180;

/** Follows every agent's pose: `sample` after each step, `result` at the end. */
class SwapMeter {
  private worst = 0;
  private steps = 0;
  private t = 0;
  private last: Array<{ x: number; y: number; theta: number; v: number }> = [];
  /** Per agent: when its current stretch at rest inside D_tol began (NaN: not at rest). */
  private readonly since: number[];
  constructor(private readonly sc: SwapScenario, private readonly r: number) {
    this.since = sc.agents.map(() => NaN);
  }

  sample(poses: Array<{ x: number; y: number; theta: number; v: number }>, t: number): void {
    let pairs = 0;
    for (let i = 0; i < poses.length; i++)
      for (let j = i + 1; j < poses.length; j++) if (Math.hypot(poses[i]!.x - poses[j]!.x, poses[i]!.y - poses[j]!.y) < 2 * this.r) pairs++;
    this.worst = Math.max(this.worst, pairs);
    if (pairs > 0) this.steps++;
    poses.forEach((p, i) => {
      const g = this.sc.agents[i]!.goals[0]!;
      const rests = p.v <= REST_SPEED && Math.hypot(p.x - g.x, p.y - g.y) <= g.dTol;
      if (!rests) this.since[i] = NaN;
      else if (Number.isNaN(this.since[i])) this.since[i] = t;
    });
    this.last = poses;
    this.t = t;
  }

  /** At the end: the agents at rest for HOLD_S at least, their headings' errors, and when the last of them came to rest. */
  result(): SwapResult {
    const errs: number[] = [];
    const unsettled: SwapResult["unsettled"] = [];
    let all = 0;
    this.last.forEach((p, i) => {
      const s = this.since[i]!;
      const g = this.sc.agents[i]!.goals[0]!;
      if (!(this.t - s >= HOLD_S)) {
        unsettled.push({ i, d: Math.hypot(p.x - g.x, p.y - g.y), v: p.v });
        return;
      }
      errs.push(Math.abs(wrap(p.theta - this.sc.agents[i]!.goals[0]!.betaDeg * DEG)) / DEG);
      all = Math.max(all, s);
    });
    const n = this.sc.agents.length;
    return { agents: n, worstOverlaps: this.worst, overlapSteps: this.steps, arrived: errs.length, allArrivedTime: errs.length === n ? all : NaN, restHeadingP50: quantile(errs, 0.5), restHeadingMax: Math.max(0, ...errs), unsettled };
  }
}

/** Our core on the scenario `text` (its JSON), for its duration. */
export function swapOurs(lab: Lab, sc: SwapScenario, text: string): SwapResult {
  lab.clear();
  lab.loadScenario(text);
  const n = lab.count();
  const stride = Lab.stateStride();
  const state = new Float32Array(n * stride);
  const m = new SwapMeter(sc, sc.avoidance.radius);
  const dt = VEHICLE.dt;
  for (let k = 1; k * dt <= sc.duration; k++) {
    lab.stepInto(state);
    const poses = Array.from({ length: n }, (_, i) => {
      const o = i * stride;
      return { x: state[o + StateField.X]!, y: state[o + StateField.Y]!, theta: state[o + StateField.Theta]!, v: state[o + StateField.V]! };
    });
    m.sample(poses, k * dt);
  }
  lab.clear();
  return m.result();
}

/** DetourCrowd on the same scenario, on `mesh`, for its duration. */
export function swapDetour(mesh: NavMesh, sc: SwapScenario): SwapResult {
  const crowd = new Crowd(mesh, { maxAgents: sc.agents.length, maxAgentRadius: BODY_RADIUS });
  try {
    const agents = sc.agents.map((a) => {
      const g = a.goals[0]!;
      const ag = crowd.addAgent({ x: a.x, y: 0, z: a.y }, { radius: sc.avoidance.radius, height: 1, maxSpeed: g.speed, maxAcceleration: VEHICLE.accelMax });
      ag.requestMoveTarget({ x: g.x, y: 0, z: g.y });
      return { ag, h: new Heading(a.thetaDeg * DEG) };
    });
    const m = new SwapMeter(sc, sc.avoidance.radius);
    const dt = VEHICLE.dt;
    for (let k = 1; k * dt <= sc.duration; k++) {
      crowd.update(dt);
      m.sample(agents.map(({ ag, h }) => h.pose(ag)), k * dt);
    }
    return m.result();
  } finally {
    crowd.destroy();
  }
}
