// The "Controller" panel section: the funnelling settings a researcher
// compares live (μ bound, gain, seek threshold) and their mapping to the
// core's FunnelConfig. Every change goes straight to the core; agents keep
// running.

import { section, select, slider } from "../controls";
import type { BoundKey, FunnelSettings } from "./state";
import type { FunnelConfig, MuBound } from "../wasm";

export const BOUND_CHOICES: ReadonlyArray<{ value: BoundKey; label: string; bound: MuBound }> = [
  { value: "tr", label: "turning radius ×6 (default)", bound: { kind: "turningRadius", factor: 6 } },
  { value: "sl", label: "6 × literal", bound: { kind: "scaledLiteral", gain: 6 } },
  { value: "lit", label: "literal (paper)", bound: { kind: "literal" } },
  { value: "const", label: "constant π/2", bound: { kind: "constant" } },
];

/** The core's config for the page's settings. */
export function funnelConfig(f: FunnelSettings): FunnelConfig {
  const choice = BOUND_CHOICES.find((c) => c.value === f.bound) ?? BOUND_CHOICES[0]!;
  return { bound: choice.bound, gain: f.gain, seekThreshold: f.threshold };
}

/** Builds the section; edits `f` in place and calls `onChange` after each change. */
export function funnelSettingsSection(panel: HTMLElement, f: FunnelSettings, onChange: () => void): void {
  const box = section(panel, "Controller");
  const bound = select(box, {
    id: "mu-bound", label: "μ bound", options: BOUND_CHOICES, value: f.bound,
    onChange: (v) => { f.bound = v; onChange(); },
  });
  bound.el.title = "How |μ| is bounded: the paper's literal |η(D, Δη, 0, v_c, v_dt)|, six times it, atan(6·R_min / D), or π/2";
  const gain = slider(box, {
    id: "mu-gain", label: "gain k", unit: "", min: 1, max: 4, step: 0.25, value: f.gain,
    onInput: (v) => { f.gain = v; onChange(); },
  });
  const threshold = slider(box, {
    id: "seek-th", label: "seek threshold", unit: "ε_tol", min: 0.1, max: 1, step: 0.05, value: f.threshold,
    onInput: (v) => { f.threshold = v; onChange(); },
  });
  gain.el.title = "μ = −k·Δη before the bound (paper: k = 1)";
  threshold.el.title = "Plain seek (Position_only) once |Δη| is below this fraction of ε_tol (paper: 1)";
}
