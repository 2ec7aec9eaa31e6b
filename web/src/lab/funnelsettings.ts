// The "Controller" panel section: the funnelling settings a researcher
// compares live (μ bound, aim, last stretch, gain, seek threshold) and their mapping to the
// core's FunnelConfig. Every change goes straight to the core; agents keep
// running.

import { section, select, type Control } from "../ui/controls";
import { READING_SETTINGS, type AimKey, type BoundKey, type FunnelSettings, type ReadingKey, type RelaxedAimKey } from "./state";
import type { FunnelConfig, MuBound, Reading, RelaxedConfig } from "../core/wasm";

/** The reading menu: which is which, in words a user can tell apart. */
const READING_CHOICES: ReadonlyArray<{ value: ReadingKey; label: string }> = [
  { value: "ours", label: "ours (this lab's defaults)" },
  { value: "paper", label: "paper as written (000 standard, 001 relaxed)" },
  { value: "custom", label: "custom (settings below)" },
];

/** The core's reading for the page's settings, null when custom. */
export function readingOf(f: FunnelSettings): Reading | null {
  return f.reading === "custom" ? null : f.reading;
}

export const BOUND_CHOICES: ReadonlyArray<{ value: BoundKey; label: string; bound: MuBound }> = [
  { value: "tr", label: "turning radius ×8 (default)", bound: { kind: "turningRadius", factor: 8 } },
  { value: "sl", label: "6 × literal", bound: { kind: "scaledLiteral", gain: 6 } },
  { value: "lit", label: "literal (paper)", bound: { kind: "literal" } },
  { value: "const", label: "constant π/2", bound: { kind: "constant" } },
];

export const AIM_CHOICES: ReadonlyArray<{ value: AimKey; label: string }> = [
  { value: "entry", label: "disk entry point (default)" },
  { value: "centre", label: "centre (paper)" },
];

const PURSUIT_CHOICES: ReadonlyArray<{ value: "on" | "off"; label: string }> = [
  { value: "on", label: "line pursuit (default)" },
  { value: "off", label: "table only (paper)" },
];

const RELAXED_AIM_CHOICES: ReadonlyArray<{ value: RelaxedAimKey; label: string }> = [
  { value: "entry", label: "entry point (default)" },
  { value: "paperArc", label: "relaxed point (paper)" },
];

/** The panel's name of a relaxed aim ("relaxed aims at"), as its menu shows it. */
export function relaxedAimLabel(k: RelaxedAimKey): string {
  return RELAXED_AIM_CHOICES.find((c) => c.value === k)?.label ?? k;
}

/** The core's relaxed settings for the page's (the rest at the core's defaults). */
export function relaxedConfig(f: FunnelSettings): RelaxedConfig {
  return { aim: f.relaxedAim };
}

/** The core's config for the page's settings. The line pursuit's numbers
 *  and the bound's radius floor stay the core's defaults (absent fields);
 *  turning the pursuit off sends `terminal: null`. */
export function funnelConfig(f: FunnelSettings): FunnelConfig {
  const choice = BOUND_CHOICES.find((c) => c.value === f.bound) ?? BOUND_CHOICES[0]!;
  return {
    bound: choice.bound, gain: f.gain, seekThreshold: f.threshold, aim: f.aim,
    ...(f.pursuit ? {} : { terminal: null }),
  };
}

/** A slider with a number box for the lab field `url` (its range the core's),
 *  over the handy window [lo, hi]. */
export type NumericControl = (parent: HTMLElement, url: string, w: { id: string; lo: number; hi: number; step: number }, onInput: (v: number) => void) => Control;

/** Builds the section; edits `f` in place and calls `onChange` after each change. */
export function funnelSettingsSection(panel: HTMLElement, f: FunnelSettings, onChange: () => void, numeric: NumericControl): FunnelSection {
  const box = section(panel, "Controller");
  // Any setting edited by hand makes the reading custom.
  const edited = (apply: () => void) => (): void => {
    apply();
    f.reading = "custom";
    reading.set("custom");
    onChange();
  };
  const reading = select(box, {
    id: "reading", label: "reading", options: READING_CHOICES, value: f.reading,
    onChange: (v) => {
      f.reading = v;
      if (v !== "custom") {
        Object.assign(f, READING_SETTINGS[v]);
        show();
      }
      onChange();
    },
  });
  reading.el.title = "The papers' controllers exactly as written (paper 000's standard funnelling, paper 001's relaxed funnelling), or this lab's reading, the defaults (the project's notes on the readings say what differs and why)";
  const inForce = document.createElement("p");
  inForce.className = "help controller-label";
  box.append(inForce);
  const bound = select(box, {
    id: "mu-bound", label: "μ bound", options: BOUND_CHOICES, value: f.bound,
    onChange: (v) => edited(() => { f.bound = v; })(),
  });
  bound.el.title = "How |μ| is bounded: atan(8·max(R_min, 1 m) / D), six times the paper's literal |η(D, Δη, 0, v_c, v_dt)|, the literal bound, or π/2";
  const aim = select(box, {
    id: "aim", label: "aim at", options: AIM_CHOICES, value: f.aim,
    onChange: (v) => edited(() => { f.aim = v; })(),
  });
  aim.el.title = "The table predicts the heading on reaching 0.25 m of the point it is asked about: asked about the disk's entry point, it predicts the heading on entering the tolerance";
  const pursuit = select(box, {
    id: "pursuit", label: "last stretch", options: PURSUIT_CHOICES, value: f.pursuit ? "on" : "off",
    onChange: (v) => edited(() => { f.pursuit = v === "on"; })(),
  });
  pursuit.el.title = "Lined up behind the disk, pursue a carrot on the goal's line one second ahead: heading error and lateral offset decay together";
  const relaxedAim = select(box, {
    id: "relaxed-aim", label: "relaxed aims at", options: RELAXED_AIM_CHOICES, value: f.relaxedAim,
    onChange: (v) => edited(() => { f.relaxedAim = v; })(),
  });
  relaxedAim.el.title = "For a relaxed (region) goal: the disk's entry point, as the standard controller (orients on entry), or paper 001's relaxed point on the ring arc (shorter paths, turns to the interval after entering)";
  const gain = numeric(box, "gain", { id: "mu-gain", lo: 1, hi: 4, step: 0.25 }, (v) => edited(() => { f.gain = v; })());
  const threshold = numeric(box, "th", { id: "seek-th", lo: 0.1, hi: 1, step: 0.05 }, (v) => edited(() => { f.threshold = v; })());
  /** The controls from `f` (a reading chosen). */
  const show = (): void => {
    bound.set(f.bound);
    aim.set(f.aim);
    pursuit.set(f.pursuit ? "on" : "off");
    relaxedAim.set(f.relaxedAim);
    gain.set(f.gain);
    threshold.set(f.threshold);
  };
  gain.el.title = "μ = −k·Δη before the bound (paper: k = 1)";
  threshold.el.title = "Plain seek (Position_only) once |Δη| is below this fraction of ε_tol (paper: 1)";
  return {
    inForce: (label, error) => {
      inForce.textContent = error ?? `In force: ${label ?? (f.reading === "custom" ? "custom settings" : f.reading === "paper" ? "the papers' reading" : "ours")}`;
    },
  };
}

/** What the panel updates once the controller is in force. */
export interface FunnelSection {
  /** Shows the core's name of the controller in force (null: not known
   *  here, the world steps in workers: the reading's name instead). */
  inForce(label: string | null, error: string | null): void;
}
