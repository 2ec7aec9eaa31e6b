// The recipe of the world the page's state describes (../world/worldcalls.ts): the
// page's simulation builds its worlds from it (sim.ts), and so does the
// build's first frame (firstdata.ts), so the frame drawn from the HTML is
// the core's scene at t = 0, bit for bit.

import type { VehicleParams } from "../core/wasm";
import { funnelConfig, readingOf, relaxedConfig } from "./funnelsettings";
import { goalConfig, type LabState } from "./state";
import type { Recipe, TableSource } from "../world/worldcalls";

/** `st`'s world on `table` with the vehicle limits `params`: the preset
 *  `scenario` (its name and text), or the playground when null. */
export function recipeFor(st: LabState, params: VehicleParams, table: TableSource, scenario: { name: string; text: string } | null): Recipe {
  const settings = {
    table, params, limits: { ...st.limits }, funnel: funnelConfig(st.funnel), relaxed: relaxedConfig(st.funnel), reading: readingOf(st.funnel),
    avoid: { method: st.avoidance, replanEvery: st.replanEvery, obstacles: st.obstacles },
  };
  if (scenario) return { ...settings, build: { kind: "scenario", ...scenario } };
  const n = st.agents;
  const spawn = n > 0 ? { n, seed: st.seed, extent: Math.max(10, Math.sqrt(n) * 1.5), speed: st.speed } : null;
  const agent = { x: st.vehicle.x, y: st.vehicle.y, theta: st.vehicle.theta, goals: [goalConfig(st)] };
  return { ...settings, build: { kind: "playground", agent, spawn } };
}
