// The ONLY seam to the generated bindings (../pkg, built by `make wasm`).
// Everything else imports the core through this module's names and types.

import init, { Lab, version } from "../../pkg/steering.js";
import { fromPlanes } from "./tableplanes";

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
} from "../../pkg/steering.js";
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
  Reading,
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
} from "../../pkg/steering.js";

/** Floats per sample in `Lab.etaField()` / `Lab.etaRing()`: D, α, α+η, reachable. */
export const FIELD_STRIDE = 4;

let ready: Promise<string> | null = null;

/** The smallest module using a SIMD instruction (`i32x4.splat` in a
 *  function returning v128): WebAssembly.validate accepts it exactly where
 *  the engine runs WebAssembly SIMD. */
const SIMD_PROBE = new Uint8Array([
  0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11,
]);

/** Which build of the core runs: "simd128" (the core compiled with
 *  WebAssembly SIMD, same bits) where the engine has SIMD, else
 *  "baseline". Set by loadCore. */
export let coreBuild: "simd128" | "baseline" | null = null;

/** Instantiates the wasm module once (every page calls this first); resolves to the core's version. */
export function loadCore(): Promise<string> {
  ready ??= (() => {
    const simd = typeof WebAssembly.validate === "function" && WebAssembly.validate(SIMD_PROBE);
    coreBuild = simd ? "simd128" : "baseline";
    // Both builds share the glue (pkg/steering.js; `make wasm` checks it is
    // byte-identical); the baseline module is init()'s default.
    if (!simd) return init().then(() => version());
    const url = new URL("../../pkg/steering_simd_bg.wasm", import.meta.url);
    // The lab page starts compiling the SIMD build from its HTML,
    // while the scripts load (index.html); taken here, else fetched now
    // (globalThis: workers load the core too).
    const early = (globalThis as { __coreCompile?: Promise<WebAssembly.Module> }).__coreCompile;
    // A SIMD module that does not load (missing from a partial deploy,
    // refused by the engine) falls back to the baseline one: same bits.
    return init({ module_or_path: early ? early.catch(() => url) : url })
      .catch(() => {
        coreBuild = "baseline";
        return init();
      })
      .then(() => version());
  })();
  return ready;
}

/** Instantiates the baseline module from beside its glue (the glue's own
 *  default: the npm package's element, whose package ships that build
 *  only); resolves to the core's version. */
export function loadBaselineCore(): Promise<string> {
  ready ??= (coreBuild = "baseline", init().then(() => version()));
  return ready;
}

/** Fetches the committed η table (`fetchTable`: a `.planes` URL is
 *  rejoined) and hands its bytes to the core (the learn page; the lab
 *  draws before its table, `Lab.withoutTable`). Throws an Error whose
 *  message is fit to show on the page. */
export async function createLab(tableUrl: string): Promise<Lab> {
  // The fetch runs while the core instantiates.
  const fetching = fetchTable(tableUrl);
  await loadCore();
  const bytes = await fetching;
  try {
    return new Lab(bytes);
  } catch (e) {
    throw new Error(`the η table ${tableUrl} was rejected: ${errorText(e)}`);
  }
}

/** Starts fetching the η table (the lab's first frame does not wait for
 *  it, see `Lab.withoutTable`); a `.planes` URL is the file in
 *  byte planes (tableplanes.ts), rejoined here. Rejects with a message fit
 *  to show. */
export function fetchTable(tableUrl: string): Promise<Uint8Array> {
  const p = (async (): Promise<Uint8Array> => {
    let res: Response;
    try {
      res = await fetch(tableUrl);
      if (!res.ok) throw new Error(`HTTP ${res.status} ${res.statusText}`.trim());
      const bytes = new Uint8Array(await res.arrayBuffer());
      return tableUrl.endsWith(".planes") ? fromPlanes(bytes) : bytes;
    } catch (e) {
      throw new Error(`could not fetch the η table ${tableUrl}: ${errorText(e)}`);
    }
  })();
  p.catch(() => undefined);
  return p;
}

/** Puts the fetched table `bytes` in force in `lab` (`Lab.setTable`);
 *  throws an Error fit to show when the core refuses them. */
export function installTable(lab: Lab, bytes: Uint8Array, tableUrl: string): void {
  try {
    lab.setTable(bytes);
  } catch (e) {
    throw new Error(`the η table ${tableUrl} was rejected: ${errorText(e)}`);
  }
}

/** The message of a thrown value (the core's errors are JsErrors whose message is fit to show). */
export function errorText(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}
