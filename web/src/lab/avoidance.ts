// The lab's avoidance (issue 18): the method in force (the scenario's own,
// or the one chosen in the panel or the link), the obstacles as last read
// from the core, and the edits that go to it (method, obstacles dragged,
// added, removed). A refused edit leaves the core unchanged and says why.

import { showMessage } from "../page";
import type { Drag } from "../pointer";
import type { Vec, View } from "../view";
import { errorText, type Lab } from "../wasm";
import { dragObstacle, pickObstacle, type ObstacleLimits } from "./obstacles";
import { AVOID_KEYS, type AvoidKey, type LabState } from "./state";

export class LabAvoidance {
  /** The method in force in the core. */
  method: AvoidKey = "off";
  /** The obstacles in force (lab/obstacles.ts layout). */
  obstacles: number[] = [];
  /** Steps between an agent's avoidance plans in force in the core. */
  replanEvery = 2;
  /** The agents' body radius, m. */
  radius = 0.3;
  /** Called after every change (redraw, URL, the panel's select). */
  onChange: () => void = () => {};

  constructor(private readonly lab: Lab, private readonly st: LabState) {}

  /** After a (re)build: the page's choices over the scenario's own, then
   *  what the core holds. */
  apply(): void {
    const { lab, st } = this;
    try {
      if (st.avoidance !== null) lab.setAvoidance(st.avoidance);
      if (st.replanEvery !== null) lab.setAvoidanceReplanEvery(st.replanEvery);
      if (st.obstacles !== null) lab.setObstacles(new Float32Array(st.obstacles));
    } catch (e) {
      showMessage(`Avoidance settings rejected: ${errorText(e)}`, "warn");
    }
    this.pull();
  }

  /** Reads the method, obstacles and radius back from the core. */
  pull(): void {
    const m = this.lab.avoidance();
    this.method = (AVOID_KEYS as readonly string[]).includes(m) ? (m as AvoidKey) : "off";
    this.obstacles = Array.from(this.lab.obstacles());
    this.radius = this.lab.avoidanceRadius();
    this.replanEvery = this.lab.avoidanceReplanEvery();
    this.onChange();
  }

  setMethod(m: AvoidKey): void {
    this.edit("Avoidance", () => {
      this.lab.setAvoidance(m);
      this.st.avoidance = m;
    });
  }

  setReplanEvery(n: number): void {
    this.edit("Avoidance plan rate", () => {
      this.lab.setAvoidanceReplanEvery(n);
      this.st.replanEvery = n;
    });
  }

  /** The whole list to the core (a drag sends every move). */
  setObstacles(list: number[]): void {
    this.edit("Obstacles", () => {
      this.lab.setObstacles(new Float32Array(list));
      this.st.obstacles = Array.from(this.lab.obstacles());
    });
  }

  /** One edit to the core: a refusal (nothing changed there) is shown as
   *  `what rejected: why`; either way the page reads the core back. */
  private edit(what: string, f: () => void): void {
    try {
      f();
    } catch (e) {
      showMessage(`${what} rejected: ${errorText(e)}`, "warn");
    }
    this.pull();
  }
}

/** Drags of the obstacles' parts (lab/obstacles.ts), for handles.ts's
 *  pointer handler: null where no obstacle is under the press; `done`
 *  after every move (redraw, URL). */
export function obstacleDrags(view: View, avoid: LabAvoidance, lim: ObstacleLimits, done: () => void): (p: Vec) => Drag | null {
  return (p) => {
    const g = pickObstacle(view, avoid.obstacles, p);
    if (!g) return null;
    const start = [...avoid.obstacles];
    const from = view.toWorld(p.x, p.y);
    return {
      move: (q) => {
        avoid.setObstacles(dragObstacle(start, g, from, view.toWorld(q.x, q.y), lim));
        done();
      },
    };
  };
}
