// DetourCrowd (@recast-navigation/core 0.43.1: Recast/Detour in wasm) on
// the peers' cases: a flat square navmesh (@recast-navigation/generators),
// one crowd, agents with the pedestrian's radius (the avoidance scenarios'
// 0.3 m), max speed v_max and max acceleration A, every other parameter
// Detour's default (updateFlags 7: anticipate turns, obstacle avoidance,
// separation). A Detour agent has no heading: its heading here is its
// velocity's direction (the last one while it stands). Detour is 3D with y
// up: our (x, y) is its (x, z).

import { Crowd, init, type CrowdAgent, type NavMesh } from "@recast-navigation/core";
import { generateSoloNavMesh } from "@recast-navigation/generators";
import { MAX_TIME_S, VEHICLE, type OrientedCase } from "./cases";
import { Meter, type RunResult } from "./meter";

export const DETOUR = "@recast-navigation/core 0.43.1 (DetourCrowd)";

/** The agents' body radius, m (the avoidance scenarios' `avoidance.radius`). */
export const BODY_RADIUS = 0.3;

/** Loads Recast/Detour's wasm (once). */
export function detourReady(): Promise<void> {
  return init();
}

/** A flat square navmesh of half-side `half` m round the origin; cells of
 *  `cs` m (the plane has no obstacle: the cell only sets the border). */
export function planeNavMesh(half: number, cs: number): NavMesh {
  const positions = [-half, 0, -half, half, 0, -half, half, 0, half, -half, 0, half];
  // Wound so that the triangles' normals point up (walkable).
  const indices = [0, 2, 1, 0, 3, 2];
  const r = generateSoloNavMesh(positions, indices, { cs, ch: 0.2, walkableRadius: Math.ceil(BODY_RADIUS / cs), walkableHeight: 10, walkableClimb: 2, maxEdgeLen: 0, maxVertsPerPoly: 6 });
  if (!r.success) throw new Error(`Recast could not build the plane's navmesh: ${r.error}`);
  return r.navMesh;
}

/** The agent parameters: the pedestrian's where Detour has them. */
export const AGENT = { radius: BODY_RADIUS, height: 1, maxSpeed: VEHICLE.vMax, maxAcceleration: VEHICLE.accelMax } as const;

/** Follows a Detour agent's heading: its velocity's direction while it moves. */
export class Heading {
  constructor(public theta: number) {}
  pose(a: CrowdAgent): { x: number; y: number; theta: number; v: number } {
    const p = a.position();
    const u = a.velocity();
    const v = Math.hypot(u.x, u.z);
    if (v > 1e-4) this.theta = Math.atan2(u.z, u.x);
    return { x: p.x, y: p.z, theta: this.theta, v };
  }
}

/** Runs `cases` one agent at a time in one crowd on `mesh`; one result per case. */
export function runDetour(mesh: NavMesh, cases: OrientedCase[]): RunResult[] {
  const crowd = new Crowd(mesh, { maxAgents: 1, maxAgentRadius: BODY_RADIUS });
  const dt = VEHICLE.dt;
  const steps = Math.ceil(MAX_TIME_S / dt);
  try {
    return cases.map((c) => {
      const a = crowd.addAgent({ x: c.start.x, y: 0, z: c.start.y }, AGENT);
      a.requestMoveTarget({ x: c.goal.x, y: 0, z: c.goal.y });
      const h = new Heading(c.start.theta);
      const m = new Meter(c, VEHICLE);
      for (let k = 1; k <= steps; k++) {
        crowd.update(dt);
        const p = h.pose(a);
        m.sample(p.x, p.y, p.theta, p.v, k * dt, dt);
      }
      crowd.removeAgent(a);
      return m.result();
    });
  } finally {
    crowd.destroy();
  }
}

/** `n` Detour agents going to random targets in a square of half-side
 *  `extent` (seeded) on `mesh`: the timer runs `steps` crowd updates;
 *  `destroy` frees the crowd. */
export function detourWorld(mesh: NavMesh, n: number, rand: () => number, extent: number): { run: (steps: number) => void; destroy: () => void } {
  const crowd = new Crowd(mesh, { maxAgents: n, maxAgentRadius: BODY_RADIUS });
  const at = (): number => (2 * rand() - 1) * extent;
  for (let i = 0; i < n; i++) crowd.addAgent({ x: at(), y: 0, z: at() }, AGENT).requestMoveTarget({ x: at(), y: 0, z: at() });
  return { run: (steps) => { for (let k = 0; k < steps; k++) crowd.update(VEHICLE.dt); }, destroy: () => crowd.destroy() };
}
