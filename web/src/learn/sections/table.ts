// Section 3, "The η table" (paper 000 §3, Fig. 2; paper 001 §3, Fig. 3):
// the field of final directions α+η around the vehicle as the lab draws it,
// changing with the current speed v_c, angular speed ω_c and desired speed
// v_d; where the seek orbits instead of arriving (darker arrows), and the
// stored proactive speed v_dt that makes the target reachable.

import { slider } from "../../ui/controls";
import { FIELD_STRIDE, type Ghost, type Internals, type Lab } from "../../core/wasm";
import { backdrop, COLOURS, deg, drawField, drawGhost, ray, vehicle } from "../draw";
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
      if (orbit) drawGhost(ctx, v, { points: orbit.points, reached: false, finalDir: NaN, slowed: false }, 1.5);
      if (ghost) drawGhost(ctx, v, { points: ghost.points, reached: ghost.reached, finalDir: ghost.finalDir, slowed: ghost.slowed });
      if (inter && Number.isFinite(inter.eta)) ray(ctx, v, probe.x, probe.y, run.field(0, 2) + inter.alpha + inter.eta, 40, COLOURS.eta, 2.5);
      vehicle(ctx, v, run.x(0), run.y(0), run.field(0, 2));
    },
    numbers() {
      // Once the vehicle is at the probe there is nothing to look up: the
      // prose keeps the last state it had.
      if (run.time > 0 && !inter) return;
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
  }, lab.params().dt);
  const s = (id: string, lbl: string, key: "vC" | "omegaC" | "vD", min: number, max: number): void => {
    slider(fig.controls, { id, label: lbl, unit: key === "omegaC" ? "rad/s" : "m/s", min, max, step: 0.05, value: speeds[key], onInput: (x) => { speeds[key] = x; fig.changed(); } });
  };
  s("table-vc-slider", "current speed v_c", "vC", 0, 2);
  s("table-wc-slider", "angular speed ω_c", "omegaC", -2, 2);
  s("table-vd-slider", "desired speed v_d", "vD", 0.25, 2);
  return fig;
}
