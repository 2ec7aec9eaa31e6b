//! What crosses the boundary for [`Lab`](super::lab::Lab), declared once on
//! each side: the TypeScript interfaces the page compiles against
//! (`typescript_custom_section`) and the serde shapes that carry them
//! (flat, camelCase). Conversion only: the core validates what they carry.

use glam::Vec2;
use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::ghost::Ghost;
use crate::funnelling::goal::Goal;
use crate::funnelling::update::Internals;
use crate::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule};

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
/** One user-settable field's accepted range (crate::base::ranges): the
 *  key as errors name it (`vMax`, `goal.dTol`, `funnel.gain`), the closed
 *  interval [min, max] in SI units and radians, whole numbers only when
 *  `integer`, and `atMost`: a field whose current value also bounds this one
 *  (its magnitude, for a range symmetric about 0), e.g. goal.speed ≤ vMax. */
export interface FieldRange {
  key: string;
  min: number;
  max: number;
  unit: string;
  integer: boolean;
  atMost: string | null;
  what: string;
}
/** Where f32 positions resolve an agent's steps (crate::world::precision):
 *  |coordinate| ≤ min(⌊stepScale·v·dt⌋, ⌊toleranceScale·D_tol⌋, coordMax), in f32. */
export interface PrecisionRule {
  stepScale: number;
  toleranceScale: number;
  coordMax: number;
}
/** Vehicle limits and seek gains (crate::base::vehicle::VehicleParams). Units: m, s, rad. */
export interface VehicleParams {
  dt: number;
  vMax: number;
  accelMax: number;
  omegaMax: number;
  omegaAccelMax: number;
  normalAccelMax: number;
  kp: number;
  kd: number;
  integrator: "euler" | "semiImplicitEuler";
  /** Minimum turning radius at every speed, m (car-like); absent or 0: turns on the spot. */
  minTurnRadius?: number;
  /** Largest reverse speed, m/s (a car-like vehicle backs where shorter); absent or 0: forward only. */
  vReverse?: number;
  /** What one gear change is worth, m of path; absent or 0: the shortest path. */
  gearChangeCost?: number;
}
/** How the modulation μ is bounded (crate::funnelling::config::MuBound). `literal`: the
 *  paper's |η(D, Δη, 0, v_c, v_dt)|; `scaledLiteral`: `gain` × that, capped at
 *  π/2; `turningRadius`: atan(factor·max(R_min, minBoundRadius) / D), the
 *  default (factor 8); `constant`: π/2 (does not vanish with distance). */
export type MuBound =
  | { kind: "literal" }
  | { kind: "scaledLiteral"; gain: number }
  | { kind: "turningRadius"; factor: number }
  | { kind: "constant" };
/** The funnelling controller's settings, shared by every agent
 *  (crate::funnelling::config::FunnelConfig). μ = −gain·Δη (gain in [0, 100], default 2),
 *  bounded by `bound`; Position_only once |Δη| < seekThreshold·ε_tol
 *  (seekThreshold in [0, 1], default 0.25). */
export interface FunnelConfig {
  bound: MuBound;
  gain: number;
  seekThreshold: number;
  /** Aim at the disk's entry point (default) or at the centre (the paper). */
  aim?: "entry" | "centre";
  /** Smallest turning radius of the `turningRadius` bound, m (default 1). */
  minBoundRadius?: number;
  /** The terminal line pursuit (default on; null or absent: off). */
  terminal?: TerminalConfig | null;
  /** Reachability from the weighted vote of 32 samples (default) or the
   *  closest element (paper 000 Fig. 4). */
  reachability?: "vote" | "closest";
  /** Orientation_only's speed for a goal that is not halting: "stop"
   *  (default) or "keepSpeed" (the paper is silent). */
  orientationOnly?: "stop" | "keepSpeed";
  /** Tolerance phase: "latched" (default) or "fig5" (paper 000 Fig. 5 as written). */
  tolerance?: "latched" | "fig5";
  /** Aim a moving goal where it will be met (default true). */
  lead?: boolean;
  /** Near the target, cap the speed so the turning circle passes through it (default true). */
  orbitFree?: boolean;
  /** Keep the turn direction near the ±π seam (default true). */
  commitTurn?: boolean;
}
/** Which reading of the papers (crate::funnelling::controller::Reading):
 *  "paper", paper 000's standard and paper 001's relaxed funnelling as
 *  written, or "ours", the defaults (docs/READINGS.md). */
export type Reading = "paper" | "ours";
/** The terminal line pursuit (crate::funnelling::config::Terminal): carrot
 *  `lookahead` seconds of travel ahead on the goal's line; starts within
 *  `range` carrot distances of the disk when |β − θ| < `heading` (rad). */
