// What every <funnel-figure> of a page shares: the core (instantiated
// once, from beside its glue), the core's ranges and default limits (the
// lab's URL decoder checks attributes against them), and the η tables by
// key: the package's own, fetched once relative to the element's module,
// and any other vehicle's, built here in slices between frames (the
// package has no workers) and kept for the page's other figures.

import { assembleTable, errorText, Lab, loadBaselineCore, precision, ranges, referenceVehicles, tableJob, tableSlice, type VehicleParams } from "../core/wasm";
import { limitDefaults, RangeTable, type LimitDefaults } from "../lab/fields";

export interface FigureContext {
  /** A lab on the package's table: each figure forks it. */
  base: Lab;
  ranges: RangeTable;
  defaults: VehicleParams & LimitDefaults;
  /** The reference vehicles by name (`vehicle="car"`). */
  vehicles: ReadonlyMap<string, VehicleParams>;
  /** Where the element's module is: its table and presets are beside it. */
  home: string;
}

let shared: Promise<FigureContext> | null = null;

/** The shared context, made on first use; `home` is the element module's URL. */
export function figureContext(home: string): Promise<FigureContext> {
  shared ??= (async () => {
    const fetching = fetchBytes(new URL("eta.bin", home));
    await loadBaselineCore();
    const bytes = await fetching;
    const base = new Lab(bytes);
    tables.set(base.tableKey(), Promise.resolve(bytes));
    const vehicles = new Map(referenceVehicles().map((r) => [r.name, r.vehicle] as const));
    return { base, ranges: new RangeTable(ranges(), precision()), defaults: limitDefaults(base.params()), vehicles, home };
  })();
  return shared;
}

async function fetchBytes(url: URL): Promise<Uint8Array> {
  const res = await fetch(url);
  if (!res.ok) throw new Error(`${url}: HTTP ${res.status}`);
  return new Uint8Array(await res.arrayBuffer());
}

/** A preset's scenario file (the package's scenarios/NAME.json). */
export async function presetText(home: string, name: string): Promise<string> {
  const res = await fetch(new URL(`scenarios/${encodeURIComponent(name)}.json`, home));
  if (!res.ok) throw new Error(`no preset "${name}" (HTTP ${res.status})`);
  return res.text();
}

/** Table bytes by key: fetched or being built. */
const tables = new Map<string, Promise<Uint8Array>>();

/** Entries built per slice: a few milliseconds of a frame. */
const SLICE = 256;

/** The η table for `params` (its bytes), built once per page; `progress`
 *  hears the share done. Rejects with a message fit to show. */
export function tableFor(params: VehicleParams, progress: (share: number) => void): Promise<Uint8Array> {
  const job = tableJob(params, undefined);
  let t = tables.get(job.key);
  if (!t) {
    t = build(params, job.entries, progress).catch((e: unknown) => {
      tables.delete(job.key);
      throw new Error(`η table for these limits: ${errorText(e)}`);
    });
    tables.set(job.key, t);
  }
  return t;
}

/** The key of `params`' table. */
export function tableKey(params: VehicleParams): string {
  return tableJob(params, undefined).key;
}

async function build(params: VehicleParams, entries: number, progress: (share: number) => void): Promise<Uint8Array> {
  const data = new Float32Array(entries * 3);
  for (let start = 0; start < entries; start += SLICE) {
    const end = Math.min(entries, start + SLICE);
    data.set(tableSlice(params, undefined, start, end), start * 3);
    progress(end / entries);
    await new Promise((ok) => setTimeout(ok, 0));
  }
  return assembleTable(params, undefined, data);
}
