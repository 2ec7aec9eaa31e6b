// The funnelling step on the GPU (funnel.wgsl; docs/DESIGN.md §20): the η
// table, the agents and their goals in storage buffers, one compute pass
// per step. The core packs the arrays (Lab.gpuTableMeta/Axes/Cells,
// Lab.gpuWorld: crate/funnelling/table/gpu_table.rs, crate/world/gpu_world.rs)
// and says why a world cannot run here (Lab.gpuRefusal); this module only
// moves them onto the device and dispatches.
//
// The kernel's contract (checked by web/test/e2e-gpu.mjs against the wasm
// core): from the same states one step gives the same mode for >= 99.9 %
// of agents, positions within 1e-4 m and headings within 1e-4 rad (and
// speeds within 1e-4); over a free run every agent's arrival verdict is
// the core's; a table read is within 1e-5 rad of the core's lookup. Not
// the bits: a GPU may fuse multiply-adds, sums the blend's 32 corners in
// its own order, and the kernel's sin/cos are f32 where the core's are f64.
//
// With separation between agents (GpuWorld::avoidance_settings; no
// obstacles, ORCA refused) a step is ten dispatches (passes.ts: the plans,
// the core's hashed grid by a counting sort and a prefix sum, grid.wgsl,
// the separation commands and the move, separation.wgsl): the same
// one-step contract, the grid the GPU built equal to the CPU's counts, and
// the free run's verdicts the core's for at least 98 % of agents, not all
// (a dense crowd under separation is chaotic: e2e-gpu.mjs SEP_VERDICTS).
//
// The short-range choice near a static goal (crate/funnelling/short_range.rs
// decide: simulated ways in) is the core's: made for the current goals
// when the world is packed, and for a goal the kernel moves an agent on
// to by FunnelKernel.decide between steps (Lab.gpuDecide); the kernel
// follows the choice every update. A host that steps on without deciding
// (the timing page, the lab's GPU crowd) gets plain funnelling for those
// goals: the same figures' cost, not the core's trajectory near them.

import funnel from "./funnel.wgsl?raw";
import grid from "./grid.wgsl?raw";
import separation from "./separation.wgsl?raw";
import { USAGE, readBack, storage } from "./buffers";
import { SeparationPasses } from "./passes";
import { compile, pipelineOf } from "./pipelines";

export { USAGE, readBack };

/** The kernel's WGSL, one module: the funnel's step, the neighbour grid and
 *  separation (a parity check may plant a change in a copy). */
export const FUNNEL_WGSL: string = [funnel, grid, separation].join("\n");

/** Floats per agent record (crate/world/state_field.rs STATE_STRIDE). */
export const RECORD_STRIDE = 19;
/** Words per agent (crate/world/gpu_world.rs GpuWorld::AGENT_WORDS). */
export const AGENT_WORDS = 14;
/** Agent word offsets: the flags, the current goal, goals in the queue, goals entered oriented, the mode. */
export const AGENT_FLAGS = 5;
export const AGENT_CURRENT = 6;
export const AGENT_COUNT = 8;
export const AGENT_ORIENTED = 9;
export const AGENT_MODE = 10;
/** The agent's count of table reads (funnel.wgsl `counted`): blends in the low 16 bits, axes located above. */
export const AGENT_COUNTED = 11;
/** Agent flags' bit: the short-range choice for the current goal is awaited from the host (GpuWorld::PENDING). */
export const PENDING = 2;
/** Agent word offsets of the short-range choice: the speed cap (f32, 0: none) and the side turned round (i32, 0: funnelling). */
export const AGENT_CAP = 12;
export const AGENT_SIDE = 13;
/** Words per goal (GpuWorld::GOAL_WORDS). */
export const GOAL_WORDS = 8;
/** Words per held command (GpuWorld::COMMAND_WORDS). */
export const COMMAND_WORDS = 4;
/** Settings' indices (GpuWorld::avoidance_settings): separation on, the grid's buckets, the first step's number. */
export const SETTING_SEPARATION = 24;
export const SETTING_BUCKETS = 31;
export const SETTING_STEP0 = 32;
export const WORKGROUP = 64;


/** The η table as the kernel reads it (Lab.gpuTableMeta, gpuTableAxes, gpuTableCells). */
export interface GpuTableArrays {
  meta: Uint32Array;
  axes: Float32Array;
  cells: Float32Array;
}

/** A world as the kernel steps it. */
export interface GpuWorldArrays {
  agents: Uint32Array;
  goals: Uint32Array;
  /** The commands held between plans (separation; empty: none held). */
  commands: Uint32Array;
  settings: Float32Array;
}