export interface TerminalConfig {
  lookahead: number;
  heading: number;
  range: number;
}
/** Relaxed funnelling's settings (crate::funnelling::relaxed::RelaxedConfig). `aim`:
 *  "entry", the disk's entry point (default, as the standard controller), or
 *  "paperArc", paper 001 Fig. 7's relaxed point on the ring arc 𝒜. Margins
 *  in (0, 1]. */
export interface RelaxedConfig {
  aim?: "entry" | "paperArc";
  diskMargin?: number;
  orientationMargin?: number;
  endEta?: "linear" | "multilinear";
  /** Δη funnelled with: "lookup" (default, measured again at the relaxed
   *  point) or "fig7" (paper 001 Fig. 7's own). */
  deltaEta?: "lookup" | "fig7";
}
/** An oriented goal (crate::funnelling::goal::Goal): position (m), β (rad), tolerances, desired speed (m/s). */
export interface GoalConfig {
  x: number;
  y: number;
  beta: number;
  dTol: number;
  epsTol: number;
  speed: number;
  /** Comes to rest inside the tolerances (default false: passes through at speed). */
  halting?: boolean;
  /** Relaxed funnelling towards the region goal, paper 001 (default false; world-wide). */
  relaxed?: boolean;
}
/** One agent: start pose and its goal queue (each reached in turn). */
export interface AgentConfig {
  x: number;
  y: number;
  theta: number;
  v?: number;
  omega?: number;
  goals: GoalConfig[];
}
/** What one controller update computed (crate::funnelling::update::Internals). Angles in rad. */
export interface Internals {
  /** The control mode (paper 000 Fig. 5). */
  mode: Mode;
  d: number;
  alpha: number;
  eta: number;
  deltaEta: number;
  mu: number;
  muMax: number;
  gamma: number;
  reachable: boolean;
  vDt: number;
  /** Where the table was asked (the aim point, vehicle frame: distance m, radial angle rad; 0 when not
   *  asked) and with which desired speed (m/s). */
  aimD: number;
  aimAlpha: number;
  vQuery: number;
  /** Relaxed funnelling (paper 001 Fig. 7), vehicle frame: arc 𝒜 = [alphaMin, alphaMax] on the ring
   *  `radius`, chosen α_r, final-orientation span F = [fMin, fMax] (may pass ±π), searched interval
   *  T = [tMin, tMax], Fig. 7 branch (crate::funnelling::relaxed::Fig7Branch: 0 none … 8 entry point). */
  arc?: {
    alphaMin: number; alphaMax: number; alphaR: number; radius: number;
    fMin: number; fMax: number; tMin: number; tMax: number; branch: number;
  } | null;
}
/** A predicted seek path (crate::funnelling::ghost): `points` x, y pairs (world, m; start first, on arrival the
 *  crossing of the reach circle last); η and the final direction (world) in rad, NaN when not reached. */
export interface Ghost {
  reached: boolean;
  eta: number;
  finalDir: number;
  time: number;
  length: number;
  /** Desired speed simulated, m/s. */
  speed: number;
  /** Seeking at the queried speed failed: this is the path at the fallback speed v_dt (paper 000 §3). */
  slowed: boolean;
  targetX: number;
  targetY: number;
  points: Float32Array;
}
/** The loaded η table's shape. */
export interface TableInfo {
  entries: number;
  distances: number[];
  alphas: number[];
  omegaFractions: number[];
  speeds: number[];
  desiredSpeeds: number[];
  /** Smallest sampled distance D_η, m. */
  dEta: number;
  params: VehicleParams;
}
/** A loaded scenario: its name, description and the world box to show. */
export interface ScenarioInfo {
  name: string;
  description: string;
  source: string;
  /** What the paper claims for this figure, and what we measure (empty
   *  for scenarios that do not say). */
  claim: string;
  measured: string;
  /** Non-empty when the scenario's vehicle differs from the table's. */
  warning: string;
  agents: number;
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}
"#;

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct TableInfo<'a> {
    pub(super) entries: usize,
    pub(super) distances: &'a [f32],
    pub(super) alphas: &'a [f32],
    pub(super) omega_fractions: &'a [f32],
    pub(super) speeds: &'a [f32],
    pub(super) desired_speeds: &'a [f32],
    pub(super) d_eta: f32,
    pub(super) params: VehicleParams,
}

/// A goal as the page edits it (flat, camelCase); `relaxed` selects relaxed
/// funnelling towards the region goal (paper 001): the disk is `dTol`, the
/// orientation interval is β ± `epsTol`. The controller is world-wide.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
pub(super) struct GoalConfig {
    pub(super) x: f32,
    pub(super) y: f32,
    pub(super) beta: f32,
    pub(super) d_tol: f32,
    pub(super) eps_tol: f32,
    pub(super) speed: f32,
    #[serde(default)]
    pub(super) halting: bool,
    #[serde(default)]
    pub(super) relaxed: bool,
}

