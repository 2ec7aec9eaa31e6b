// The whole lab state in the URL fragment (#k=v&…), so a link reproduces
// the view. Decoding never throws: every bad field falls back to its default
// and is reported, so the page can show what was ignored. Numbers are checked
// against the core's ranges (fields.ts), cross-field rules included: a state
// the decoder returns is one the core accepts.

import type { View } from "../ui/view";
import { clampToLimits, clip, FIELDS, parseField, type LimitDefaults, type RangeTable } from "./fields";
import { decodeObstacles, encodeObstacles } from "./obstacles";
import { AIM_KEYS, BOUND_KEYS, READING_KEYS, RELAXED_AIM_KEYS, defaultState, settleReading, type AimKey, type ReadingKey, type BoundKey, type RelaxedAimKey, type LabState, type Overlays } from "./state";
import { AVOID_KEYS, type AvoidKey } from "../world/worldcalls";
import { GPU_KEYS, decodeGpu, encodeGpu } from "./gpukeys";

const OVERLAY_KEYS: ReadonlyArray<keyof Overlays> = ["radial", "eta", "gamma", "ring", "field", "trails", "arc", "ghost"];
const FLAGS: ReadonlyArray<"halting" | "relaxed" | "slow"> = ["halting", "relaxed", "slow"];

function isBoundKey(k: string): k is BoundKey {
  return (BOUND_KEYS as readonly string[]).includes(k);
}

function fmt(v: number): string {
  return String(Math.round(v * 1e4) / 1e4);
}

/** The fragment for `s`: 4 decimals, or every digit when rounding would
 *  take a value out of its range (a value at a bound). */
