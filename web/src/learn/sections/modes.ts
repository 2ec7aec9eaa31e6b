// Section 5, "Modes" (paper 000 §5, Fig. 5; colours §6): the decision
// diagram of the four control modes, the one in force lit live in the
// lab's words and colours (src/ui/modes.ts) while the vehicle runs, and the
// target drawn as the lab draws it (circle: seeking, triangle: turning on
// the spot, both: funnelling, grey: arrived). The prose's mode names
// (b[data-mode]) take their words and colours from the same module, so the
// page and the lab's legend cannot drift apart.

import { slider } from "../../ui/controls";
import { Mode, StateField, type Internals, type Lab } from "../../core/wasm";
import { backdrop, COLOURS, deg, drawTarget, path, vehicle } from "../draw";
import { LiveFigure } from "../figure";
import { typesetText } from "../glossary";
import { goal, labState, live, Run, type Outcome } from "../run";
import { MODE_WORDS, modeColour, modeTextColour, modeWords, type ModeKey } from "../../ui/modes";

export { modeColour };

const DEG = Math.PI / 180;

/** Fig. 5, top to bottom: the test and the mode it selects. */
const DIAGRAM: ReadonlyArray<{ mode: number; test: string }> = [
  { mode: Mode.EndOfSteering, test: "D < D_tol and |β − θ| < ε_tol" },
  { mode: Mode.OrientationOnly, test: "else if D < D_tol" },
  { mode: Mode.PositionOnly, test: "else if D < D_η or |Δη| < 0.25·ε_tol" },
  { mode: Mode.Funnelling, test: "else" },
];

/** The lab's word for mode `m` ("—" for none). */
function word(m: number): string {
  return modeWords(m)?.word ?? "—";
}

/** A run's modes in the order lit, in words; a long flicker between two
 *  modes shortened to its ends and the number of changes. */
export function modeSequence(seq: readonly number[]): string {
  const w = seq.map(word);
  if (w.length <= 7) return w.join(" → ");
  return `${w.slice(0, 3).join(" → ")} → … → ${w.slice(-2).join(" → ")} (${w.length - 1} mode changes)`;
}

/** Each lighting of the diagram's boxes, numbered in order: box mode → "1, 3". */
function litOrder(seq: readonly number[]): Map<number, string> {
  const out = new Map<number, number[]>();
  seq.forEach((m, k) => out.set(m, [...(out.get(m) ?? []), k + 1]));
  const text = new Map<number, string>();
  for (const [m, ks] of out) text.set(m, ks.length <= 4 ? ks.join(", ") : `${ks.slice(0, 2).join(", ")}, … ${ks[ks.length - 1]}`);
  return text;
}

/** Writes the lab's word (capitalised) and text colour into each
 *  b[data-mode] of `root`, keyed by the core's mode name. */
export function nameModes(root: ParentNode): void {
  for (const b of root.querySelectorAll<HTMLElement>("b[data-mode]")) {
    const w = MODE_WORDS[b.dataset["mode"] as ModeKey] as (typeof MODE_WORDS)[ModeKey] | undefined;
    if (!w) continue;
    b.textContent = w.word.charAt(0).toUpperCase() + w.word.slice(1);
    b.style.color = w.text;
  }
}