impl GoalConfig {
    /// The core's goal (validated by the world that receives it).
    pub(super) fn to_spec(&self) -> GoalSpec {
        GoalSpec {
            goal: Goal {
                pos: Vec2::new(self.x, self.y),
                beta: self.beta,
                d_tol: self.d_tol,
                eps_tol: self.eps_tol,
                speed: self.speed,
                halting: self.halting,
                vel: Vec2::ZERO,
            },
            motion: GoalMotion::Static,
            switch: SwitchRule::EndOfSteering,
        }
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
pub(super) struct AgentConfig {
    pub(super) x: f32,
    pub(super) y: f32,
    pub(super) theta: f32,
    #[serde(default)]
    pub(super) v: f32,
    #[serde(default)]
    pub(super) omega: f32,
    pub(super) goals: Vec<GoalConfig>,
}

impl AgentConfig {
    /// Whether a goal of its queue asks for relaxed funnelling.
    pub(super) fn relaxed(&self) -> bool {
        self.goals.iter().any(|g| g.relaxed)
    }

    /// The core's start state and goal queue (validated by the world that
    /// receives them).
    pub(super) fn into_core(self) -> (VehicleState, Vec<GoalSpec>) {
        let goals = self.goals.iter().map(GoalConfig::to_spec).collect();
        let state = VehicleState::new(Vec2::new(self.x, self.y), self.theta, self.v, self.omega);
        (state, goals)
    }
}

/// Internals as the page reads them: the mode as its number.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct InternalsOut {
    pub(super) mode: u8,
    pub(super) d: f32,
    pub(super) alpha: f32,
    pub(super) eta: f32,
    pub(super) delta_eta: f32,
    pub(super) mu: f32,
    pub(super) mu_max: f32,
    pub(super) gamma: f32,
    pub(super) reachable: bool,
    pub(super) v_dt: f32,
    pub(super) aim_d: f32,
    pub(super) aim_alpha: f32,
    pub(super) v_query: f32,
    pub(super) arc: Option<ArcOut>,
}

/// Relaxed funnelling's restricted arc 𝒜 and chosen α_r (vehicle frame).
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct ArcOut {
    pub(super) alpha_min: f32,
    pub(super) alpha_max: f32,
    pub(super) alpha_r: f32,
    pub(super) radius: f32,
    pub(super) f_min: f32,
    pub(super) f_max: f32,
    pub(super) t_min: f32,
    pub(super) t_max: f32,
    pub(super) branch: u8,
}

/// A predicted seek path's summary (the points are attached as a
/// `Float32Array` by the binding).
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct GhostOut {
    pub(super) reached: bool,
    pub(super) eta: f32,
    pub(super) final_dir: f32,
    pub(super) time: f32,
    pub(super) length: f32,
    pub(super) speed: f32,
    pub(super) slowed: bool,
    pub(super) target_x: f32,
    pub(super) target_y: f32,
}

impl From<&Ghost> for GhostOut {
    fn from(g: &Ghost) -> Self {
        Self {
            reached: g.reached,
            eta: g.eta,
            final_dir: g.final_dir,
            time: g.time,
            length: g.length,
            speed: g.speed,
            slowed: g.slowed,
            target_x: g.target.x,
            target_y: g.target.y,
        }
    }
}

impl From<Internals> for InternalsOut {
    fn from(i: Internals) -> Self {
        Self {
            mode: i.mode as u8,
            d: i.d,
            alpha: i.alpha,
            eta: i.eta,
            delta_eta: i.delta_eta,
            mu: i.mu,
            mu_max: i.mu_max,
            gamma: i.gamma,
            reachable: i.reachable,
            v_dt: i.v_dt,
            aim_d: i.aim_d,
            aim_alpha: i.aim_alpha,
            v_query: i.v_query,
            arc: None,
        }
    }
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct ScenarioInfo {
    pub(super) name: String,
    pub(super) description: String,
    pub(super) source: String,
    pub(super) claim: String,
    pub(super) measured: String,
    pub(super) agents: usize,
    pub(super) min_x: f32,
    pub(super) min_y: f32,
    pub(super) max_x: f32,
    pub(super) max_y: f32,
    pub(super) warning: String,
}

/// [`PrecisionRule`](precision) on the wire.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub struct PrecisionRule {
    pub step_scale: f32,
    pub tolerance_scale: f32,
    pub coord_max: f32,
}
