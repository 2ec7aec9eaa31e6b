// The crowd page (main.ts) in one record: its status, its session, the
// paper's presets, the loop's counters and its work probe. The HUD reads
// the counters; the test build's hook (hook.ts) reads the rest.

import type { CrowdConfig } from "../core/wasm";
import type { CrowdSession } from "./session";

/** What the loop (loop.ts) counts; the figures over the last second are the HUD's. */
export interface CrowdStats {
  frames: number;
  /** Frames that drew a new state. */
  drawnFrames: number;
  /** Steps and boid updates completed (the page's thread or the workers). */
  steps: number;
  updates: number;
  /** Workers: wall ms of their jobs, and of the slowest worker's stepping in them. */
  jobMs: number;
  workerStepMs: number;
  /** Over the last second: ms per completed step (workers: the slowest
   *  worker's), ms per drawn frame (NaN: none), frames drawn per second. */
  stepMs: number;
  drawMs: number;
  fps: number;
  /** Over the last second: steps completed, and steps asked for (playing), per second. */
  stepsPerSecond: number;
  askedPerSecond: number;
}

export interface CrowdPage {
  ready: boolean;
  error: string | null;
  session: CrowdSession;
  presets: CrowdConfig[];
  stats: CrowdStats;
  /** Told each frame's work, ms (the test build's record). */
  probe: ((workMs: number) => void) | null;
}
