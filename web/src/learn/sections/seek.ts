// Section 1, "Seek, and why it is not enough" (paper 000 §3, Fig. 1;
// paper 001 Fig. 1a): three vehicles seek the same target; their predicted
// seek paths arrive with three different headings. Play runs them.

import type { Lab } from "../../core/wasm";
import { backdrop, COLOURS, deg, drawGhost, label, path, positionTarget, ray, vehicle } from "../draw";
import { LiveFigure } from "../figure";
import { goal, labState, live, Run } from "../run";
import type { Ghost } from "../../core/wasm";
import type { Pose } from "../../lab/state";

const STARTS: Pose[] = [
  { x: -6, y: -3, theta: 0 },
  { x: -6, y: 3.5, theta: -0.5 },
  { x: -1, y: -5, theta: Math.PI / 2 },
];
const NAMES = ["A", "B", "C"];
/** Start speed, m/s: the vehicles are already walking. */
const V0 = 1.0;

export function seekSection(host: HTMLElement, base: Lab): LiveFigure {
  const target = { x: 4, y: 1 };
  const lab = base.fork();
  let ghosts: Ghost[] = [];
  // Plain seek through the controller: β equal to each vehicle's own
  // predicted final heading, so Δη = 0 and the funnel never modulates.
  const run = new Run(lab, (l) => {
    ghosts = STARTS.map((s) => l.ghostFrom(s.x, s.y, s.theta, V0, 0, target.x, target.y, 1.3));
    STARTS.forEach((s, i) => {
      const beta = ghosts[i]!.reached ? ghosts[i]!.finalDir : 0;
      l.addAgent({ x: s.x, y: s.y, theta: s.theta, v: V0, goals: [goal(target.x, target.y, beta, { dTol: 0.25, epsTol: Math.PI / 2, halting: false })] });
    });
  });
  return new LiveFigure(host, {
    name: "seek",
    label: "three vehicles seeking one target; dashed: their predicted seek paths and final headings",
    box: () => [-7, -6, 6, 5],
    handles: [{ name: "target", label: "target", colour: COLOURS.seek, get: () => target, set: (p) => { target.x = p.x; target.y = p.y; } }],
    reset: () => run.reset(),
    step: () => run.step(),
    time: () => run.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      ghosts.forEach((g) => drawGhost(ctx, v, { points: g.points, reached: g.reached, finalDir: g.finalDir, slowed: false }));
      positionTarget(ctx, v, target.x, target.y);
      for (let i = 0; i < run.count; i++) {
        path(ctx, v, run.trails[i]!, COLOURS.trail, 1.5);
        vehicle(ctx, v, run.x(i), run.y(i), run.field(i, 2));
        label(ctx, v, STARTS[i]!.x, STARTS[i]!.y, NAMES[i]!, COLOURS.vehicle, -18, -14);
        const g = ghosts[i];
        if (g?.reached) ray(ctx, v, target.x, target.y, g.finalDir, 34, COLOURS.eta, 1.5);
      }
    },
    numbers() {
      const heads = ghosts.map((g) => g.finalDir);
      NAMES.forEach((n, i) => live(`seek-${n}`, deg(heads[i] ?? NaN)));
      const ok = heads.filter(Number.isFinite);
      let spread = 0;
      for (const a of ok) for (const b of ok) spread = Math.max(spread, Math.abs(Math.atan2(Math.sin(a - b), Math.cos(a - b))));
      live("seek-spread", deg(spread));
    },
    labState: () => labState(STARTS[0]!, goal(target.x, target.y, 0)),
  }, lab.params().dt);
}
