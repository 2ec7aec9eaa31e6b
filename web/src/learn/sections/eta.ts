// Section 2, "What η is" (paper 000 §3, Fig. 1c; paper 001 §3, Fig. 2a):
// the predicted seek path from the vehicle's state to the target (the
// core's ghost, the very simulation the table was generated with), its
// final direction, and η between the initial radial direction and that
// final direction — next to the η the table interpolates.

import type { Ghost, Internals, Lab } from "../../core/wasm";
import { angleArc, backdrop, COLOURS, deg, drawGhost, line, path, positionTarget, ray, vehicle } from "../draw";
import { LiveFigure } from "../figure";
import { goal, labState, live, Run } from "../run";

/** The vehicle's speed at the start, m/s (η is small from rest: the
 *  vehicle turns on the spot first, then drives straight). */
const V0 = 1.3;

export function etaSection(host: HTMLElement, base: Lab): LiveFigure {
  const start = { x: -4, y: -1, theta: 0 };
  const target = { x: -2, y: 1.5 };
  const lab = base.fork();
  let ghost: Ghost | null = null;
  let inter: Internals | null = null;
  // β = the seek's own final heading: Δη = 0, so the vehicle simply seeks
  // and follows its ghost.
  const run = new Run(lab, (l) => {
    const g = l.ghostFrom(start.x, start.y, start.theta, V0, 0, target.x, target.y, 1.3);
    l.addAgent({ x: start.x, y: start.y, theta: start.theta, v: V0, goals: [goal(target.x, target.y, g.reached ? g.finalDir : 0, { dTol: 0.25, epsTol: Math.PI / 2, halting: false })] });
  });
  /** The start state's predicted path: what the figure is zoomed to. */
  let startPath: ArrayLike<number> = [];
  const refresh = (): void => {
    inter = run.count > 0 && lab.internals(0).mode !== 0 ? lab.internals(0) : null;
    ghost = inter ? lab.ghost(0) : null;
  };
  const box = (): [number, number, number, number] => {
    let [x0, y0, x1, y1] = [Math.min(start.x, target.x), Math.min(start.y, target.y), Math.max(start.x, target.x), Math.max(start.y, target.y)];
    for (let k = 0; k + 1 < startPath.length; k += 2) {
      x0 = Math.min(x0, startPath[k]!);
      x1 = Math.max(x1, startPath[k]!);
      y0 = Math.min(y0, startPath[k + 1]!);
      y1 = Math.max(y1, startPath[k + 1]!);
    }
    // Room for the radial line's extension, the arrows and the labels.
    return [x0 - 1, y0 - 1, x1 + 1.3, y1 + 1.3];
  };
  return new LiveFigure(host, {
    name: "eta",
    label: "the predicted seek path (dashed) from the vehicle to the target, its final direction, and the angle η",
    box,
    handles: [
      { name: "target", label: "target", colour: COLOURS.seek, get: () => target, set: (p) => { target.x = p.x; target.y = p.y; } },
      { name: "vehicle", label: "vehicle", colour: COLOURS.vehicle, get: () => start, set: (p) => { start.x = p.x; start.y = p.y; } },
    ],
    reset: () => {
      run.reset();
      refresh();
      if (ghost) startPath = ghost.points;
    },
    step: () => { const more = run.step(); refresh(); return more; },
    time: () => run.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      path(ctx, v, run.trails[0] ?? [], COLOURS.trail, 1.5);
      const x = run.x(0);
      const y = run.y(0);
      const th = run.field(0, 2);
      positionTarget(ctx, v, target.x, target.y);
      if (inter && ghost) {
        const radial = th + inter.alpha;
        // The radial direction, extended past the target: η is measured from it.
        const ext = 1.6;
        line(ctx, v, x, y, target.x + Math.cos(radial) * ext, target.y + Math.sin(radial) * ext, COLOURS.radial, 1, [6, 4]);
        drawGhost(ctx, v, { points: ghost.points, reached: ghost.reached, finalDir: ghost.finalDir, slowed: ghost.slowed });
        if (ghost.reached) {
          ray(ctx, v, target.x, target.y, ghost.finalDir, 96, COLOURS.eta, 2.5);
          angleArc(ctx, v, target.x, target.y, 74, radial, ghost.finalDir, COLOURS.eta, `η ${deg(ghost.eta)}`);
        }
        // The heading, from which α is measured.
        ray(ctx, v, x, y, th, 64, COLOURS.vehicle, 1.5);
        angleArc(ctx, v, x, y, 44, th, radial, COLOURS.radial, "α");
      }
      vehicle(ctx, v, x, y, th);
    },
    numbers() {
      // The first paragraph quotes the set-up (the start state, where the
      // figure waits); the third the η still to come while the run plays.
      if (run.time === 0) {
        live("eta-D", inter ? `${inter.d.toFixed(2)} m` : "—");
        live("eta-alpha", deg(inter?.alpha ?? NaN));
        live("eta-sim", ghost?.reached ? deg(ghost.eta) : "unreachable");
        live("eta-table", deg(inter?.eta ?? NaN));
        const err = inter && ghost?.reached ? Math.abs(Math.atan2(Math.sin(ghost.eta - inter.eta), Math.cos(ghost.eta - inter.eta))) : NaN;
        live("eta-err", deg(err));
      }
      // Past the target's reach there is no η left to predict: the text
      // keeps the last one.
      if (inter && ghost?.reached) live("eta-now", deg(ghost.eta));
    },
    shows: () => ({ t: run.time, eta: inter && ghost?.reached ? deg(ghost.eta) : "" }),
    labState: () => labState(start, goal(target.x, target.y, Math.PI / 2)),
  }, lab.params().dt);
}