/** What the core's Lab gives for the kernel (core/wasm.ts's Lab has these). */
export interface GpuSource {
  gpuTableMeta(): Uint32Array;
  gpuTableAxes(): Float32Array;
  gpuTableCells(): Float32Array;
  gpuWorld(): Uint32Array;
}

/** What makes the short-range choices the kernel awaits (the core's Lab). */
export interface GpuDecider {
  gpuDecide(agents: Uint32Array, goals: Uint32Array): number;
}

/** Lab.gpuWorld's one array split: agents', goals' and commands' word counts first, then the three, then the settings. */
export function splitWorld(words: Uint32Array): GpuWorldArrays {
  const na = words[0] ?? 0;
  const ng = words[1] ?? 0;
  const nc = words[2] ?? 0;
  const agents = words.subarray(3, 3 + na);
  const goals = words.subarray(3 + na, 3 + na + ng);
  const commands = words.subarray(3 + na + ng, 3 + na + ng + nc);
  const rest = words.slice(3 + na + ng + nc);
  return { agents, goals, commands, settings: new Float32Array(rest.buffer, rest.byteOffset, rest.length) };
}

/** True when the world avoids by separation (GpuWorld::avoidance_settings). */
export function separating(world: GpuWorldArrays): boolean {
  return (world.settings[SETTING_SEPARATION] ?? 0) === 1;
}

export function tableArrays(lab: GpuSource): GpuTableArrays {
  return { meta: lab.gpuTableMeta(), axes: lab.gpuTableAxes(), cells: lab.gpuTableCells() };
}

/** The η table on the device, shared by the step and the probes. */
export class GpuTable {
  readonly meta: GPUBuffer;
  readonly axes: GPUBuffer;
  readonly cells: GPUBuffer;
  constructor(device: GPUDevice, t: GpuTableArrays) {
    this.meta = storage(device, t.meta, 0, "η table meta");
    this.axes = storage(device, t.axes, 0, "η table axes");
    this.cells = storage(device, t.cells, 0, "η table cells");
  }
  destroy(): void {
    this.meta.destroy();
    this.axes.destroy();
    this.cells.destroy();
  }
}

export interface KernelOptions {
  /** WGSL to compile instead of FUNNEL_WGSL (a parity check's planted change). */
  source?: string;
  /** Write every agent's record each step (the parity checks); else only the ringed agent's. */
  records?: boolean;
}

/** The agents of one world on the device, stepped by the kernel. */
export class FunnelKernel {
  readonly n: number;
  readonly agents: GPUBuffer;
  readonly records: GPUBuffer;
  private readonly goals: GPUBuffer;
  private readonly goalWords: Uint32Array;
  private readonly settings: GPUBuffer;
  private readonly frame: GPUBuffer;
  private readonly bind: GPUBindGroup;
  private readonly frameWords = new Uint32Array(4);
  /** Separation's passes (null: avoidance off, one dispatch per step). */
  separation: SeparationPasses | null = null;

  private constructor(
    private readonly device: GPUDevice,
    private readonly pipeline: GPUComputePipeline,
    table: GpuTable,
    world: GpuWorldArrays,
    private readonly allRecords: boolean,
  ) {
    this.n = world.agents.length / AGENT_WORDS;
    this.agents = storage(device, world.agents, USAGE.VERTEX, "agents");
    this.goals = storage(device, world.goals, 0, "goals");
    this.goalWords = world.goals.slice();
    this.settings = storage(device, world.settings, 0, "settings");
    const recordFloats = allRecords ? this.n * RECORD_STRIDE : RECORD_STRIDE;
    this.records = storage(device, new Float32Array(recordFloats), 0, "records");
    this.frame = device.createBuffer({ size: 16, usage: USAGE.UNIFORM | USAGE.COPY_DST });
    this.frameWords.set([this.n, allRecords ? 1 : 0, 0xffffffff, 0]);
    device.queue.writeBuffer(this.frame, 0, this.frameWords);
    const buffers = this.bindings(table);
    this.bind = device.createBindGroup({
      layout: pipeline.getBindGroupLayout(0),
      entries: buffers.map((buffer, binding) => ({ binding, resource: { buffer } })),
    });
  }

  /** The kernel's buffers by binding (funnel.wgsl 0–7). */
  private bindings(table: GpuTable): GPUBuffer[] {
    return [this.settings, table.meta, table.axes, table.cells, this.agents, this.goals, this.records, this.frame];
  }

  static async create(device: GPUDevice, table: GpuTable, world: GpuWorldArrays, opts: KernelOptions = {}): Promise<FunnelKernel> {
    const module = await compile(device, opts.source ?? FUNNEL_WGSL);
    const k = new FunnelKernel(device, await pipelineOf(device, module, "step_agents"), table, world, opts.records ?? false);
    if (separating(world)) {
      const buckets = world.settings[SETTING_BUCKETS] ?? 64;
      const step0 = world.settings[SETTING_STEP0] ?? 0;
      k.separation = await SeparationPasses.create(device, module, k.bindings(table), k.n, buckets, world.commands, step0);
    }
    return k;
  }

