// The kernel against the core on this device (docs/DESIGN.md §20): one step
// from the same states sampled along a run of the wasm core (with
// separation, also the grid the kernel built for it, gridcheck.ts, and how
// many agents were pushed), a free run's arrival verdicts, and table reads
// at random probes. The e2e suite
// (web/test/e2e-gpu.mjs) asserts the kernel's contract on these numbers
// over SwiftShader; the timing page shows them for the user's own GPU.

import type { Lab } from "../core/wasm";
import { separationCost, type SeparationCost } from "./cost";
import { checkGrid, type GridParity } from "./gridcheck";
import { AGENT_CAP, AGENT_COUNT, AGENT_SIDE, AGENT_CURRENT, AGENT_ORIENTED, AGENT_WORDS, COMMAND_WORDS, FunnelKernel, GpuTable, RECORD_STRIDE, probeTable, splitWorld, tableArrays } from "./kernel";

/** One sampled step: agents, how many chose the core's mode, and the largest differences of the next state. */
export interface StepParity {
  step: number;
  agents: number;
  modesAgree: number;
  maxPos: number;
  maxHeading: number;
  maxSpeed: number;
  maxOmega: number;
  /** Largest difference of the commanded heading γ among agents of the same mode. */
  maxGamma: number;
  /** With separation: the grid the kernel built for the step, against the CPU's counts. */
  grid?: GridParity;
  /** With separation: agents whose command after the step is the avoidance's (active), of `agents`. */
  pushed?: number;
  /** With separation: what it adds per agent update, counted from that grid. */
  cost?: SeparationCost;
}

/** A free run: agents whose verdict (goals left, entered oriented, at rest inside both tolerances at the end) differs. */
export interface RunParity {
  steps: number;
  agents: number;
  differ: number;
  /** The first few that differ: index, core's verdict, kernel's. */
  examples: string[];
  /** Goals left and entered oriented in all, core's and kernel's. */
  left: [number, number];
  oriented: [number, number];
  restInside: [number, number];
  /** Short-range choices the core made between steps, for goals the kernel moved agents on to. */
  decided: number;
  /** Agents whose packed current goal is approached by turning first, or funnelling slowed (the choice in force at the start). */
  turnFirst: number;
  slowed: number;
  /** At the end: the largest distance between an agent's positions in the core and the kernel, m, and how many are more than 1 cm apart. */
  maxPos: number;
  apart: number;
}

export interface ProbeParity {
  probes: number;
  /** Largest |Δη| where both say η is valid and agree on reachability, rad. */
  maxEta: number;
  reachDiffer: number;
  validDiffer: number;
  /** Largest |Δv_dt| where reachability agrees. */
  maxVdt: number;
}

const F = { x: 0, y: 1, theta: 2, v: 3, omega: 4, mode: 5, gamma: 11, gx: 14, gy: 15, gb: 16, dtol: 17, eps: 18 } as const;

function wrap(a: number): number {
  const r = (a + Math.PI) % (2 * Math.PI);
  return (r < 0 ? r + 2 * Math.PI : r) - Math.PI;
}

function compareStep(step: number, cpu: Float32Array, gpu: Float32Array): StepParity {
  const n = cpu.length / RECORD_STRIDE;
  const out: StepParity = { step, agents: n, modesAgree: 0, maxPos: 0, maxHeading: 0, maxSpeed: 0, maxOmega: 0, maxGamma: 0 };
  for (let i = 0; i < n; i++) {
    const c = (f: number) => cpu[i * RECORD_STRIDE + f] ?? NaN;
    const g = (f: number) => gpu[i * RECORD_STRIDE + f] ?? NaN;
    const same = c(F.mode) === g(F.mode);
    if (same) out.modesAgree++;
    out.maxPos = Math.max(out.maxPos, Math.hypot(c(F.x) - g(F.x), c(F.y) - g(F.y)));
    out.maxHeading = Math.max(out.maxHeading, Math.abs(wrap(c(F.theta) - g(F.theta))));
    out.maxSpeed = Math.max(out.maxSpeed, Math.abs(c(F.v) - g(F.v)));
    out.maxOmega = Math.max(out.maxOmega, Math.abs(c(F.omega) - g(F.omega)));
    if (same) out.maxGamma = Math.max(out.maxGamma, Math.abs(wrap(c(F.gamma) - g(F.gamma))));
  }
  // NaN anywhere must fail, not hide in Math.max.
  for (const k of ["maxPos", "maxHeading", "maxSpeed", "maxOmega", "maxGamma"] as const) if (Number.isNaN(out[k])) out[k] = Infinity;
  return out;
}

