// Section 4, "The modulation" (paper 000 §4, Figs. 3–4; paper 001 §3,
// Fig. 2b): Δη = β − (θ + α + η), μ = −gain·Δη bounded by μ_max, and the
// modulated heading γ = θ + α + μ fed to the seek controller. Sliders for
// the gain and the bound; the path with the chosen settings is drawn next
// to the path with the paper's literal bound (or the default, when the
// literal bound is the one chosen).

import { select, slider } from "../../ui/controls";
import { BOUND_CHOICES, funnelConfig } from "../../lab/funnelsettings";
import { defaultState, type BoundKey, type FunnelSettings } from "../../lab/state";
import type { Ghost, Internals, Lab } from "../../core/wasm";
import { angleArc, backdrop, COLOURS, deg, drawGhost, drawTarget, line, path, ray, tipLabel, vehicle } from "../draw";
import { LiveFigure } from "../figure";
import { goal, labState, live, Run, type Outcome } from "../run";

export function modulationSection(host: HTMLElement, base: Lab): LiveFigure {
  const start = { x: -5, y: -1, theta: 0 };
  const target = { x: 3, y: 1.5 };
  let beta = Math.PI / 2;
  const knob = { get: () => ({ x: target.x + 1.6 * Math.cos(beta), y: target.y + 1.6 * Math.sin(beta) }) };
  const settings: FunnelSettings = { ...defaultState().funnel };
  const other = (): BoundKey => (settings.bound === "lit" ? "tr" : "lit");
  const g = (): ReturnType<typeof goal> => goal(target.x, target.y, beta);
  const make = (bound: () => BoundKey): Run => {
    const lab = base.fork();
    return new Run(lab, (l) => {
      l.setFunnel(funnelConfig({ ...settings, bound: bound() }));
      l.addAgent({ x: start.x, y: start.y, theta: start.theta, goals: [g()] });
    });
  };
  const run = make(() => settings.bound);
  const cmp = make(other);
  let inter: Internals | null = null;
  let ghost: Ghost | null = null;
  let mine: Outcome | null = null;
  let theirs: Outcome | null = null;
  const refresh = (): void => {
    inter = run.lab.internals(0);
    ghost = inter.mode === 3 || inter.mode === 2 ? run.lab.ghost(0) : null;
  };
  const fig = new LiveFigure(host, {
    name: "modulation",
    label: "funnelling: the seek path (dashed), the modulated heading γ (green), and the paths with the chosen bound and with the comparison bound",
    box: () => [-6, -3, 5.5, 4.5],
    handles: [
      { name: "target", label: "target", colour: COLOURS.seek, get: () => target, set: (p) => { target.x = p.x; target.y = p.y; } },
      { name: "beta", label: "target orientation β", colour: COLOURS.seek, get: knob.get, set: (p) => { beta = Math.atan2(p.y - target.y, p.x - target.x); } },
    ],
    reset() {
      mine = run.ahead();
      theirs = cmp.ahead();
      refresh();
    },
    step: () => { const more = run.step(); refresh(); return more; },
    time: () => run.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      if (theirs) path(ctx, v, theirs.trails[0]!, "#8a8f98", 1.5, [3, 3]);
      if (mine) path(ctx, v, mine.trails[0]!, COLOURS.gamma, 2.5);
      path(ctx, v, run.trails[0]!, COLOURS.vehicle, 1);
      if (ghost) drawGhost(ctx, v, { points: ghost.points, reached: ghost.reached, finalDir: ghost.finalDir, slowed: ghost.slowed }, 1.5);
      drawTarget(ctx, v, { x: target.x, y: target.y, beta, dTol: 0.3, epsTol: (10 * Math.PI) / 180, mode: inter?.mode ?? 3 }, 1.6 * v.scale - 12, false);
      const th = run.field(0, 2);
      const x = run.x(0);
      const y = run.y(0);
      tipLabel(ctx, v, target.x, target.y, beta, 1.6 * v.scale + 18, "β", COLOURS.seek);
      if (inter && inter.mode !== 0) {
        const radial = th + inter.alpha;
        // The radial direction, from which μ turns the heading to γ.
        line(ctx, v, x, y, target.x, target.y, COLOURS.radial, 1, [6, 4]);
        if (Number.isFinite(inter.eta) && inter.mode === 3) {
          // η's prediction at the target, and Δη from it to β.
          const fin = radial + inter.eta;
          ray(ctx, v, target.x, target.y, fin, 80, COLOURS.eta, 2.5);
          tipLabel(ctx, v, target.x, target.y, fin, 96, "θ+α+η", COLOURS.eta);
          angleArc(ctx, v, target.x, target.y, 58, fin, beta, "#b3141c", "Δη");
        }
        ray(ctx, v, x, y, inter.gamma, 90, COLOURS.gamma, 3);
        tipLabel(ctx, v, x, y, inter.gamma, 106, "γ", COLOURS.gamma);
        if (Math.abs(inter.mu) > 0.01) angleArc(ctx, v, x, y, 62, radial, inter.gamma, COLOURS.gamma, "μ");
      }
      vehicle(ctx, v, x, y, th);
    },
    numbers() {
      const f = inter && inter.mode === 3;
      // Near the end the vehicle seeks (no modulation): the prose keeps the
      // last funnelling state it showed.
      if (!f && run.time > 0) return;
      live("mod-deta", deg(inter?.deltaEta ?? NaN));
      live("mod-mu", deg(inter?.mu ?? NaN));
      live("mod-mumax", f ? deg(inter!.muMax) : "— (not funnelling)");
      live("mod-gamma", deg(inter ? inter.gamma - run.field(0, 2) : NaN));
      live("mod-beta", deg(beta));
      live("mod-gain", settings.gain.toFixed(2));
      const name = (k: BoundKey): string => BOUND_CHOICES.find((c) => c.value === k)?.label ?? k;
      live("mod-bound", name(settings.bound));
      live("mod-other", name(other()));
      const res = (o: Outcome | null): string => !o ? "—" : Number.isFinite(o.time)
        ? `${o.time.toFixed(1)} s, ${o.length[0]!.toFixed(1)} m, ${deg(o.headingError[0]!)} off β`
        : "not finished in 40 s";
      live("mod-mine", res(mine));
      live("mod-theirs", res(theirs));
    },
    labState: () => labState(start, g(), { funnel: { ...settings } }),
  }, base.params().dt);
  slider(fig.controls, { id: "mod-gain-slider", label: "gain (μ = −gain·Δη)", unit: "", min: 1, max: 4, step: 0.1, value: settings.gain, onInput: (x) => { settings.gain = x; fig.changed(); } });
  select(fig.controls, { id: "mod-bound-select", label: "bound μ_max", options: BOUND_CHOICES.map((c) => ({ value: c.value, label: c.label })), value: settings.bound, onChange: (b) => { settings.bound = b; fig.changed(); } });
  return fig;
}
