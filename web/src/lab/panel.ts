// The funnelling page's side panel: the playground's target, the controller
// settings, the vehicle limits, the overlays, the η field view, and sharing
// and export. Every control edits the page's state and hands it on. Each
// number's slider spans the core's range (crate/funnelling/ranges.rs) within
// a handy window, and its number box takes the whole range; the desired
// speeds' maximum follows the max speed, and lowering the max speed below
// the desired speed clamps the desired speed, with a message at its field.

import { button, checkbox, help, row, section, select, slider, type Control } from "../ui/controls";
import { referenceVehicles } from "../core/wasm";
import { bounds, field, parseField } from "./fields";
import { $ } from "../ui/page";
import { downloadPng } from "../ui/download";
import { downloadCsv, downloadJson } from "./export";
import { funnelSettingsSection, relaxedAimLabel } from "./funnelsettings";
import type { LabSim } from "./sim";
import type { Limits, Overlays } from "./state";

const DEG = Math.PI / 180;

/** A slider's handy window (stored units), within the core's range. */
interface Window {
  id: string;
  lo: number;
  hi: number;
  step: number;
  digits?: number;
}

/** The target sliders a drag on the canvas moves too. */
export interface GoalControls {
  beta: Control;
  epsTol: Control;
  dTol: Control;
}