/** At rest inside both tolerances of the record's goal, once done. */
function restInside(rec: Float32Array, i: number, done: boolean): boolean {
  const r = (f: number) => rec[i * RECORD_STRIDE + f] ?? NaN;
  return done && r(F.v) === 0 && Math.abs(r(F.omega)) <= 1e-4
    && Math.hypot(r(F.x) - r(F.gx), r(F.y) - r(F.gy)) < r(F.dtol)
    && Math.abs(wrap(r(F.gb) - r(F.theta))) < r(F.eps);
}

export interface RunOptions {
  /** Steps of the free run. */
  steps: number;
  /** Steps (from the start) at which one step is compared. */
  samples: number[];
  /** WGSL instead of the kernel's own (a planted change). */
  source?: string;
}

/** Runs `lab` (its world and table in force) `steps` steps in the core and,
 *  from the same start, in the kernel; compares one step from the core's
 *  state at each sample, and every agent's verdict at the end. The lab's
 *  world is advanced by `steps`. */
export async function runParity(device: GPUDevice, lab: Lab, opts: RunOptions): Promise<{ samples: StepParity[]; run: RunParity; drift: Drift[] }> {
  const table = new GpuTable(device, tableArrays(lab));
  const start = splitWorld(lab.gpuWorld());
  const kOpts = { records: true, ...(opts.source === undefined ? {} : { source: opts.source }) };
  const free = await FunnelKernel.create(device, table, start, kOpts);
  // One step at a time: the core's short-range choice for a goal an agent
  // moves on to is made between steps, as the core makes it at the next.
  let decided = 0;
  const marks = [...new Set(opts.samples)].filter((s) => s >= 0 && s < opts.steps).sort((a, b) => a - b);
  // The free run's records at the marks, to measure how far it has drifted
  // from the core's own run there.
  const freeAt = new Map<number, Float32Array>();
  for (let s = 0; s < opts.steps; s++) {
    free.step(1);
    decided += await free.decide(lab);
    if (marks.includes(s + 1)) freeAt.set(s + 1, await free.readRecords());
  }
  const n = free.n;
  const oriented = new Uint32Array(n);
  let verdicts: Uint32Array = new Uint32Array(2 * n);
  const add = (v: Uint32Array): void => {
    verdicts = v;
    for (let i = 0; i < n; i++) oriented[i] = (oriented[i] ?? 0) + (v[2 * i + 1] ?? 0);
  };
  const samples: StepParity[] = [];
  const drift: Drift[] = [];
  let t = 0;
  for (const s of [...marks, opts.steps]) {
    if (s > t) add(lab.stepJudging(s - t));
    t = s;
    if (s === opts.steps) break;
    const gpuFree = freeAt.get(s);
    if (gpuFree) drift.push({ step: s, ...apart(lab.state(), gpuFree) });
    const world = splitWorld(lab.gpuWorld());
    const k = await FunnelKernel.create(device, table, world, kOpts);
    k.step(1);
    const gpu = await k.readRecords();
    const extra = k.separation ? await separationChecks(k.separation, world.agents, world.settings) : {};
    k.destroy();
    add(lab.stepJudging(1));
    t++;
    samples.push({ ...compareStep(s, lab.state(), gpu), ...extra });
  }
  const agents = await free.readAgents();
  const gpuRec = await free.readRecords();
  free.destroy();
  table.destroy();
  const cpuRec = lab.state();
  const run: RunParity = { steps: opts.steps, agents: n, differ: 0, examples: [], left: [0, 0], oriented: [0, 0], restInside: [0, 0], decided, turnFirst: 0, slowed: 0, ...apart(cpuRec, gpuRec) };
  const f32 = new Float32Array(start.agents.buffer, start.agents.byteOffset, start.agents.length);
  for (let i = 0; i < n; i++) {
    if ((start.agents[i * AGENT_WORDS + AGENT_SIDE] ?? 0) !== 0) run.turnFirst++;
    if ((f32[i * AGENT_WORDS + AGENT_CAP] ?? 0) > 0) run.slowed++;
  }
  for (let i = 0; i < n; i++) {
    const w = (k: number) => agents[i * AGENT_WORDS + k] ?? 0;
    const cpuLeft = verdicts[2 * i] ?? 0;
    const gpuLeft = w(AGENT_CURRENT);
    const count = w(AGENT_COUNT);
    const cpu = [cpuLeft, oriented[i] ?? 0, restInside(cpuRec, i, cpuLeft >= count)];
    const gpu = [gpuLeft, w(AGENT_ORIENTED), restInside(gpuRec, i, gpuLeft >= count)];
    run.left[0] += Number(cpu[0]);
    run.left[1] += Number(gpu[0]);
    run.oriented[0] += Number(cpu[1]);
    run.oriented[1] += Number(gpu[1]);
    run.restInside[0] += Number(cpu[2]);
    run.restInside[1] += Number(gpu[2]);
    if (cpu.some((x, k) => x !== gpu[k])) {
      run.differ++;
      if (run.examples.length < 5) run.examples.push(`agent ${i}: core ${cpu.join("/")}, kernel ${gpu.join("/")}`);
    }
  }
  return { samples, run, drift };
}

