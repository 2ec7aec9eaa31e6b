// One frame's picture and HUD figures from the simulation: the other
// agents' targets, the followed agent's overlays (η at the target, γ, the
// relaxed arc), the η ring and field, the playground's editable target.
// The η field is cached while its three inputs stay the same.

import { Mode, StateField, type Internals, type VehicleParams } from "../core/wasm";
import type { LabAvoidance } from "./avoidance";
import type { HudData } from "./hud";
import { vehicleKind } from "../ui/glyphs";
import type { Speed } from "../ui/speedmeter";
import { COLOURS, CROWD_THRESHOLD, type FieldDraw, type GhostDraw, type Overlay, type Scene, type TargetDraw } from "./render";
import type { LabSim } from "./sim";
import type { LabWorld } from "../world/world";

/** Screen length of the orientation/heading handles, CSS px. */
export const HANDLE_PX = 56;

/** Before the η table has arrived the agents show seek steering:
 *  the provisional plan's Funnelling (towards the centre, no η yet) is drawn
 *  as Position_only, and turns into Funnelling when the table is in. */
function seekView(mode: number, live: boolean): number {
  return !live && mode === Mode.Funnelling ? Mode.PositionOnly : mode;
}

/** What a scene is built from: the page's simulation (sim.ts), or, for
 *  the first frame, the core's picture of the default playground at t = 0
 *  carried in the HTML (firstframe.ts). */
export type SceneSource = Pick<LabSim, "st" | "count" | "state" | "stride" | "focus" | "shown" | "live" | "pose" | "field" | "trails" | "usPerUpdate" | "time" | "paused" | "tableLine" | "steppingLine" | "etaField"> & {
  world: Pick<LabWorld, "ghost" | "ring">;
  avoid: Pick<LabAvoidance, "method" | "radius" | "obstacles">;
  /** The vehicle limits in force (its kind and turning radius); absent:
   *  the core's default vehicle, a pedestrian that turns on the spot. */
  params?: () => Pick<VehicleParams, "vMax" | "omegaMax" | "minTurnRadius" | "vReverse">;
};

/** The core's default vehicle as far as the scene needs it (scenarios/vehicles/pedestrian.json). */
const PEDESTRIAN = { vMax: 2, omegaMax: 2 } as const;

export class SceneBuilder {
  private fieldCache: { key: string; samples: Float32Array } | null = null;

  constructor(private readonly sim: SceneSource) {}

  /** Every agent's target but the focus agent's (none for large crowds). */
  private targets(): TargetDraw[] {
    const { sim } = this;
    const out: TargetDraw[] = [];
    if (sim.count > CROWD_THRESHOLD) return out;
    const s = sim.state;
    const live = sim.live;
    for (let i = 0; i < sim.count; i++) {
      if (i === sim.focus) continue;
      const o = i * sim.stride;
      out.push({
        x: s[o + StateField.GoalX]!, y: s[o + StateField.GoalY]!, beta: s[o + StateField.GoalBeta]!,
        dTol: s[o + StateField.GoalDTol]!, epsTol: s[o + StateField.GoalEpsTol]!, mode: seekView(s[o + StateField.Mode]!, live),
      });
    }
    return out;
  }

  /** The scene for `inter`, the internals of the followed agent (sim.shown). */
  scene(inter: Internals | null): Scene {
    const { sim } = this;
    const { st, count } = sim;
    const who = sim.shown;
    const pose = sim.pose(who);
    let overlay: Overlay | null = null;
    if (inter && count > 0) {
      overlay = {
        x: pose.x, y: pose.y, theta: pose.theta,
        targetX: sim.field(who, StateField.GoalX) ?? 0, targetY: sim.field(who, StateField.GoalY) ?? 0,
        etaDir: st.overlays.eta && Number.isFinite(inter.eta) ? pose.theta + inter.alpha + inter.eta : null,
        gamma: st.overlays.gamma && Number.isFinite(inter.gamma) ? inter.gamma : null,
        arc: st.overlays.arc && inter.arc ? { r: inter.arc.radius, a0: pose.theta + inter.arc.alphaMin, a1: pose.theta + inter.arc.alphaMax, ar: pose.theta + inter.arc.alphaR } : null,
      };
    }
    let ring: FieldDraw | null = null;
    // The ring and the ghost where the world steps on this thread.
    const samples = st.overlays.ring && count > 0 ? sim.world.ring(who) : null;
    if (samples) ring = { samples, originX: pose.x, originY: pose.y, theta: pose.theta, light: COLOURS.ring, dark: COLOURS.ringDark };
    let field: FieldDraw | null = null;
    if (st.overlays.field && count > 0) {
      const key = `${st.field.vC}|${st.field.omegaC}|${st.field.vD}`;
      if (!this.fieldCache || this.fieldCache.key !== key) {
        const samples = sim.etaField(st.field.vC, st.field.omegaC, st.field.vD);
        // Empty before the table has arrived: not kept, asked again.
        this.fieldCache = samples.length > 0 ? { key, samples } : null;
      }
      if (this.fieldCache) field = { samples: this.fieldCache.samples, originX: pose.x, originY: pose.y, theta: pose.theta, light: COLOURS.field, dark: COLOURS.fieldDark };
    }
    const focusTarget: TargetDraw | null = sim.focus >= 0
      ? { x: st.target.x, y: st.target.y, beta: st.target.theta, dTol: st.dTol, epsTol: st.epsTol, mode: seekView(this.modeInForce(inter) ?? Mode.Funnelling, sim.live) }
      : null;
    let ghost: GhostDraw | null = null;
    const g = st.overlays.ghost && inter && count > 0 && count <= CROWD_THRESHOLD ? sim.world.ghost(who) : null;
    if (g) ghost = { points: g.points, reached: g.reached, finalDir: g.finalDir, slowed: g.slowed };
    return {
      state: sim.state, stride: sim.stride, count, ghost,
      targets: this.targets(),
      trails: st.overlays.trails && count <= sim.trails.maxAgents ? sim.trails : null,
      focus: sim.focus, shown: who, focusTarget, overlay,
      showRadial: st.overlays.radial,
      ring, field, handlePx: HANDLE_PX,
      obstacles: sim.avoid.obstacles,
      bodyRadius: sim.avoid.method === "off" ? null : sim.avoid.radius,
      kind: vehicleKind(sim.params?.() ?? PEDESTRIAN),
    };
  }

