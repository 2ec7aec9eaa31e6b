// The peers harness page (peers.html, built in the test mode only): our
// core (through the one seam, ../wasm), Yuka and DetourCrowd on the same
// seeded cases and vehicle limits, in one page. web/test/e2e-peers.mjs
// drives it through window.__peers and writes the figures records.

import { createLab, errorText } from "../core/wasm";
import circle8 from "../../../scenarios/avoid_circle8.json?raw";
import circle32 from "../../../scenarios/avoid_circle32.json?raw";
import { GOAL, MAX_TIME_S, REST_SPEED, VEHICLE, orientedCases } from "./cases";
import { summarize } from "./meter";
import { runOurs } from "./ours";
import { runYuka, YUKA } from "./yukaside";
import { DETOUR, detourReady, planeNavMesh, runDetour, AGENT } from "./detourside";
import { swapDetour, swapOurs, type SwapScenario } from "./swap";
import { costs, extentFor } from "./bench";

const SWAPS: Record<string, string> = { avoid_circle8: circle8, avoid_circle32: circle32 };

async function start(): Promise<void> {
  const [lab] = await Promise.all([createLab("tables/eta.planes"), detourReady()]);
  // One navmesh for the cases and the swaps (every target within 10 m).
  const mesh = planeNavMesh(20, 0.1);
  const hook = {
    ready: true,
    error: null as string | null,
    /** The settings every row names. */
    settings: () => ({ vehicle: VEHICLE, goal: GOAL, restSpeed: REST_SPEED, maxTimeS: MAX_TIME_S, yuka: YUKA, detour: DETOUR, detourAgent: AGENT }),
    /** The oriented cases of `seed` (`n` of them), every side. */
    oriented: (seed: number, n: number) => {
      const cases = orientedCases(seed, n);
      return {
        ours: summarize(runOurs(lab, cases)),
        yukaArrive: summarize(runYuka("arrive", cases)),
        yukaSeek: summarize(runYuka("seek", cases)),
        detour: summarize(runDetour(mesh, cases)),
      };
    },
    /** A circle swap, ours and DetourCrowd's. */
    swap: (name: string) => {
      const text = SWAPS[name];
      if (!text) throw new Error(`no swap named ${name}`);
      const sc = JSON.parse(text) as SwapScenario;
      return { ours: swapOurs(lab, sc, text), detour: swapDetour(mesh, sc) };
    },
    /** Cost per agent update at `n` agents, the three sides in alternating rounds. */
    costs: (n: number, rounds: number, roundMs: number, seed: number, detourMax: number) => {
      const big = n <= detourMax ? planeNavMesh(extentFor(n) + 2, extentFor(n) > 50 ? 1 : 0.25) : null;
      try {
        return costs(lab, big, n, rounds, roundMs, seed, detourMax);
      } finally {
        big?.destroy();
      }
    },
  };
  (window as unknown as { __peers: typeof hook }).__peers = hook;
}

start().catch((e: unknown) => {
  (window as unknown as { __peers: unknown }).__peers = { ready: false, error: errorText(e) };
});
