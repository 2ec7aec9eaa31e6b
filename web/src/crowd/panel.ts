// The crowd page's side panel: seek, separation, boid count (one box), path radius,
// display switches, path editing buttons, metrics. Built on ../controls.

import { button, checkbox, help, row, section, slider } from "../ui/controls";
import { decideCount, PAGE_MAX_BOIDS } from "./count";
import type { CrowdMetrics, CrowdSeek } from "../core/wasm";

/** The paper's five seeks, in preset order. */
export const SEEKS: { tag: string; label: string; seek: CrowdSeek }[] = [
  { tag: "reynolds", label: "Reynolds", seek: { kind: "reynolds" } },
  { tag: "parker100", label: "Parker 100 %", seek: { kind: "parker", fraction: 1 } },
  { tag: "parker10", label: "Parker 10 %", seek: { kind: "parker", fraction: 0.1 } },
  { tag: "parker1", label: "Parker 1 %", seek: { kind: "parker", fraction: 0.01 } },
  { tag: "parker0.1", label: "Parker 0.1 %", seek: { kind: "parker", fraction: 0.001 } },
];

/** Index into SEEKS of a seek (nearest Parker fraction), or -1. */
export function seekIndex(s: CrowdSeek): number {
  if (s.kind === "reynolds") return 0;
  let best = -1;
  let bestD = Infinity;
  SEEKS.forEach((o, i) => {
    if (o.seek.kind !== "parker") return;
    const d = Math.abs(Math.log(o.seek.fraction) - Math.log(s.fraction));
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  });
  return bestD < 1e-3 ? best : -1;
}

export interface PanelActions {
  seek(s: CrowdSeek): void;
  separation(on: boolean, weight: number): void;
  boids(n: number): void;
  radius(r: number): void;
  closed(c: boolean): void;
  speed(stepsPerFrame: number): void;
  /** Count changes scale the pathway (Test IV's boids per length). */
  density(on: boolean): void;
  showTrace(on: boolean): void;
  showHandles(on: boolean): void;
  addPoint(): void;
  removePoint(): void;
  fit(): void;
  resetMetrics(): void;
  newTrace(): void;
  png(): void;
}

export interface PanelState {
  seek: CrowdSeek;
  separation: boolean;
  weight: number;
  boids: number;
  radius: number;
  closed: boolean;
}

export interface Panel {
  set(s: PanelState): void;
  showMetrics(m: CrowdMetrics, overlapsNow: number, boids: number): void;
  /** No measures (the crowd steps in workers): `why` instead. */
  metricsOff(why: string): void;
}

function fmt(v: number | null, digits: number, unit = ""): string {
  return v === null ? "—" : `${v.toFixed(digits)}${unit}`;
}

/** The seek select, the separation switch and its weight. */
function steeringSection(parent: HTMLElement, initial: PanelState, a: PanelActions): (s: PanelState) => void {
  const strat = section(parent, "Steering");
  const seekRow = document.createElement("label");
  seekRow.className = "numrow";
  seekRow.append("Seek");
  const seekSel = document.createElement("select");
  seekSel.id = "seek";
  for (const s of SEEKS) seekSel.add(new Option(s.label, s.tag));
  seekSel.addEventListener("change", () => {
    const o = SEEKS[seekSel.selectedIndex];
    if (o) a.seek(o.seek);
  });
  seekRow.append(seekSel);
  strat.append(seekRow);
  let weight = initial.weight;
  let sepOn = initial.separation;
  const sep = checkbox(strat, "separation", "separation", initial.separation, (on) => {
    sepOn = on;
    a.separation(on, weight);
  });
  const w = slider(strat, {
    id: "sepweight", label: "separation weight", unit: "", min: 0, max: 1, step: 0.005, value: initial.weight, digits: 3,
    onInput: (v) => {
      weight = v;
      a.separation(sepOn, v);
    },
  });
  help(strat).textContent = "Weight 1 is the paper's literal separation sum; the presets use 0.05.";
  return (s) => {
    seekSel.selectedIndex = seekIndex(s.seek);
    sep.set(s.separation);
    sepOn = s.separation;
    weight = s.weight;
    w.set(s.weight);
  };
}

/** The boid count: one box (typed, or picked from its list of the
 *  paper's and larger counts; a heavy count asks first), the density
 *  switch and the steps per frame. */
function crowdSection(parent: HTMLElement, initial: PanelState, a: PanelActions): (boids: number) => void {
  const crowd = section(parent, "Crowd");
  let boids = initial.boids;
  /** Test IV density on: count changes scale the pathway (other limits, ./count). */
  let dense = false;
  /** The count in force, where it shows. */
  const showBoids = (n: number): void => {
    boids = n;
    num.value = String(n);
  };
  /** Runs `n` boids, after asking when the count is heavy; a refused count changes nothing. */
  const askBoids = (text: string): void => {
    const d = decideCount(text, boids, dense);
    if (d.kind === "run") {
      note.hidden = true;
      showBoids(d.n);
      a.boids(d.n);
      return;
    }
    showBoids(boids);
    note.hidden = false;
    note.className = d.kind === "ask" ? "field-msg warn" : "field-msg";
    note.textContent = d.message;
    if (d.kind === "ask") {
      button(note, "boids-confirm", `Run ${d.n.toLocaleString("en")} boids`, "run the heavy count anyway", () => {
        note.hidden = true;
        showBoids(d.n);
        a.boids(d.n);
      });
    }
  };
  const num = countBox(crowd, initial.boids, askBoids);
  const note = document.createElement("div");
  note.id = "boids-msg";
  note.className = "field-msg";
  note.setAttribute("role", "alert");
  note.hidden = true;
  crowd.append(note);
  help(crowd).textContent = "The paper's tests: 1, 10, 100 and 300 boids (the preset menu). Type any count up to 200,000, or pick one from the box's list.";
  checkbox(crowd, "density", "Test IV density (the pathway grows with the count)", false, (on) => {
    dense = on;
    a.density(on);
  });
  slider(crowd, {
    id: "speed", label: "steps / frame", unit: "", min: 1, max: 20, step: 1, value: 1, digits: 0, onInput: a.speed,
  });
  return (n) => {
    note.hidden = true;
    showBoids(n);
  };
}

