// The lab page (main.ts) in one record: its status, the loop's frame
// count, its parts once started, and the loop's frame probe. The page
// itself reads none of it back; the test build's hook (hook.ts) does.

import type { View } from "../ui/view";
import type { PeerCompare } from "./compareview";
import type { Handles } from "./handles";
import type { LabSim } from "./sim";
import type { Transport } from "./transport";

export interface LabStatus {
  ready: boolean;
  error: string | null;
  /** What the link carried that was not taken. */
  problems: string[];
  version: string;
  /** performance.now() when the η table was in force and the clock free. */
  tableAt: number;
}

/** What the loop (loop.ts) counts. */
export interface LoopStats {
  /** Frames drawn. */
  frames: number;
  /** performance.now() when the first frame with agents was drawn by the loop. */
  firstDrawnMs: number;
}

/** Told about every frame (the test build's frame-time record). */
export interface FrameProbe {
  /** `updates` agent updates were drawn; they took `ms`. */
  stepped(updates: number, ms: number): void;
  frame(interval: number, work: number, step: number, draw: number): void;
}

export interface LabParts {
  sim: LabSim;
  view: View;
  transport: Transport;
  /** The compare view (Yuka's ghosts beside ours). */
  compare: PeerCompare;
  /** CSS-pixel canvas positions of the focus target's handles and of the vehicle. */
  handles(): Handles | null;
}

export interface LabPage {
  status: LabStatus;
  loop: LoopStats;
  parts: LabParts | null;
  probe: FrameProbe | null;
}
