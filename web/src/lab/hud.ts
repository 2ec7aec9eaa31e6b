// The heads-up display: the focus agent's controller internals (μ and its
// bound μ_max included) and timing.

import { Mode, type Internals } from "../wasm";
import { MODE_NAMES } from "./render";

/** The focus agent's internals as the core declares them (`Internals`,
 *  crate/bindings/lab_types.rs; NaN where there is no agent) and timing. */
export type HudData = Pick<Internals, "d" | "alpha" | "eta" | "deltaEta" | "mu" | "muMax" | "reachable"> & {
  mode: number | null;
  speed: number;
  usPerUpdate: number;
  frameMs: number;
  agents: number;
  time: number;
  paused: boolean;
  slow: boolean;
  /** The η table's status line (exact, or approximate while the
   *  table of the limits in force is built). */
  table: string;
  /** Where the world is stepped ("this thread", "2 workers, shared memory"). */
  stepping?: string | undefined;
};

const DEG = 180 / Math.PI;

function deg(a: number): string {
  return Number.isFinite(a) ? `${(a * DEG).toFixed(1).padStart(7)}°` : "      —";
}

/** The HUD's text, and its settled part: everything but the numbers that
 *  change while the world runs (mode, table, stepping, agents, pause). */
function hudText(h: HudData): { text: string; key: string } {
  const mode = h.mode === null ? "—" : (MODE_NAMES[h.mode] ?? `mode ${h.mode}`);
  const reach = h.reachable ? "" : " (unreachable: v_dt)";
  const flags = `${h.paused ? "  paused" : ""}${h.slow ? "  ×¼" : ""}`;
  const lines = [
    `mode   ${mode}${reach}`,
    `D      ${Number.isFinite(h.d) ? h.d.toFixed(3).padStart(7) : "      —"} m`,
    `α      ${deg(h.alpha)}`,
    `η      ${deg(h.eta)}`,
    `Δη     ${deg(h.deltaEta)}`,
    `μ      ${deg(h.mu)}`,
    `μ_max  ${h.mode === Mode.Funnelling ? deg(h.muMax) : "      —"}`,
    `speed  ${h.speed.toFixed(3).padStart(7)} m/s`,
    `update ${h.usPerUpdate.toFixed(2).padStart(7)} µs/agent`,
    `frame  ${h.frameMs.toFixed(2).padStart(7)} ms`,
    `table  ${h.table}`,
    ...(h.stepping ? [`step   ${h.stepping}`] : []),
    `agents ${String(h.agents).padStart(7)}   t ${h.time.toFixed(2)} s${flags}`,
  ];
  return { text: lines.join("\n"), key: [mode, reach, h.table, h.stepping ?? "", h.agents, flags].join("\u0000") };
}

/** Writes the HUD once (the first frame's HUD, before the loop runs). */
export function renderHud(el: HTMLElement, h: HudData): void {
  el.textContent = hudText(h).text;
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
  private shown = "";
  private key = "";
  private at = -Infinity;
  private pending: string | null = null;

  constructor(private readonly el: HTMLElement) {}

  /** The HUD of the frame drawn at `now` (ms). */
  show(h: HudData, now: number): void {
    const { text, key } = hudText(h);
    if (key !== this.key || now - this.at >= HUD_MS) this.write(text, key, now);
    else this.pending = text;
  }

  /** A frame at `now`: writes the held-back text once it is due. */
  flush(now: number): void {
    if (this.pending !== null && now - this.at >= HUD_MS) this.write(this.pending, this.key, now);
  }

  private write(text: string, key: string, now: number): void {
    this.pending = null;
    this.key = key;
    this.at = now;
    if (text !== this.shown) {
      this.el.textContent = text;
      this.shown = text;
    }
  }
}
