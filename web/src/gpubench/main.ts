// The GPU timing page (gpu.html; docs/DESIGN.md §20): the funnelling kernel
// on this device. It prints agents stepped per 16.7 ms (a 60 Hz frame) for
// the kernel alone and stepped + drawn, beside the wasm core on one thread
// of this CPU in the same run; checks the kernel against the core here
// (one step from the same states, a free run's verdicts, table reads); and
// reports the kernel's counted cost per update with what it projects for a
// laptop GPU (a projection, labelled so). On a software adapter
// (SwiftShader) every GPU figure is a CPU emulation, and says so.

import { fetchTable, Lab, loadCore } from "../core/wasm";
import { projectedAgents, type CountedCost } from "../gpu/cost";
import { openGpu, type GpuOpened } from "../gpu/device";
import { AgentDrawer, type AgentView } from "../gpu/draw";
import { AGENT_WORDS, GpuTable, tableArrays } from "../gpu/kernel";
import { probeParity, randomProbes, runParity } from "../gpu/parity";
import { installHook, type GpuPage } from "./hook";
import { crowdExtent, measureCore, measureCost, measureGpu, type Timing } from "./measure";
import { seedWorld, vehicleLab } from "./worlds";

const page: GpuPage = { ready: false, error: null, adapter: "", emulated: false, timestamps: false, rows: [], cost: null, gpu: null, table: null };
// The test build's window.__gpu; the shipped build drops this line and hook.ts.
if (import.meta.env.MODE === "test") installHook(page);

const el = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;
const fmt = (x: number) => (x >= 100 ? Math.round(x).toLocaleString("en") : x.toPrecision(3));

function showRows(rows: Timing[], emulated: boolean): void {
  const body = el<HTMLTableSectionElement>("gpu-rows");
  body.replaceChildren(...rows.map((r) => {
    const tr = document.createElement("tr");
    const what = r.backend.startsWith("wasm") ? r.backend : `${r.backend}${emulated ? " (CPU emulation)" : ""}`;
    for (const cell of [what, r.agents.toLocaleString("en"), r.drawn ? "stepped + drawn" : "stepped", fmt(r.stepMs), fmt(r.perFrame), r.clock]) {
      const td = document.createElement("td");
      td.textContent = cell;
      tr.append(td);
    }
    return tr;
  }));
}

function showCost(c: CountedCost): void {
  const lines = [
    `Counted per agent update (60 steps of 100,000 agents): ${c.blends.toFixed(2)} table blends of 32 cells, ${c.locates.toFixed(2)} axes located, ${c.passes} compute pass per step and no grid pass (this crowd has no avoidance; with separation a step is ten dispatches: the plans, the neighbour grid's counting sort and prefix sum, the separation commands and the move).`,
    `Bytes per update: ${Math.round(c.bytes)} (agent ${AGENT_WORDS * 4} read + ${AGENT_WORDS * 4} written, goal 32, η table ${Math.round(c.tableBytes)}).`,
    `Projection, not a measurement: a laptop GPU moving 100 GB/s would step ${fmt(projectedAgents(c.bytes, 100))} agents per 16.7 ms if every byte came from memory, ${fmt(projectedAgents(128, 100))} if the 5.8 MB table stays in cache; a 300 GB/s one, three times that.`,
  ];
  el("gpu-cost").replaceChildren(...lines.map((t) => Object.assign(document.createElement("p"), { textContent: t })));
}

function view(canvas: HTMLCanvasElement, n: number): AgentView {
  const e = crowdExtent(n);
  const aspect = canvas.width / Math.max(1, canvas.height);
  return {
    scale: [1 / (e * Math.max(1, aspect)), 1 / (e * Math.max(1, 1 / aspect))],
    offset: [0, 0],
    size: Math.max(0.3, (2.5 * e) / Math.max(1, canvas.width)),
    colors: [[0.5, 0.5, 0.5, 1], [0.85, 0.45, 0.1, 1], [0.15, 0.45, 0.85, 1], [0.1, 0.6, 0.3, 1]],
  };
}

