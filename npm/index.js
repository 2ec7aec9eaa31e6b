// steering-core: the wasm-bindgen module of the steering lab's core (built
// with `make npm`: wasm-pack --target web, no default features), plus the
// reference pedestrian's η table and the helpers that load them, in a
// browser (fetch) and in Node (the files read from disk: Node's fetch does
// not read file: URLs).
import init, { Lab, Mode } from "./pkg/steering.js";

export * from "./pkg/steering.js";
export { init };

/** Where the package's η table is (the reference pedestrian's). */
export const TABLE_URL = new URL("./eta.bin", import.meta.url);

/** Where the package's module is. */
export const WASM_URL = new URL("./pkg/steering_bg.wasm", import.meta.url);

/** The bytes at `url`: read from disk for a file: URL (Node, Deno, Bun),
 *  else fetched; rejects with the address and the reason. */
async function bytesAt(url, what) {
  const u = url instanceof URL ? url : new URL(String(url), import.meta.url);
  if (u.protocol === "file:") {
    // A computed specifier: bundlers for the browser leave it alone.
    const fs = "node:fs/promises";
    const { readFile } = await import(/* @vite-ignore */ /* webpackIgnore: true */ fs);
    try {
      return new Uint8Array(await readFile(u));
    } catch (e) {
      throw new Error(`${what}: ${u.href}: ${e.message}`);
    }
  }
  const response = await fetch(u);
  if (!response.ok) throw new Error(`${what}: ${u.href}: HTTP ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

/** The bytes of an η table: the package's own by default. */
export function loadTable(url = TABLE_URL) {
  return bytesAt(url, "η table");
}

let ready;

/** Initialises the module once (its .wasm beside this file unless
 *  `options.wasm` says otherwise; read from disk in Node) and returns a
 *  Lab on the package's η table (or `options.table`'s: a URL, or the
 *  bytes themselves). */
export async function createLab(options = {}) {
  const table = options.table instanceof Uint8Array ? Promise.resolve(options.table) : loadTable(options.table ?? TABLE_URL);
  table.catch(() => undefined);
  ready ??= (async () => {
    const wasm = options.wasm ?? WASM_URL;
    const local = (wasm instanceof URL || typeof wasm === "string") && new URL(String(wasm), import.meta.url).protocol === "file:";
    await init({ module_or_path: local ? await bytesAt(wasm, "wasm module") : wasm });
  })();
  await ready;
  return new Lab(await table);
}

/** The core's mode names by number (`MODE_NAMES[lab.mode(i)]`). */
export const MODE_NAMES = Object.freeze(
  Object.fromEntries(Object.entries(Mode).filter(([, v]) => typeof v === "number").map(([k, v]) => [v, k])),
);
