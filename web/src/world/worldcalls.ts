// The calls that build and edit the lab's world, made by whichever thread
// steps it: the page's (world.ts, `HereWorld`) or a stepping worker's
// (../workers/step.worker.ts). The page describes a world (`Recipe`) and its
// edits (`Edit`) as plain data; the core of the thread that steps checks
// each call once and says what it refused (`EditAnswer`). No DOM here: the
// worker bundle imports this module.

import { errorText, type AgentConfig, type FunnelConfig, type GoalConfig, type Lab, type Reading, type RelaxedConfig, type VehicleParams } from "../core/wasm";

/** The avoidance methods, as the core and the URL name them. */
export const AVOID_KEYS = ["off", "separation", "orca"] as const;
export type AvoidKey = (typeof AVOID_KEYS)[number];

/** Where the η table in force comes from: its bytes (a table built for
 *  other limits) or the committed table's URL. */
export interface TableSource {
  key: string;
  url: string;
  bytes: Uint8Array | null;
}

/** The page's choices of avoidance over a scenario's own (null: the scenario's). */
export interface AvoidChoice {
  method: AvoidKey | null;
  replanEvery: number | null;
  obstacles: number[] | null;
}

/** Everything that builds one world at t = 0. */
export interface Recipe {
  table: TableSource;
  params: VehicleParams;
  /** The limits the page set (over a preset's own vehicle). */
  limits: Partial<VehicleParams>;
  funnel: FunnelConfig;
  relaxed: RelaxedConfig;
  /** A reading of the papers in force (`Lab.setReading`, every setting of
   *  it), or null: `funnel` and `relaxed` as they are. */
  reading: Reading | null;
  build:
    | { kind: "scenario"; name: string; text: string }
    | { kind: "playground"; agent: AgentConfig; spawn: { n: number; seed: number; extent: number; speed: number } | null };
  avoid: AvoidChoice;
}

/** The avoidance in force in a world, as its core reports it. */
export interface AvoidInfo {
  method: AvoidKey;
  obstacles: number[];
  radius: number;
  replanEvery: number;
}

/** A message of a build (shown on the page). */
export interface BuildMessage {
  text: string;
  level: "warn" | "error";
}

/** What a build says about the world it made. */
export interface BuildInfo {
  count: number;
  dt: number;
  /** The vehicle parameters in force (the recipe's unless refused). */
  params: VehicleParams;
  /** The scenario's caption and bounding box (a preset), else null. */
  scenario: { caption: string; claim?: string; measured?: string; box: [number, number, number, number] } | null;
  avoid: AvoidInfo;
  messages: BuildMessage[];
  /** Whether the limits were refused (the page then shows the world's). */
  paramsRefused: boolean;
}

/** An edit of the running world (`i`: an agent's index in the whole world). */
export type Edit =
  | { kind: "goal"; i: number; goal: GoalConfig }
  | { kind: "pose"; i: number; x: number; y: number; theta: number }
  | { kind: "funnel"; funnel: FunnelConfig; relaxed: RelaxedConfig; reading: Reading | null }
  | { kind: "params"; params: VehicleParams }
  | { kind: "table"; bytes: Uint8Array; key: string }
  | { kind: "avoid"; method?: AvoidKey; replanEvery?: number; obstacles?: number[] };

/** What the world says to an edit: why it was refused (null: applied), and
 *  after an avoidance edit the avoidance in force. */
export interface EditAnswer {
  error: string | null;
  avoid: AvoidInfo | null;
}

/** What a refused edit of each kind is called in a message. */
const EDIT_NAMES: Record<Edit["kind"], string> = {
  goal: "Goal",
  pose: "Pose",
  funnel: "Controller settings",
  params: "Vehicle limits",
  table: "η table",
  avoid: "Avoidance settings",
};

/** The avoidance in force in `lab`. */
export function avoidInfo(lab: Lab): AvoidInfo {
  const m = lab.avoidance();
  return {
    method: (AVOID_KEYS as readonly string[]).includes(m) ? (m as AvoidKey) : "off",
    obstacles: Array.from(lab.obstacles()),
    radius: lab.avoidanceRadius(),
    replanEvery: lab.avoidanceReplanEvery(),
  };
}

