// Section 6, "Moving and successive targets" (paper 000 §6, Figs. 6–7):
// two agents whose targets are each other's pose meet face to face (the
// target moves every step, the update costs the same), and one agent
// chains three oriented targets, switching at End_of_Steering. The set-up
// is a scenario file written here and parsed by the core.

import { defaultState } from "../../lab/state";
import { StateField, type Lab } from "../../core/wasm";
import { backdrop, COLOURS, drawTarget, label, path, vehicle } from "../draw";
import { LiveFigure } from "../figure";
import { live, Run, type Outcome } from "../run";
import { modeColour } from "./modes";

const RAD = 180 / Math.PI;

export function movingSection(host: HTMLElement, base: Lab): LiveFigure {
  const b = { x: 5, y: 4.5 };
  const mid = { x: 1, y: -1.5 };
  const chain = (): Array<{ x: number; y: number; beta: number }> => [
    { x: -3, y: -3, beta: 0 },
    { x: mid.x, y: mid.y, beta: Math.PI / 2 },
    { x: 5, y: -4, beta: -Math.PI / 2 },
  ];
  const scenario = (): string => JSON.stringify({
    name: "learn_moving",
    description: "face to face, and three successive targets",
    duration: 40,
    agents: [
      { x: -6, y: 3, thetaDeg: 0, v: 1, goals: [{ x: b.x, y: b.y, betaDeg: 0, dTol: 1.0, epsTolDeg: 10, speed: 1.2, halting: true, motion: { kind: "faceAgent", agent: 1, distance: 0 } }] },
      { x: b.x, y: b.y, thetaDeg: 180, v: 1, goals: [{ x: -6, y: 3, betaDeg: 0, dTol: 1.0, epsTolDeg: 10, speed: 1.2, halting: true, motion: { kind: "faceAgent", agent: 0, distance: 0 } }] },
      { x: -7, y: -5, thetaDeg: 0, v: 0, goals: chain().map((g, i) => ({ x: g.x, y: g.y, betaDeg: g.beta * RAD, dTol: 0.4, epsTolDeg: 10, speed: 1.3, halting: i === 2 })) },
    ],
  });
  const lab = base.fork();
  const run = new Run(lab, (l) => { l.loadScenario(scenario()); });
  let ahead: Outcome | null = null;
  const fig = new LiveFigure(host, {
    name: "moving",
    label: "two agents meeting face to face (each one's target is the other's pose) and one agent reaching three successive targets",
    box: () => [-8, -6.5, 7, 6],
    handles: [
      { name: "partner", label: "the second agent's start (the first one's moving target)", colour: COLOURS.vehicle, get: () => b, set: (p) => { b.x = p.x; b.y = p.y; } },
      { name: "middle", label: "the chain's second target", colour: COLOURS.seek, get: () => mid, set: (p) => { mid.x = p.x; mid.y = p.y; } },
    ],
    reset: () => { ahead = run.ahead(); run.reset(); },
    step: () => run.step(),
    time: () => run.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      if (ahead) for (const t of ahead.trails) path(ctx, v, t, "rgba(60,60,60,0.18)", 1, [3, 3]);
      for (let i = 0; i < run.count; i++) path(ctx, v, run.trails[i]!, COLOURS.trail, 1.5);
      // The chain's targets (static), the current one in its mode's colours.
      const cur = { x: run.field(2, StateField.GoalX), y: run.field(2, StateField.GoalY) };
      chain().forEach((g, k) => {
        const now = Math.hypot(g.x - cur.x, g.y - cur.y) < 1e-3;
        drawTarget(ctx, v, { x: g.x, y: g.y, beta: g.beta, dTol: 0.4, epsTol: 10 / RAD, mode: now ? run.field(2, StateField.Mode) : 0 }, 36, false);
        label(ctx, v, g.x, g.y, String(k + 1), COLOURS.vehicle, 10, 12);
      });
      for (const i of [0, 1]) {
        const gx = run.field(i, StateField.GoalX);
        const gy = run.field(i, StateField.GoalY);
        drawTarget(ctx, v, { x: gx, y: gy, beta: run.field(i, StateField.GoalBeta), dTol: 1.0, epsTol: 10 / RAD, mode: run.field(i, StateField.Mode) }, 30, false);
      }
      for (let i = 0; i < run.count; i++) vehicle(ctx, v, run.x(i), run.y(i), run.field(i, StateField.Theta), i < 2 ? COLOURS.vehicle : modeColour(3));
    },
    numbers() {
      const o = ahead;
      const meet = o ? o.time : NaN;
      live("moving-chain", o ? `${o.length[2]!.toFixed(1)} m` : "—");
      live("moving-pair", o ? `${o.length[0]!.toFixed(1)} m and ${o.length[1]!.toFixed(1)} m` : "—");
      live("moving-time", Number.isFinite(meet) ? `${meet.toFixed(1)} s` : "more than 40 s");
      live("moving-goal", `${Math.min(3, 1 + chain().findIndex((g) => Math.hypot(g.x - run.field(2, StateField.GoalX), g.y - run.field(2, StateField.GoalY)) < 1e-3))}`);
    },
    labState: () => ({ ...defaultState(), preset: "p000_fig6_face_to_face" }),
  }, base.params().dt);
  return fig;
}
