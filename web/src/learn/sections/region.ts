// Section 7, "Region goals" (paper 001 §4, Figs. 6–7): relaxed funnelling
// with the paper's relaxed point. Live from the core's relaxed internals:
// the table ring nearest the disk centre, the restricted arc 𝒜 where it
// crosses the disk, the span F of final orientations over 𝒜, the interval
// T = β ± τ, the chosen αᵣ and the Fig. 7 branch that chose it; next to
// the standard controller's path to the same disk.

import { defaultState } from "../../lab/state";
import { StateField, type Internals, type Lab } from "../../core/wasm";
import { backdrop, COLOURS, deg, drawTarget, line, path, vehicle, wedge } from "../draw";
import { LiveFigure } from "../figure";
import { goal, labState, live, Run, type Outcome } from "../run";

const DEG = Math.PI / 180;

/** crate::relaxed::Fig7Branch, as a sentence. */
const BRANCHES = [
  "not searched",
  "centres of F and T of opposite signs, straight ahead valid: αᵣ = 0, Δη = 0",
  "centres of opposite signs, F overlaps T (mod 2π): Δη = 0, αᵣ the overlap point nearest straight ahead",
  "centres of opposite signs, no overlap: αᵣ the end of 𝒜 with the smallest gap",
  "centres of the same sign, straight ahead valid: αᵣ = 0, Δη = 0",
  "centres of the same sign, F overlaps T: Δη = 0, αᵣ the overlap point nearest straight ahead",
  "centres of the same sign, no overlap: αᵣ the end of 𝒜 with the smallest gap",
  "closer than the first ring: the standard update",
  "entry point (the default aim)",
];

export function regionSection(host: HTMLElement, base: Lab): LiveFigure {
  const start = { x: -6, y: -1, theta: 0 };
  const centre = { x: 2, y: 1.5 };
  let beta = 45 * DEG;
  const g = (): ReturnType<typeof goal> => goal(centre.x, centre.y, beta, { dTol: 1.5, epsTol: 20 * DEG, halting: false, relaxed: true });
  const relaxed = new Run(base.fork(), (l) => {
    l.setRelaxed({ aim: "paperArc" });
    l.addAgent({ x: start.x, y: start.y, theta: start.theta, goals: [g()] });
  });
  const standard = new Run(base.fork(), (l) => {
    l.addAgent({ x: start.x, y: start.y, theta: start.theta, goals: [{ ...g(), relaxed: false }] });
  });
  let inter: Internals | null = null;
  let rel: Outcome | null = null;
  let std: Outcome | null = null;
  const refresh = (): void => { inter = relaxed.lab.internals(0); };
  return new LiveFigure(host, {
    name: "region",
    label: "relaxed funnelling towards a disk: the table ring, the arc 𝒜 inside the disk, the span F, the interval T and the chosen direction αᵣ",
    box: () => [-7, -3.5, 5, 5],
    handles: [
      { name: "centre", label: "region goal (disk centre)", colour: COLOURS.arc, get: () => centre, set: (p) => { centre.x = p.x; centre.y = p.y; } },
      { name: "beta", label: "region goal orientation β", colour: COLOURS.seek, get: () => ({ x: centre.x + 2.2 * Math.cos(beta), y: centre.y + 2.2 * Math.sin(beta) }), set: (p) => { beta = Math.atan2(p.y - centre.y, p.x - centre.x); } },
    ],
    reset() {
      rel = relaxed.ahead();
      std = standard.ahead();
      refresh();
    },
    step: () => { const more = relaxed.step(); refresh(); return more; },
    time: () => relaxed.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      if (std) path(ctx, v, std.trails[0]!, "#8a8f98", 1.5, [3, 3]);
      if (rel) path(ctx, v, rel.trails[0]!, COLOURS.arc, 2);
      drawTarget(ctx, v, { x: centre.x, y: centre.y, beta, dTol: 1.5, epsTol: 20 * DEG, mode: inter?.mode ?? 3 }, 2.2 * v.scale - 12, false);
      const x = relaxed.x(0);
      const y = relaxed.y(0);
      const th = relaxed.field(0, StateField.Theta);
      const a = inter?.arc;
      if (a && a.branch > 0 && a.branch < 7) {
        const p = v.toScreen(x, y);
        const r = a.radius * v.scale;
        ctx.save();
        ctx.strokeStyle = COLOURS.ring;
        ctx.globalAlpha = 0.5;
        ctx.lineWidth = 1;
        ctx.beginPath();
        ctx.arc(p.x, p.y, r, 0, 2 * Math.PI);
        ctx.stroke();
        ctx.globalAlpha = 1;
        ctx.strokeStyle = COLOURS.arc;
        ctx.lineWidth = 5;
        ctx.beginPath();
        ctx.arc(p.x, p.y, r, -(th + a.alphaMax), -(th + a.alphaMin));
        ctx.stroke();
        ctx.restore();
        const rx = x + a.radius * Math.cos(th + a.alphaR);
        const ry = y + a.radius * Math.sin(th + a.alphaR);
        line(ctx, v, x, y, rx, ry, COLOURS.arc, 1.5);
        // F at the relaxed point, T at the centre (world angles).
        wedge(ctx, v, rx, ry, 44, th + a.fMin, th + a.fMax, COLOURS.eta, 0.2);
        wedge(ctx, v, centre.x, centre.y, 70, th + a.tMin, th + a.tMax, COLOURS.gamma, 0.15);
        const q = v.toScreen(rx, ry);
        ctx.fillStyle = COLOURS.arc;
        ctx.beginPath();
        ctx.arc(q.x, q.y, 4, 0, 2 * Math.PI);
        ctx.fill();
      }
      vehicle(ctx, v, x, y, th);
    },
    numbers() {
      const a = inter?.arc;
      const searched = a && a.branch > 0 && a.branch < 7;
      // Once the run is inside the disk there is no arc left to search:
      // the prose keeps the last search it showed.
      if (!searched && relaxed.time > 0) return;
      live("region-arc", searched ? `[${deg(a.alphaMin)}, ${deg(a.alphaMax)}]` : "—");
      live("region-F", searched ? `[${deg(a.fMin)}, ${deg(a.fMax)}]` : "—");
      live("region-T", searched ? `[${deg(a.tMin)}, ${deg(a.tMax)}]` : "—");
      live("region-ar", searched ? deg(a.alphaR) : "—");
      live("region-ring", searched ? `${a.radius.toFixed(2)} m` : "—");
      live("region-branch", a ? (BRANCHES[a.branch] ?? "—") : "—");
      live("region-rel", rel ? `${rel.length[0]!.toFixed(1)} m` : "—");
      live("region-std", std ? `${std.length[0]!.toFixed(1)} m` : "—");
    },
    labState: () => labState(start, g(), {
      funnel: { ...defaultState().funnel, relaxedAim: "paperArc" },
      overlays: { ...defaultState().overlays, arc: true },
    }),
  }, base.params().dt);
}
