// Typings of steering-core's entry: everything the wasm-bindgen module
// exports (its generated typings), the default initialiser as `init`, and
// the table helpers of index.js.
import type { InitInput, Lab } from "./pkg/steering.js";

export * from "./pkg/steering.js";
export { default as init } from "./pkg/steering.js";

/** Where the package's η table is: the reference pedestrian's (the
 *  default VehicleParams), 3.3 MB. */
export declare const TABLE_URL: URL;

/** The bytes of an η table (the package's own by default), fetched;
 *  rejects on an HTTP error. `new Lab(bytes)` checks them (CRC, every
 *  field) and refuses a corrupt or truncated table with a message. */
export declare function loadTable(url?: string | URL): Promise<Uint8Array>;

/** Options of {@link createLab}. */
export interface CreateLabOptions {
  /** The module's .wasm (URL, Response, bytes or compiled module); default: beside this file. */
  wasm?: InitInput | Promise<InitInput>;
  /** Another η table's URL (one built for other vehicle limits). */
  table?: string | URL;
}

/** Initialises the module once and returns a Lab (a world of funnelling
 *  agents and its η table) on the package's table. */
export declare function createLab(options?: CreateLabOptions): Promise<Lab>;
