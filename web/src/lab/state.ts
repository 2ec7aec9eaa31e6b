// The lab's user-editable state: everything the URL shares. Plain data.

import type { Insets, View } from "../ui/view";
import type { GoalConfig } from "../core/wasm";
import type { AvoidKey } from "../world/worldcalls";

export interface Pose {
  x: number;
  y: number;
  theta: number;
}

export interface Overlays {
  radial: boolean;
  eta: boolean;
  gamma: boolean;
  ring: boolean;
  field: boolean;
  trails: boolean;
  arc: boolean;
  /** The predicted seek path behind η (paper 000 Fig. 1c; crate::ghost). */
  ghost: boolean;
}

/** Vehicle limits the sliders edit; absent = the core's default. */
export interface Limits {
  vMax?: number;
  accelMax?: number;
  omegaMax?: number;
  omegaAccelMax?: number;
  normalAccelMax?: number;
  /** Seek gains (a reference vehicle may set them). */
  kp?: number;
  kd?: number;
  /** Minimum turning radius at every speed, m (car-like: |ω| ≤ v/R_min;
   *  0, the core's default, turns on the spot). */
  minTurnRadius?: number;
  /** Largest reverse speed, m/s (0, the core's default: forward only; a
   *  car-like vehicle with one backs where that is shorter). */
  vReverse?: number;
}

/** The μ-bound choices of the controller section, as the URL writes them:
 *  turning radius ×8 (the core's default), 6 × literal, literal, constant π/2. */
export const BOUND_KEYS = ["tr", "sl", "lit", "const"] as const;
export type BoundKey = (typeof BOUND_KEYS)[number];

/** Where the funnel aims: the disk's entry point (the core's default) or the
 *  goal centre (the paper). */
export const AIM_KEYS = ["entry", "centre"] as const;
export type AimKey = (typeof AIM_KEYS)[number];

/** Where the relaxed controller aims: the disk's entry point (the core's
 *  default) or paper 001's relaxed point on the ring arc. */
export const RELAXED_AIM_KEYS = ["entry", "paperArc"] as const;
export type RelaxedAimKey = (typeof RELAXED_AIM_KEYS)[number];

/** Which reading of the papers is in force (the core's `Reading`): the
 *  papers' algorithms as written, ours (the defaults), or custom (a
 *  setting edited by hand). */
export const READING_KEYS = ["ours", "paper", "custom"] as const;
export type ReadingKey = (typeof READING_KEYS)[number];

/** The funnelling controller's settings as the page edits them. */
export interface FunnelSettings {
  /** The reading the settings below are (custom: edited by hand). */
  reading: ReadingKey;
  bound: BoundKey;
  aim: AimKey;
  /** The terminal line pursuit on the last stretch (core default: on). */
  pursuit: boolean;
  /** Where the relaxed controller aims (core default: the entry point). */
  relaxedAim: RelaxedAimKey;
  /** μ = −gain·Δη before the bound. */
  gain: number;
  /** Position_only once |Δη| < threshold·ε_tol. */
  threshold: number;
}

/** The page's controls as each reading sets them (the core's
 *  `FunnelConfig::default` / `paper_000`, `RelaxedConfig::default` /
 *  `paper_001`; what the panel does not show, `Lab.setReading` sets). */
export const READING_SETTINGS: Readonly<Record<"ours" | "paper", Omit<FunnelSettings, "reading">>> = {
  ours: { bound: "tr", aim: "entry", pursuit: true, relaxedAim: "entry", gain: 2, threshold: 0.25 },
  paper: { bound: "lit", aim: "centre", pursuit: false, relaxedAim: "paperArc", gain: 1, threshold: 1 },
};

/** `f` made consistent: a named reading puts its settings on the
 *  controls; without one (`named` false: an older link) the settings
 *  are ours if they equal ours, else custom. */
export function settleReading(f: FunnelSettings, named: boolean): void {
  if (named && f.reading !== "custom") {
    Object.assign(f, READING_SETTINGS[f.reading]);
    return;
  }
  if (!named) {
    const o = READING_SETTINGS.ours;
    const same = (Object.keys(o) as Array<keyof typeof o>).every((k) => o[k] === f[k]);
    f.reading = same ? "ours" : "custom";
  }
}

