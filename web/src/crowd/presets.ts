// The paper's crowd presets (Tests I–IV × five seeks, from the core) in the
// header's menu, grouped by test.

import type { CrowdConfig } from "../core/wasm";
import { SEEKS } from "./panel";

/** The preset the page opens with: Test IV's 300 boids, Parker 10 %. */
export function isDefaultPreset(p: CrowdConfig): boolean {
  return p.boids === 300 && p.seek.kind === "parker" && Math.abs(p.seek.fraction - 0.1) < 1e-6;
}

/** Fills `sel` with one option per preset (value: its index); returns the default's index. */
export function fillPresetMenu(sel: HTMLSelectElement, presets: readonly CrowdConfig[]): number {
  let group: HTMLOptGroupElement | null = null;
  presets.forEach((p, i) => {
    const test = /^Test (\d+)/.exec(p.name ?? "")?.[1] ?? "?";
    const label = `Test ${["", "I", "II", "III", "IV"][Number(test)] ?? test} (${p.boids} ${p.boids === 1 ? "boid" : "boids"}${p.separation ? ", separation" : ""})`;
    if (!group || group.label !== label) {
      group = document.createElement("optgroup");
      group.label = label;
      sel.append(group);
    }
    const seek = SEEKS.find((s) => s.seek.kind === p.seek.kind && (s.seek.kind === "reynolds" || (p.seek.kind === "parker" && s.seek.kind === "parker" && Math.abs(s.seek.fraction - p.seek.fraction) < 1e-6)));
    group.append(new Option(`${label.split(" (")[0]} — ${seek?.label ?? p.seek.kind}`, String(i)));
  });
  return Math.max(0, presets.findIndex(isDefaultPreset));
}
