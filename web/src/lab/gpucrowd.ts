// The lab's random crowd on the GPU (docs/DESIGN.md §20): with the engine
// "gpu" (gpukeys.ts) the crowd is the core's random crowd packed for the
// kernel (Lab.gpuRandomCrowd: spawnRandom's agents, bit for bit), stepped
// one compute pass per step (with the lab's separation on, the kernel's
// grid and separation passes in it: the lab's avoidance settings, no
// obstacles) and drawn straight from the agent buffer on a
// WebGPU canvas over the lab's, with the lab's view. Nothing is read back
// per frame: the ringed agent is the playground's, stepped by the core.
// Without WebGPU, or for a world the kernel refuses, `start` says why and
// the page steps the crowd in its workers.

import type { Lab } from "../core/wasm";
import { openGpu, type GpuOpened } from "../gpu/device";
import { AgentDrawer } from "../gpu/draw";
import { FunnelKernel, GpuTable, splitWorld, tableArrays } from "../gpu/kernel";
import { MODE_WORDS } from "../ui/modes";
import type { View } from "../ui/view";
import type { Recipe } from "../world/worldcalls";
import type { LabState } from "./state";

/** The crowd's spawn (recipe.ts's: agents, seed, square half-side, speed). */
export interface CrowdSpawn {
  n: number;
  seed: number;
  extent: number;
  speed: number;
}

/** The workers' largest random crowd (the core's `agents` range). */
const WORKERS_MAX = 100_000;

/** With the engine "gpu": the playground's recipe without its random crowd
 *  and the GPU's crowd (`gpuAgents` agents, recipe.ts's square for that
 *  many); `onGpu` false (the GPU could not take it): the crowd in the
 *  recipe, for the workers, at most their largest. Otherwise as it is. */
export function splitCrowd(st: LabState, recipe: Recipe, onGpu: boolean): { recipe: Recipe; spawn: CrowdSpawn | null } {
  const b = recipe.build;
  if (st.engine !== "gpu" || b.kind !== "playground") return { recipe, spawn: null };
  const n = onGpu ? st.gpuAgents : Math.min(st.gpuAgents, WORKERS_MAX);
  const spawn = n > 0 ? { n, seed: st.seed, extent: Math.max(10, Math.sqrt(n) * 1.5), speed: st.speed } : null;
  if (!onGpu) return { recipe: { ...recipe, build: { ...b, spawn } }, spawn: null };
  return { recipe: { ...recipe, build: { ...b, spawn: null } }, spawn };
}

/** Goals per agent the GPU holds: all 16 up to a quarter million agents, then as many as 128 MiB of goals allow. */
function goalsFor(n: number): number {
  return Math.max(1, Math.min(16, Math.floor((128 * 1024 * 1024) / (32 * Math.max(1, n)))));
}

function rgba(hex: string): [number, number, number, number] {
  const v = parseInt(hex.slice(1), 16);
  return [((v >> 16) & 255) / 255, ((v >> 8) & 255) / 255, (v & 255) / 255, 1];
}

export class LabGpu {
  private gpu: GpuOpened | null = null;
  private kernel: FunnelKernel | null = null;
  private table: { key: string; table: GpuTable } | null = null;
  private drawer: AgentDrawer | null = null;
  private canvas: HTMLCanvasElement | null = null;
  private goals = 0;
  /** Why the crowd is not on the GPU (shown; null while it is or was never asked). */
  note: string | null = null;

  constructor(private readonly stage: HTMLElement) {}

  get agents(): number {
    return this.kernel?.n ?? 0;
  }

  /** Puts `spawn`'s crowd on the GPU for `core`'s vehicle, settings and table;
   *  resolves to null, or why it cannot (the workers then step it). */
  async start(core: Lab, spawn: CrowdSpawn): Promise<string | null> {
    try {
      return await this.open(core, spawn);
    } catch (e) {
      this.stop();
      return (this.note = `the GPU could not take the crowd (${e instanceof Error ? e.message : String(e)}): it steps in the workers`);
    }
  }