function applyAvoid(lab: Lab, a: { method?: AvoidKey | null; replanEvery?: number | null; obstacles?: number[] | null }): void {
  if (a.method != null) lab.setAvoidance(a.method);
  if (a.replanEvery != null) lab.setAvoidanceReplanEvery(a.replanEvery);
  if (a.obstacles != null) lab.setObstacles(new Float32Array(a.obstacles));
}

/** Builds `recipe`'s whole world in `lab` (an empty one on the table in
 *  force): the limits, the scenario or the playground, the controller
 *  settings, the avoidance. A refused part is a message; the rest is built. */
export function buildWorld(lab: Lab, recipe: Recipe): BuildInfo {
  const messages: BuildMessage[] = [];
  const warn = (text: string, level: BuildMessage["level"] = "warn"): void => void messages.push({ text, level });
  let paramsRefused = false;
  const setParams = (params: VehicleParams): void => {
    try {
      lab.setParams(params);
    } catch (e) {
      paramsRefused = true;
      warn(`Vehicle limits rejected: ${errorText(e)}`);
    }
  };
  setParams(recipe.params);
  let scenario: BuildInfo["scenario"] = null;
  const b = recipe.build;
  if (b.kind === "scenario") {
    try {
      const info = lab.loadScenario(b.text);
      // The page's vehicle limits apply to presets too (`#preset=…&vmax=0.05`
      // runs at 0.05 m/s), over the preset's own vehicle (a car-like
      // preset keeps its turning radius).
      setParams({ ...lab.params(), ...recipe.limits });
      scenario = {
        caption: `${info.description}${info.source ? ` (${info.source})` : ""} — ${info.agents} agent${info.agents === 1 ? "" : "s"}.`,
        ...(info.claim ? { claim: info.claim } : {}),
        ...(info.measured ? { measured: info.measured } : {}),
        box: [info.minX, info.minY, info.maxX, info.maxY],
      };
      // The core's warning is a table built for other limits: the page
      // builds the matching one and the HUD labels the old one approximate
      // meanwhile (../lab/sim.ts, syncTable).
    } catch (e) {
      warn(`Preset ${b.name} could not be loaded: ${errorText(e)}`, "error");
    }
  } else {
    try {
      lab.addAgent(b.agent);
      if (b.spawn) lab.spawnRandom(b.spawn.n, b.spawn.seed, b.spawn.extent, b.spawn.speed);
    } catch (e) {
      warn(`The playground could not be set up: ${errorText(e)}`, "error");
    }
  }
  try {
    setController(lab, recipe);
  } catch (e) {
    warn(`Controller settings rejected: ${errorText(e)}`);
  }
  try {
    applyAvoid(lab, recipe.avoid);
  } catch (e) {
    warn(`Avoidance settings rejected: ${errorText(e)}`);
  }
  const params = lab.params();
  return { count: lab.count(), dt: params.dt, params, scenario, avoid: avoidInfo(lab), messages, paramsRefused };
}

/** The controller's settings: a whole reading, or the page's own. */
function setController(lab: Lab, c: { funnel: FunnelConfig; relaxed: RelaxedConfig; reading: Reading | null }): void {
  if (c.reading !== null) {
    lab.setReading(c.reading);
  } else {
    lab.setFunnel(c.funnel);
    lab.setRelaxed(c.relaxed);
  }
}

/** Applies `e` to `lab`, which holds the world's agents `start..end`
 *  (renumbered from 0): an agent's edit outside them is not this slice's.
 *  The core checks it; a refusal changes nothing and is answered. */
export function applyEdit(lab: Lab, e: Edit, start: number, end: number): EditAnswer {
  let error: string | null = null;
  try {
    switch (e.kind) {
      case "goal":
        if (e.i >= start && e.i < end) lab.setGoal(e.i - start, e.goal);
        break;
      case "pose":
        if (e.i >= start && e.i < end) lab.setPose(e.i - start, e.x, e.y, e.theta);
        break;
      case "funnel":
        setController(lab, e);
        break;
      case "params":
        lab.setParams(e.params);
        break;
      case "table":
        lab.setTable(e.bytes, e.key);
        break;
      case "avoid":
        applyAvoid(lab, e);
        break;
    }
  } catch (err) {
    error = `${EDIT_NAMES[e.kind]} rejected: ${errorText(err)}`;
  }
  return { error, avoid: e.kind === "avoid" ? avoidInfo(lab) : null };
}
