// The side panel's avoidance section: the method (off,
// separation, ORCA) for the world in force, a preset's own until changed;
// the steps between an agent's plans (the core's range); buttons that add
// a disc or a wall at the view's centre and remove the last obstacle. The obstacles themselves are dragged on the canvas.

import { button, help, row, section, select } from "../ui/controls";
import { ranges } from "../core/wasm";
import type { Vec } from "../ui/view";
import type { LabAvoidance } from "./avoidance";
import { OBSTACLE_STRIDE } from "./obstacles";
import { AVOID_KEYS, type AvoidKey } from "../world/worldcalls";

const LABELS: Record<AvoidKey, string> = { off: "off (ghosts)", separation: "separation", orca: "ORCA" };

/** Builds the section after the panel's first section; `centre` is the
 *  world point at the canvas centre. */
export function avoidanceSection(panel: HTMLElement, avoid: LabAvoidance, centre: () => Vec, changed: () => void): void {
  const box = section(panel, "Avoidance");
  panel.querySelector("fieldset")?.after(box);
  const method = select(box, {
    id: "avoidance", label: "method", value: avoid.method,
    options: AVOID_KEYS.map((k) => ({ value: k, label: LABELS[k] })),
    onChange: (m) => { avoid.setMethod(m); changed(); },
  });
  method.el.title = "off: agents pass through each other; separation: paper 003's push, no guarantee; ORCA: reciprocal velocity obstacles for the forward-only vehicle";
  // The core's range (`avoidance.replanEvery`, 1 to 4 steps).
  const span = ranges().find((f) => f.key === "avoidance.replanEvery");
  if (!span) throw new Error("the core exports no range for avoidance.replanEvery");
  const plans: string[] = [];
  for (let k = span.min; k <= span.max; k++) plans.push(String(k));
  const plan = select(box, {
    id: "avoidance-plan", label: "plans", value: String(avoid.replanEvery),
    options: plans.map((k) => ({ value: k, label: k === "1" ? "every step" : `every ${k} steps${k === "2" ? " (default)" : ""}` })),
    onChange: (k) => { avoid.setReplanEvery(Number(k)); changed(); },
  });
  plan.el.title = "How often each agent plans its avoidance (agents take turns); in between it keeps its last plan's command. Every 2 steps (30 Hz at the default step) costs about half as much as every step and met every target on the report seeds; every 3 let one pair of the circle swap of 32 touch in 100 runs, every 4 left Fig. 6 and Fig. 8 agents unfinished";
  const r = row(box);
  const add = (list: number[]): void => {
    avoid.setObstacles([...avoid.obstacles, ...list]);
    changed();
  };
  button(r, "add-disc", "+ disc", "Add a disc obstacle at the view's centre", () => {
    const c = centre();
    add([0, c.x, c.y, 0.8, 0]);
  });
  button(r, "add-wall", "+ wall", "Add a wall 4 m long, 1.5 m below the view's centre", () => {
    const c = centre();
    // Below a disc added at the same centre, not across it.
    add([1, c.x - 2, c.y - 1.5, c.x + 2, c.y - 1.5]);
  });
  const remove = button(r, "remove-obstacle", "− last", "Remove the last obstacle", () => {
    avoid.setObstacles(avoid.obstacles.slice(0, -OBSTACLE_STRIDE));
    changed();
  });
  const count = document.createElement("span");
  count.className = "muted";
  count.id = "obstacle-count";
  r.append(count);
  help(box).textContent = "Drag a disc by its centre (rim knob: radius), a wall by its middle or its ends. A preset's own method and obstacles apply until you change them; the link keeps your changes.";
  const show = avoid.onChange;
  avoid.onChange = () => {
    show();
    method.set(avoid.method);
    plan.set(String(avoid.replanEvery));
    const n = avoid.obstacles.length / OBSTACLE_STRIDE;
    count.textContent = ` ${n} obstacle${n === 1 ? "" : "s"}`;
    remove.disabled = n === 0;
  };
  avoid.onChange();
}
