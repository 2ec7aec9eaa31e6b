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
  /** The η table's status line (issue 14: exact, or approximate while the
   *  table of the limits in force is built). */
  table: string;
  /** Issue 17: where the world is stepped ("this thread", "2 workers, shared memory"). */
  stepping?: string | undefined;
};

const DEG = 180 / Math.PI;

function deg(a: number): string {
  return Number.isFinite(a) ? `${(a * DEG).toFixed(1).padStart(7)}°` : "      —";
}

export function renderHud(el: HTMLElement, h: HudData): void {
  const mode = h.mode === null ? "—" : (MODE_NAMES[h.mode] ?? `mode ${h.mode}`);
  const lines = [
    `mode   ${mode}${h.reachable ? "" : " (unreachable: v_dt)"}`,
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
    `agents ${String(h.agents).padStart(7)}   t ${h.time.toFixed(2)} s${h.paused ? "  paused" : ""}${h.slow ? "  ×¼" : ""}`,
  ];
  el.textContent = lines.join("\n");
}