  /** The described agent's mode in force: its internals' (evaluated
   *  afresh, so a drag while paused shows the new mode at once), but for a
   *  vehicle that cannot turn on the spot the mode its last step ran: the
   *  internals are a plan without the manoeuvre the car has begun (its
   *  goal's memory), and said "funnelling" while it drove its loop. */
  private modeInForce(inter: Internals | null): number | null {
    const { sim } = this;
    if (!inter) return null;
    if ((sim.params?.().minTurnRadius ?? 0) > 0 && sim.count > 0) return sim.field(sim.shown, StateField.Mode) ?? inter.mode;
    return inter.mode;
  }

  /** Agent i's controller quantities as its last step recorded them. */
  private stepped(i: number): Pick<Internals, "d" | "alpha" | "eta" | "deltaEta" | "mu" | "muMax" | "reachable" | "vDt"> {
    const f = (k: StateField): number => this.sim.field(i, k) ?? NaN;
    return {
      d: f(StateField.D), alpha: f(StateField.Alpha), eta: f(StateField.Eta), deltaEta: f(StateField.DeltaEta),
      mu: f(StateField.Mu), muMax: NaN, reachable: f(StateField.Reachable) > 0.5, vDt: f(StateField.VDt),
    };
  }

  /** The HUD's figures for `inter` (as for scene). */
  hud(inter: Internals | null, frameMs: number, rate?: Speed): HudData {
    const { sim } = this;
    // A finished agent's internals carry no measurement (D 0, "unreachable"):
    // the HUD shows its distance to the last goal and no reachability.
    const mode = this.modeInForce(inter);
    const done = mode === Mode.EndOfSteering;
    const i = sim.shown;
    // A car-like vehicle's numbers as its last step computed them (see modeInForce).
    if (inter && mode !== inter.mode) inter = { ...inter, ...this.stepped(i) };
    const dx = (sim.field(i, StateField.GoalX) ?? NaN) - (sim.field(i, StateField.X) ?? NaN);
    const dy = (sim.field(i, StateField.GoalY) ?? NaN) - (sim.field(i, StateField.Y) ?? NaN);
    return {
      mode: inter && mode !== null ? seekView(mode, sim.live) : null,
      d: done ? Math.hypot(dx, dy) : (inter?.d ?? NaN),
      alpha: done ? NaN : (inter?.alpha ?? NaN), eta: done ? NaN : (inter?.eta ?? NaN),
      deltaEta: done ? NaN : (inter?.deltaEta ?? NaN), mu: done ? NaN : (inter?.mu ?? NaN), muMax: inter?.muMax ?? NaN,
      speed: sim.field(sim.shown, StateField.V) ?? 0,
      reachable: done || (inter?.reachable ?? true),
      vDt: inter?.vDt ?? NaN, shown: i,
      usPerUpdate: sim.usPerUpdate, frameMs, agents: sim.count, time: sim.time, paused: sim.paused, slow: sim.st.slow,
      table: sim.tableLine(),
      stepping: sim.steppingLine(),
      rate: rate && rate.spanMs > 0 ? rate : undefined,
      live: sim.live,
      minTurnRadius: sim.params?.().minTurnRadius ?? 0,
      vReverse: sim.params?.().vReverse ?? 0,
    };
  }
}
