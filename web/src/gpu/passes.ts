// Separation's passes on the device (grid.wgsl, separation.wgsl; docs/DESIGN.md
// §20): with separation on, a step is, in one compute pass, the funnels'
// plans (plan_agents), the core's hashed neighbour grid by a counting sort
// (clear the counts, count, the prefix sum in three dispatches, scatter,
// each bucket by index), each agent's separation command (separate) and
// the move with it (move_agents). This module owns the buffers the step
// adds (plans, held commands, the step number, the grid) and dispatches
// the passes; the kernel (kernel.ts) owns the agents, goals and table.

import { readBack, storage } from "./buffers";
import { pipelineOf } from "./pipelines";

/** Words per plan (funnel.wgsl Plan: the Internals, the position met, the reads counted). */
const PLAN_WORDS = 11;
/** Words per held command (GpuWorld::COMMAND_WORDS). */
const COMMAND_WORDS = 4;
const AGENT_GROUP = 64;
/** The grid's passes over buckets run 256 invocations a workgroup (grid.wgsl SCAN). */
const BUCKET_GROUP = 256;
/** A dispatch's most workgroups a side (WebGPU's default limit). */
const MAX_GROUPS = 65535;

/** The bindings each entry point reads (its "auto" layout's; funnel.wgsl 0–12, grid.wgsl 13–17). */
const USES = {
  plan_agents: [0, 1, 2, 3, 4, 5, 7, 10],
  clear_counts: [0, 14],
  count_agents: [0, 4, 7, 13],
  scan_blocks: [0, 14, 15],
  scan_sums: [0, 15],
  scan_add: [0, 7, 14, 15, 16],
  scatter_agents: [0, 4, 7, 16, 17],
  sort_buckets: [0, 14, 17],
  separate: [0, 4, 7, 10, 11, 12, 14, 17],
  move_agents: [0, 4, 5, 6, 7, 10, 11, 12],
} as const;
type Entry = keyof typeof USES;

/** The grid as the last step built it: each bucket's start (buckets + 1) and the agents in bucket order. */
export interface GpuGrid {
  starts: Uint32Array;
  order: Uint32Array;
}

/** Workgroups (x, y) covering `count` invocations of `group` each: y rows of at most MAX_GROUPS. */
function groups(count: number, group: number): [number, number] {
  const wg = Math.max(1, Math.ceil(count / group));
  const x = Math.min(wg, MAX_GROUPS);
  return [x, Math.ceil(wg / x)];
}

export class SeparationPasses {
  private readonly plans: GPUBuffer;
  private readonly commands: GPUBuffer;
  private readonly ctl: GPUBuffer;
  private readonly starts: GPUBuffer;
  private readonly blockSums: GPUBuffer;
  private readonly cursor: GPUBuffer;
  private readonly order: GPUBuffer;
  private readonly steps: { pipeline: GPUComputePipeline; bind: GPUBindGroup; size: [number, number] }[] = [];

  private constructor(
    private readonly device: GPUDevice,
    readonly n: number,
    readonly buckets: number,
    commands: Uint32Array,
    step0: number,
  ) {
    this.plans = storage(device, new Uint32Array(n * PLAN_WORDS), 0, "plans");
    const held = commands.length === n * COMMAND_WORDS ? commands : new Uint32Array(n * COMMAND_WORDS);
    this.commands = storage(device, held, 0, "commands");
    this.ctl = storage(device, Uint32Array.from([step0, 0, 0, 0]), 0, "avoider step");
    this.starts = storage(device, new Uint32Array(buckets + 1), 0, "grid starts");
    this.blockSums = storage(device, new Uint32Array(Math.ceil(buckets / BUCKET_GROUP)), 0, "grid block sums");
    this.cursor = storage(device, new Uint32Array(buckets), 0, "grid cursor");
    this.order = storage(device, new Uint32Array(n), 0, "grid order");
  }

  /** The passes for `n` agents over `buckets` buckets, in `module`, reading
   *  the kernel's buffers by binding (`core[b]`: 0 settings … 7 frame). */
  static async create(device: GPUDevice, module: GPUShaderModule, core: GPUBuffer[], n: number, buckets: number, commands: Uint32Array, step0: number): Promise<SeparationPasses> {
    const p = new SeparationPasses(device, n, buckets, commands, step0);
    const byBinding = new Map<number, GPUBuffer>(core.map((b, i) => [i, b]));
    const own: [number, GPUBuffer][] = [[10, p.plans], [11, p.commands], [12, p.ctl], [13, p.starts], [14, p.starts], [15, p.blockSums], [16, p.cursor], [17, p.order]];
    for (const [b, buf] of own) byBinding.set(b, buf);
    const sizes: Record<Entry, [number, number]> = {
      plan_agents: groups(n, AGENT_GROUP),
      clear_counts: groups(buckets + 1, BUCKET_GROUP),
      count_agents: groups(n, AGENT_GROUP),
      scan_blocks: groups(buckets, BUCKET_GROUP),
      scan_sums: [1, 1],
      scan_add: groups(buckets + 1, BUCKET_GROUP),
      scatter_agents: groups(n, AGENT_GROUP),
      sort_buckets: groups(buckets, BUCKET_GROUP),
      separate: groups(n, AGENT_GROUP),
      move_agents: groups(n, AGENT_GROUP),
    };
    for (const entry of Object.keys(USES) as Entry[]) {
      const pipeline = await pipelineOf(device, module, entry);
      const bind = device.createBindGroup({
        label: entry,
        layout: pipeline.getBindGroupLayout(0),
        entries: USES[entry].map((binding) => ({ binding, resource: { buffer: byBinding.get(binding) as GPUBuffer } })),
      });
      p.steps.push({ pipeline, bind, size: sizes[entry] });
    }
    return p;
  }

  /** One step's dispatches, in order, into `pass`. */
  dispatch(pass: GPUComputePassEncoder): void {
    for (const s of this.steps) {
      pass.setPipeline(s.pipeline);
      pass.setBindGroup(0, s.bind);
      pass.dispatchWorkgroups(s.size[0], s.size[1]);
    }
  }

  /** The grid the last step built (the parity checks'). */
  async readGrid(): Promise<GpuGrid> {
    const starts = new Uint32Array(await readBack(this.device, this.starts, (this.buckets + 1) * 4));
    const order = new Uint32Array(await readBack(this.device, this.order, Math.max(1, this.n) * 4));
    return { starts, order: order.subarray(0, this.n) };
  }

  /** The commands the agents stepped with in the last step (heading, speed, active, 0 each). */
  async readCommands(): Promise<Uint32Array> {
    return new Uint32Array(await readBack(this.device, this.commands, Math.max(1, this.n) * COMMAND_WORDS * 4));
  }

  /** Bytes of the buffers this adds per agent (plans, commands, grid order) and per bucket (starts, cursor, block sums). */
  static bytes(): { perAgent: number; perBucket: number } {
    return { perAgent: (PLAN_WORDS + COMMAND_WORDS + 1) * 4, perBucket: 8 + 4 / BUCKET_GROUP };
  }

  destroy(): void {
    for (const b of [this.plans, this.commands, this.ctl, this.starts, this.blockSums, this.cursor, this.order]) b.destroy();
  }
}
