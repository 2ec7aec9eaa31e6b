// Typings of steering-core's entry: everything the wasm-bindgen module
// exports (its generated typings), the default initialiser as `init`, and
// the helpers of index.js. Clean under `tsc --strict` with
// `lib: ["es2022", "dom"]` (no ESNext.Disposable needed: the classes'
// `[Symbol.dispose]` is left out of the typings; call `free()`).
import type { InitInput, Lab, Mode } from "./pkg/steering.js";

export * from "./pkg/steering.js";
export { default as init } from "./pkg/steering.js";

/** Where the package's η table is: the reference pedestrian's (the
 *  default VehicleParams), 3.3 MB. */
export declare const TABLE_URL: URL;

/** Where the package's .wasm is. */
export declare const WASM_URL: URL;

/** The bytes of an η table (the package's own by default): read from
 *  disk for a file: URL (Node), else fetched; rejects on an HTTP or file
 *  error. `new Lab(bytes)` checks them (CRC, every field) and refuses a
 *  corrupt or truncated table with a message. */
export declare function loadTable(url?: string | URL): Promise<Uint8Array>;

/** Options of {@link createLab}. */
export interface CreateLabOptions {
  /** The module's .wasm (URL, Response, bytes or compiled module); default: beside this file. */
  wasm?: InitInput | Promise<InitInput>;
  /** Another η table (one built for other vehicle limits): its URL or its bytes. */
  table?: string | URL | Uint8Array;
}

/** Initialises the module once and returns a Lab (a world of funnelling
 *  agents and its η table) on the package's table; in a browser and in
 *  Node alike. */
export declare function createLab(options?: CreateLabOptions): Promise<Lab>;

/** The core's mode names by number: `MODE_NAMES[lab.mode(0)]` is
 *  `"EndOfSteering"` once agent 0 has arrived. */
export declare const MODE_NAMES: Readonly<Record<Mode, keyof typeof Mode>>;