export interface LabState {
  /** Start pose of the playground vehicle (agent 0). */
  vehicle: Pose;
  /** Target position and orientation β (rad). */
  target: Pose;
  /** Position tolerance (m) = circle radius. */
  dTol: number;
  /** Orientation tolerance (rad) = triangle half-opening. */
  epsTol: number;
  /** Desired speed (m/s). */
  speed: number;
  halting: boolean;
  /** The compare view: Yuka's arrive and seek ghosts beside ours (compareview.ts). */
  compare: boolean;
  relaxed: boolean;
  limits: Limits;
  /** Controller settings, shared by every agent (presets included). */
  funnel: FunnelSettings;
  overlays: Overlays;
  /** η field view inputs: current speed, angular speed, desired speed. */
  field: { vC: number; omegaC: number; vD: number };
  /** Avoidance method chosen in the panel or the link; null = the
   *  scenario's own (the playground's: off). A preset change resets it. */
  avoidance: AvoidKey | null;
  /** Steps between an agent's avoidance plans (the core's
   *  `avoidance.replanEvery`); null = the scenario's own. A preset change
   *  resets it. */
  replanEvery: number | null;
  /** Obstacles as edited (lab/obstacles.ts layout); null = the scenario's
   *  own. A preset change resets them. */
  obstacles: number[] | null;
  /** Scenario file name without .json; "" = playground. */
  preset: string;
  /** Extra funnelling agents spawned at random (performance runs). */
  agents: number;
  seed: number;
  /** What steps the random crowd: the workers, or the GPU kernel (gpukeys.ts, docs/DESIGN.md §20). */
  engine: "workers" | "gpu";
  /** The GPU crowd's agents (with engine "gpu"). */
  gpuAgents: number;
  slow: boolean;
  /** The view (world point at the canvas centre, px per m); null = fit. */
  view: { cx: number; cy: number; scale: number } | null;
}

export function defaultState(): LabState {
  return {
    vehicle: { x: -4, y: -1, theta: 0 },
    target: { x: 3, y: 1.5, theta: Math.PI / 2 },
    dTol: 0.3,
    epsTol: (10 * Math.PI) / 180,
    speed: 1.3,
    halting: true,
    compare: false,
    relaxed: false,
    limits: {},
    // The core's FunnelConfig::default() (e2e checks they agree).
    funnel: { reading: "ours", bound: "tr", aim: "entry", pursuit: true, relaxedAim: "entry", gain: 2, threshold: 0.25 },
    overlays: { radial: true, eta: true, gamma: true, ring: false, field: false, trails: true, arc: false, ghost: true },
    field: { vC: 0.5, omegaC: 0, vD: 1.3 },
    avoidance: null,
    replanEvery: null,
    obstacles: null,
    preset: "",
    agents: 0,
    seed: 1,
    engine: "workers",
    gpuAgents: 1_000_000,
    slow: false,
    view: null,
  };
}

/** The playground agent's goal in the core's terms (the page's sim, and the
 *  build's first frame, vite.config.ts). */
export function goalConfig(st: LabState): GoalConfig {
  return {
    x: st.target.x,
    y: st.target.y,
    beta: st.target.theta,
    dTol: st.dTol,
    epsTol: st.epsTol,
    speed: st.speed,
    halting: st.halting,
    relaxed: st.relaxed,
  };
}

/** The view of the playground without extra agents: the vehicle and the
 *  target with 3 m around them (the page's first build, and the first
 *  frame drawn from the HTML, which must not jump when the core takes
 *  over). */
export function fitPlayground(view: View, st: LabState): void {
  const xs = [st.vehicle.x, st.target.x];
  const ys = [st.vehicle.y, st.target.y];
  // A phone's stage is small: less world round the two, so that the
  // target's tolerance circle is not a dot; the handles (56 px) fit in the margins.
  const pad = Math.max(view.width < PHONE_PX ? 1.2 : 3, loopReach(st.limits.minTurnRadius));
  view.fit(Math.min(...xs) - pad, Math.min(...ys) - pad, Math.max(...xs) + pad, Math.max(...ys) + pad, (v) => stageInsets(v, 60));
}

/** How far beyond its start and its goal a fitted view keeps room for a
 *  car-like vehicle's loops, m: a shortest (Dubins) path turns at most
 *  two radii out, and the funnel's turns are wider than Dubins' (its path
 *  is about 1.3 times as long), so three radii. Zero for a vehicle that
 *  turns on the spot. */
export function loopReach(minTurnRadius: number | undefined): number {
  return 3 * (minTurnRadius ?? 0);
}

/** Below this stage width (CSS px) the lab lays out for a phone. */
export const PHONE_PX = 560;

/** Below this stage height (CSS px) the lab's stage is short (a phone on
 *  its side): its HUD is folded, its margins are a phone's. */
export const SHORT_PX = 360;

/** The room the unfolded HUD takes at the stage's top left on a wide
 *  stage, CSS px (style.css: 21em of 12 px, padding, border, 8 px off the
 *  edge), and its usual height with its numbers. */
export const HUD_BOX = { right: 290, bottom: 250 } as const;

/** The margins of a fit of many agents (presets, a crowd): as
 *  {@link stageInsets}, and on a wide stage clear of the unfolded HUD too:
 *  beside it on a landscape stage, below it on a portrait one. */
export function crowdInsets(view: View, margin: number): number | Insets {
  const base = stageInsets(view, margin);
  if (typeof base !== "number") return base;
  return view.width >= view.height
    ? { left: HUD_BOX.right + 12, right: margin, top: margin, bottom: margin }
    : { left: margin, right: margin, top: HUD_BOX.bottom + 12, bottom: margin };
}

/** The margins a fit keeps on the lab's stage: `margin` on a wide one; on
 *  a phone or a short stage, room for the folded HUD above (its mode, what
 *  the agent does, the speed line) and the legend below. */
export function stageInsets(view: View, margin: number): number | Insets {
  return view.width < PHONE_PX || view.height < SHORT_PX ? { left: 28, right: 28, top: 92, bottom: 64 } : margin;
}
