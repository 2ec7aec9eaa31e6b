// The whole lab state in the URL fragment (#k=v&…), so a link reproduces
// the view. Decoding never throws: every bad field falls back to its default
// and is reported, so the page can show what was ignored.

import type { View } from "../view";
import { AIM_KEYS, BOUND_KEYS, RELAXED_AIM_KEYS, defaultState, type AimKey, type BoundKey, type RelaxedAimKey, type LabState, type Limits, type Overlays } from "./state";

const DEG = Math.PI / 180;

interface NumField {
  key: string;
  min: number;
  max: number;
  get(s: LabState): number;
  set(s: LabState, v: number): void;
  integer?: boolean;
}

const LIMIT_KEYS: ReadonlyArray<[string, keyof Limits, number, number]> = [
  ["vmax", "vMax", 0.05, 50],
  ["amax", "accelMax", 0.05, 100],
  ["wmax", "omegaMax", 0.05, 50],
  ["awmax", "omegaAccelMax", 0.05, 500],
  ["anmax", "normalAccelMax", 0.05, 100],
];

const NUMS: NumField[] = [
  { key: "vx", min: -1e4, max: 1e4, get: (s) => s.vehicle.x, set: (s, v) => { s.vehicle.x = v; } },
  { key: "vy", min: -1e4, max: 1e4, get: (s) => s.vehicle.y, set: (s, v) => { s.vehicle.y = v; } },
  { key: "vth", min: -360, max: 360, get: (s) => s.vehicle.theta / DEG, set: (s, v) => { s.vehicle.theta = v * DEG; } },
  { key: "tx", min: -1e4, max: 1e4, get: (s) => s.target.x, set: (s, v) => { s.target.x = v; } },
  { key: "ty", min: -1e4, max: 1e4, get: (s) => s.target.y, set: (s, v) => { s.target.y = v; } },
  { key: "tb", min: -360, max: 360, get: (s) => s.target.theta / DEG, set: (s, v) => { s.target.theta = v * DEG; } },
  { key: "dtol", min: 0.01, max: 20, get: (s) => s.dTol, set: (s, v) => { s.dTol = v; } },
  { key: "etol", min: 0.1, max: 90, get: (s) => s.epsTol / DEG, set: (s, v) => { s.epsTol = v * DEG; } },
  { key: "vd", min: 0, max: 50, get: (s) => s.speed, set: (s, v) => { s.speed = v; } },
  { key: "fvc", min: 0, max: 50, get: (s) => s.field.vC, set: (s, v) => { s.field.vC = v; } },
  { key: "fwc", min: -50, max: 50, get: (s) => s.field.omegaC, set: (s, v) => { s.field.omegaC = v; } },
  { key: "fvd", min: 0, max: 50, get: (s) => s.field.vD, set: (s, v) => { s.field.vD = v; } },
  // Controller settings, within the ranges the panel's sliders offer.
  { key: "gain", min: 1, max: 4, get: (s) => s.funnel.gain, set: (s, v) => { s.funnel.gain = v; } },
  { key: "th", min: 0.1, max: 1, get: (s) => s.funnel.threshold, set: (s, v) => { s.funnel.threshold = v; } },
  { key: "n", min: 0, max: 100000, integer: true, get: (s) => s.agents, set: (s, v) => { s.agents = v; } },
  { key: "seed", min: 0, max: 2 ** 32 - 1, integer: true, get: (s) => s.seed, set: (s, v) => { s.seed = v; } },
];

const OVERLAY_KEYS: ReadonlyArray<keyof Overlays> = ["radial", "eta", "gamma", "ring", "field", "trails", "arc", "ghost"];
const FLAGS: ReadonlyArray<"halting" | "relaxed" | "slow"> = ["halting", "relaxed", "slow"];

function isBoundKey(k: string): k is BoundKey {
  return (BOUND_KEYS as readonly string[]).includes(k);
}

function fmt(v: number): string {
  return String(Math.round(v * 1e4) / 1e4);
}

export function encodeState(s: LabState): string {
  const p = new URLSearchParams();
  for (const f of NUMS) p.set(f.key, fmt(f.get(s)));
  for (const [key, field] of LIMIT_KEYS) {
    const v = s.limits[field];
    if (v !== undefined) p.set(key, fmt(v));
  }
  for (const k of FLAGS) p.set(k, s[k] ? "1" : "0");
  p.set("bound", s.funnel.bound);
  p.set("aim", s.funnel.aim);
  p.set("lp", s.funnel.pursuit ? "1" : "0");
  p.set("raim", s.funnel.relaxedAim);
  p.set("ov", OVERLAY_KEYS.filter((k) => s.overlays[k]).join(","));
  if (s.preset) p.set("preset", s.preset);
  if (s.view) {
    p.set("zx", fmt(s.view.cx));
    p.set("zy", fmt(s.view.cy));
    p.set("zs", fmt(s.view.scale));
  }
  return p.toString();
}

