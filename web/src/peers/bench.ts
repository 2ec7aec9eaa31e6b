// Cost per agent update, same run, for the three sides at one size: our
// core (one thread, the page's), Yuka and DetourCrowd each stepping `n`
// agents to random targets, measured in alternating rounds (a drift of
// the host's speed favours no side); the median round's ms per step.

import type { NavMesh } from "@recast-navigation/core";
import type { Lab } from "../core/wasm";
import { mulberry32 } from "./cases";
import { quantile } from "./meter";
import { ourWorld } from "./ours";
import { yukaWorld } from "./yukaside";
import { detourWorld } from "./detourside";

export interface Cost {
  /** Median ms per step of the whole world, over the rounds. */
  msPerStep: number;
  /** µs per agent update. */
  usPerUpdate: number;
  /** Agents stepped per 16.7 ms frame (one step of dt each). */
  perFrame: number;
  rounds: number;
  error: string | null;
}

/** The square's half-side for `n` agents (the lab's crowd playground's). */
export const extentFor = (n: number): number => Math.max(10, Math.sqrt(n) * 1.5);

/** Steps `run` for about `ms` of wall time; ms per step. */
function timed(run: (steps: number) => void, perStep: number, ms: number): number {
  const steps = Math.max(1, Math.round(ms / Math.max(perStep, 1e-3)));
  const t0 = performance.now();
  run(steps);
  return (performance.now() - t0) / steps;
}

const FRAME_MS = 1000 / 60;

/** The three sides at `n` agents, `rounds` rounds of about `roundMs` each;
 *  DetourCrowd only up to `detourMax` agents (`mesh` null above). */
export function costs(lab: Lab, mesh: NavMesh | null, n: number, rounds: number, roundMs: number, seed: number, detourMax: number): Record<"ours" | "yuka" | "detour", Cost> {
  const extent = extentFor(n);
  const sides: Array<[string, () => { run: (k: number) => void; destroy: () => void }]> = [
    ["ours", () => ({ run: ourWorld(lab, n, seed, extent), destroy: () => lab.clear() })],
    ["yuka", () => ({ run: yukaWorld(n, mulberry32(seed), extent), destroy: () => undefined })],
  ];
  const out: Record<string, Cost> = {};
  if (mesh && n <= detourMax) sides.push(["detour", () => detourWorld(mesh, n, mulberry32(seed), extent)]);
  else out.detour = { msPerStep: NaN, usPerUpdate: NaN, perFrame: NaN, rounds: 0, error: `not run above ${detourMax} agents (--detour-max)` };
  const worlds: Array<{ name: string; run: (k: number) => void; destroy: () => void; per: number; ms: number[] }> = [];
  for (const [name, make] of sides) {
    try {
      const w = make();
      const t0 = performance.now();
      w.run(1);
      worlds.push({ name, ...w, per: performance.now() - t0, ms: [] });
    } catch (e) {
      out[name] = { msPerStep: NaN, usPerUpdate: NaN, perFrame: NaN, rounds: 0, error: e instanceof Error ? e.message : String(e) };
    }
  }
  for (let r = 0; r < rounds; r++) {
    for (let k = 0; k < worlds.length; k++) {
      const w = worlds[(k + r) % worlds.length]!;
      w.per = timed(w.run, w.per, roundMs);
      w.ms.push(w.per);
    }
  }
  for (const w of worlds) {
    const ms = quantile(w.ms, 0.5);
    out[w.name] = { msPerStep: ms, usPerUpdate: (ms * 1000) / n, perFrame: (FRAME_MS / ms) * n, rounds: w.ms.length, error: null };
    w.destroy();
  }
  return out as Record<"ours" | "yuka" | "detour", Cost>;
}
