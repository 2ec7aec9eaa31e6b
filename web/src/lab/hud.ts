// The heads-up display: what the described agent is doing, in plain words
// (a mode chip linking to the learn page's mode list, and why it slows
// down when it does), its controller quantities, and, behind a toggle, the
// diagnostics (update cost, frame time, table, stepping).

import { Mode, type Internals } from "../core/wasm";
import { modeWords } from "../ui/modes";
import { realTime } from "../ui/speedmeter";

/** A phone's width or a short window (a phone on its side): the HUD
 *  starts folded there, its numbers a tap away. style.css's compact rules
 *  use the same query. */
export const COMPACT_QUERY = "(max-width: 760px), (max-height: 480px)";

/** The focus agent's internals as the core declares them (`Internals`,
 *  crate/bindings/lab_types.rs; NaN where there is no agent) and timing. */
export type HudData = Pick<Internals, "d" | "alpha" | "eta" | "deltaEta" | "mu" | "muMax" | "reachable" | "vDt"> & {
  mode: number | null;
  speed: number;
  usPerUpdate: number;
  frameMs: number;
  agents: number;
  /** The agent described (0-based). */
  shown: number;
  time: number;
  paused: boolean;
  slow: boolean;
  /** The η table's status line (exact, or approximate while the
   *  table of the limits in force is built). */
  table: string;
  /** Where the world is stepped ("this thread", "2 workers, shared memory"). */
  stepping?: string | undefined;
  /** Measured over the last second: frames drawn and simulation time per
   *  second of wall time (ui/speedmeter.ts); absent before any reading. */
  rate?: { fps: number; ratio: number } | undefined;
  /** The clock runs (the η table is in). */
  live?: boolean;
  /** The vehicle's minimum turning radius, m (0: it turns on the spot). */
  minTurnRadius?: number;
  /** The largest reverse speed (m/s; 0 or absent: forward only). */
  vReverse?: number;
};

const DEG = 180 / Math.PI;

function deg(a: number): string {
  return Number.isFinite(a) ? `${(a * DEG).toFixed(1).padStart(7)}°` : "      —";
}

/** The HUD's parts as text. */
interface HudText {
  /** The mode in words (the chip), and its number for its colour. */
  chip: string;
  mode: number | null;
  /** The vehicle's minimum turning radius (its mode's colour depends on it). */
  radius: number;
  /** What the agent is doing, and which agent it is. */
  say: string;
  /** Why it slows down (unreachable at the desired speed), or why a
   *  car-like vehicle drives round, or "". */
  warn: string;
  /** Frames drawn and simulation speed, measured. */
  speed: string;
  numbers: string;
  diagnostics: string;
}

/** The HUD's text, and its settled part: everything but the numbers that
 *  change while the world runs (mode, table, stepping, agents, pause). */
