// The side panel's crowd section: how many funnelling agents the
// playground spawns at random besides its own (the link's `n`, up to the
// core's range), their seed, and whether they avoid each other. A count
// or a seed builds the world again (the playground, from t = 0); the
// HUD's speed line then says how fast it runs.

import { checkbox, help, row, section, select } from "../ui/controls";
import { field, parseField } from "./fields";
import type { LabSim } from "./sim";
import type { Transport } from "./transport";

/** The menu's counts; the core's largest is added. */
const COUNTS = [0, 10, 100, 1000, 3000, 10_000, 30_000] as const;

const fmt = (n: number): string => n.toLocaleString("en");

/** Builds the section before the avoidance section (or at the panel's end). */
export function crowdSection(panel: HTMLElement, sim: LabSim, transport: Transport): void {
  const st = sim.st;
  const box = section(panel, "Crowd");
  box.id = "crowd";
  const avoidBox = [...panel.querySelectorAll("fieldset")].find((f) => f.querySelector("#avoidance"));
  avoidBox?.before(box);
  const max = sim.ranges.get(field("n").core).max;
  const counts = [...COUNTS.filter((n) => n < max), max];
  const custom = "custom";
  const value = (): string => (counts.includes(st.agents) ? String(st.agents) : custom);
  const apply = async (n: number, seed: number): Promise<void> => {
    st.agents = n;
    st.seed = seed;
    // The agents join the playground: a preset is left for it.
    if (st.preset) await transport.setPreset("");
    else await sim.rebuild(true);
    sim.url.save();
    menu.set(value());
    typed.value = String(n);
  };
  const menu = select(box, {
    id: "crowd-count", label: "random agents",
    options: [...counts.map((n) => ({ value: String(n), label: n === max ? `${fmt(n)} (the most)` : fmt(n) })), { value: custom, label: "other (type below)" }],
    value: value(),
    onChange: (v) => {
      if (v === custom) typed.focus();
      else void apply(Number(v), st.seed);
    },
  });
  menu.el.title = "Funnelling agents spawned at random round the playground, each with a target of its own (besides the vehicle you drag)";
  const r = row(box);
  const typed = numberBox(r, "crowd-n", "count", String(st.agents), (t) => parseField(field("n"), t, sim.ranges, st, sim.defaults), (v) => void apply(v, st.seed));
  numberBox(r, "crowd-seed", "seed", String(st.seed), (t) => parseField(field("seed"), t, sim.ranges, st, sim.defaults), (v) => void apply(st.agents, v));
  const avoid = checkbox(box, "crowd-avoid", "avoid each other (ORCA)", sim.avoid.method !== "off", (on) => {
    sim.avoid.setMethod(on ? "orca" : "off");
    sim.dirty = true;
    sim.url.save();
  });
  avoid.el.title = "On: reciprocal velocity obstacles keep the agents apart (the Avoidance section has the other methods); it couples every agent, so the world then steps on this page's thread";
  const show = sim.avoid.onChange;
  sim.avoid.onChange = () => {
    show();
    avoid.set(sim.avoid.method !== "off");
  };
  help(box).textContent = `Up to ${fmt(max)} agents. The HUD's speed line says how many frames a second are drawn and how much simulated time passes per second: below 1× the simulation runs slower than real time.`;
}

/** A labelled number box that applies on Enter or on leaving it, or shows why not. */
function numberBox(parent: HTMLElement, id: string, label: string, value: string, parse: (t: string) => { value: number } | { error: string }, apply: (v: number) => void): HTMLInputElement {
  const l = document.createElement("label");
  l.className = "numbox";
  l.append(`${label} `);
  const input = document.createElement("input");
  input.id = id;
  input.type = "text";
  input.inputMode = "numeric";
  input.value = value;
  input.size = 7;
  l.append(input);
  parent.append(l);
  let last = value;
  input.addEventListener("change", () => {
    const r = parse(input.value);
    if ("error" in r) {
      input.setCustomValidity(r.error);
      input.reportValidity();
      input.title = r.error;
      return;
    }
    input.setCustomValidity("");
    input.title = "";
    if (input.value === last) return;
    last = input.value;
    apply(r.value);
  });
  return input;
}
