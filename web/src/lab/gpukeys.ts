// The GPU path's part of the lab's state and link (docs/DESIGN.md §20):
// which engine steps the random crowd (`eng=gpu`; the workers, the
// default, write nothing) and how many agents the GPU crowd has (`gn`).

import { clip } from "./fields";
import type { LabState } from "./state";

/** The engines that step the lab's random crowd. */
export const ENGINES: ReadonlyArray<LabState["engine"]> = ["workers", "gpu"];

/** The link's keys of the GPU path. */
export const GPU_KEYS = ["eng", "gn"] as const;

/** Most agents of the GPU crowd (the core's gpuRandomCrowd bound). */
export const GPU_AGENTS_MAX = 4_000_000;

/** Writes the GPU path's keys of `s` (nothing for the workers). */
export function encodeGpu(s: LabState, p: URLSearchParams): void {
  if (s.engine !== "gpu") return;
  p.set("eng", "gpu");
  p.set("gn", String(s.gpuAgents));
}

/** Reads the GPU path's keys into `s`; a bad value keeps the default and is reported. */
export function decodeGpu(p: URLSearchParams, s: LabState, problems: string[]): void {
  const eng = p.get("eng");
  if (eng !== null) {
    if ((ENGINES as readonly string[]).includes(eng)) s.engine = eng as LabState["engine"];
    else problems.push(`eng="${clip(eng)}" must be workers or gpu; workers kept`);
  }
  const gn = p.get("gn");
  if (gn !== null) {
    const n = Number(gn);
    if (Number.isInteger(n) && n >= 0 && n <= GPU_AGENTS_MAX) s.gpuAgents = n;
    else problems.push(`gn="${clip(gn)}" must be a whole number in [0, ${GPU_AGENTS_MAX}]; ${s.gpuAgents} kept`);
  }
}