function hudText(h: HudData): { parts: HudText; key: string } {
  const radius = h.minTurnRadius ?? 0;
  const words = h.mode === null ? undefined : modeWords(h.mode, radius > 0);
  const chip = h.mode === null ? "—" : (words?.word ?? `mode ${h.mode}`);
  const who = h.agents > 1 ? `agent ${h.shown + 1} of ${h.agents} (ringed): ` : "";
  // A car-like vehicle with a reverse gear backs where that is shorter:
  // its speed is then negative, and the HUD says so in words.
  const backing = h.speed < 0;
  // Backing is never a loop: the mode's own words ("looping round") would
  // contradict what the reader sees.
  const say = `${who}${backing ? "reverse gear: backing up on its way to arrive facing β" : (words?.meaning ?? "")}`;
  const manoeuvre = radius > 0 && h.mode === Mode.OrientationOnly;
  const warn = manoeuvre
    ? (h.vReverse ?? 0) > 0
      ? `Why this path: a car-like vehicle cannot turn on the spot (its turning circle has a radius of at least ${radius.toFixed(1)} m); with a reverse gear it takes the shortest path of arcs and straights, forwards and backwards, that ends facing β, changing gear only at rest.`
      : `Why the loop: a car-like vehicle cannot turn on the spot (its turning circle has a radius of at least ${radius.toFixed(1)} m), and the target is closer than a few turning circles, too close to turn in and face β directly; so it drives round and comes back in along β.`
    : h.reachable
      ? ""
      : `slowing down to ${Number.isFinite(h.vDt) ? h.vDt.toFixed(2) : "—"} m/s: at the desired speed the turn is too tight to arrive facing β`;
  const speed = speedLine(h);
  const flags = `${h.paused ? "  paused" : ""}${h.slow ? "  ×¼" : ""}`;
  const numbers = [
    `D      ${Number.isFinite(h.d) ? h.d.toFixed(3).padStart(7) : "      —"} m`,
    `α      ${deg(h.alpha)}`,
    `η      ${deg(h.eta)}`,
    `Δη     ${deg(h.deltaEta)}`,
    `μ      ${deg(h.mu)}`,
    `μ_max  ${h.mode === Mode.Funnelling ? deg(h.muMax) : "      —"}`,
    `speed  ${h.speed.toFixed(3).padStart(7)} m/s${backing ? "  reverse" : ""}`,
    `agents ${String(h.agents).padStart(7)}   t ${h.time.toFixed(2)} s${flags}`,
  ].join("\n");
  const diagnostics = [
    `update ${h.usPerUpdate.toFixed(2).padStart(7)} µs/agent`,
    `frame  ${h.frameMs.toFixed(2).padStart(7)} ms`,
    `table  ${h.table}`,
    ...(h.stepping ? [`step   ${h.stepping}`] : []),
  ].join("\n");
  const parts = { chip, mode: h.mode, radius, say, warn, speed, numbers, diagnostics };
  const slower = / slower /.test(speed);
  return { parts, key: [chip, say, warn, h.table, h.stepping ?? "", h.agents, flags, slower].join("\u0000") };
}

/** The measured speed in words: frames drawn per second and simulation
 *  time per second of wall time, saying plainly when the simulation runs
 *  slower than real time (slower than ¼ in slow motion). */
function speedLine(h: HudData): string {
  if (h.live === false) return "clock held at t = 0 until the η table is in";
  if (h.paused) return "paused";
  const s = h.rate;
  if (!s) return "measuring speed…";
  const aim = h.slow ? 0.25 : 1;
  const rt = realTime(s.ratio, aim);
  const fps = `${s.fps.toFixed(0)} fps`;
  if (h.slow) return `${fps} · ${rt.text}${rt.slower ? ", slower than the slow motion asked (¼)" : " (slow motion ×¼)"}`;
  return `${fps} · ${rt.text}${rt.slower ? ": slower than real time, this computer cannot keep up" : ""}`;
}

/** The HUD's elements, made once inside #hud. */
class HudView {
  private readonly chip: HTMLAnchorElement;
  private readonly say: HTMLElement;
  private readonly warn: HTMLElement;
  private readonly speed: HTMLElement;
  private readonly numbers: HTMLElement;
  private readonly diagnostics: HTMLElement;

  constructor(el: HTMLElement) {
    const made = el.querySelector(".hud-chip") === null;
    if (made) {
      el.replaceChildren();
      const head = document.createElement("div");
      head.className = "hud-head";
      const chip = document.createElement("a");
      chip.className = "hud-chip";
      chip.href = "learn.html#modes";
      chip.title = "the control modes, explained (Learn, section 5)";
      const fold = document.createElement("button");
      fold.type = "button";
      fold.className = "hud-fold";
      fold.textContent = "numbers";
      fold.setAttribute("aria-expanded", matchMedia(COMPACT_QUERY).matches ? "false" : "true");
      fold.title = "show or hide the numbers";
      fold.addEventListener("click", () => {
        const open = fold.getAttribute("aria-expanded") !== "true";
        fold.setAttribute("aria-expanded", String(open));
        el.classList.toggle("folded", !open);
      });
      el.classList.toggle("folded", fold.getAttribute("aria-expanded") !== "true");
      head.append(chip, fold);
      const say = document.createElement("p");
      say.className = "hud-say";
      const warn = document.createElement("p");
      warn.className = "hud-warn";
      warn.hidden = true;
      const speed = document.createElement("p");
      speed.className = "hud-speed";
      const numbers = document.createElement("pre");
      numbers.className = "hud-num";
      const details = document.createElement("details");
      details.className = "hud-diag";
      const summary = document.createElement("summary");
      summary.textContent = "diagnostics";
      const diag = document.createElement("pre");
      details.append(summary, diag);
      el.append(head, say, warn, speed, numbers, details);
    }
    this.chip = el.querySelector<HTMLAnchorElement>(".hud-chip")!;
    this.say = el.querySelector<HTMLElement>(".hud-say")!;
    this.warn = el.querySelector<HTMLElement>(".hud-warn")!;
    this.speed = el.querySelector<HTMLElement>(".hud-speed")!;
    this.numbers = el.querySelector<HTMLElement>(".hud-num")!;
    this.diagnostics = el.querySelector<HTMLElement>(".hud-diag pre")!;
  }

