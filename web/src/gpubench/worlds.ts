// The seeded worlds the kernel is checked on (web/test/e2e-gpu.mjs, and the
// page's own check): a reference vehicle (pedestrian, car, robot) with
// its η table, and agents with two goals each, the first passed through
// (the tolerance switch, not halting), the second to rest in (halting,
// the End_of_Steering switch), drawn from a seed in a square the vehicle
// crosses in about 10 s, with tolerances at its scale.
// The car's and the robot's tables are coarse (the parity does not
// depend on a table's resolution, and the full ones take minutes to
// build); the pedestrian's is the committed one.

import { Lab, assembleTable, referenceVehicles, tableJob, tableSlice, type VehicleParams } from "../core/wasm";

/** The reference vehicles the worlds use. */
export type VehicleName = "pedestrian" | "car" | "robot";

/** A coarse table's sample counts (D, α, ω fraction, v_c, v_d). */
const COARSE = Uint32Array.from([8, 24, 3, 5, 5]);

/** The turning radius at full speed over the pedestrian's (crate/funnelling/table/spec.rs VehicleScale). */
function lengthScale(p: VehicleParams): number {
  const r = (q: { vMax: number; omegaMax: number; normalAccelMax: number }) => q.vMax / Math.min(q.omegaMax, q.normalAccelMax / q.vMax);
  return r(p) / r({ vMax: 2, omegaMax: 2, normalAccelMax: 1.5 });
}

/** A small PRNG for the worlds' draws (xorshift32). */
function draws(seed: number): () => number {
  let s = seed >>> 0 || 1;
  return () => {
    s ^= s << 13;
    s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5;
    s >>>= 0;
    return s / 4294967296;
  };
}

/** A lab with `vehicle`'s limits and table (the pedestrian's from `pedestrianTable`, the others built coarse here). */
export function vehicleLab(vehicle: VehicleName, pedestrianTable: Uint8Array): Lab {
  const lab = new Lab(pedestrianTable);
  if (vehicle === "pedestrian") return lab;
  const ref = (referenceVehicles() as { name: string; vehicle: VehicleParams }[]).find((v) => v.name === vehicle);
  if (!ref) throw new Error(`no reference vehicle ${vehicle}`);
  const params = { ...lab.params(), ...ref.vehicle };
  lab.setParams(params);
  const job = tableJob(params, COARSE) as { entries: number };
  lab.setTable(assembleTable(params, COARSE, tableSlice(params, COARSE, 0, job.entries)));
  return lab;
}

/** Puts `n` agents drawn from `seed` in `lab`'s world (a scenario at the
 *  lab's vehicle's scale), in a square the vehicle crosses in about 10 s. */
export function seedWorld(lab: Lab, n: number, seed: number): void {
  // A square the agents cross in about 10 s (600 steps): goals are
  // reached and rested in within a free run, for every vehicle.
  const half = 5 * lab.params().vMax;
  placeWorld(lab, n, seed, half, null);
}

/** A seeded dense world for separation: `n` agents in a square holding
 *  `density` agents per m², each goal within about 3 s of travel of the
 *  last point (so that within a free run agents arrive and rest among
 *  their pushing neighbours), separation on with the core's default
 *  settings (body 0.3 m, margin 0.15 m, reach 3 m, 10 neighbours). */
export function separationWorld(lab: Lab, n: number, seed: number, density: number): void {
  placeWorld(lab, n, seed, Math.sqrt(n / density) / 2, 3 * lab.params().vMax);
  lab.setAvoidance("separation");
}

/** `n` agents drawn from `seed` in a square of half-side `half` m, with
 *  two goals each, each at most `hop` m from the last point on each axis
 *  (kept in the square; null: anywhere in it): the first passed through
 *  (the tolerance switch), the second to rest in (halting,
 *  End_of_Steering). */
function placeWorld(lab: Lab, n: number, seed: number, half: number, hop: number | null): void {
  const p = lab.params();
  const k = lengthScale(p);
  const next = draws(seed);
  const r3 = (v: number) => Math.round(v * 1000) / 1000;
  const at = () => r3((2 * next() - 1) * half);
  const near = (v: number) => (hop === null ? at() : r3(Math.max(-half, Math.min(half, v + (2 * next() - 1) * hop))));
  const deg = () => Math.round(360 * next() - 180);
  const speed = r3(0.65 * p.vMax);
  const goal = (from: { x: number; y: number }, last: boolean) => ({
    x: near(from.x), y: near(from.y), betaDeg: deg(), dTol: r3(0.3 * k), epsTolDeg: 10, speed,
    halting: last, switch: last ? "endOfSteering" : "tolerance",
  });
  const agents = Array.from({ length: n }, () => {
    const start = { x: at(), y: at(), thetaDeg: deg() };
    const first = goal(start, false);
    return { ...start, goals: [first, goal(first, true)] };
  });
  lab.loadScenario(JSON.stringify({ name: `gpu parity ${n}`, duration: 20, vehicle: p, agents }));
}
