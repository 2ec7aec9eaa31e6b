// The ONLY seam to the generated bindings (../pkg, built by `make wasm`).
// Everything else imports the core through this module's names and types.

import init, { Lab, version } from "../pkg/steering.js";
import type {
  AgentConfig,
  FunnelConfig,
  GoalConfig,
  Internals,
  MuBound,
  ScenarioInfo,
  TableInfo,
  VehicleParams,
} from "../pkg/steering.js";

export type { AgentConfig, FunnelConfig, GoalConfig, Internals, MuBound, ScenarioInfo, TableInfo, VehicleParams };
export { Lab };

/** Floats per agent in `Lab.state()` (crate::world::STATE_STRIDE). */
export const STATE_STRIDE = 19;
/** Offsets within one agent's record of `Lab.state()`. */
export const S = {
  x: 0, y: 1, theta: 2, v: 3, omega: 4, mode: 5,
  d: 6, alpha: 7, eta: 8, deltaEta: 9, mu: 10, gamma: 11, reachable: 12, vDt: 13,
  goalX: 14, goalY: 15, goalBeta: 16, goalDTol: 17, goalEpsTol: 18,
} as const;
/** Floats per sample in `Lab.etaField()` / `Lab.etaRing()`: D, α, α+η, reachable. */
export const FIELD_STRIDE = 4;

let ready: Promise<string> | null = null;

/** Instantiates the wasm module once; resolves to the core's version. */
export function loadCore(): Promise<string> {
  ready ??= init().then(() => {
    if (Lab.stateStride() !== STATE_STRIDE) {
      throw new Error(`the core writes ${Lab.stateStride()} floats per agent, the page expects ${STATE_STRIDE}: rebuild both`);
    }
    return version();
  });
  return ready;
}

/** Fetches the committed η table and hands its bytes to the core.
 *  Throws an Error whose message is fit to show on the page. */
export async function createLab(tableUrl: string): Promise<Lab> {
  await loadCore();
  let bytes: Uint8Array;
  try {
    const res = await fetch(tableUrl);
    if (!res.ok) throw new Error(`HTTP ${res.status} ${res.statusText}`.trim());
    bytes = new Uint8Array(await res.arrayBuffer());
  } catch (e) {
    throw new Error(`could not fetch the η table ${tableUrl}: ${errorText(e)}`);
  }
  try {
    return new Lab(bytes);
  } catch (e) {
    throw new Error(`the η table ${tableUrl} was rejected: ${errorText(e)}`);
  }
}

export function errorText(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}

// --- The gallery pages (crowd.html, wander.html): crowded path following
// (paper 003) and the random steering toolkit (paper 004). Both call
// loadCore() first; errors are JsErrors whose message is fit to show.
import { CrowdLab, WanderLab } from "../pkg/steering.js";
import type {
  CrowdConfig,
  CrowdMetrics,
  CrowdPathConfig,
  CrowdSeek,
  WanderConfig,
  WanderControl,
  WanderHold,
  WanderPreset,
  WanderSource,
  WanderVariant,
} from "../pkg/steering.js";

export { CrowdLab, WanderLab };
export type {
  CrowdConfig,
  CrowdMetrics,
  CrowdPathConfig,
  CrowdSeek,
  WanderConfig,
  WanderControl,
  WanderHold,
  WanderPreset,
  WanderSource,
  WanderVariant,
};