export function modesSection(host: HTMLElement, base: Lab): LiveFigure {
  const start = { x: -4, y: -2, theta: 0 };
  const target = { x: 2, y: 1 };
  let beta = Math.PI;
  const tol = { dTol: 0.6, epsTol: 10 * DEG };
  const lab = base.fork();
  const dEta = lab.tableInfo().dEta;
  const g = (): ReturnType<typeof goal> => goal(target.x, target.y, beta, { dTol: tol.dTol, epsTol: tol.epsTol });
  const run = new Run(lab, (l) => { l.addAgent({ x: start.x, y: start.y, theta: start.theta, goals: [g()] }); }, 30);
  let inter: Internals | null = null;
  /** The set-up run to its end at once: what the text says Play will show. */
  let ahead: Outcome | null = null;
  const refresh = (): void => { inter = lab.internals(0); };
  const diagram = document.createElement("ol");
  diagram.className = "diagram";
  diagram.setAttribute("aria-label", "paper 000 Fig. 5: the choice of the control mode; the mode in force is highlighted");
  for (const d of DIAGRAM) {
    const li = document.createElement("li");
    li.dataset["mode"] = String(d.mode);
    li.innerHTML = `<code></code> → <b></b> <span class="lit-order"></span>`;
    li.querySelector("code")!.innerHTML = typesetText(d.test);
    const b = li.querySelector("b")!;
    b.textContent = word(d.mode);
    b.style.color = modeTextColour(d.mode);
    diagram.append(li);
  }
  const fig = new LiveFigure(host, {
    name: "modes",
    label: "a vehicle reaching an oriented target; the target's drawing and the diagram below show the control mode in force",
    box: () => [-5, -3.5, 4, 3],
    handles: [
      { name: "target", label: "target", colour: COLOURS.seek, get: () => target, set: (p) => { target.x = p.x; target.y = p.y; } },
      { name: "beta", label: "target orientation β", colour: COLOURS.seek, get: () => ({ x: target.x + 1.5 * Math.cos(beta), y: target.y + 1.5 * Math.sin(beta) }), set: (p) => { beta = Math.atan2(p.y - target.y, p.x - target.x); } },
    ],
    reset: () => { ahead = run.ahead(); run.reset(); refresh(); },
    step: () => { const more = run.step(); refresh(); return more; },
    time: () => run.time,
    draw(ctx, v) {
      backdrop(ctx, v);
      path(ctx, v, run.trails[0]!, COLOURS.trail, 1.5);
      drawTarget(ctx, v, { x: target.x, y: target.y, beta, dTol: tol.dTol, epsTol: tol.epsTol, mode: inter?.mode ?? Mode.Funnelling }, 1.5 * v.scale - 12, false);
      vehicle(ctx, v, run.x(0), run.y(0), run.field(0, StateField.Theta));
    },
    numbers() {
      const m = inter?.mode ?? Mode.Funnelling;
      live("modes-mode", word(m));
      live("modes-D", inter ? `${inter.d.toFixed(2)} m` : "—");
      const e = beta - run.field(0, StateField.Theta);
      live("modes-head", deg(Math.abs(Math.atan2(Math.sin(e), Math.cos(e)))));
      live("modes-dtol", `${tol.dTol.toFixed(2)} m`);
      live("modes-etol", deg(tol.epsTol));
      live("modes-deta", `${dEta.toFixed(2)} m`);
      const planned = ahead?.modes[0] ?? [];
      live("modes-seq", planned.length > 0 ? modeSequence(planned) : "—");
      // Turning on the spot is named only when this run does it.
      live("modes-spot", planned.includes(Mode.OrientationOnly) ? " In position but still off β by more than the orientation tolerance, it then turns on the spot before it arrives." : "");
      const order = litOrder(run.modes[0] ?? []);
      for (const el of diagram.querySelectorAll<HTMLElement>("[data-mode]")) {
        const at = order.get(Number(el.dataset["mode"]));
        el.querySelector(".lit-order")!.textContent = at ? `lit ${at}` : "";
        const on = Number(el.dataset["mode"]) === m;
        el.classList.toggle("on", on);
        el.style.borderColor = on ? modeColour(m) : "";
        el.setAttribute("aria-current", on ? "step" : "false");
      }
    },
    labState: () => labState(start, g()),
    shows: () => ({ t: run.time, lit: word(inter?.mode ?? Mode.Funnelling), seq: modeSequence(run.modes[0] ?? []) }),
  }, lab.params().dt);
  fig.controls.before(diagram);
  slider(fig.controls, { id: "modes-dtol-slider", label: "position tol. D_tol", unit: "m", min: 0.1, max: 2, step: 0.05, value: tol.dTol, onInput: (x) => { tol.dTol = x; fig.changed(); } });
  slider(fig.controls, { id: "modes-etol-slider", label: "orient. tol. ε_tol", unit: "°", min: 2 * DEG, max: 45 * DEG, step: DEG, value: tol.epsTol, display: 1 / DEG, digits: 0, onInput: (x) => { tol.epsTol = x; fig.changed(); } });
  fig.spec.numbers();
  return fig;
}
