// The funnelling page's side panel: the playground's target, the controller
// settings, the vehicle limits, the overlays, the η field view, and sharing
// and export. Every control edits the page's state and hands it on.

import { button, checkbox, help, row, section, slider, type Control } from "../controls";
import { $ } from "../page";
import { downloadPng } from "../download";
import { downloadCsv, downloadJson } from "./export";
import { funnelSettingsSection } from "./funnelsettings";
import type { LabSim } from "./sim";
import type { Overlays } from "./state";

const DEG = Math.PI / 180;

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

  const goalBox = section(panel, "Target (playground)");
  sim.onScene = (text, playground) => {
    caption.textContent = text;
    goalBox.disabled = !playground;
  };
  slider(goalBox, {
    id: "speed", label: "desired speed v_d", unit: "m/s", min: 0.1, max: 4, step: 0.05, value: st.speed,
    onInput: (v) => { st.speed = v; updateGoal(); },
  });
  const dTol = slider(goalBox, {
    id: "dtol", label: "position tol. D_tol", unit: "m", min: 0.02, max: 3, step: 0.01, value: st.dTol,
    onInput: (v) => { st.dTol = v; updateGoal(); },
  });
  const epsTol = slider(goalBox, {
    id: "etol", label: "orient. tol. ε_tol", unit: "°", min: 0.5 * DEG, max: 90 * DEG, step: 0.5 * DEG, value: st.epsTol,
    display: 1 / DEG, digits: 1, onInput: (v) => { st.epsTol = v; updateGoal(); },
  });
  const beta = slider(goalBox, {
    id: "beta", label: "orientation β", unit: "°", min: -180 * DEG, max: 180 * DEG, step: DEG, value: st.target.theta,
    display: 1 / DEG, digits: 0, onInput: (v) => { st.target.theta = v; updateGoal(); },
  });
  const goalRow = row(goalBox);
  checkbox(goalRow, "halting", "final halting", st.halting, (v) => { st.halting = v; updateGoal(); });
  const relaxedBox = checkbox(goalRow, "relaxed", "relaxed (region goal)", st.relaxed, (v) => { st.relaxed = v; updateGoal(); });
  relaxedBox.el.title = "paper 001: any point of the disk and any heading within β ± ε_tol is a valid goal";

  funnelSettingsSection(panel, st.funnel, () => { sim.applyFunnel(); sim.url.save(); });

  const limBox = section(panel, "Vehicle limits");
  const lim = (id: string, key: "vMax" | "accelMax" | "omegaMax" | "omegaAccelMax" | "normalAccelMax", label: string, unit: string, max: number): void => {
    slider(limBox, {
      id, label, unit, min: 0.05, max, step: 0.05, value: st.limits[key] ?? sim.defaults[key],
      onInput: (v) => { st.limits[key] = v; sim.applyParams(); sim.url.save(); },
    });
  };
  lim("vmax", "vMax", "max speed", "m/s", 6);
  lim("amax", "accelMax", "max accel.", "m/s²", 10);
  lim("wmax", "omegaMax", "max ang. speed", "rad/s", 10);
  lim("awmax", "omegaAccelMax", "max ang. accel.", "rad/s²", 60);
  lim("anmax", "normalAccelMax", "max normal acc. A", "m/s²", 10);

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
  const fieldSlider = (id: string, key: "vC" | "omegaC" | "vD", label: string, unit: string, min: number, max: number): void => {
    slider(fieldBox, {
      id, label, unit, min, max, step: 0.05, value: st.field[key],
      onInput: (v) => { st.field[key] = v; sim.dirty = true; sim.url.save(); },
    });
  };
  fieldSlider("fvc", "vC", "current v_c", "m/s", 0, 4);
  fieldSlider("fwc", "omegaC", "current ω_c", "rad/s", -3, 3);
  fieldSlider("fvd", "vD", "desired v_d", "m/s", 0.1, 4);
  help(fieldBox).textContent = "Arrows: final direction α+η at each sampled target around the vehicle; darker = unreachable at v_d (η shown for the stored v_dt).";

  const exBox = section(panel, "Share and export");
  const exRow = row(exBox);
  button(exRow, "copy-link", "Copy link", "Copy a link with the whole state", () => {
    sim.url.writeNow();
    void navigator.clipboard?.writeText(location.href).catch(() => {});
  });
  button(exRow, "csv", "CSV", "Trajectories as CSV", () => downloadCsv(sim.trails));
  button(exRow, "json", "JSON", "Trajectories as JSON", () => downloadJson(sim.trails, { state: st, params: sim.params() }));
  button(exRow, "png", "PNG", "The canvas as PNG", () => downloadPng(canvas));
  help(exBox).innerHTML = "<kbd>space</kbd> pause · <kbd>s</kbd> step · <kbd>r</kbd> reset · drag empty space to pan, wheel to zoom.";

  return { beta, epsTol, dTol };
}
