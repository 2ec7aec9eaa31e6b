// The lab's one world, wherever it steps. `LabWorld` is what the page's
// simulation (../lab/sim.ts) talks to: it builds the world from a recipe, sends it
// edits, asks it for steps once per animation frame and draws `state`, a
// view of the buffer the stepping world writes. Two implementations:
// `HereWorld` (this file: the page's own core steps) and `WorkerWorld`
// (../lab/stepping.ts: Web Workers step slices of it). The page keeps
// no other copy of the world: an edit is checked once, by the core that
// steps, and its answer comes back (at once here, with the workers' next
// reply there).

import { Lab, type Ghost, type Internals } from "../core/wasm";
import { applyEdit, buildWorld, type BuildInfo, type Edit, type EditAnswer, type Recipe } from "./worldcalls";

/** What a frame (or `run`) took from the world: steps whose state is now
 *  drawn, the wall ms they took, and the stepping ms of the slowest thread. */
export interface Took {
  steps: number;
  ms: number;
  stepMs: number;
  /** `state` (or the internals) changed since the last frame. */
  fresh: boolean;
}

export interface LabWorld {
  /** Every agent's record (`Lab.stateStride()` floats each), as drawn. */
  readonly state: Float32Array;
  readonly count: number;
  /** The shown agent's internals in `state` (null: none yet). */
  readonly internals: Internals | null;
  /** Builds `recipe`'s world at t = 0 in place of the last one; resolves
   *  with what the build says, or null when this world cannot step it (the
   *  workers: avoidance couples every agent). */
  start(recipe: Recipe, shown: number): Promise<BuildInfo | null>;
  /** `e` for the world; `answer` gets the core's answer once applied. */
  edit(e: Edit, answer: (a: EditAnswer) => void): void;
  /** The page's core took the table `bytes` (`key`). */
  tableChanged(bytes: Uint8Array, key: string): void;
  /** One animation frame: `k` steps asked for (0: paused, edits still go
   *  out); what is now drawable. Never waits. */
  frame(k: number, shown: number): Took;
  /** Runs `k` steps now; resolves once `state` is theirs. */
  run(k: number, shown: number): Promise<Took>;
  /** The predicted seek path and η ring of agent `i` (null where the world
   *  is not on this thread). */
  ghost(i: number): Ghost | null;
  ring(i: number): Float32Array | null;
  /** The page's core when it holds the world (tests read settings there). */
  core(): Lab | null;
  /** Stops stepping and forgets the world. */
  stop(): void;
}

const NOTHING: Took = { steps: 0, ms: 0, stepMs: 0, fresh: false };

/** The world stepped by the page's core (`lab`, which also holds the η
 *  table the page draws its field from). Edits are applied at once;
 *  `state` is read from the core at most once a frame: with the frame's
 *  last step (`stepInto`), or after edits (`stateInto`). */
export class HereWorld implements LabWorld {
  state: Float32Array = new Float32Array(0);
  count = 0;
  internals: Internals | null = null;
  private readonly stride = Lab.stateStride();
  /** Edits since the last read: the next frame reads the state. */
  private stale = false;
  private shown = -1;

  constructor(private readonly lab: Lab) {}

  start(recipe: Recipe, shown: number): Promise<BuildInfo> {
    this.stop();
    const info = buildWorld(this.lab, recipe);
    this.count = this.lab.count();
    this.state = new Float32Array(this.count * this.stride);
    this.stale = true;
    this.frame(0, shown);
    return Promise.resolve(info);
  }

  edit(e: Edit, answer: (a: EditAnswer) => void): void {
    if (e.kind === "table") {
      // The page's core is this world's: it already holds the table.
      this.tableChanged();
      answer({ error: null, avoid: null });
      return;
    }
    answer(applyEdit(this.lab, e, 0, this.count));
    this.stale = true;
  }

  tableChanged(): void {
    // A lab's first table plans its agents (`Lab.setTable`).
    this.stale = true;
  }

  frame(k: number, shown: number): Took {
    if (this.count === 0) return NOTHING;
    let ms = 0;
    if (k > 0) {
      const t0 = performance.now();
      if (k > 1) this.lab.step(k - 1);
      this.lab.stepInto(this.state);
      ms = performance.now() - t0;
    } else if (this.stale) {
      this.lab.stateInto(this.state);
    } else if (shown === this.shown) {
      return NOTHING;
    }
    this.stale = false;
    this.shown = shown;
    this.internals = this.plan(shown);
    return { steps: k, ms, stepMs: ms, fresh: true };
  }

  run(k: number, shown: number): Promise<Took> {
    return Promise.resolve(this.frame(k, shown));
  }

  private plan(i: number): Internals | null {
    if (i < 0 || i >= this.count) return null;
    try {
      return this.lab.internals(i);
    } catch {
      return null;
    }
  }

  ghost(i: number): Ghost | null {
    if (i < 0 || i >= this.count) return null;
    try {
      return this.lab.ghost(i);
    } catch {
      return null;
    }
  }

  ring(i: number): Float32Array | null {
    return i >= 0 && i < this.count ? this.lab.etaRing(i) : null;
  }

  core(): Lab {
    return this.lab;
  }

  stop(): void {
    this.lab.clear();
    this.count = 0;
    this.state = new Float32Array(0);
    this.internals = null;
    this.shown = -1;
    this.stale = false;
  }
}
