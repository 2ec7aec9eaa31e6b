// A figure's simulation: its own Lab (forked from the page's, sharing the
// one η table), the agents' trails since the start state, and "run ahead":
// the same set-up simulated to its end at once, so the prose can quote
// what *will* happen (arrival time, heading error, modes visited) while the
// figure still shows the start. Also the live-number writer and the lab
// link's state.

import { defaultState, type LabState, type Pose } from "../lab/state";
import { Lab, Mode, StateField, type GoalConfig } from "../core/wasm";

/** Writes `text` into every `[data-live="name"]` of the page. */
export function live(name: string, text: string): void {
  for (const el of document.querySelectorAll<HTMLElement>(`[data-live="${name}"]`)) {
    if (el.textContent !== text) el.textContent = text;
  }
}

/** A goal with the lab's playground defaults (β in rad). */
export function goal(x: number, y: number, beta: number, more: Partial<GoalConfig> = {}): GoalConfig {
  return { x, y, beta, dTol: 0.3, epsTol: (10 * Math.PI) / 180, speed: 1.3, halting: true, relaxed: false, ...more };
}

/** The lab's state for a playground set-up (the rest at its defaults). */
export function labState(vehicle: Pose, g: GoalConfig, more: Partial<LabState> = {}): LabState {
  return {
    ...defaultState(),
    vehicle: { ...vehicle },
    target: { x: g.x, y: g.y, theta: g.beta },
    dTol: g.dTol,
    epsTol: g.epsTol,
    speed: g.speed,
    halting: g.halting ?? false,
    relaxed: g.relaxed ?? false,
    ...more,
  };
}

/** What a run did from its start state to its end. */
export interface Outcome {
  /** Seconds until every agent reached End_of_Steering (NaN: not within the limit). */
  time: number;
  /** Each agent's final heading error |β − θ|, rad. */
  headingError: number[];
  /** Each agent's path length, m. */
  length: number[];
  /** Each agent's modes in the order first entered. */
  modes: number[][];
  /** Each agent's trail: x, y pairs. */
  trails: number[][];
}

export class Run {
  readonly stride: number;
  state: Float32Array = new Float32Array(0);
  trails: number[][] = [];
  modes: number[][] = [];
  time = 0;

  /** `build` adds the agents to an empty lab (called on every reset). */
  constructor(readonly lab: Lab, private readonly build: (lab: Lab) => void, readonly maxTime = 40) {
    this.stride = Lab.stateStride();
  }

  reset(): void {
    this.lab.clear();
    this.build(this.lab);
    this.time = 0;
    this.pull();
    this.trails = [];
    this.modes = [];
    for (let i = 0; i < this.count; i++) {
      this.trails.push([this.x(i), this.y(i)]);
      this.modes.push([this.field(i, StateField.Mode)]);
    }
  }

  get count(): number {
    return Math.floor(this.state.length / this.stride);
  }

  field(i: number, f: StateField): number {
    return this.state[i * this.stride + f] ?? NaN;
  }

  x(i: number): number {
    return this.field(i, StateField.X);
  }

  y(i: number): number {
    return this.field(i, StateField.Y);
  }

  private pull(): void {
    this.state = this.lab.state();
  }

  /** Every agent in End_of_Steering. */
  done(): boolean {
    for (let i = 0; i < this.count; i++) {
      if (this.field(i, StateField.Mode) !== Mode.EndOfSteering) return false;
    }
    return this.count > 0;
  }

  /** One step; false once the run is over (done, or past maxTime). */
  step(): boolean {
    this.lab.step(1);
    this.time += this.lab.params().dt;
    this.pull();
    for (let i = 0; i < this.count; i++) {
      const t = this.trails[i]!;
      const px = t[t.length - 2]!;
      const py = t[t.length - 1]!;
      if (Math.hypot(this.x(i) - px, this.y(i) - py) > 0.05) t.push(this.x(i), this.y(i));
      const m = this.modes[i]!;
      const mode = this.field(i, StateField.Mode);
      if (m[m.length - 1] !== mode) m.push(mode);
    }
    return !this.done() && this.time < this.maxTime;
  }

  /** Runs from the start state to the end (the figure is reset afterwards by its caller). */
  ahead(): Outcome {
    this.reset();
    let finished = NaN;
    while (this.time < this.maxTime) {
      this.step();
      if (this.done()) {
        finished = this.time;
        break;
      }
    }
    const out: Outcome = { time: finished, headingError: [], length: [], modes: this.modes.map((m) => [...m]), trails: this.trails.map((t) => [...t]) };
    for (let i = 0; i < this.count; i++) {
      const e = this.field(i, StateField.GoalBeta) - this.field(i, StateField.Theta);
      out.headingError.push(Math.abs(Math.atan2(Math.sin(e), Math.cos(e))));
      const t = this.trails[i]!;
      let len = 0;
      for (let k = 2; k < t.length; k += 2) len += Math.hypot(t[k]! - t[k - 2]!, t[k + 1]! - t[k - 1]!);
      out.length.push(len);
    }
    this.reset();
    return out;
  }
}
