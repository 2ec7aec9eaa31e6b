// The funnelling page's header controls: play/pause, single step, slow
// motion, reset, the preset menu, and their keys (space, s, r).

import { button } from "../ui/controls";
import { $ } from "../ui/page";
import { PRESET_GROUPS, PRESETS, presetGroup, presetOrder, presetTitle } from "./presets";
import type { LabSim } from "./sim";

export interface Transport {
  setPaused(p: boolean): void;
  /** Loads a preset ("" = the playground), fitting the view. */
  setPreset(name: string): Promise<void>;
}

export function buildTransport(sim: LabSim): Transport {
  const st = sim.st;
  const bar = $("transport");
  const playBtn = button(bar, "play", "Pause", "Play / pause (space)", () => setPaused(!sim.paused));
  button(bar, "step", "Step", "Single step (s)", () => stepOnce());
  const slowBtn = button(bar, "slow", "Slow ×¼", "Slow motion", () => {
    st.slow = !st.slow;
    slowBtn.setAttribute("aria-pressed", String(st.slow));
    sim.url.save();
  });
  slowBtn.setAttribute("aria-pressed", String(st.slow));
  button(bar, "reset", "Reset", "Reset (r)", () => void sim.rebuild(false));

  const setPaused = (p: boolean): void => {
    sim.paused = p;
    // A frame for the HUD's "paused" (a paused world draws only edits).
    sim.dirty = true;
    playBtn.textContent = p ? "▶ Play" : "Pause";
    playBtn.setAttribute("aria-pressed", String(p));
  };
  const stepOnce = (): void => {
    setPaused(true);
    sim.stepOnce();
  };

  const presetSel = $<HTMLSelectElement>("preset");
  const addOpt = (parent: HTMLElement, value: string, label: string): void => {
    const o = document.createElement("option");
    o.value = value;
    o.textContent = label;
    parent.append(o);
  };
  addOpt(presetSel, "", "playground");
  // Grouped by paper and figure; each preset's claim and our
  // measurement show in the side panel's caption.
  const groups = new Map<string, HTMLOptGroupElement>();
  for (const label of PRESET_GROUPS) {
    const g = document.createElement("optgroup");
    g.label = label;
    groups.set(label, g);
  }
  for (const p of [...PRESETS].sort((a, b) => presetOrder(a.name, b.name))) {
    const g = groups.get(presetGroup(p.name));
    if (g) addOpt(g, p.name, presetTitle(p.name));
  }
  for (const g of groups.values()) if (g.children.length > 0) presetSel.append(g);
  presetSel.value = st.preset;
  const setPreset = async (name: string): Promise<void> => {
    sim.dropPresetVehicle();
    st.preset = name;
    // Each scenario brings its own avoidance and obstacles.
    st.avoidance = null;
    st.replanEvery = null;
    st.obstacles = null;
    presetSel.value = name;
    await sim.rebuild(true);
    sim.url.save();
  };
  presetSel.addEventListener("change", () => void setPreset(presetSel.value));

  window.addEventListener("keydown", (e) => {
    const t = e.target;
    // A focused control keeps its own keys (space ticks a checkbox); a
    // canvas handle's focus target (keyboard.ts) has only its arrows.
    const handle = t instanceof HTMLElement && t.classList.contains("keyhandle");
    if (!handle && (t instanceof HTMLSelectElement || t instanceof HTMLButtonElement || (t instanceof HTMLInputElement && (t.type === "text" || t.type === "checkbox")))) return;
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    if (e.key === " ") {
      e.preventDefault();
      setPaused(!sim.paused);
    } else if (e.key === "s" || e.key === "S") {
      stepOnce();
    } else if (e.key === "r" || e.key === "R") {
      void sim.rebuild(false);
    }
  });
  return { setPaused, setPreset };
}
