// Section 8, "Try to break it": three set-ups that stress the funnel
// (paper 000 §3 orbits, §5 mode relaxation near the target): a target just
// behind a moving vehicle, a tiny tolerance, a target very close. Each runs
// to its end at once so the prose can say what happened (time, heading
// error, modes visited); the reader can drag the target to try worse.

import { Mode, StateField, type Lab } from "../../core/wasm";
import { backdrop, COLOURS, deg, drawTarget, path, vehicle } from "../draw";
import { modeWords } from "../../ui/modes";
import { LiveFigure } from "../figure";
import { goal, labState, live, Run, type Outcome } from "../run";

const DEG = Math.PI / 180;

interface Challenge {
  key: string;
  title: string;
  v: number;
  target: { x: number; y: number; beta: number };
  dTol: number;
  epsTol: number;
}

const CHALLENGES: readonly Challenge[] = [
  { key: "behind", title: "Target just behind", v: 1.3, target: { x: -1.5, y: 0.2, beta: Math.PI }, dTol: 0.3, epsTol: 10 * DEG },
  { key: "tiny", title: "Tiny tolerance", v: 0, target: { x: 4, y: 2, beta: -Math.PI / 2 }, dTol: 0.05, epsTol: 1 * DEG },
  { key: "close", title: "Very close", v: 1.0, target: { x: 0.7, y: 0.5, beta: Math.PI }, dTol: 0.2, epsTol: 10 * DEG },
];

export function challengesSection(host: HTMLElement, base: Lab): LiveFigure {
  let ch = CHALLENGES[0]!;
  const target = { ...ch.target };
  const g = (): ReturnType<typeof goal> => goal(target.x, target.y, target.beta, { dTol: ch.dTol, epsTol: ch.epsTol });
  const run = new Run(base.fork(), (l) => { l.addAgent({ x: 0, y: 0, theta: 0, v: ch.v, goals: [g()] }); });
  let ahead: Outcome | null = null;
  const fig = new LiveFigure(host, {
    name: "challenges",
    label: "a challenge set-up: the vehicle, the target and the path the controller takes",
    box() {
      // The whole run in view (a target behind sends the vehicle far out).
      const t = ahead?.trails[0] ?? [];
      let [x0, y0, x1, y1] = [Math.min(-3, target.x - 1), Math.min(-3, target.y - 1), Math.max(4, target.x + 1), Math.max(3, target.y + 1)];
      for (let k = 0; k < t.length; k += 2) {
        x0 = Math.min(x0, t[k]! - 0.5);
        x1 = Math.max(x1, t[k]! + 0.5);
        y0 = Math.min(y0, t[k + 1]! - 0.5);
        y1 = Math.max(y1, t[k + 1]! + 0.5);
      }
      return [x0, y0, x1, y1];
    },
    handles: [{ name: "target", label: "target", colour: COLOURS.seek, get: () => target, set: (p) => { target.x = p.x; target.y = p.y; } }],
    reset: () => { ahead = run.ahead(); run.reset(); },
    step: () => run.step(),
    time: () => run.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      if (ahead) path(ctx, v, ahead.trails[0]!, "rgba(60,60,60,0.25)", 1.5, [3, 3]);
      path(ctx, v, run.trails[0]!, COLOURS.vehicle, 1.5);
      drawTarget(ctx, v, { x: target.x, y: target.y, beta: target.beta, dTol: ch.dTol, epsTol: ch.epsTol, mode: run.field(0, StateField.Mode) }, 40, false);
      vehicle(ctx, v, run.x(0), run.y(0), run.field(0, StateField.Theta));
    },
    numbers() {
      const o = ahead;
      live("break-time", o && Number.isFinite(o.time) ? `${o.time.toFixed(1)} s` : "not within 40 s");
      live("break-error", o ? deg(o.headingError[0]!) : "—");
      live("break-length", o ? `${o.length[0]!.toFixed(1)} m` : "—");
      // Modes in the order first entered, and how often the mode changed
      // (funnelling ⇄ seeking alternate where |Δη| hovers at the threshold).
      const seq = o ? o.modes[0]! : [];
      const firsts = seq.filter((m, k) => seq.indexOf(m) === k);
      live("break-modes", o ? `${firsts.map((m) => modeWords(m)?.word ?? "?").join(" → ")} (${seq.length - 1} mode changes)` : "—");
      live("break-D", `${Math.hypot(target.x, target.y).toFixed(2)} m`);
      live("break-tol", `position tolerance ${ch.dTol.toFixed(2)} m, orientation tolerance ${deg(ch.epsTol)}`);
      live("break-mode-now", modeWords(run.field(0, StateField.Mode))?.word ?? "—");
      const orbit = o ? o.modes[0]!.filter((m) => m === Mode.OrientationOnly).length : 0;
      live("break-returns", String(orbit));
      for (const el of document.querySelectorAll<HTMLElement>("[data-challenge]")) el.hidden = el.dataset["challenge"] !== ch.key;
    },
    labState: () => labState({ x: 0, y: 0, theta: 0 }, g()),
  }, base.params().dt);
  const row = document.createElement("div");
  row.className = "row";
  row.setAttribute("role", "group");
  row.setAttribute("aria-label", "challenges");
  const buttons = CHALLENGES.map((c) => {
    const b = document.createElement("button");
    b.type = "button";
    b.dataset["challengeButton"] = c.key;
    b.textContent = c.title;
    b.addEventListener("click", () => {
      ch = c;
      Object.assign(target, c.target);
      for (const x of buttons) x.setAttribute("aria-pressed", String(x === b));
      fig.setPlaying(false);
      fig.changed();
      fig.refit();
    });
    row.append(b);
    return b;
  });
  buttons[0]!.setAttribute("aria-pressed", "true");
  fig.controls.append(row);
  return fig;
}
