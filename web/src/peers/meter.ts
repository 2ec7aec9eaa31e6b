// What one run of one side did, measured the same way for every side from
// its poses step by step: at rest inside D_tol at the end (REST_SPEED for
// HOLD_S at least), the heading error it stands with and the one it first
// entered D_tol with, the path length against
// the Dubins shortest, and the steps that broke the vehicle's speed or
// turn-rate limit.

import { GOAL, HOLD_S, REST_SPEED, wrap, type OrientedCase, type VehicleLimits } from "./cases";
import { dubinsLength, minTurnRadius } from "./dubins";

export interface RunResult {
  /** At rest (speed ≤ REST_SPEED) inside D_tol over the run's last HOLD_S at least. */
  arrived: boolean;
  /** When that last stretch at rest began, s; NaN when none. */
  arriveTime: number;
  /** |θ − β| at the end, at rest, rad; NaN when not at rest. */
  restHeadingErr: number;
  /** Inside D_tol at least once. */
  reached: boolean;
  /** |θ − β| at the first entry into D_tol, rad; NaN when none. */
  entryHeadingErr: number;
  /** Path length to the rest (or, without one, to the first entry; or the
   *  whole run), m, over the Dubins shortest at v_d's turning radius. */
  lengthRatio: number;
  /** Steps with speed above v_max (1e-3 relative slack). */
  speedViolations: number;
  /** Steps whose heading turned faster than ω_max (1e-3 relative slack). */
  turnViolations: number;
  /** The largest heading rate seen, rad/s. */
  maxTurnRate: number;
}

/** Follows one run: `sample` after every step, `result` at the end. */
export class Meter {
  private x: number;
  private y: number;
  private theta: number;
  private length = 0;
  private lengthAtEntry = NaN;
  /** When the current stretch at rest inside D_tol began (NaN: not at rest), and the length then. */
  private restSince = NaN;
  private lengthAtRest = NaN;
  private t = 0;
  private readonly r: RunResult;
  private readonly dubins: number;

  constructor(private readonly c: OrientedCase, private readonly limits: VehicleLimits) {
    this.x = c.start.x;
    this.y = c.start.y;
    this.theta = c.start.theta;
    this.r = { arrived: false, arriveTime: NaN, restHeadingErr: NaN, reached: false, entryHeadingErr: NaN, lengthRatio: NaN, speedViolations: 0, turnViolations: 0, maxTurnRate: 0 };
    const rho = minTurnRadius(GOAL.speed, limits.omegaMax, limits.normalAccelMax);
    this.dubins = dubinsLength(c.start.x, c.start.y, c.start.theta, c.goal.x, c.goal.y, c.goal.theta, rho);
  }

  /** The pose and speed after a step of `dt` ending at time `t`. */
  sample(x: number, y: number, theta: number, v: number, t: number, dt: number): void {
    const r = this.r;
    this.length += Math.hypot(x - this.x, y - this.y);
    const rate = Math.abs(wrap(theta - this.theta)) / dt;
    r.maxTurnRate = Math.max(r.maxTurnRate, rate);
    if (rate > this.limits.omegaMax * 1.001) r.turnViolations++;
    if (v > this.limits.vMax * 1.001) r.speedViolations++;
    this.x = x;
    this.y = y;
    this.theta = theta;
    this.t = t;
    const g = this.c.goal;
    const inside = Math.hypot(x - g.x, y - g.y) <= GOAL.dTol;
    if (inside && !r.reached) {
      r.reached = true;
      r.entryHeadingErr = Math.abs(wrap(theta - g.theta));
      this.lengthAtEntry = this.length;
    }
    if (!(inside && v <= REST_SPEED)) this.restSince = NaN;
    else if (Number.isNaN(this.restSince)) {
      this.restSince = t;
      this.lengthAtRest = this.length;
    }
  }

  /** At the run's end: at rest if the last stretch at rest lasted HOLD_S;
   *  the heading error is the final heading's (what the vehicle stands with). */
  result(): RunResult {
    const r = { ...this.r };
    r.arrived = this.t - this.restSince >= HOLD_S;
    if (r.arrived) {
      r.arriveTime = this.restSince;
      r.restHeadingErr = Math.abs(wrap(this.theta - this.c.goal.theta));
    }
    const len = r.arrived ? this.lengthAtRest : r.reached ? this.lengthAtEntry : this.length;
    return { ...r, lengthRatio: len / this.dubins };
  }
}

/** What a side did over every case. */
export interface Summary {
  runs: number;
  /** Runs at rest inside D_tol, %. */
  restPct: number;
  /** Runs at rest inside D_tol with |θ − β| ≤ ε_tol: oriented arrivals, %. */
  orientedPct: number;
  /** Heading error at rest, median and p95 over the runs at rest, °. */
  restHeadingP50: number;
  restHeadingP95: number;
  /** Heading error at the first entry into D_tol, median over the runs that entered, °. */
  entryHeadingP50: number;
  /** Path length over the Dubins shortest, median over every run. */
  lengthRatioP50: number;
  /** Runs with any step over v_max / over ω_max. */
  speedViolationRuns: number;
  turnViolationRuns: number;
  /** The largest heading rate of any run, rad/s. */
  maxTurnRate: number;
  /** Seconds to rest, median over the runs at rest. */
  arriveTimeP50: number;
}

/** The `q`-quantile (nearest rank) of `xs`; NaN when empty. */
export function quantile(xs: number[], q: number): number {
  if (xs.length === 0) return NaN;
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))] ?? NaN;
}

const DEG = 180 / Math.PI;

export function summarize(rs: RunResult[]): Summary {
  const rest = rs.filter((r) => r.arrived);
  const pct = (k: number): number => (100 * k) / Math.max(1, rs.length);
  return {
    runs: rs.length,
    restPct: pct(rest.length),
    orientedPct: pct(rest.filter((r) => r.restHeadingErr <= GOAL.epsTol).length),
    restHeadingP50: quantile(rest.map((r) => r.restHeadingErr * DEG), 0.5),
    restHeadingP95: quantile(rest.map((r) => r.restHeadingErr * DEG), 0.95),
    entryHeadingP50: quantile(rs.filter((r) => r.reached).map((r) => r.entryHeadingErr * DEG), 0.5),
    lengthRatioP50: quantile(rs.map((r) => r.lengthRatio), 0.5),
    speedViolationRuns: rs.filter((r) => r.speedViolations > 0).length,
    turnViolationRuns: rs.filter((r) => r.turnViolations > 0).length,
    maxTurnRate: Math.max(0, ...rs.map((r) => r.maxTurnRate)),
    arriveTimeP50: quantile(rest.map((r) => r.arriveTime), 0.5),
  };
}
