// window.__gpu, in the test build only (main.ts installs it under
// `import.meta.env.MODE === "test"`, so the shipped bundle holds none of
// it): what web/test/e2e-gpu.mjs drives, the kernel's parity with the
// core on seeded worlds (with the kernel's own WGSL or a planted copy),
// its table reads, the page's measurements and a world's refusal.

import type { Lab } from "../core/wasm";
import type { CountedCost } from "../gpu/cost";
import type { GpuOpened } from "../gpu/device";
import { AGENT_WORDS, FUNNEL_WGSL, FunnelKernel, GpuTable, splitWorld, tableArrays } from "../gpu/kernel";
import { probeParity, randomProbes, runParity } from "../gpu/parity";
import { measureCore, measureCost, measureGpu, type Timing } from "./measure";
import { seedWorld, separationWorld, vehicleLab, type VehicleName } from "./worlds";

/** The page's record, which the hook reads. */
export interface GpuPage {
  ready: boolean;
  error: string | null;
  adapter: string;
  emulated: boolean;
  timestamps: boolean;
  rows: Timing[];
  cost: CountedCost | null;
  gpu: GpuOpened | null;
  table: { lab: Lab; table: GpuTable; bytes: Uint8Array } | null;
}

function parts(page: GpuPage): { g: GpuOpened; lab: Lab; table: GpuTable; bytes: Uint8Array } {
  if (!page.gpu || !page.table) throw new Error("no GPU device or table on this page");
  return { g: page.gpu, ...page.table };
}

export function installHook(page: GpuPage): void {
  const hook = {
    page,
    /** The kernel's WGSL, for a planted change. */
    source: FUNNEL_WGSL,
    /** A seeded world of `vehicle` run `steps` steps in both, one step
     *  compared at `samples`; with `density` (agents per m²), a dense world
     *  with separation on. */
    async parity(vehicle: VehicleName, n: number, seed: number, steps: number, samples: number[], source?: string, density?: number) {
      const { g, bytes } = parts(page);
      const lab = vehicleLab(vehicle, bytes);
      if (density === undefined) seedWorld(lab, n, seed);
      else separationWorld(lab, n, seed, density);
      const t0 = performance.now();
      const r = await runParity(g.device, lab, { steps, samples, ...(source === undefined ? {} : { source }) });
      lab.free();
      return { ...r, ms: performance.now() - t0 };
    },
    /** The lab's GPU crowd with separation on (Lab.gpuRandomCrowd packs the
     *  world's avoidance, as gpucrowd.ts does): `n` agents stepped `steps`
     *  steps; whether the grid's passes ran, and the agents' states all finite. */
    async crowdSeparation(n: number, steps: number) {
      const { g, bytes } = parts(page);
      const lab = vehicleLab("pedestrian", bytes);
      lab.setAvoidance("separation");
      const table = new GpuTable(g.device, tableArrays(lab));
      const k = await FunnelKernel.create(g.device, table, splitWorld(lab.gpuRandomCrowd(n, 3, Math.sqrt(n) / 2, 1.3, 4)));
      k.step(steps);
      const words = await k.readAgents();
      const f = new Float32Array(words.buffer);
      let finite = true;
      for (let i = 0; i < k.n; i++) for (let w = 0; w < 5; w++) finite &&= Number.isFinite(f[i * AGENT_WORDS + w]);
      const out = { separating: k.separation !== null, agents: k.n, finite };
      k.destroy();
      table.destroy();
      lab.free();
      return out;
    },
    /** `n` table reads against the core's lookup (the pedestrian's committed table). */
    async probes(n: number, seed: number, source?: string) {
      const { g, lab } = parts(page);
      const p = lab.params();
      return probeParity(g.device, lab, randomProbes(n, seed, 32, p.vMax, p.omegaMax), source);
    },
    /** The timing rows for `sizes`: the kernel (stepped; no draw here) and the core on one thread. */
    async measure(sizes: number[]) {
      const { g, lab, table } = parts(page);
      const rows: Timing[] = [];
      for (const n of sizes) {
        rows.push(...(await measureGpu(g.device, lab, table, n, `GPU kernel on ${g.label}`, g.timestamps)));
        if (n <= 100_000) rows.push(measureCore(lab, n));
      }
      return { rows, cost: await measureCost(g.device, lab, table, Math.min(5_000, Math.max(...sizes))) };
    },
    /** Why the kernel refuses a seeded world changed by `change` (undefined: it does not). */
    refusal(change: "none" | "carLike" | "paper" | "separation" | "orca" | "obstacle"): string | undefined {
      const { bytes } = parts(page);
      const lab = vehicleLab("pedestrian", bytes);
      seedWorld(lab, 3, 1);
      if (change === "carLike") lab.setParams({ ...lab.params(), minTurnRadius: 5 });
      if (change === "paper") lab.setReading("paper");
      if (change === "separation" || change === "obstacle") lab.setAvoidance("separation");
      if (change === "orca") lab.setAvoidance("orca");
      if (change === "obstacle") lab.setObstacles(Float32Array.from([0, 0, 0, 1, 0]));
      const why = lab.gpuRefusal();
      lab.free();
      return why;
    },
  };
  (window as unknown as { __gpu: typeof hook }).__gpu = hook;
}
