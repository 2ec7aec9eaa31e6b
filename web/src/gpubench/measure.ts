// The timing page's measurements: the kernel stepping (and drawing) a
// random crowd on this device, timed by timestamp queries where the
// device has them, else by the wall clock around submitted work; the
// wasm core stepping the same crowd on this page's thread; and the
// kernel's counted cost per update.

import type { Lab } from "../core/wasm";
import { countedCost, type CountedCost } from "../gpu/cost";
import type { AgentDrawer, AgentView } from "../gpu/draw";
import { FunnelKernel, GpuTable, USAGE, readBack, splitWorld } from "../gpu/kernel";

/** One row of the page's table. */
export interface Timing {
  backend: string;
  agents: number;
  /** Milliseconds per step (with the draw when `drawn`). */
  stepMs: number;
  /** Agents stepped per 16.7 ms at that rate. */
  perFrame: number;
  drawn: boolean;
  /** How it was timed. */
  clock: string;
}

/** The random crowd's square half-side for `n` agents, m: the lab's density (about 4 m² per agent). */
export function crowdExtent(n: number): number {
  return Math.max(10, Math.sqrt(n));
}

const FRAME_MS = 1000 / 60;

async function gpuTime(device: GPUDevice, k: FunnelKernel, steps: number, timestamps: boolean, draw?: () => void): Promise<[number, string]> {
  if (timestamps && !draw) {
    const qs = device.createQuerySet({ type: "timestamp", count: 2 });
    const resolved = device.createBuffer({ size: 16, usage: USAGE.QUERY_RESOLVE | USAGE.COPY_SRC });
    const enc = device.createCommandEncoder();
    k.encode(enc, steps, qs);
    enc.resolveQuerySet(qs, 0, 2, resolved, 0);
    device.queue.submit([enc.finish()]);
    const t = new BigUint64Array(await readBack(device, resolved, 16));
    qs.destroy();
    resolved.destroy();
    const ns = Number((t[1] ?? 0n) - (t[0] ?? 0n));
    if (ns > 0) return [ns / 1e6 / steps, "timestamp queries"];
  }
  const t0 = performance.now();
  for (let s = 0; s < steps; s++) {
    k.step(1);
    draw?.();
  }
  await device.queue.onSubmittedWorkDone();
  return [(performance.now() - t0) / steps, "wall clock around submitted work"];
}

/** The kernel on `n` agents of the random crowd (4 goals each): stepped
 *  alone, and stepped and drawn with `drawer` when given. */
export async function measureGpu(device: GPUDevice, lab: Lab, table: GpuTable, n: number, label: string, timestamps: boolean, drawer?: { d: AgentDrawer; view: AgentView }): Promise<Timing[]> {
  const world = splitWorld(lab.gpuRandomCrowd(n, 1, crowdExtent(n), 1.3, 4));
  const k = await FunnelKernel.create(device, table, world);
  k.step(3);
  await device.queue.onSubmittedWorkDone();
  const steps = n >= 500_000 ? 10 : 30;
  const [ms, clock] = await gpuTime(device, k, steps, timestamps);
  const rows: Timing[] = [{ backend: label, agents: n, stepMs: ms, perFrame: (n * FRAME_MS) / ms, drawn: false, clock }];
  if (drawer) {
    const draw = () => {
      const enc = device.createCommandEncoder();
      drawer.d.encode(enc, k, drawer.view);
      device.queue.submit([enc.finish()]);
    };
    const [dms, dclock] = await gpuTime(device, k, steps, false, draw);
    rows.push({ backend: label, agents: n, stepMs: dms, perFrame: (n * FRAME_MS) / dms, drawn: true, clock: dclock });
  }
  k.destroy();
  return rows;
}

/** The wasm core stepping the same crowd (all 16 goals) on this page's thread. */
export function measureCore(lab: Lab, n: number): Timing {
  const w = lab.fork();
  w.spawnRandom(n, 1, crowdExtent(n), 1.3);
  w.step(2);
  const steps = n >= 50_000 ? 3 : 10;
  const t0 = performance.now();
  w.step(steps);
  const ms = (performance.now() - t0) / steps;
  w.free();
  return { backend: "wasm core, one thread of this CPU", agents: n, stepMs: ms, perFrame: (n * FRAME_MS) / ms, drawn: false, clock: "wall clock" };
}

/** The kernel's counted cost per update over 60 steps of `n` agents. */
export async function measureCost(device: GPUDevice, lab: Lab, table: GpuTable, n: number): Promise<CountedCost> {
  const k = await FunnelKernel.create(device, table, splitWorld(lab.gpuRandomCrowd(n, 1, crowdExtent(n), 1.3, 4)));
  const steps = 60;
  k.step(steps);
  const agents = await k.readAgents();
  k.destroy();
  return countedCost(agents, steps);
}