export function encodeState(s: LabState, ranges: RangeTable, d: LimitDefaults): string {
  const p = new URLSearchParams();
  for (const f of FIELDS) {
    if (f.limit && s.limits[f.limit] === undefined) continue;
    const v = f.get(s, d) * f.scale;
    const short = fmt(v);
    p.set(f.url, "value" in parseField(f, short, ranges, s, d) ? short : String(v));
  }
  for (const k of FLAGS) p.set(k, s[k] ? "1" : "0");
  p.set("rd", s.funnel.reading);
  p.set("bound", s.funnel.bound);
  p.set("aim", s.funnel.aim);
  p.set("lp", s.funnel.pursuit ? "1" : "0");
  p.set("raim", s.funnel.relaxedAim);
  p.set("ov", OVERLAY_KEYS.filter((k) => s.overlays[k]).join(","));
  if (s.avoidance !== null) p.set("avoid", s.avoidance);
  if (s.replanEvery !== null) p.set("plan", String(s.replanEvery));
  if (s.obstacles !== null) p.set("obs", encodeObstacles(s.obstacles));
  if (s.compare) p.set("cmp", "1");
  encodeGpu(s, p);
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

/** Decodes a fragment (with or without '#'); `presets` are the valid names,
 *  `ranges` the core's and `d` its default vehicle limits. */
export function decodeState(fragment: string, presets: readonly string[], ranges: RangeTable, d: LimitDefaults): Decoded {
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
  const known = new Set<string>(["cmp", "rd", "ov", "bound", "preset", "avoid", "plan", "obs", "aim", "raim", "lp", "zx", "zy", "zs", ...GPU_KEYS, ...FLAGS, ...FIELDS.map((f) => f.url)]);
  const seen = new Set<string>();
  for (const key of p.keys()) {
    if (seen.has(key)) problems.push(`field "${clip(key)}" given twice; the first kept`);
    else if (!known.has(key)) problems.push(`unknown field "${clip(key)}" ignored`);
    seen.add(key);
  }
  const num = (key: string, min: number, max: number, integer: boolean): number | undefined => {
    const t = p.get(key);
    if (t === null) return undefined;
    const v = t.trim() === "" ? NaN : Number(t);
    if (!Number.isFinite(v) || v < min || v > max || (integer && !Number.isInteger(v))) {
      problems.push(`${key}="${clip(t)}" is not ${integer ? "an integer" : "a number"} in [${min}, ${max}]; default kept`);
      return undefined;
    }
    return v;
  };
  // Vehicle limits first: the desired speed's bound is the max speed.
  for (const f of FIELDS) {
    const t = p.get(f.url);
    if (t === null) continue;
    const r = parseField(f, t, ranges, s, d);
    if ("value" in r) f.set(s, r.value);
    else problems.push(`${f.url}="${clip(t)}": ${r.error}; ${f.limit ? "the core's default" : "default"} kept`);
  }
  const clamped = clampToLimits(ranges, s, d);
  clamped.fields.forEach((f, i) => problems.push(`${f.url}: ${clamped.messages[i] ?? ""}`));
  for (const k of FLAGS) {
    const t = p.get(k);
    if (t === null) continue;
    if (t === "1" || t === "0") s[k] = t === "1";
    else problems.push(`${k}="${clip(t)}" must be 0 or 1; default kept`);
  }
  const rd = p.get("rd");
  if (rd !== null) {
    if ((READING_KEYS as readonly string[]).includes(rd)) s.funnel.reading = rd as ReadingKey;
    else problems.push(`rd="${clip(rd)}" is not one of ${READING_KEYS.join(", ")}; default kept`);
  }
  const bound = p.get("bound");
  if (bound !== null) {
    if (isBoundKey(bound)) s.funnel.bound = bound;
    else problems.push(`bound="${clip(bound)}" is not one of ${BOUND_KEYS.join(", ")}; default kept`);
  }
  const aim = p.get("aim");
  if (aim !== null) {
    if ((AIM_KEYS as readonly string[]).includes(aim)) s.funnel.aim = aim as AimKey;
    else problems.push(`aim="${clip(aim)}" is not one of ${AIM_KEYS.join(", ")}; default kept`);
  }
  const raim = p.get("raim");
  if (raim !== null) {
    if ((RELAXED_AIM_KEYS as readonly string[]).includes(raim)) s.funnel.relaxedAim = raim as RelaxedAimKey;
    else problems.push(`raim="${clip(raim)}" is not one of ${RELAXED_AIM_KEYS.join(", ")}; default kept`);
  }
  decodeGpu(p, s, problems);
  const cmp = p.get("cmp");
  if (cmp !== null) {
    if (cmp === "1" || cmp === "0") s.compare = cmp === "1";
    else problems.push(`cmp="${clip(cmp)}" must be 0 or 1; default kept`);
  }
  const lp = p.get("lp");
  if (lp !== null) {
    if (lp === "1" || lp === "0") s.funnel.pursuit = lp === "1";
    else problems.push(`lp="${clip(lp)}" must be 0 or 1; default kept`);
  }
  settleReading(s.funnel, rd !== null && s.funnel.reading === rd);
  // The avoidance method and the obstacles (absent: the scenario's own).
  const avoid = p.get("avoid");
  if (avoid !== null) {
    if ((AVOID_KEYS as readonly string[]).includes(avoid)) s.avoidance = avoid as AvoidKey;
    else problems.push(`avoid="${clip(avoid)}" is not one of ${AVOID_KEYS.join(", ")}; the scenario's own kept`);
  }
  const plan = p.get("plan");
  if (plan !== null) {
    const r = ranges.get("avoidance.replanEvery");
    const v = /^\d{1,2}$/.test(plan) ? Number(plan) : NaN;
    if (v >= r.min && v <= r.max) s.replanEvery = v;
    else problems.push(`plan="${clip(plan)}" is not a whole number of steps in [${r.min}, ${r.max}]; the scenario's own kept`);
  }
  const obs = p.get("obs");
  if (obs !== null) {
    const r = decodeObstacles(obs, ranges);
    if ("list" in r) s.obstacles = r.list;
    else problems.push(`obs: ${r.error}; the scenario's own obstacles kept`);
  }
  const ov = p.get("ov");
  if (ov !== null) {
    const names = ov.split(",").filter((x) => x !== "");
    const bad = names.filter((n) => !(OVERLAY_KEYS as readonly string[]).includes(n));
    if (bad.length > 0) problems.push(`unknown overlay(s) ${clip(bad.join(", "))} ignored`);
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
    else problems.push(`unknown preset "${clip(preset)}"; playground shown`);
  }
  return { state: s, problems };
}

/** Keeps the address bar's fragment in step with the state and the view:
 *  `save` after an edit (at most one write per 250 ms), `writeNow` before
 *  the link is copied. */
export class UrlSync {
  private timer = 0;

  constructor(private readonly st: LabState, private readonly view: View, private readonly ranges: RangeTable, private readonly defaults: LimitDefaults) {}

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
    history.replaceState(null, "", `#${encodeState(this.st, this.ranges, this.defaults)}`);
  }
}