export interface Decoded {
  state: LabState;
  /** Human-readable notes about every ignored or malformed field. */
  problems: string[];
}

/** Decodes a fragment (with or without '#'); `presets` are the valid names. */
export function decodeState(fragment: string, presets: readonly string[]): Decoded {
  const s = defaultState();
  const problems: string[] = [];
  const raw = fragment.startsWith("#") ? fragment.slice(1) : fragment;
  if (raw.trim() === "") return { state: s, problems };
  let p: URLSearchParams;
  try {
    decodeURIComponent(raw);
    p = new URLSearchParams(raw);
  } catch {
    return { state: s, problems: ["the link's state is not valid URL encoding; using defaults"] };
  }
  const known = new Set<string>(["ov", "bound", "aim", "lp", "raim", "preset", "zx", "zy", "zs", ...FLAGS, ...NUMS.map((f) => f.key), ...LIMIT_KEYS.map((l) => l[0])]);
  for (const key of p.keys()) {
    if (!known.has(key)) problems.push(`unknown field "${key}" ignored`);
  }
  const num = (key: string, min: number, max: number, integer: boolean): number | undefined => {
    const t = p.get(key);
    if (t === null) return undefined;
    const v = t.trim() === "" ? NaN : Number(t);
    if (!Number.isFinite(v) || v < min || v > max || (integer && !Number.isInteger(v))) {
      problems.push(`${key}="${t}" is not ${integer ? "an integer" : "a number"} in [${min}, ${max}]; default kept`);
      return undefined;
    }
    return v;
  };
  for (const f of NUMS) {
    const v = num(f.key, f.min, f.max, f.integer ?? false);
    if (v !== undefined) f.set(s, v);
  }
  for (const [key, field, min, max] of LIMIT_KEYS) {
    const v = num(key, min, max, false);
    if (v !== undefined) s.limits[field] = v;
  }
  for (const k of FLAGS) {
    const t = p.get(k);
    if (t === null) continue;
    if (t === "1" || t === "0") s[k] = t === "1";
    else problems.push(`${k}="${t}" must be 0 or 1; default kept`);
  }
  const bound = p.get("bound");
  if (bound !== null) {
    if (isBoundKey(bound)) s.funnel.bound = bound;
    else problems.push(`bound="${bound}" is not one of ${BOUND_KEYS.join(", ")}; default kept`);
  }
  const aim = p.get("aim");
  if (aim !== null) {
    if ((AIM_KEYS as readonly string[]).includes(aim)) s.funnel.aim = aim as AimKey;
    else problems.push(`aim="${aim}" is not one of ${AIM_KEYS.join(", ")}; default kept`);
  }
  const raim = p.get("raim");
  if (raim !== null) {
    if ((RELAXED_AIM_KEYS as readonly string[]).includes(raim)) s.funnel.relaxedAim = raim as RelaxedAimKey;
    else problems.push(`raim="${raim}" is not one of ${RELAXED_AIM_KEYS.join(", ")}; default kept`);
  }
  const lp = p.get("lp");
  if (lp !== null) {
    if (lp === "1" || lp === "0") s.funnel.pursuit = lp === "1";
    else problems.push(`lp="${lp}" must be 0 or 1; default kept`);
  }
  const ov = p.get("ov");
  if (ov !== null) {
    const names = ov.split(",").filter((x) => x !== "");
    const bad = names.filter((n) => !(OVERLAY_KEYS as readonly string[]).includes(n));
    if (bad.length > 0) problems.push(`unknown overlay(s) ${bad.join(", ")} ignored`);
    for (const k of OVERLAY_KEYS) s.overlays[k] = names.includes(k);
  }
  if (p.has("zx") || p.has("zy") || p.has("zs")) {
    const cx = num("zx", -1e5, 1e5, false);
    const cy = num("zy", -1e5, 1e5, false);
    const scale = num("zs", 2, 2000, false);
    if (cx !== undefined && cy !== undefined && scale !== undefined) s.view = { cx, cy, scale };
    else problems.push("the view (zx, zy, zs) needs all three; fitted instead");
  }
  const preset = p.get("preset");
  if (preset !== null && preset !== "") {
    if (presets.includes(preset)) s.preset = preset;
    else problems.push(`unknown preset "${preset}"; playground shown`);
  }
  return { state: s, problems };
}

/** Keeps the address bar's fragment in step with the state and the view:
 *  `save` after an edit (at most one write per 250 ms), `writeNow` before
 *  the link is copied. */
export class UrlSync {
  private timer = 0;

  constructor(private readonly st: LabState, private readonly view: View) {}

  save(): void {
    if (this.timer) return;
    this.timer = window.setTimeout(() => {
      this.timer = 0;
      this.writeNow();
    }, 250);
  }

  writeNow(): void {
    const { view } = this;
    this.st.view = { cx: view.cx, cy: view.cy, scale: view.scale };
    history.replaceState(null, "", `#${encodeState(this.st)}`);
  }
}