export function buildPanel(sim: LabSim, canvas: HTMLCanvasElement): GoalControls {
  const st = sim.st;
  const panel = $("panel");
  const caption = $("caption");
  const updateGoal = (): void => sim.updateGoal();
  const controls = new Map<string, Control>();
  /** The slider and number box of the lab field with URL key `url`. */
  const numeric = (parent: HTMLElement, url: string, w: Window, onInput: (v: number) => void): Control => {
    const f = field(url);
    const b = bounds(f, sim.ranges, st, sim.defaults);
    const c = slider(parent, {
      id: w.id, label: f.label, unit: f.unit, min: Math.max(b.min, w.lo), max: Math.min(b.max, w.hi), step: w.step,
      value: f.get(st, sim.defaults), display: f.scale, digits: w.digits ?? 2,
      parse: (t) => parseField(f, t, sim.ranges, st, sim.defaults),
      onInput,
    });
    controls.set(url, c);
    return c;
  };
  /** Moves the sliders bounded by a vehicle limit (desired speeds ≤ max speed). */
  const followLimits = (): void => {
    for (const [url, hi, lo] of [["vd", 4, 0], ["fvd", 4, 0], ["fvc", 4, 0], ["fwc", 3, -3]] as const) {
      const b = bounds(field(url), sim.ranges, st, sim.defaults);
      controls.get(url)?.setRange(Math.max(b.min, lo), Math.min(b.max, hi));
    }
  };

  const goalBox = section(panel, "Target (playground)");
  // Under a preset the targets are the scenario's: the playground's
  // controls are hidden (not left greyed with the playground's values).
  const presetNote = document.createElement("p");
  presetNote.className = "help preset-note";
  presetNote.textContent = "This preset brings its own vehicles and targets. Choose \u201cplayground\u201d in the preset menu to drag and edit a target of your own.";
  presetNote.hidden = true;
  goalBox.before(presetNote);
  sim.onScene = (text, playground, claim, measured) => {
    caption.textContent = text;
    for (const [cls, head, body] of [["claim", "Paper: ", claim], ["measured", "Ours: ", aimWords(sim, measured)]] as const) {
      if (!body) continue;
      const p = document.createElement("span");
      p.className = `fidelity ${cls}`;
      p.append(Object.assign(document.createElement("b"), { textContent: head }), body);
      caption.append(p);
    }
    goalBox.hidden = !playground;
    presetNote.hidden = playground;
  };
  numeric(goalBox, "vd", { id: "speed", lo: 0, hi: 4, step: 0.01 }, (v) => { st.speed = v; updateGoal(); });
  const dTol = numeric(goalBox, "dtol", { id: "dtol", lo: 0, hi: 3, step: 0.01 }, (v) => { st.dTol = v; updateGoal(); });
  const epsTol = numeric(goalBox, "etol", { id: "etol", lo: 0.5 * DEG, hi: 90 * DEG, step: 0.5 * DEG, digits: 1 }, (v) => { st.epsTol = v; updateGoal(); });
  const beta = numeric(goalBox, "tb", { id: "beta", lo: -180 * DEG, hi: 180 * DEG, step: DEG, digits: 1 }, (v) => { st.target.theta = v; updateGoal(); });
  const goalRow = row(goalBox);
  checkbox(goalRow, "halting", "final halting", st.halting, (v) => { st.halting = v; updateGoal(); });
  const relaxedBox = checkbox(goalRow, "relaxed", "relaxed (region goal)", st.relaxed, (v) => { st.relaxed = v; updateGoal(); });
  relaxedBox.el.title = "paper 001: any point of the disk and any heading within β ± ε_tol is a valid goal";

  const controller = funnelSettingsSection(panel, st.funnel, () => { sim.applyFunnel(); sim.url.save(); }, (parent, url, w, onInput) => numeric(parent, url, w, onInput));
  sim.onController = (error) => controller.inForce(sim.controllerLabel(), error);

  const limBox = section(panel, "Vehicle limits");
  /** Clamped fields and a refusal of the core noted at their controls. */
  const applyLimits = (at: string): void => {
    const clamped = sim.applyParams((error) => controls.get(at)?.note(error));
    for (const c of clamped) {
      const ctl = controls.get(c.field.url);
      ctl?.set(c.field.get(st, sim.defaults));
      ctl?.note(c.message);
    }
    sim.url.save();
  };
  const lim = (url: string, key: keyof Limits, lo: number, hi: number, step = 0.05): void => {
    numeric(limBox, url, { id: url, lo, hi, step }, (v) => {
      st.limits[key] = v;
      followLimits();
      applyLimits(url);
    });
  };
  const vehicleSelect = vehicleMenu(limBox, sim, controls, (radiusChanged) => {
    followLimits();
    applyLimits("rmin");
    if (radiusChanged) sim.refitPlayground();
  });
  lim("vmax", "vMax", 0.05, 20);
  lim("amax", "accelMax", 0.05, 10);
  lim("wmax", "omegaMax", 0.05, 10);
  lim("awmax", "omegaAccelMax", 0.05, 60);
  lim("anmax", "normalAccelMax", 0.05, 10);
  lim("kp", "kp", 0.05, 400);
  lim("kd", "kd", 0.05, 60);
  lim("rmin", "minTurnRadius", 0, 20, 0.1);
  lim("vrev", "vReverse", 0, 20, 0.1);
  help(limBox).textContent = "Changing a limit builds the η table for it in Web Workers (the HUD's table line; the old table is approximate until then), cached in the browser for the next visit. Min. turning radius 0: turns on the spot; above 0 the vehicle is car-like (|ω| ≤ v/R_min): it arrives oriented by driving round. Max reverse speed above 0 gives a car-like vehicle a reverse gear: near its target it backs up where that is shorter, stopping at each change of gear.";
  // A limit edited by hand shows "custom" (or the vehicle it matches); the
  // select's own events are its own business.
  const syncVehicle = (ev: Event): void => {
    if (!(ev.target instanceof HTMLSelectElement)) vehicleSelect.sync();
  };
  limBox.addEventListener("input", syncVehicle);
  limBox.addEventListener("change", syncVehicle);
  // A preset bringing its own vehicle puts its limits on the controls.
  sim.onLimits = () => {
    for (const k of LIMIT_KEYS) controls.get(LIMIT_URL[k])?.set(st.limits[k] ?? sim.defaults[k]);
    followLimits();
    vehicleSelect.sync();
  };

  overlaySections(panel, sim, numeric);
  followLimits();
  exportSection(panel, sim, canvas);

  return { beta, epsTol, dTol };
}

/** Presets whose measurement (docs/presets.json) was made with the relaxed
 *  controller aiming at paper 001's relaxed point, not at our default. */
const MEASURED_WITH_PAPER_AIM = /^p001_fig10_/;

/** A preset's measurement in the panel's words: the aim it was measured
 *  with named as the "relaxed aims at" menu names it, and, when the menu
 *  is set otherwise, how to run it as measured. */
function aimWords(sim: LabSim, measured: string | undefined): string | undefined {
  if (!measured || !MEASURED_WITH_PAPER_AIM.test(sim.st.preset)) return measured;
  const paper = relaxedAimLabel("paperArc");
  const body = measured.replace(/^Paper-arc aim\b(\s*\([^)]*\))?:?\s*/i, "");
  const now = sim.st.funnel.relaxedAim === "paperArc" ? "" : ` (the Controller section's \u201crelaxed aims at\u201d is now \u201c${relaxedAimLabel(sim.st.funnel.relaxedAim)}\u201d: choose \u201c${paper}\u201d to run it as measured)`;
  return `Measured with \u201crelaxed aims at: ${paper}\u201d${now}: ${body}`;
}

