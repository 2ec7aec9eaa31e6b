// Section 3, "The η table" (paper 000 §3, Fig. 2; paper 001 §3, Fig. 3):
// the field of final directions α+η around the vehicle as the lab draws it,
// changing with the current speed v_c, angular speed ω_c and desired speed
// v_d; where the seek orbits instead of arriving (darker arrows), and the
// stored proactive speed v_dt that makes the target reachable.

import { slider } from "../../ui/controls";
import { FIELD_STRIDE, type Ghost, type Internals, type Lab } from "../../core/wasm";
import { backdrop, COLOURS, deg, drawField, label, LABEL_FONT, path, ray, vehicle } from "../draw";
import type { View } from "../../ui/view";
import { LiveFigure } from "../figure";
import { goal, labState, live, Run } from "../run";

/** Times `f` (which does `n` of something) until a call takes at least
 *  `ms`, doubling `n`: µs per item. */
function perItemUs(f: (n: number) => void, n0: number, ms: number): number {
  let n = n0;
  for (;;) {
    const t0 = performance.now();
    f(n);
    const dt = performance.now() - t0;
    if (dt >= ms || n >= 1_000_000) return (1000 * dt) / n;
    n *= dt > 0 ? Math.min(8, Math.max(2, Math.ceil(ms / dt))) : 8;
  }
}

function us(x: number): string {
  return x >= 100 ? `${x.toFixed(0)} µs` : x >= 1 ? `${x.toFixed(1)} µs` : `${(1000 * x).toFixed(0)} ns`;
}

/** Why the table exists, measured by the core on the reader's machine
 *  once the page is idle: a plain seek simulated to its end (what η
 *  means; the table's entries were made so) against a table lookup, on the
 *  same seeded targets and speeds. */
function measureCost(lab: Lab): void {
  const seed = 7;
  const sim = perItemUs((n) => lab.seekSimulations(n, seed), 8, 60);
  const look = perItemUs((n) => lab.tableLookups(n, seed), 2000, 20);
  live("table-sim-us", us(sim));
  live("table-lookup-us", us(look));
  live("table-ratio", `${Math.round(sim / look).toLocaleString("en")}`);
  // 1,000 agents, one η each per update, 60 updates a second.
  live("table-sim-frame", `${((1000 * sim) / 1000).toFixed(0)} ms`);
  live("table-lookup-frame", `${((1000 * look) / 1000).toFixed(2)} ms`);
}

/** The two ghosts' looks: the seek at v_d that orbits, and the one at v_dt. */
const ORBIT = { colour: "#3d3d3d", width: 2, dash: [] as number[] };
const SLOWED = { colour: COLOURS.eta, width: 3, dash: [2, 5] };

/** A ghost drawn over the arrow field: a halo of the background under it
 *  (so the field's arrows do not hide it), its own colour and dash, a cross
 *  where it ends unreached or an arrow along its final direction, and a
 *  label in words at its end. */
function labelledGhost(ctx: CanvasRenderingContext2D, v: View, g: Ghost, look: typeof ORBIT, text: string, dy: number): void {
  const pts = g.points;
  const n = Math.floor(pts.length / 2);
  if (n < 2) return;
  path(ctx, v, pts, COLOURS.background, look.width + 5);
  path(ctx, v, pts, look.colour, look.width, look.dash);
  const ex = pts[2 * n - 2]!;
  const ey = pts[2 * n - 1]!;
  if (g.reached && Number.isFinite(g.finalDir)) {
    ray(ctx, v, ex, ey, g.finalDir, 26, look.colour, 2);
  } else {
    const p = v.toScreen(ex, ey);
    ctx.save();
    ctx.strokeStyle = look.colour;
    ctx.lineWidth = 2.5;
    ctx.beginPath();
    ctx.moveTo(p.x - 6, p.y - 6);
    ctx.lineTo(p.x + 6, p.y + 6);
    ctx.moveTo(p.x + 6, p.y - 6);
    ctx.lineTo(p.x - 6, p.y + 6);
    ctx.stroke();
    ctx.restore();
  }
  // The label: an orbit's above its highest point (clear of the vehicle
  // it circles), an arrival's beside its end; inside the canvas either way.
  let [lx, ly] = [ex, ey];
  if (!g.reached) {
    for (let k = 1; k < 2 * n; k += 2) if (pts[k]! > ly) [lx, ly] = [pts[k - 1]!, pts[k]!];
  }
  ctx.save();
  ctx.font = LABEL_FONT;
  const w = ctx.measureText(text).width;
  ctx.restore();
  const p = v.toScreen(lx, ly);
  let dx = g.reached ? 12 : -w / 2;
  let ldy = g.reached ? dy : -14;
  // No room on the right (a phone): under the end, clear of the orbit above.
  if (p.x + dx + w > v.width - 4) [dx, ldy] = g.reached ? [-w / 2, 22] : [v.width - 4 - w - p.x, ldy];
  dx = Math.max(4 - p.x, Math.min(v.width - 4 - w - p.x, dx));
  label(ctx, v, lx, ly, text, look.colour, dx, ldy);
}

/** The labels of the two ghosts (the figure's data-shows and its canvas). */
const orbitText = (): string => "at the desired speed: orbits";
const slowedText = (vDt: number): string => `slowed to ${vDt.toFixed(2)} m/s: arrives`;