/** Counts the box suggests. */
const QUICK_COUNTS = [1, 10, 100, 300, 1000, 3000, 10_000, 30_000, 100_000] as const;

/** The boid count's text box; `ask` gets what was typed or picked. */
function countBox(parent: HTMLElement, value: number, ask: (text: string) => void): HTMLInputElement {
  const numRow = document.createElement("label");
  numRow.className = "numrow";
  numRow.append("boids");
  const num = document.createElement("input");
  num.id = "boids";
  num.min = "0";
  num.max = String(PAGE_MAX_BOIDS);
  num.step = "1";
  num.value = String(value);
  // A text box reads what was typed: type=number hides "1e6" and "0x10" behind "".
  num.type = "text";
  num.inputMode = "numeric";
  const list = document.createElement("datalist");
  list.id = "boid-counts";
  for (const n of QUICK_COUNTS) list.append(new Option(n.toLocaleString("en"), String(n)));
  num.setAttribute("list", list.id);
  num.addEventListener("change", () => ask(num.value));
  numRow.append(num, list);
  parent.append(numRow);
  return num;
}

/** The pathway's radius, whether it is closed, and its point buttons. */
function pathSection(parent: HTMLElement, initial: PanelState, a: PanelActions): (s: PanelState) => void {
  const path = section(parent, "Pathway");
  const radius = slider(path, {
    id: "radius", label: "radius", unit: "u", min: 2, max: 150, step: 1, value: initial.radius, digits: 0, onInput: a.radius,
  });
  const closed = checkbox(path, "closed", "closed circuit", initial.closed, a.closed);
  const prow = row(path);
  button(prow, "add-point", "Add point", "split the segment after the selected point (or the longest); double-click a segment also adds one", a.addPoint);
  button(prow, "remove-point", "Remove point", "remove the selected path point (also Delete)", a.removePoint);
  button(prow, "fit", "Fit view", "fit the pathway in the canvas", a.fit);
  help(path).innerHTML = "Drag a point to move it; double-click a segment to add one; click a point and press <kbd>Delete</kbd> to remove it. Drag elsewhere to pan, wheel to zoom.";
  return (s) => {
    radius.set(s.radius);
    closed.set(s.closed);
  };
}

/** The metrics since their reset, as text. */
function metricsText(m: CrowdMetrics, overlapsNow: number, boids: number): string {
  return [
    `steps measured   ${m.steps}`,
    `laps timed       ${m.laps}`,
    `mean lap         ${fmt(m.mean_lap_steps, 1, " steps")}`,
    `mean distance    ${fmt(m.mean_distance, 2, " u")}`,
    `p95 distance     ${fmt(m.p95_distance, 2, " u")}`,
    `outside radius   ${m.outside_share === null ? "—" : `${(100 * m.outside_share).toFixed(2)} %`}`,
    `mean offset      ${fmt(m.mean_offset, 2, " u")} (+ left)`,
    `overlaps / step  ${fmt(m.overlapping_pairs_per_step, 2)} (now ${overlapsNow})`,
    `trace spread     ${fmt(m.trace_spread, 2, " u")}`,
    `steer / sep      ${fmt(m.mean_steer, 3)} / ${fmt(m.mean_separation, 3)}`,
    `boids            ${boids.toLocaleString("en")}`,
  ].join("\n");
}

export function buildPanel(parent: HTMLElement, initial: PanelState, a: PanelActions): Panel {
  const setSteering = steeringSection(parent, initial, a);
  const setBoids = crowdSection(parent, initial, a);
  const setPath = pathSection(parent, initial, a);

  const disp = section(parent, "Display");
  checkbox(disp, "show-trace", "lap trace", true, a.showTrace);
  checkbox(disp, "show-handles", "path points", true, a.showHandles);
  const drow = row(disp);
  button(drow, "new-trace", "Another boid", "highlight another random boid's lap", a.newTrace);
  button(drow, "png", "PNG", "download the canvas as PNG", a.png);

  const met = section(parent, "Metrics (since reset)");
  const pre = document.createElement("pre");
  pre.className = "metrics";
  pre.id = "metrics";
  met.append(pre);
  const mrow = row(met);
  button(mrow, "reset-metrics", "Reset metrics", "start measuring again from now", a.resetMetrics);
  help(met).textContent = "Distance: boid to the closest path point. Outside: share of boid-steps beyond the radius. Trace spread: how much laps differ (std of lateral offset per stretch; near 0 = one ideal line).";

  const panel: Panel = {
    set(s) {
      setSteering(s);
      setBoids(s.boids);
      setPath(s);
    },
    metricsOff(why) {
      pre.textContent = why;
    },
    showMetrics(m, overlapsNow, boids) {
      pre.textContent = metricsText(m, overlapsNow, boids);
    },
  };
  panel.set(initial);
  return panel;
}