  write(p: HudText): void {
    if (this.chip.textContent !== p.chip) {
      this.chip.textContent = p.chip;
      const w = p.mode === null ? undefined : modeWords(p.mode, p.radius > 0);
      this.chip.style.setProperty("--mode", w?.colour ?? "#888888");
      this.chip.dataset["mode"] = p.mode === null ? "" : String(p.mode);
    }
    if (this.say.textContent !== p.say) this.say.textContent = p.say;
    if (this.warn.textContent !== p.warn) {
      this.warn.textContent = p.warn;
      this.warn.hidden = p.warn === "";
    }
    if (this.speed.textContent !== p.speed) {
      this.speed.textContent = p.speed;
      const slower = / slower /.test(p.speed);
      this.speed.classList.toggle("slower", slower);
      // Folded, the line is hidden (it would cover a small stage); the
      // fold button says "slow" instead, the warning a tap away.
      this.speed.closest(".hud")?.classList.toggle("slow", slower);
    }
    if (this.numbers.textContent !== p.numbers) this.numbers.textContent = p.numbers;
    if (this.diagnostics.textContent !== p.diagnostics) this.diagnostics.textContent = p.diagnostics;
  }
}

/** Writes the HUD once (the first frame's HUD, before the loop runs). */
export function renderHud(el: HTMLElement, h: HudData): void {
  new HudView(el).write(hudText(h).parts);
}

/** At most this often, ms, the HUD's running numbers are rewritten. */
export const HUD_MS = 1000 / 15;

/** The loop's HUD. Rewriting its text costs the page a layout, a paint
 *  and a raster of its box, on the page's thread and the compositor's, a
 *  sizeable share of what the page spends per drawn state at 100,000
 *  agents (`make bench-budget` measures it), where the stepping workers
 *  need every core. Numbers that
 *  change 60 times a second cannot be read anyway, so while only they
 *  change the text is rewritten at most every {@link HUD_MS} (15 Hz); any
 *  change of its settled part (mode, table, stepping, agents, pause) shows
 *  at once, a held-back text shows once due even if no frame is drawn, and
 *  an unchanged text is not written at all. */
export class Hud {
  private readonly view: HudView;
  private shown = "";
  private key = "";
  private at = -Infinity;
  private pending: HudText | null = null;

  constructor(el: HTMLElement) {
    this.view = new HudView(el);
  }

  /** The HUD of the frame drawn at `now` (ms). */
  show(h: HudData, now: number): void {
    const { parts, key } = hudText(h);
    if (key !== this.key || now - this.at >= HUD_MS) this.write(parts, key, now);
    else this.pending = parts;
  }

  /** A frame at `now`: writes the held-back text once it is due. */
  flush(now: number): void {
    if (this.pending !== null && now - this.at >= HUD_MS) this.write(this.pending, this.key, now);
  }

  private write(parts: HudText, key: string, now: number): void {
    this.pending = null;
    this.key = key;
    this.at = now;
    const text = Object.values(parts).join("\u0000");
    if (text !== this.shown) {
      this.view.write(parts);
      this.shown = text;
    }
  }
}