export function tableSection(host: HTMLElement, base: Lab): LiveFigure {
  const probe = { x: 1.2, y: 1.4 };
  const speeds = { vC: 1.6, omegaC: 0, vD: 1.6 };
  const lab = base.fork();
  const idle = window.requestIdleCallback ?? ((f: () => void) => window.setTimeout(f, 300));
  idle(() => {
    try {
      measureCost(lab);
    } catch {
      live("table-sim-us", "(not measured)");
    }
  });
  const A = lab.params().normalAccelMax;
  const wMax = lab.params().omegaMax;
  let field: Float32Array = new Float32Array(0);
  let fieldKey = "";
  let inter: Internals | null = null;
  let ghost: Ghost | null = null;
  let orbit: Ghost | null = null;
  const omega = (): number => {
    const lim = Math.min(wMax, speeds.vC > 0 ? A / speeds.vC : wMax);
    return Math.max(-lim, Math.min(lim, speeds.omegaC));
  };
  const run = new Run(lab, (l) => {
    l.addAgent({ x: 0, y: 0, theta: 0, v: speeds.vC, omega: omega(), goals: [goal(probe.x, probe.y, 0, { dTol: 0.25, epsTol: Math.PI, speed: speeds.vD, halting: false })] });
  });
  const refresh = (): void => {
    const key = `${speeds.vC}|${omega()}|${speeds.vD}`;
    if (key !== fieldKey) {
      fieldKey = key;
      field = lab.etaField(speeds.vC, omega(), speeds.vD);
    }
    inter = run.count > 0 && lab.internals(0).mode !== 0 ? lab.internals(0) : null;
    ghost = inter ? lab.ghost(0) : null;
    orbit = ghost?.slowed ? lab.ghostFrom(run.x(0), run.y(0), run.field(0, 2), run.field(0, 3), run.field(0, 4), probe.x, probe.y, speeds.vD) : null;
  };
  const fig = new LiveFigure(host, {
    name: "table",
    label: "the η field: at each sampled target around the vehicle, an arrow along the final direction α+η; darker arrows are unreachable at v_d",
    box: () => [-4.5, -4.5, 4.5, 4.5],
    handles: [{ name: "probe", label: "probe target", colour: COLOURS.ring, get: () => probe, set: (p) => { probe.x = p.x; probe.y = p.y; } }],
    reset: () => { run.reset(); refresh(); },
    step: () => { const more = run.step(); refresh(); return more; },
    time: () => run.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      drawField(ctx, v, { samples: field, originX: 0, originY: 0, theta: 0, light: COLOURS.field, dark: COLOURS.fieldDark }, 12, 1.2);
      if (inter && Number.isFinite(inter.eta)) ray(ctx, v, probe.x, probe.y, run.field(0, 2) + inter.alpha + inter.eta, 40, COLOURS.eta, 2.5);
      // Both ghosts over the field, each with its own colour, dash and label.
      if (orbit) labelledGhost(ctx, v, orbit, ORBIT, orbitText(), 0);
      if (ghost) labelledGhost(ctx, v, ghost, ghost.slowed ? SLOWED : { ...SLOWED, dash: [8, 5] }, ghost.slowed && inter ? slowedText(inter.vDt) : "seek at the desired speed: arrives", -16);
      vehicle(ctx, v, run.x(0), run.y(0), run.field(0, 2));
    },
    numbers() {
      // The prose quotes the set-up (where the figure waits until Play).
      if (run.time > 0) return;
      live("table-vc", `${speeds.vC.toFixed(2)} m/s`);
      live("table-vd", `${speeds.vD.toFixed(2)} m/s`);
      live("table-D", inter ? `${inter.d.toFixed(2)} m` : "—");
      live("table-eta", deg(inter?.eta ?? NaN));
      live("table-reach", inter ? (inter.reachable ? "reachable" : "unreachable") : "—");
      live("table-vdt", inter ? `${inter.vDt.toFixed(2)} m/s` : "—");
      let n = 0;
      let dark = 0;
      for (let k = 0; k < field.length; k += FIELD_STRIDE) {
        n++;
        if (field[k + 3]! < 0.5) dark++;
      }
      live("table-dark", `${dark} of ${n}`);
    },
    labState: () => labState({ x: 0, y: 0, theta: 0 }, goal(probe.x, probe.y, 0, { speed: speeds.vD }), {
      field: { vC: speeds.vC, omegaC: omega(), vD: speeds.vD },
      overlays: { ...labState({ x: 0, y: 0, theta: 0 }, goal(0, 0, 0)).overlays, field: true },
    }),
    shows: () => ({
      t: run.time,
      D: inter ? `${inter.d.toFixed(2)} m` : "",
      reach: inter ? (inter.reachable ? "reachable" : "unreachable") : "",
      ghosts: [orbit ? orbitText() : "", ghost ? (ghost.slowed && inter ? slowedText(inter.vDt) : "seek at the desired speed: arrives") : ""].filter((x) => x !== "").join(" | "),
    }),
  }, lab.params().dt);
  const s = (id: string, lbl: string, key: "vC" | "omegaC" | "vD", min: number, max: number): void => {
    slider(fig.controls, { id, label: lbl, unit: key === "omegaC" ? "rad/s" : "m/s", min, max, step: 0.05, value: speeds[key], onInput: (x) => { speeds[key] = x; fig.changed(); } });
  };
  s("table-vc-slider", "current speed v_c", "vC", 0, 2);
  s("table-wc-slider", "angular speed ω_c", "omegaC", -2, 2);
  s("table-vd-slider", "desired speed v_d", "vD", 0.25, 2);
  return fig;
}