  private async open(core: Lab, spawn: CrowdSpawn): Promise<string | null> {
    this.stop();
    const g = await openGpu();
    if ("absent" in g) return (this.note = `WebGPU is absent here (${g.absent}): the crowd steps in the workers`);
    this.gpu = g;
    const why = core.gpuRefusal();
    if (why) return (this.note = `${why}; the crowd steps in the workers`);
    const key = core.tableKey();
    if (this.table?.key !== key) {
      this.table?.table.destroy();
      this.table = { key, table: new GpuTable(g.device, tableArrays(core)) };
    }
    this.goals = goalsFor(spawn.n);
    const world = splitWorld(core.gpuRandomCrowd(spawn.n, spawn.seed, spawn.extent, spawn.speed, this.goals));
    this.kernel = await FunnelKernel.create(g.device, this.table.table, world);
    this.overlay(g);
    this.note = null;
    return null;
  }

  private overlay(g: GpuOpened): void {
    if (this.canvas) return;
    const c = document.createElement("canvas");
    c.className = "gpu-overlay";
    c.setAttribute("aria-hidden", "true");
    // Just over the lab's canvas, under the HUD and the legend.
    const lab = this.stage.querySelector("canvas#lab");
    if (lab) lab.after(c);
    else this.stage.append(c);
    const ctx = c.getContext("webgpu") as GPUCanvasContext | null;
    if (!ctx) return;
    this.canvas = c;
    try {
      this.drawer = new AgentDrawer(g.device, ctx);
    } catch (e) {
      // Stepping goes on; the note says why nothing is drawn.
      this.note = `the GPU crowd steps but cannot be drawn here (${e instanceof Error ? e.message : String(e)})`;
    }
  }

  /** Work submitted and not yet done: new steps and draws wait for it, so
   *  a device slower than the clock (a CPU emulation, a million agents)
   *  runs the crowd slower instead of queueing frames without end. */
  private busy = false;

  /** `k` steps, one compute pass each (none while paused, or while the last are running). */
  step(k: number): void {
    const { kernel, gpu } = this;
    if (k <= 0 || !kernel || !gpu || this.busy) return;
    kernel.step(Math.min(k, 4));
    this.settle(gpu);
  }

  private settle(gpu: GpuOpened): void {
    this.busy = true;
    void gpu.device.queue.onSubmittedWorkDone().then(() => { this.busy = false; });
  }

  /** Draws the crowd as `view` shows the world (CSS px per m about the centre). */
  draw(view: View): void {
    const { kernel, drawer, canvas, gpu } = this;
    if (!kernel || !drawer || !canvas || !gpu) return;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(view.width * dpr));
    const h = Math.max(1, Math.round(view.height * dpr));
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
    const sx = (2 * view.scale) / view.width;
    const sy = (2 * view.scale) / view.height;
    const colors = [MODE_WORDS.EndOfSteering, MODE_WORDS.OrientationOnly, MODE_WORDS.PositionOnly, MODE_WORDS.Funnelling].map((m) => rgba(m.colour));
    const enc = gpu.device.createCommandEncoder();
    // An arrow about 0.4 m long (the lab's vehicles are 0.5 m), never under 3 px.
    drawer.encode(enc, kernel, { scale: [sx, sy], offset: [-view.cx * sx, -view.cy * sy], size: Math.max(0.22, 2 / view.scale), colors });
    gpu.device.queue.submit([enc.finish()]);
    this.settle(gpu);
  }

  /** The HUD's stepping line while the crowd is on the GPU. */
  line(): string | undefined {
    if (!this.kernel || !this.gpu) return undefined;
    const goals = this.goals < 16 ? `, the first ${this.goals} of 16 goals each` : "";
    const sep = this.kernel.separation ? ", separating through a GPU grid" : "";
    return `GPU kernel on ${this.gpu.label}${this.gpu.emulated ? " (CPU emulation)" : ""}: ${this.kernel.n.toLocaleString("en")} agents${goals}${sep}, drawn from its buffers`;
  }

  stop(): void {
    this.kernel?.destroy();
    this.kernel = null;
    this.canvas?.remove();
    this.canvas = null;
    this.drawer?.destroy();
    this.drawer = null;
  }
}
