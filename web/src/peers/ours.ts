// Our core on the peers' cases: every case an agent of one world (no
// avoidance: the agents do not see each other), stepped together, each
// agent's pose read after every step through the one seam (../wasm).

import { Lab, StateField, type GoalConfig } from "../core/wasm";
import { GOAL, MAX_TIME_S, VEHICLE, type OrientedCase } from "./cases";
import { Meter, type RunResult } from "./meter";

/** The goal our agents are given for target `g`: halting, standard funnelling. */
export function ourGoal(g: { x: number; y: number; theta: number }): GoalConfig {
  return { x: g.x, y: g.y, beta: g.theta, dTol: GOAL.dTol, epsTol: GOAL.epsTol, speed: GOAL.speed, halting: true, relaxed: false };
}

/** Runs `cases` in `lab` (which holds the pedestrian's η table; its
 *  world is replaced); one result per case. */
export function runOurs(lab: Lab, cases: OrientedCase[]): RunResult[] {
  lab.clear();
  lab.setParams({ ...lab.params(), ...VEHICLE });
  for (const c of cases) lab.addAgent({ x: c.start.x, y: c.start.y, theta: c.start.theta, goals: [ourGoal(c.goal)] });
  const meters = cases.map((c) => new Meter(c, VEHICLE));
  const stride = Lab.stateStride();
  const state = new Float32Array(cases.length * stride);
  const dt = VEHICLE.dt;
  const steps = Math.ceil(MAX_TIME_S / dt);
  for (let k = 1; k <= steps; k++) {
    lab.stepInto(state);
    meters.forEach((m, i) => {
      const o = i * stride;
      m.sample(state[o + StateField.X]!, state[o + StateField.Y]!, state[o + StateField.Theta]!, state[o + StateField.V]!, k * dt, dt);
    });
  }
  lab.clear();
  return meters.map((m) => m.result());
}

/** Our core's cost per agent update with `n` funnelling agents
 *  (`Lab.spawnRandom`: random poses and goals in a square of half-side
 *  `extent`): `lab`'s world is replaced; the timer runs `timed`. */
export function ourWorld(lab: Lab, n: number, seed: number, extent: number): (steps: number) => void {
  lab.clear();
  lab.setParams({ ...lab.params(), ...VEHICLE });
  lab.spawnRandom(n, seed, extent, GOAL.speed);
  return (steps) => lab.step(steps);
}
