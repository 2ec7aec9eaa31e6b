// Yuka 0.7.8 on the peers' cases: a `Vehicle` per case with
// `ArriveBehavior` (Yuka's defaults: deceleration 3, tolerance 0) or
// `SeekBehavior`, its limits the pedestrian's where Yuka has them:
// maxSpeed = v_max, maxTurnRate = ω_max, maxForce = the forward
// acceleration A (mass 1). Yuka's `Vehicle.update` turns the heading to the
// velocity at once (`lookAt`); its maxTurnRate bounds only
// `GameEntity.rotateTo`, which the vehicle's update does not call: the
// turn-rate violations measured below are Yuka's model, not a setting.
// Yuka is 3D with y up: our (x, y) is Yuka's (x, z).

import { ArriveBehavior, SeekBehavior, Vector3, Vehicle } from "yuka";
import { MAX_TIME_S, VEHICLE, type OrientedCase, type Pose } from "./cases";
import { Meter, type RunResult } from "./meter";

export type YukaKind = "arrive" | "seek";

/** Yuka's name and version, as the records give them. */
export const YUKA = "Yuka 0.7.8";

/** The limits a Yuka vehicle takes from ours. */
export interface YukaLimits {
  vMax: number;
  omegaMax: number;
  accelMax: number;
}

/** A Yuka vehicle at `start` (at rest, facing θ) steering to `goal`
 *  under `limits` (the pedestrian's by default). */
export function yukaVehicle(kind: YukaKind, start: Pose, goal: Pose, limits: YukaLimits = VEHICLE): Vehicle {
  const v = new Vehicle();
  v.maxSpeed = limits.vMax;
  v.maxTurnRate = limits.omegaMax;
  v.mass = 1;
  v.maxForce = limits.accelMax;
  v.position.set(start.x, 0, start.y);
  v.lookAt(new Vector3(start.x + Math.cos(start.theta), 0, start.y + Math.sin(start.theta)));
  const target = new Vector3(goal.x, 0, goal.y);
  v.steering.add(kind === "arrive" ? new ArriveBehavior(target) : new SeekBehavior(target));
  return v;
}

const dir = new Vector3();

/** The vehicle's pose and speed in our plane. */
export function yukaPose(v: Vehicle): { x: number; y: number; theta: number; v: number } {
  v.getDirection(dir);
  return { x: v.position.x, y: v.position.z, theta: Math.atan2(dir.z, dir.x), v: v.velocity.length() };
}

/** Runs `cases` with Yuka's `kind`; one result per case. */
export function runYuka(kind: YukaKind, cases: OrientedCase[]): RunResult[] {
  const dt = VEHICLE.dt;
  const steps = Math.ceil(MAX_TIME_S / dt);
  return cases.map((c) => {
    const v = yukaVehicle(kind, c.start, c.goal);
    const m = new Meter(c, VEHICLE);
    for (let k = 1; k <= steps; k++) {
      v.update(dt);
      const p = yukaPose(v);
      m.sample(p.x, p.y, p.theta, p.v, k * dt, dt);
    }
    return m.result();
  });
}

/** `n` Yuka vehicles arriving at random targets in a square of half-side
 *  `extent` (seeded): the timer runs `steps` updates of every vehicle. */
export function yukaWorld(n: number, rand: () => number, extent: number): (steps: number) => void {
  const at = (): number => (2 * rand() - 1) * extent;
  const vs: Vehicle[] = [];
  for (let i = 0; i < n; i++) vs.push(yukaVehicle("arrive", { x: at(), y: at(), theta: (2 * rand() - 1) * Math.PI }, { x: at(), y: at(), theta: 0 }));
  const dt = VEHICLE.dt;
  return (steps) => {
    for (let k = 0; k < steps; k++) for (const v of vs) v.update(dt);
  };
}
