// The lab's compare view: for the playground's vehicle, limits and
// oriented target, where our funnelling goes and where a peer's steering
// goes, drawn as ghost trajectories with their arrival headings, so a
// learner sees what a peer does and what funnelling adds. The peer is Yuka
// 0.7.8 (npm `yuka`, JavaScript game AI): its `ArriveBehavior` (slows to a
// stop at the target's position) and plain `SeekBehavior`; neither takes
// the target's orientation β. Ours runs in a fork of the page's core (the
// same η table and settings); Yuka is loaded only once the view is on.

import { Lab, Mode, StateField, type VehicleParams } from "../core/wasm";
import { funnelConfig, readingOf, relaxedConfig } from "./funnelsettings";
import { goalConfig, type LabState } from "./state";

/** One side's ghost: its path and where its arrival heading is marked. */
export interface PeerGhost {
  /** "ours", "arrive" or "seek". */
  side: "ours" | "arrive" | "seek";
  /** x, y pairs, world. */
  points: number[];
  /** At rest inside D_tol (seek never stops). */
  arrived: boolean;
  /** Where the arrival heading is marked: the rest pose, or (seek, or a
   *  side that never rested) the first entry into D_tol; null: never inside. */
  mark: { x: number; y: number; heading: number; headingErr: number } | null;
  /** Simulated seconds to the mark (or the whole ghost without one). */
  time: number;
}

export const PEER_NAMES = { ours: "ours (funnelling)", arrive: "Yuka 0.7.8 arrive", seek: "Yuka 0.7.8 seek" } as const;
export const PEER_COLOURS = { ours: "#c2185b", arrive: "#1565c0", seek: "#8d6e63" } as const;

const REST_SPEED = 0.01;
const MAX_TIME_S = 40;
/** Seek never stops: its ghost runs this long past its first entry into D_tol. */
const SEEK_AFTER_S = 2.5;
const HOLD_S = 1;
/** A point every few steps is enough for a ghost. */
const EVERY = 3;
const wrap = (a: number): number => Math.atan2(Math.sin(a), Math.cos(a));

/** Builds a ghost from poses step by step (`add`), marking the arrival
 *  as the peers harness measures it (src/peers/meter.ts): at rest when the
 *  run ends inside D_tol below REST_SPEED for HOLD_S at least, marked
 *  with the heading it stands with; else at its first entry into D_tol. */
class Track {
  readonly points: number[];
  private entry: PeerGhost["mark"] = null;
  private entryTime = NaN;
  private restSince = NaN;
  private last = { x: 0, y: 0, theta: 0, t: 0 };
  constructor(private readonly st: LabState, x: number, y: number) {
    this.points = [x, y];
  }
  /** The pose after step `k` (time t). */
  add(k: number, t: number, x: number, y: number, theta: number, v: number): void {
    const g = this.st.target;
    const inside = Math.hypot(x - g.x, y - g.y) <= this.st.dTol;
    if (k % EVERY === 0) this.points.push(x, y);
    if (inside && this.entry === null) {
      this.entry = { x, y, heading: theta, headingErr: Math.abs(wrap(theta - g.theta)) };
      this.entryTime = t;
    }
    if (!(inside && v <= REST_SPEED)) this.restSince = NaN;
    else if (Number.isNaN(this.restSince)) this.restSince = t;
    this.last = { x, y, theta, t };
  }
  /** How long the run has been at rest inside D_tol at time `t`. */
  restFor(t: number): number {
    return Number.isNaN(this.restSince) ? 0 : t - this.restSince;
  }
  /** The first entry's time (NaN: none yet). */
  get entered(): number {
    return this.entryTime;
  }
  ghost(side: PeerGhost["side"]): PeerGhost {
    const l = this.last;
    this.points.push(l.x, l.y);
    const arrived = side !== "seek" && l.t - this.restSince >= HOLD_S;
    if (arrived) return { side, points: this.points, arrived, mark: { x: l.x, y: l.y, heading: l.theta, headingErr: Math.abs(wrap(l.theta - this.st.target.theta)) }, time: this.restSince };
    return { side, points: this.points, arrived, mark: this.entry, time: this.entry ? this.entryTime : l.t };
  }
}

/** Our funnelling from the playground's pose to its target, in a fork of `core`. */
export function oursGhost(core: Lab, st: LabState, params: VehicleParams): PeerGhost {
  const lab = core.fork();
  try {
    lab.setParams(params);
    const reading = readingOf(st.funnel);
    if (reading !== null) lab.setReading(reading);
    else {
      lab.setFunnel(funnelConfig(st.funnel));
      lab.setRelaxed(relaxedConfig(st.funnel));
    }
    lab.addAgent({ x: st.vehicle.x, y: st.vehicle.y, theta: st.vehicle.theta, goals: [goalConfig(st)] });
    const s = new Float32Array(Lab.stateStride());
    const tr = new Track(st, st.vehicle.x, st.vehicle.y);
    for (let k = 1; k * params.dt <= MAX_TIME_S; k++) {
      lab.stepInto(s);
      tr.add(k, k * params.dt, s[StateField.X]!, s[StateField.Y]!, s[StateField.Theta]!, s[StateField.V]!);
      // Halting: the end of steering at rest is for good.
      if (s[StateField.Mode] === Mode.EndOfSteering && tr.restFor(k * params.dt) >= HOLD_S) break;
    }
    return tr.ghost("ours");
  } finally {
    lab.free();
  }
}

type YukaSide = typeof import("../peers/yukaside");

/** Yuka's `side` from the same pose to the same target position, under
 *  the same limits (maxSpeed v_max, maxTurnRate ω_max, maxForce A). */
export function yukaGhost(y: YukaSide, side: "arrive" | "seek", st: LabState, params: VehicleParams): PeerGhost {
  const v = y.yukaVehicle(side, st.vehicle, st.target, params);
  const tr = new Track(st, st.vehicle.x, st.vehicle.y);
  const dt = params.dt;
  for (let k = 1; k * dt <= MAX_TIME_S; k++) {
    v.update(dt);
    const p = y.yukaPose(v);
    tr.add(k, k * dt, p.x, p.y, p.theta, p.v);
    if (side === "seek" && k * dt >= tr.entered + SEEK_AFTER_S) break;
  }
  return tr.ghost(side);
}
