// A <funnel-figure>'s attributes are the lab's link keys (lab/urlstate.ts:
// tx, ty, tb in degrees, dtol, etol, vd, vx, vy, vth, the limits vmax …
// rmin, rd, ov, preset, …), read by the lab's own decoder, so a figure and
// `index.html#<the same keys>` (the iframe for hosts that refuse scripts)
// show the same set-up; plus `vehicle`, a reference vehicle's name, whose
// limits apply unless a limit attribute says otherwise.

import { FIELDS } from "../lab/fields";
import { defaultState, type LabState, type Limits } from "../lab/state";
import { decodeState, encodeState } from "../lab/urlstate";
import type { FigureContext } from "./context";

/** The lab's link keys a figure reads (its view keys aside: a figure fits
 *  its box). */
export const LINK_KEYS: readonly string[] = [
  ...FIELDS.map((f) => f.url),
  "halting", "relaxed", "rd", "bound", "aim", "lp", "raim", "ov", "avoid", "plan", "obs", "preset",
];

/** Every attribute a figure observes. */
export const ATTRIBUTES: readonly string[] = [...LINK_KEYS, "vehicle"];

/** The limits a state carries, by its Limits key. */
const LIMIT_KEYS = FIELDS.flatMap((f) => (f.limit ? [f.limit] : []));

/** The figure's set-up from its attributes: the lab's state, and what the
 *  decoder refused (each bad attribute falls back to its default, as a
 *  bad key of a link does). */
export function stateOf(el: Element, cx: FigureContext): { state: LabState; problems: string[] } {
  const p = new URLSearchParams();
  for (const k of LINK_KEYS) {
    const v = el.getAttribute(k);
    if (v !== null) p.set(k, v);
  }
  const problems: string[] = [];
  const name = el.getAttribute("vehicle");
  const reference = name === null ? undefined : cx.vehicles.get(name);
  if (name !== null && !reference) problems.push(`unknown vehicle "${name}" (known: ${[...cx.vehicles.keys()].join(", ")}); the default kept`);
  // A reference vehicle's limits go in first, as if written as attributes,
  // so the decoder bounds the rest (the desired speed) by them.
  const fieldOf = (k: keyof Limits) => FIELDS.find((f) => f.limit === k);
  for (const k of LIMIT_KEYS) {
    const f = fieldOf(k);
    const v = reference?.[k];
    if (f && v !== undefined && !p.has(f.url)) p.set(f.url, String(v));
  }
  // The preset named is checked by loading it (the package's file).
  const preset = p.get("preset");
  const decoded = decodeState(p.toString(), preset ? [preset] : [], cx.ranges, cx.defaults);
  return { state: decoded.state, problems: [...problems, ...decoded.problems] };
}

/** The lab link's fragment for `st` (without '#'). */
export function fragmentOf(st: LabState, cx: FigureContext): string {
  return encodeState(st, cx.ranges, cx.defaults);
}

export { defaultState };
