// One figure's simulation: its own Lab (forked from the shared one, so the
// η table is shared), the world the lab's recipe builds from the figure's
// state (lab/recipe.ts, world/worldcalls.ts: the lab page's own world for
// the same link), the trails, and what the lab's scene builder reads
// (lab/scene.ts), so the figure draws exactly as the lab draws.

import { Lab, StateField, type Ghost, type Internals, type VehicleParams } from "../core/wasm";
import type { LabState, Pose } from "../lab/state";
import { recipeFor } from "../lab/recipe";
import type { SceneSource } from "../lab/scene";
import { Trails } from "../lab/trails";
import { buildWorld, type AvoidInfo, type BuildInfo } from "../world/worldcalls";

export class FigureSim implements SceneSource {
  readonly stride = Lab.stateStride();
  readonly trails = new Trails(50, 3000);
  state: Float32Array = new Float32Array(0);
  internals: Internals | null = null;
  time = 0;
  paused = false;
  readonly usPerUpdate = 0;
  readonly live = true;
  avoid: Pick<AvoidInfo, "method" | "radius" | "obstacles"> = { method: "off", radius: 0.3, obstacles: [] };
  readonly world: SceneSource["world"];

  constructor(readonly lab: Lab, public st: LabState) {
    this.world = {
      ghost: (i: number): Ghost | null => {
        try {
          return this.lab.ghost(i);
        } catch {
          return null;
        }
      },
      ring: (i: number): Float32Array | null => (i >= 0 && i < this.count ? this.lab.etaRing(i) : null),
    };
  }

  get count(): number {
    return Math.floor(this.state.length / this.stride);
  }

  /** The playground's agent is editable (handles); a preset's are not. */
  get focus(): number {
    return this.st.preset === "" && this.count > 0 ? 0 : -1;
  }

  get shown(): number {
    return this.count > 0 ? 0 : -1;
  }

  /** Builds the world of `st` (a preset's text when it names one) with
   *  the vehicle limits `params`, at t = 0. */
  build(st: LabState, params: VehicleParams, scenario: { name: string; text: string } | null): BuildInfo {
    this.st = st;
    this.lab.clear();
    const info = buildWorld(this.lab, recipeFor(st, params, { key: "", url: "", bytes: null }, scenario));
    this.avoid = info.avoid;
    this.time = 0;
    this.trails.clear();
    this.pull();
    return info;
  }

  /** `n` steps of dt. */
  step(n: number, dt: number): void {
    if (n <= 0) return;
    this.lab.step(n);
    this.time += n * dt;
    this.pull();
  }

  /** The agents' records and the shown agent's internals, read anew (and
   *  a trail sample). */
  pull(): void {
    this.state = this.lab.state();
    this.internals = this.count > 0 ? this.lab.internals(0) : null;
    if (this.st.overlays.trails && this.count <= this.trails.maxAgents) this.trails.record(this.time, this.state, this.stride, this.count);
  }

  /** Whether every agent is done and at rest (a halting last goal). */
  arrived(): boolean {
    if (this.count === 0) return false;
    for (let i = 0; i < this.count; i++) if (!this.lab.atRest(i)) return false;
    return true;
  }

  pose(i: number): Pose {
    const o = i * this.stride;
    return { x: this.state[o + StateField.X] ?? 0, y: this.state[o + StateField.Y] ?? 0, theta: this.state[o + StateField.Theta] ?? 0 };
  }

  field(i: number, f: StateField): number | undefined {
    return i >= 0 && i < this.count ? this.state[i * this.stride + f] : undefined;
  }

  etaField(vC: number, omegaC: number, vD: number): Float32Array {
    return this.lab.etaField(vC, omegaC, vD);
  }

  tableLine(): string {
    return "";
  }

  steppingLine(): string | undefined {
    return undefined;
  }
}
