// The lab's numbers and the core's ranges for them (crate/funnelling/ranges.rs,
// exported as `ranges()`): the URL decoder, the sliders and the number boxes
// all check a value here, so the page accepts exactly what the core
// accepts. Pure: no wasm at run time, so the Node fuzz test runs it as is.

import { parseDecimal } from "../ui/controls";
import type { FieldRange, PrecisionRule, VehicleParams } from "../core/wasm";

export { parseDecimal };
import type { LabState, Limits } from "./state";

const DEG = Math.PI / 180;

/** The core's default vehicle limits (`lab.params()`): what an unset limit
 *  is, and the time step (the coordinate rule needs it). */
export type LimitDefaults = Required<Limits> & { dt: number };

/** `p` (the core's default parameters) as the page's defaults: the core
 *  leaves a zero turning radius out of what it hands over, the page needs
 *  every limit. */
export function limitDefaults(p: VehicleParams): VehicleParams & LimitDefaults {
  return { ...p, minTurnRadius: p.minTurnRadius ?? 0, vReverse: p.vReverse ?? 0 };
}

/** One number of the lab state, tied to the core's range `core`. */
export interface LabField {
  /** Key in the URL fragment. */
  url: string;
  /** The core's range key (crate/funnelling/ranges.rs). */
  core: string;
  /** Name shown in messages. */
  label: string;
  /** Shown value = stored value × scale (rad → °). */
  scale: number;
  /** Unit of the shown value. */
  unit: string;
  get(s: LabState, d: LimitDefaults): number;
  set(s: LabState, v: number): void;
  /** A vehicle limit: absent from the state until set (the core's default). */
  limit?: keyof Limits;
}

const num = (url: string, core: string, label: string, unit: string, get: (s: LabState) => number, set: (s: LabState, v: number) => void, scale = 1): LabField =>
  ({ url, core, label, unit, scale, get: (s) => get(s), set });

const lim = (url: string, key: keyof Limits, label: string, unit: string): LabField => ({
  url, core: key, label, unit, scale: 1, limit: key,
  get: (s, d) => s.limits[key] ?? d[key],
  set: (s, v) => { s.limits[key] = v; },
});

/** Every number the lab's URL carries, vehicle limits first (the others'
 *  bounds may depend on them: desired speed ≤ max speed). */
export const FIELDS: readonly LabField[] = [
  lim("vmax", "vMax", "max speed", "m/s"),
  lim("amax", "accelMax", "max accel.", "m/s²"),
  lim("wmax", "omegaMax", "max ang. speed", "rad/s"),
  lim("awmax", "omegaAccelMax", "max ang. accel.", "rad/s²"),
  lim("anmax", "normalAccelMax", "max normal acc. A", "m/s²"),
  lim("kp", "kp", "seek gain kp", "1/s²"),
  lim("kd", "kd", "seek gain kd", "1/s"),
  lim("rmin", "minTurnRadius", "min. turning radius", "m"),
  lim("vrev", "vReverse", "max reverse speed", "m/s"),
  num("vx", "pos.x", "vehicle x", "m", (s) => s.vehicle.x, (s, v) => { s.vehicle.x = v; }),
  num("vy", "pos.y", "vehicle y", "m", (s) => s.vehicle.y, (s, v) => { s.vehicle.y = v; }),
  num("vth", "theta", "vehicle heading", "°", (s) => s.vehicle.theta, (s, v) => { s.vehicle.theta = v; }, 1 / DEG),
  num("tx", "goal.pos.x", "target x", "m", (s) => s.target.x, (s, v) => { s.target.x = v; }),
  num("ty", "goal.pos.y", "target y", "m", (s) => s.target.y, (s, v) => { s.target.y = v; }),
  num("tb", "goal.beta", "orientation β", "°", (s) => s.target.theta, (s, v) => { s.target.theta = v; }, 1 / DEG),
  num("dtol", "goal.dTol", "position tol. D_tol", "m", (s) => s.dTol, (s, v) => { s.dTol = v; }),
  num("etol", "goal.epsTol", "orient. tol. ε_tol", "°", (s) => s.epsTol, (s, v) => { s.epsTol = v; }, 1 / DEG),
  num("vd", "goal.speed", "desired speed v_d", "m/s", (s) => s.speed, (s, v) => { s.speed = v; }),
  // The η field view's inputs: a current state and a desired speed.
  num("fvc", "v", "field current v_c", "m/s", (s) => s.field.vC, (s, v) => { s.field.vC = v; }),
  num("fwc", "omega", "field current ω_c", "rad/s", (s) => s.field.omegaC, (s, v) => { s.field.omegaC = v; }),
  num("fvd", "goal.speed", "field desired v_d", "m/s", (s) => s.field.vD, (s, v) => { s.field.vD = v; }),
  num("gain", "funnel.gain", "gain k", "", (s) => s.funnel.gain, (s, v) => { s.funnel.gain = v; }),
  num("th", "funnel.seekThreshold", "seek threshold", "ε_tol", (s) => s.funnel.threshold, (s, v) => { s.funnel.threshold = v; }),
  num("n", "agents", "random agents", "", (s) => s.agents, (s, v) => { s.agents = v; }),
  num("seed", "seed", "seed", "", (s) => s.seed, (s, v) => { s.seed = v; }),
];

