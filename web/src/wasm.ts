// The ONLY seam to the generated bindings (../pkg, built by `make wasm`).
// Everything else imports the core through this module's names and types.

import init, { Lab, version } from "../pkg/steering.js";

export {
  CrowdLab,
  Lab,
  Mode,
  StateField,
  WanderLab,
  assembleTable,
  precision,
  ranges,
  referenceVehicles,
  tableJob,
  tableKeyOf,
  tableSlice,
} from "../pkg/steering.js";
export type {
  AgentConfig,
  CrowdConfig,
  CrowdMetrics,
  CrowdPathConfig,
  CrowdSeek,
  FieldRange,
  FunnelConfig,
  Ghost,
  GoalConfig,
  Internals,
  MuBound,
  PrecisionRule,
  RelaxedConfig,
  ScenarioInfo,
  TableInfo,
  VehicleParams,
  WanderConfig,
  WanderControl,
  WanderHold,
  WanderPreset,
  WanderSource,
  WanderVariant,
} from "../pkg/steering.js";

/** Floats per sample in `Lab.etaField()` / `Lab.etaRing()`: D, α, α+η, reachable. */
export const FIELD_STRIDE = 4;

let ready: Promise<string> | null = null;

/** Instantiates the wasm module once (every page calls this first); resolves to the core's version. */
export function loadCore(): Promise<string> {
  ready ??= init().then(() => version());
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

/** The message of a thrown value (the core's errors are JsErrors whose message is fit to show). */
export function errorText(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}
