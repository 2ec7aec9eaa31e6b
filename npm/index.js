// steering-core: the wasm-bindgen module of the steering lab's core (built
// with `make npm`: wasm-pack --target web, no default features), plus the
// reference pedestrian's η table and two helpers to load them.
import init, { Lab } from "./pkg/steering.js";

export * from "./pkg/steering.js";
export { init };

/** Where the package's η table is (the reference pedestrian's). */
export const TABLE_URL = new URL("./eta.bin", import.meta.url);

/** The bytes of an η table: the package's own by default. */
export async function loadTable(url = TABLE_URL) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`η table: ${url}: HTTP ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

let ready;

/** Initialises the module once (its .wasm beside this file unless
 *  `options.wasm` says otherwise) and returns a Lab on the package's η
 *  table (or `options.table`'s). */
export async function createLab(options = {}) {
  ready ??= init(options.wasm === undefined ? undefined : { module_or_path: options.wasm });
  await ready;
  return new Lab(await loadTable(options.table));
}