/** The field with URL key `url` (a bug when absent). */
export function field(url: string): LabField {
  const f = FIELDS.find((x) => x.url === url);
  if (!f) throw new Error(`no lab field ${url}`);
  return f;
}

/** The core's keys of the coordinates bounded by its precision rule. */
const COORDINATES = new Set(["pos.x", "pos.y", "goal.pos.x", "goal.pos.y"]);

/** The core's ranges by key, and its coordinate rule (`precision()`). */
export class RangeTable {
  private readonly byKey = new Map<string, FieldRange>();

  constructor(list: readonly FieldRange[], readonly precision: PrecisionRule) {
    for (const r of list) this.byKey.set(r.key, r);
    for (const f of FIELDS) if (!this.byKey.has(f.core)) throw new Error(`the core exports no range for ${f.core}`);
  }

  get(key: string): FieldRange {
    const r = this.byKey.get(key);
    if (!r) throw new Error(`the core exports no range for ${key}`);
    return r;
  }
}

/** The interval `f` accepts in the state `s`, in stored units: the core's
 *  range narrowed by the current value of its `atMost` field. */
export interface Bounds {
  min: number;
  max: number;
  integer: boolean;
  /** The field that narrowed the maximum, if it did. */
  by: LabField | null;
  /** Narrowed by the coordinate rule (desired speed and D_tol). */
  resolution: boolean;
}

/** The largest |coordinate| of the playground agent and its goal: where
 *  f32 still resolves a quarter of a step at the desired speed, and D_tol / 32
 *  (crate/funnelling/precision.rs), computed in f32 as the core does. */
export function coordinateLimit(ranges: RangeTable, s: LabState, d: LimitDefaults): number {
  const f = Math.fround;
  const r = ranges.precision;
  const step = Math.floor(Math.min(f(f(f(r.stepScale) * f(s.speed)) * f(d.dt)), r.coordMax));
  const tol = Math.floor(f(f(r.toleranceScale) * f(s.dTol)));
  return Math.min(step, tol, r.coordMax);
}

export function bounds(f: LabField, ranges: RangeTable, s: LabState, d: LimitDefaults): Bounds {
  const r = ranges.get(f.core);
  let { min, max } = r;
  let by: LabField | null = null;
  let resolution = false;
  if (COORDINATES.has(f.core)) {
    const lim = coordinateLimit(ranges, s, d);
    if (lim < max) {
      max = lim;
      min = Math.max(min, -lim);
      resolution = true;
    }
  }
  if (r.atMost !== null) {
    const lf = FIELDS.find((x) => x.core === r.atMost);
    if (lf) {
      const lim = lf.get(s, d);
      if (lim < max) {
        max = lim;
        by = lf;
      }
      if (min < 0) min = Math.max(min, -lim);
    }
  }
  return { min, max, integer: r.integer, by, resolution };
}

/** A number for a message: at most 4 decimals, no trailing zeros. */
export function show(v: number): string {
  if (v !== 0 && Math.abs(v) >= 1e6) return v.toExponential(3).replace(/\.?0+e/, "e");
  return String(Math.round(v * 1e4) / 1e4);
}

/** The accepted interval as shown ("[0.01, 2] m/s, at most max speed"). */
export function describe(f: LabField, b: Bounds): string {
  const k = f.scale;
  const unit = f.unit ? ` ${f.unit}` : "";
  const lo = Math.min(b.min * k, b.max * k);
  const hi = Math.max(b.min * k, b.max * k);
  const why = b.by ? ` (at most ${b.by.label})` : b.resolution ? " (where f32 resolves a step at this desired speed and D_tol)" : "";
  return `${b.integer ? "a whole number" : "a number"} in [${show(lo)}, ${show(hi)}]${unit}${why}`;
}

/** Checks the shown value `text` for `f`; the stored value, or the reason it is refused. */
export function parseField(f: LabField, text: string, ranges: RangeTable, s: LabState, d: LimitDefaults): { value: number } | { error: string } {
  const b = bounds(f, ranges, s, d);
  const shown = parseDecimal(text, b.integer);
  if (shown === null) return { error: `${f.label}: "${clip(text)}" is not ${describe(f, b)}` };
  const v = shown / f.scale;
  if (v < b.min || v > b.max) return { error: `${f.label}: ${show(shown)} is not ${describe(f, b)}` };
  return { value: v };
}

/** Brings every field bounded by another (desired speed ≤ max speed, field
 *  view speeds) inside its bound; returns one message per change. */
export function clampToLimits(ranges: RangeTable, s: LabState, d: LimitDefaults): { fields: LabField[]; messages: string[] } {
  const fields: LabField[] = [];
  const messages: string[] = [];
  for (const f of FIELDS) {
    const b = bounds(f, ranges, s, d);
    const v = f.get(s, d);
    const c = Math.min(b.max, Math.max(b.min, v));
    if (c !== v) {
      f.set(s, c);
      fields.push(f);
      const why = b.by ? `${b.by.label} is ${show(b.by.get(s, d) * b.by.scale)} ${b.by.unit}` : `the range is ${describe(f, b)}`;
      messages.push(`${f.label} ${show(v * f.scale)} ${f.unit} set to ${show(c * f.scale)} ${f.unit}: ${why}`);
    }
  }
  return { fields, messages };
}

/** At most `n` characters of a user's text for a message. */
export function clip(text: string, n = 40): string {
  return text.length > n ? `${text.slice(0, n)}…` : text;
}