/** The free run against the core's run at one step: how far apart. */
export interface Drift {
  step: number;
  maxPos: number;
  apart: number;
}

/** The largest distance between the same agent's positions in two records, m, and how many are more than 1 cm apart. */
function apart(cpu: Float32Array, gpu: Float32Array): { maxPos: number; apart: number } {
  const out = { maxPos: 0, apart: 0 };
  for (let i = 0; i < cpu.length / RECORD_STRIDE; i++) {
    const at = (r: Float32Array, f: number) => r[i * RECORD_STRIDE + f] ?? NaN;
    const d = Math.hypot(at(cpu, F.x) - at(gpu, F.x), at(cpu, F.y) - at(gpu, F.y));
    out.maxPos = Math.max(out.maxPos, Number.isNaN(d) ? Infinity : d);
    if (!(d <= 0.01)) out.apart++;
  }
  return out;
}

/** The grid a separating kernel built for its step, and how many agents its commands push. */
async function separationChecks(sep: NonNullable<FunnelKernel["separation"]>, agents: Uint32Array, settings: Float32Array): Promise<{ grid: GridParity; pushed: number; cost: SeparationCost }> {
  const built = await sep.readGrid();
  const grid = checkGrid(built, agents, settings);
  const commands = await sep.readCommands();
  let pushed = 0;
  for (let i = 0; i < sep.n; i++) pushed += (commands[i * COMMAND_WORDS + 2] ?? 0) === 1 ? 1 : 0;
  return { grid, pushed, cost: separationCost(built, agents, settings) };
}

/** `n` probes (D, α, ω, v_c, v_d) drawn from `seed` over the table's range
 *  and a little beyond (clamped axes, α across ±π). */
export function randomProbes(n: number, seed: number, dMax: number, vMax: number, omegaMax: number): Float32Array {
  let s = seed >>> 0 || 1;
  const next = () => {
    // xorshift32: enough for probes, and the same in every browser.
    s ^= s << 13;
    s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5;
    s >>>= 0;
    return s / 4294967296;
  };
  const out = new Float32Array(5 * n);
  for (let i = 0; i < n; i++) {
    out.set([1.1 * dMax * next() ** 2, 4 * Math.PI * (next() - 0.5), omegaMax * (2 * next() - 1), 1.05 * vMax * next(), 1.05 * vMax * next()], 5 * i);
  }
  return out;
}

/** The kernel's table read against the core's lookup at `probes`. */
export async function probeParity(device: GPUDevice, lab: Lab, probes: Float32Array, source?: string): Promise<ProbeParity> {
  const table = new GpuTable(device, tableArrays(lab));
  const settings = splitWorld(lab.gpuWorld()).settings;
  const gpu = await probeTable(device, table, settings, probes, source);
  table.destroy();
  const cpu = lab.lookupProbes(probes);
  const out: ProbeParity = { probes: probes.length / 5, maxEta: 0, reachDiffer: 0, validDiffer: 0, maxVdt: 0 };
  for (let i = 0; i < out.probes; i++) {
    const c = (k: number) => cpu[4 * i + k] ?? NaN;
    const g = (k: number) => gpu[4 * i + k] ?? NaN;
    if (c(1) !== g(1)) {
      out.reachDiffer++;
      continue;
    }
    out.maxVdt = Math.max(out.maxVdt, Math.abs(c(2) - g(2)));
    if (c(3) !== g(3)) out.validDiffer++;
    else if (c(3) === 1) out.maxEta = Math.max(out.maxEta, Math.abs(wrap(c(0) - g(0))));
  }
  if (Number.isNaN(out.maxEta) || Number.isNaN(out.maxVdt)) out.maxEta = Infinity;
  return out;
}
