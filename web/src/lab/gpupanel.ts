// The side panel's engine section (docs/DESIGN.md §20): whether the random
// crowd steps in the workers or on the GPU (the link's `eng`), the GPU
// crowd's size (`gn`), why the GPU is not in use when it is not, and the
// timing page for this device.

import { help, section, select } from "../ui/controls";
import { GPU_AGENTS_MAX } from "./gpukeys";
import type { LabSim } from "./sim";

const SIZES = [10_000, 100_000, 250_000, 1_000_000, 2_000_000, GPU_AGENTS_MAX];

export function gpuSection(panel: HTMLElement, sim: LabSim): { note(text: string | null): void } {
  const box = section(panel, "Engine");
  const rebuild = (): void => {
    sim.url.save();
    void sim.rebuild(true);
  };
  select(box, {
    id: "engine", label: "crowd on", value: sim.st.engine,
    options: [{ value: "workers", label: "CPU workers" }, { value: "gpu", label: "GPU (WebGPU)" }],
    onChange: (v) => { sim.st.engine = v; rebuild(); },
  });
  const sizes = SIZES.includes(sim.st.gpuAgents) ? SIZES : [...SIZES, sim.st.gpuAgents].sort((a, b) => a - b);
  select(box, {
    id: "gpu-agents", label: "GPU agents", value: String(sim.st.gpuAgents),
    options: sizes.map((n) => ({ value: String(n), label: n.toLocaleString("en") })),
    onChange: (v) => { sim.st.gpuAgents = Number(v); if (sim.st.engine === "gpu") rebuild(); },
  });
  const text = help(box);
  text.textContent = "On the GPU the random crowd is stepped by a WebGPU kernel that mirrors the core's update (checked against it in CI) and drawn from its buffers; the ringed agent stays the playground's. ";
  const link = document.createElement("a");
  link.href = "./gpu.html";
  link.textContent = "Time it on this device";
  text.append(link);
  const note = help(box);
  note.id = "gpu-note";
  note.hidden = true;
  return {
    note(t: string | null) {
      note.hidden = t === null;
      note.textContent = t ?? "";
    },
  };
}