/** The vehicle limits a reference vehicle sets, and their URL keys. */
const LIMIT_URL = { vMax: "vmax", accelMax: "amax", omegaMax: "wmax", omegaAccelMax: "awmax", normalAccelMax: "anmax", kp: "kp", kd: "kd", minTurnRadius: "rmin", vReverse: "vrev" } as const;
const LIMIT_KEYS = Object.keys(LIMIT_URL) as Array<keyof typeof LIMIT_URL>;

/** The reference vehicles' menu (every one, car-like included): choosing
 *  one sets every limit, then `applied`; `sync` shows the vehicle the
 *  limits match, or "custom". */
function vehicleMenu(parent: HTMLElement, sim: LabSim, controls: Map<string, Control>, applied: (radiusChanged: boolean) => void): { sync(): void } {
  const st = sim.st;
  const reference = referenceVehicles();
  // A unicycle's file has no radius: 0, turns on the spot.
  const limit = (r: (typeof reference)[number], k: keyof Limits): number => r.vehicle[k] ?? 0;
  const current = (): string =>
    reference.find((r) => LIMIT_KEYS.every((k) => Math.fround(st.limits[k] ?? sim.defaults[k]) === Math.fround(limit(r, k))))?.name ?? "custom";
  const menu = select(parent, {
    id: "vehicle", label: "vehicle", value: current(),
    options: [...reference.map((r) => ({ value: r.name, label: r.name.replace(/_/g, "-") })), { value: "custom", label: "custom" }],
    onChange: (name) => {
      const r = reference.find((x) => x.name === name);
      if (!r) return;
      const radius = st.limits.minTurnRadius ?? sim.defaults.minTurnRadius;
      for (const k of LIMIT_KEYS) {
        const v = limit(r, k);
        if (v === sim.defaults[k]) delete st.limits[k];
        else st.limits[k] = v;
        controls.get(LIMIT_URL[k])?.set(v);
      }
      applied(limit(r, "minTurnRadius") !== radius);
    },
  });
  menu.el.title = reference.map((r) => `${r.name}: ${r.description}`).join("\n");
  return { sync: () => menu.set(current()) };
}

type Numeric = (parent: HTMLElement, url: string, w: Window, onInput: (v: number) => void) => Control;

/** The overlay switches and the η field view's sliders. */
function overlaySections(panel: HTMLElement, sim: LabSim, numeric: Numeric): void {
  const st = sim.st;
  const ovBox = section(panel, "Overlays");
  const ov = (key: keyof Overlays, label: string): void => {
    checkbox(ovBox, `ov-${key}`, label, st.overlays[key], (v) => { st.overlays[key] = v; sim.dirty = true; sim.url.save(); });
  };
  ov("radial", "radial direction");
  ov("eta", "η at target");
  ov("ghost", "predicted seek path (η)");
  ov("gamma", "heading γ");
  ov("ring", "nearest η ring");
  ov("arc", "relaxed arc 𝒜, α_r");
  ov("trails", "trails");
  ov("field", "η field (Fig. 3b/c)");

  const fieldBox = section(panel, "η field view");
  const fieldSlider = (url: string, key: "vC" | "omegaC" | "vD", lo: number, hi: number): void => {
    numeric(fieldBox, url, { id: url, lo, hi, step: 0.05 }, (v) => { st.field[key] = v; sim.dirty = true; sim.url.save(); });
  };
  fieldSlider("fvc", "vC", 0, 4);
  fieldSlider("fwc", "omegaC", -3, 3);
  fieldSlider("fvd", "vD", 0, 4);
  help(fieldBox).textContent = "Arrows: final direction α+η at each sampled target around the vehicle; darker = unreachable at v_d (η shown for the stored v_dt).";
}

/** Share and export: link, trajectories, picture. */
function exportSection(panel: HTMLElement, sim: LabSim, canvas: HTMLCanvasElement): void {
  const exBox = section(panel, "Share and export");
  const exRow = row(exBox);
  button(exRow, "copy-link", "Copy link", "Copy a link with the whole state", () => {
    sim.url.writeNow();
    void navigator.clipboard?.writeText(location.href).catch(() => {});
  });
  button(exRow, "csv", "CSV", "Trajectories as CSV", () => downloadCsv(sim.trails));
  button(exRow, "json", "JSON", "Trajectories as JSON", () => downloadJson(sim.trails, { state: sim.st, params: sim.params() }));
  button(exRow, "png", "PNG", "The canvas as PNG", () => downloadPng(canvas));
  help(exBox).innerHTML = "<kbd>space</kbd> pause · <kbd>s</kbd> step · <kbd>r</kbd> reset · drag empty space to pan, wheel to zoom.";
}
