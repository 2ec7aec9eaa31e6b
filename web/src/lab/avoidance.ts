// The lab's avoidance: the method in force (the scenario's own, or the one
// chosen in the panel or the link), the obstacles as the world last
// reported them, and the edits that go to it (method, obstacles dragged,
// added, removed). The page shows an edit at once; the world's answer
// (at once on this thread, with the workers' next reply there) then puts
// its own values in force, and a refusal says why.

import type { Drag } from "../ui/pointer";
import type { Vec, View } from "../ui/view";
import { dragObstacle, pickObstacle, type ObstacleLimits } from "./obstacles";
import type { LabState } from "./state";
import type { AvoidInfo, AvoidKey, Edit, EditAnswer } from "../world/worldcalls";

/** Sends an avoidance edit to the world; `answer` gets its reply. */
export type SendAvoid = (e: Edit & { kind: "avoid" }, answer: (a: EditAnswer) => void) => void;

export class LabAvoidance {
  /** The method in force in the world. */
  method: AvoidKey = "off";
  /** The obstacles in force (lab/obstacles.ts layout). */
  obstacles: number[] = [];
  /** Steps between an agent's avoidance plans in force in the world. */
  replanEvery = 2;
  /** The agents' body radius, m. */
  radius = 0.3;
  /** Called after every change (redraw, URL, the panel's select). */
  onChange: () => void = () => {};

  constructor(private readonly st: LabState, private readonly send: SendAvoid) {}

  /** What the world holds (after a build, or in answer to an edit). */
  take(a: AvoidInfo): void {
    this.method = a.method;
    this.obstacles = a.obstacles;
    this.radius = a.radius;
    this.replanEvery = a.replanEvery;
    this.onChange();
  }

  setMethod(m: AvoidKey): void {
    const was = this.st.avoidance;
    this.st.avoidance = m;
    this.method = m;
    this.edit({ kind: "avoid", method: m }, () => {
      this.st.avoidance = was;
    });
  }

  setReplanEvery(n: number): void {
    const was = this.st.replanEvery;
    this.st.replanEvery = n;
    this.replanEvery = n;
    this.edit({ kind: "avoid", replanEvery: n }, () => {
      this.st.replanEvery = was;
    });
  }

  /** The whole list to the world (a drag sends every move); kept as f32, as the core keeps it. */
  setObstacles(list: number[]): void {
    const was = this.st.obstacles;
    this.obstacles = Array.from(Float32Array.from(list));
    this.st.obstacles = this.obstacles;
    this.edit({ kind: "avoid", obstacles: this.obstacles }, () => {
      this.st.obstacles = was;
    });
  }

  /** Sends `e`; on a refusal `undo` restores the page's state, and either
   *  way the world's avoidance is taken. */
  private edit(e: Edit & { kind: "avoid" }, undo: () => void): void {
    this.send(e, (a) => {
      if (a.error) undo();
      if (a.avoid) this.take(a.avoid);
    });
    this.onChange();
  }
}

/** Drags of the obstacles' parts (lab/obstacles.ts), for handles.ts's
 *  pointer handler: null where no obstacle is under the press (`hit`: the
 *  handles' hit radius, CSS px); `done`
 *  after every move (redraw, URL). */
export function obstacleDrags(view: View, avoid: LabAvoidance, lim: ObstacleLimits, done: () => void): (p: Vec, hit: number) => Drag | null {
  return (p, hit) => {
    const g = pickObstacle(view, avoid.obstacles, p, hit);
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