/** Measures every size, the GPU ones drawn on the page's canvas too. */
async function measure(g: GpuOpened, lab: Lab, table: GpuTable, sizes: number[]): Promise<void> {
  const canvas = el<HTMLCanvasElement>("gpu-canvas");
  const context = canvas.getContext("webgpu") as GPUCanvasContext | null;
  let drawer: AgentDrawer | null = null;
  try {
    drawer = context ? new AgentDrawer(g.device, context) : null;
  } catch (e) {
    el("gpu-status").textContent = `no drawing here (${e instanceof Error ? e.message : String(e)}): stepping only`;
  }
  const label = `GPU kernel on ${g.label}`;
  page.rows = [];
  for (const n of sizes) {
    el("gpu-status").textContent = `measuring ${n.toLocaleString("en")} agents…`;
    page.rows.push(...(await measureGpu(g.device, lab, table, n, label, g.timestamps, drawer ? { d: drawer, view: view(canvas, n) } : undefined)));
    if (n <= 100_000) page.rows.push(measureCore(lab, n));
    showRows(page.rows, g.emulated);
  }
  page.cost = await measureCost(g.device, lab, table, 100_000);
  showCost(page.cost);
  el("gpu-status").textContent = "done";
}

/** The kernel against the core on this device, on the pedestrian's seeded world. */
async function check(g: GpuOpened, bytes: Uint8Array): Promise<void> {
  el("gpu-status").textContent = "checking the kernel against the core…";
  const lab = vehicleLab("pedestrian", bytes);
  seedWorld(lab, 2000, 7);
  const { samples, run } = await runParity(g.device, lab, { steps: 600, samples: [0, 300] });
  const probes = await probeParity(g.device, lab, randomProbes(10_000, 7, 32, 2, 2));
  lab.free();
  const worst = samples.reduce((m, s) => Math.max(m, s.maxPos), 0);
  el("gpu-parity").textContent = `Against the core (2,000 pedestrians): modes ${samples.map((s) => `${((100 * s.modesAgree) / s.agents).toFixed(2)} %`).join(", ")} the same after one step, positions within ${worst.toExponential(1)} m; after 600 steps ${run.differ} of ${run.agents} verdicts differ; 10,000 table reads within ${probes.maxEta.toExponential(1)} rad (${probes.reachDiffer} differ on reachability).`;
  el("gpu-status").textContent = "done";
}

async function start(): Promise<void> {
  const bytes = fetchTable("./tables/eta.planes");
  await loadCore();
  const g = await openGpu();
  if ("absent" in g) {
    el("gpu-adapter").textContent = `No GPU path here: ${g.absent}. The lab steps its agents in workers.`;
    page.ready = true;
    return;
  }
  Object.assign(page, { adapter: g.label, emulated: g.emulated, timestamps: g.timestamps, gpu: g });
  el("gpu-adapter").textContent = `${g.label}${g.emulated ? " — a software adapter: every GPU figure below is a CPU emulation, for correctness, not speed" : ""}; ${g.timestamps ? "timed by timestamp queries" : "no timestamp queries: timed by the wall clock"}.`;
  const tableBytes = await bytes;
  const lab = new Lab(tableBytes);
  const table = new GpuTable(g.device, tableArrays(lab));
  page.table = { lab, table, bytes: tableBytes };
  const run = el<HTMLButtonElement>("gpu-run");
  run.disabled = false;
  run.addEventListener("click", () => {
    run.disabled = true;
    const sizes = el<HTMLSelectElement>("gpu-sizes").value.split(",").map(Number);
    measure(g, lab, table, sizes)
      .then(() => check(g, tableBytes))
      .catch((e: unknown) => { el("gpu-status").textContent = `failed: ${e instanceof Error ? e.message : String(e)}`; })
      .finally(() => { run.disabled = false; });
  });
  page.ready = true;
}

start().catch((e: unknown) => {
  page.error = e instanceof Error ? e.message : String(e);
  el("gpu-status").textContent = `failed: ${page.error}`;
});
