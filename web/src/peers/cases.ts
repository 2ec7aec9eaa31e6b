// The peers' shared inputs: the reference vehicle (scenarios/vehicles/
// pedestrian.json, the lab's default), the seeded oriented-target cases
// every side runs, and the tolerances of an arrival. Plain data, no peer.

import pedestrian from "../../../scenarios/vehicles/pedestrian.json";

/** The pedestrian's limits as its file gives them (the core's defaults). */
export const VEHICLE = pedestrian.vehicle;
export type VehicleLimits = typeof VEHICLE;

/** The goal's tolerances and speed: the lab's default D_tol and ε_tol; the
 *  desired speed is v_max, the speed Yuka's vehicles cruise at
 *  (`maxSpeed`), so both sides travel equally fast. */
export const GOAL = { dTol: 0.3, epsTol: (10 * Math.PI) / 180, speed: VEHICLE.vMax } as const;

/** A peer's vehicle counts as at rest below this speed, m/s (ours halts
 *  at exactly 0; Yuka's arrive and DetourCrowd slow down asymptotically). */
export const REST_SPEED = 0.01;

/** Simulated seconds every run lasts. */
export const MAX_TIME_S = 40;

/** A run is at rest when it has stayed inside D_tol below REST_SPEED for
 *  its last HOLD_S seconds at least: a vehicle that only turns round
 *  there (Yuka's seek swinging through the target) is not. */
export const HOLD_S = 1;

export interface Pose {
  x: number;
  y: number;
  theta: number;
}

/** One oriented-target case: a start pose at rest and a target pose. */
export interface OrientedCase {
  start: Pose;
  goal: Pose;
}

/** Mulberry32: a small seeded generator of uniform floats in [0, 1), the
 *  same sequence in every engine (32-bit integer arithmetic only). */
export function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** `n` cases from `seed`: the start at the origin with a random heading,
 *  the target 3–10 m away in a random direction with a random β (every
 *  angle uniform on the circle). */
export function orientedCases(seed: number, n: number): OrientedCase[] {
  const r = mulberry32(seed);
  const angle = (): number => (r() * 2 - 1) * Math.PI;
  const out: OrientedCase[] = [];
  for (let i = 0; i < n; i++) {
    const theta = angle();
    const dist = 3 + 7 * r();
    const bearing = angle();
    out.push({ start: { x: 0, y: 0, theta }, goal: { x: dist * Math.cos(bearing), y: dist * Math.sin(bearing), theta: angle() } });
  }
  return out;
}

/** `a` wrapped into (−π, π]. */
export function wrap(a: number): number {
  return Math.atan2(Math.sin(a), Math.cos(a));
}