  /** The agent whose record is written each step when not all are (the HUD's ringed agent). */
  setRing(i: number): void {
    this.frameWords[2] = i >= 0 && i < this.n ? i : 0xffffffff;
    this.device.queue.writeBuffer(this.frame, 0, this.frameWords);
  }

  /** Encodes `steps` steps, one compute pass each (with separation, its
   *  ten dispatches: passes.ts), into `enc`; with
   *  `timestamps`, its query 0 at the first pass's start and 1 at the last's end. */
  encode(enc: GPUCommandEncoder, steps = 1, timestamps?: GPUQuerySet): void {
    for (let s = 0; s < steps; s++) {
      const tw: GPUComputePassTimestampWrites | undefined = timestamps && {
        querySet: timestamps,
        ...(s === 0 ? { beginningOfPassWriteIndex: 0 } : {}),
        ...(s === steps - 1 ? { endOfPassWriteIndex: 1 } : {}),
      };
      const pass = enc.beginComputePass(tw && (s === 0 || s === steps - 1) ? { timestampWrites: tw } : {});
      if (this.separation) {
        this.separation.dispatch(pass);
      } else {
        pass.setPipeline(this.pipeline);
        pass.setBindGroup(0, this.bind);
        pass.dispatchWorkgroups(Math.ceil(this.n / WORKGROUP));
      }
      pass.end();
    }
  }

  step(steps = 1): void {
    const enc = this.device.createCommandEncoder();
    this.encode(enc, steps);
    this.device.queue.submit([enc.finish()]);
  }

  async readAgents(): Promise<Uint32Array> {
    return new Uint32Array(await readBack(this.device, this.agents, this.n * AGENT_WORDS * 4));
  }

  /** Makes the short-range choices the last step left awaited (agents moved
   *  on to a goal) with `core`, from the states after that step, and
   *  uploads them before the next; returns how many were made. */
  async decide(core: GpuDecider): Promise<number> {
    const agents = await this.readAgents();
    let awaited = false;
    for (let i = 0; i < this.n && !awaited; i++) awaited = ((agents[i * AGENT_WORDS + AGENT_FLAGS] ?? 0) & PENDING) !== 0;
    if (!awaited) return 0;
    const made = core.gpuDecide(agents, this.goalWords);
    this.device.queue.writeBuffer(this.agents, 0, agents);
    return made;
  }

  /** Every agent's record (with `records`), else the ringed agent's. */
  async readRecords(): Promise<Float32Array> {
    const floats = this.allRecords ? this.n * RECORD_STRIDE : RECORD_STRIDE;
    return new Float32Array(await readBack(this.device, this.records, floats * 4));
  }

  destroy(): void {
    for (const b of [this.agents, this.goals, this.settings, this.records, this.frame]) b.destroy();
    this.separation?.destroy();
  }
}

/** The kernel's table read alone at each probe (five floats: D, α, ω, v_c,
 *  v_d): four floats each, η, reachable, v_dt, η valid (Lab.lookupProbes'
 *  layout). */
export async function probeTable(device: GPUDevice, table: GpuTable, settings: Float32Array, probes: Float32Array, source?: string): Promise<Float32Array> {
  const n = probes.length / 5;
  const module = await compile(device, source ?? FUNNEL_WGSL);
  const probe = await pipelineOf(device, module, "probe_table");
  const frame = device.createBuffer({ size: 16, usage: USAGE.UNIFORM | USAGE.COPY_DST });
  device.queue.writeBuffer(frame, 0, new Uint32Array([n, 0, 0, 0]));
  const s = storage(device, settings);
  const q = storage(device, probes);
  const answers = storage(device, new Float32Array(4 * n));
  const entries: [number, GPUBuffer][] = [[0, s], [1, table.meta], [2, table.axes], [3, table.cells], [7, frame], [8, q], [9, answers]];
  const bind = device.createBindGroup({ layout: probe.getBindGroupLayout(0), entries: entries.map(([binding, buffer]) => ({ binding, resource: { buffer } })) });
  const enc = device.createCommandEncoder();
  const pass = enc.beginComputePass();
  pass.setPipeline(probe);
  pass.setBindGroup(0, bind);
  pass.dispatchWorkgroups(Math.ceil(n / WORKGROUP));
  pass.end();
  device.queue.submit([enc.finish()]);
  const out = new Float32Array(await readBack(device, answers, 16 * n));
  for (const b of [frame, s, q, answers]) b.destroy();
  return out;
}
