// The paper scenarios that exist as files (scenarios/*.json), bundled as raw
// JSON text and handed to the core's scenario parser on selection.

const files = import.meta.glob<string>("../../../scenarios/*.json", { query: "?raw", import: "default" });

export interface Preset {
  /** File name without .json: the URL's `preset` value. */
  name: string;
  load(): Promise<string>;
}

export const PRESETS: readonly Preset[] = Object.entries(files)
  .map(([path, load]) => ({ name: path.replace(/^.*\//, "").replace(/\.json$/, ""), load }))
  .sort((a, b) => a.name.localeCompare(b.name));

export function presetNames(): string[] {
  return PRESETS.map((p) => p.name);
}

export function findPreset(name: string): Preset | undefined {
  return PRESETS.find((p) => p.name === name);
}

/** The menu group of a preset, from its name: `p001_fig11_tol5_relaxed` →
 *  "Paper 001 · Fig. 11" (the texts' own numbering); others "Other". */
export function presetGroup(name: string): string {
  const m = /^p(\d{3})_fig(\d+)([a-z]?)_/.exec(name);
  return m ? `Paper ${m[1]} · Fig. ${m[2]}${m[3] ?? ""}` : "Other";
}
