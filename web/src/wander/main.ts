// The random steering gallery (paper 004): one panel per toolkit component,
// reproducing its figure series from the preset files scenarios/wander/*.json
// (loaded at runtime as separate chunks, like the funnelling page's presets).

import { button } from "../ui/controls";
import { $, showMessage, showVersion } from "../ui/page";
import { errorText, loadCore, WanderLab } from "../core/wasm";
import { GalleryPanel, type PanelStatus } from "./gallery";

/** The components in the paper's order. */
export const COMPONENTS = ["control", "distributions", "fields", "time-functions", "timed", "markov", "paths", "composed"] as const;

const files = import.meta.glob<string>("../../../scenarios/wander/*.json", { query: "?raw", import: "default" });

/** What the end-to-end test reads and drives (window.__wander, the test build only). */
export interface WanderHook {
  ready: boolean;
  error: string | null;
  frames: number;
  panels(): PanelStatus[];
  busy(): boolean;
  rerun(name?: string): void;
}

declare global {
  interface Window {
    __wander?: WanderHook;
  }
}

const panels: GalleryPanel[] = [];
const status = { ready: false, error: null as string | null, frames: 0 };

/** Replays the panel `name` (every panel if none) from step 0. */
function rerun(name?: string): void {
  for (const p of panels) if (name === undefined || p.name === name) p.rerun();
}

// The test build's hook; the shipped build drops it.
if (import.meta.env.MODE === "test") {
  window.__wander = {
    get ready() { return status.ready; },
    get error() { return status.error; },
    get frames() { return status.frames; },
    panels: () => panels.map((p) => p.status()),
    busy: () => panels.some((p) => p.busy()),
    rerun,
  };
}

function frame(): void {
  requestAnimationFrame(frame);
  status.frames++;
  for (const p of panels) p.tick();
}

async function start(): Promise<void> {
  const gallery = $("gallery");
  const problems: string[] = [];
  try {
    showVersion(await loadCore());
  } catch (e) {
    status.error = errorText(e);
    showMessage(`could not load the steering core: ${status.error}`, "error");
    return;
  }
  const texts = await Promise.all(COMPONENTS.map(async (name) => {
    const load = files[`../../../scenarios/wander/${name}.json`];
    if (!load) return { name, text: null, error: "preset file missing" };
    try {
      return { name, text: await load(), error: null };
    } catch (e) {
      return { name, text: null, error: errorText(e) };
    }
  }));
  for (const { name, text, error } of texts) {
    if (text === null) {
      problems.push(`${name}.json: ${error ?? "?"}`);
      continue;
    }
    try {
      panels.push(new GalleryPanel(gallery, name, WanderLab.parsePreset(text)));
    } catch (e) {
      problems.push(`${name}.json: ${errorText(e)}`);
    }
  }
  if (problems.length > 0) {
    status.error = problems.join("\n");
    showMessage(status.error, "error");
  }
  button($("transport"), "rerun-all", "Re-run all", "replay every panel from step 0", () => rerun());
  rerun();
  status.ready = true;
  requestAnimationFrame(frame);
}

void start();
