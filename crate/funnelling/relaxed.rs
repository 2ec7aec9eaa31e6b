//! Relaxed funnelling towards oriented *region goals* (paper 001 §4,
//! Fig. 7; docs/DESIGN.md §11).
//!
//! A region goal is a tolerance disk (centre `Goal::pos`, radius
//! `Goal::d_tol`) and an orientation interval T = [β − τ, β + τ]
//! (τ = `Goal::eps_tol`): any point of the disk is a valid target and any
//! final orientation in T is valid. The standard controller
//! ([`crate::funnelling::funnel`]) still aims at the disk centre and at β exactly,
//! which curves paths artificially (paper 001 Fig. 6b). The relaxed
//! controller instead, every update:
//!
//! 1. takes the table ring (a sampled distance `R` of
//!    [`EtaTable::distances`](crate::funnelling::table::lookup::EtaTable::distances))
//!    nearest the disk centre and intersects it with the disk: the
//!    restricted arc 𝒜 = [α_min, α_max] of candidate directions (paper 001
//!    §4.2.3: the search is restricted to keep the cost constant);
//! 2. evaluates η at the two arc ends only and forms the final-orientation
//!    span F = [α_min + η(α_min), α_max + η(α_max)] (§4.2.4: α + η is
//!    assumed monotonic over 𝒜, so the two ends bound it; F may extend past
//!    ±π, hence every comparison with T is made modulo 2π);
//! 3. picks the relaxed direction α_r ∈ 𝒜 minimising |Δη| (primary
//!    criterion §4.2.1: Δη = 0 means the funnelling reduces to a seek, the
//!    cheapest control) and then |α| (secondary criterion §4.2.2: prefer
//!    straight lines) with the boundary-only procedure of Fig. 7
//!    ([`relaxed_direction`]);
//! 4. funnels towards the relaxed point `pos + R·(cos, sin)(θ + α_r)` with
//!    the standard machinery: one full table lookup there (reachability and
//!    proactive speed `v_dt`), Δη re-measured against T with that η, then
//!    seek (Δη = 0) or the bounded modulation μ of [`FunnelConfig`].
//!
//! Choices where the paper is silent (written down, as docs/DESIGN.md §1 and §18 ask):
//! - **Ring misses the disk** (a small disk between two sparse far rings):
//!   the ring of radius equal to the centre distance is used instead, so 𝒜
//!   is the disk's angular extent seen from the vehicle.
//! - **𝒜 crossing ±π** (disk behind the vehicle): the paper handles only
//!   𝒜 ⊂ [−π, π] (α + η jumps where the turn direction flips behind the
//!   vehicle), so 𝒜 is clipped at ±π on the side of the centre's bearing.
//! - **Vehicle inside the disk**: the position is met; orientation is then
//!   completed exactly as in the standard controller
//!   ([`crate::funnelling::approach::tolerance_phase`]).
//! - **Margins**: the relaxed point lies on the disk boundary at the arc
//!   ends and Δη = 0 only puts the prediction at T's edge, so the search
//!   uses a shrunk disk and interval (`disk_margin`, `orientation_margin`)
//!   to absorb the table's interpolation error. The mode logic and the
//!   end-of-steering test use the true tolerances.
//! - **η at the arc ends** ([`EndEta`]): like the paper, a cheap plain
//!   linear interpolation by default (linear in α on the sampled ring,
//!   nearest sample on the other axes: 2 entries read); the full
//!   multilinear lookup is an option. Either way the decision that matters
//!   (Δη at α_r, hence seek or funnel) is re-measured with the full lookup.
//!
//! Two readings of *where* to aim ([`RelaxedAim`]), measured side by side
//! by the envelope study (`steer envelope`: tune seed 1, held-out seed 2;
//! variants `relaxed` and `relaxed-paper-arc`):
//! - [`RelaxedAim::PaperArc`], the paper's literal reading above. Its
//!   relaxed point lies on the ring through the disk, ~D ahead, and is
//!   chosen afresh every update at the edge of T, so it slides as the
//!   vehicle moves and the heading on *entering* the disk drifts: fewer
//!   runs enter oriented than with the standard controller. An aim point
//!   that slides across the disk costs oriented entries, so the paper's
//!   design cannot orient on entry as well as standard.
//! - [`RelaxedAim::Entry`], the default: aim at the *entry point* of the
//!   disk, `d_tol − r_reach` before the centre along β (`r_reach` the
//!   table's reach radius, so reaching it in the table's sense is entering
//!   the disk), a point fixed in the world; no orientation correction
//!   while the prediction lies inside T shrunk to `orientation_margin`·τ.
//!   The table then predicts the heading at entry, which is what a region
//!   goal asks for. The standard controller aims there too by default
//!   ([`crate::funnelling::config::Aim::Entry`]); for disks no larger than
//!   `r_reach` the entry point is the centre.
//!
//! Neither aim orbits near the disk. Closer than the first sampled ring
//! `D_η` the paper's relaxed point can fall inside the vehicle's turning
//! circle, and sought at full speed it would be circled for the whole time
//! limit; below `D_η` both aims seek at the orbit-free speed, like the
//! standard controller.
//!
//! Cost: constant per update, no allocation — paper arc: two cheap η
//! reads, one full lookup, the μ bound's interpolation and a ≤ 16-sample
//! ring scan; entry point: one full lookup and the μ bound.

use core::f32::consts::{PI, TAU};
use core::ops::ControlFlow;

use serde::{Deserialize, Serialize};

use crate::base::angle::{diff, wrap};
use crate::base::vehicle::ParamError;
use crate::funnelling::approach::Approach;
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::goal::Goal;
use crate::funnelling::update::{Internals, Mode, Update};

/// How η is evaluated at the two ends of the restricted arc 𝒜.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum EndEta {
    /// The paper's cheaper reading (§4.2.4): linear in α on the ring,
    /// nearest sample on ω, v_c, v_d
    /// ([`EtaTable::eta_ring_linear`](crate::funnelling::table::lookup::EtaTable::eta_ring_linear)).
    #[default]
    Linear,
    /// The full multilinear interpolation (16 non-zero corners on a ring).
    Multilinear,
}

/// Where the relaxed controller aims (module doc: measured side by side).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum RelaxedAim {
    /// The disk's entry point along β, fixed in the world; orientation
    /// relaxed to T.
    #[default]
    Entry,
    /// Paper 001 Fig. 7 literally: the relaxed point on the ring arc 𝒜.
    PaperArc,
}

/// Which Δη the relaxed controller funnels with once α_r is chosen
/// ([`RelaxedAim::PaperArc`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
pub enum RelaxedDeltaEta {
    /// Ours: Δη measured again against T with η of the full lookup at the
    /// relaxed point (the lookup that gives reachability and `v_dt`): the
    /// arc ends' η is the cheap linear read, and the decision that matters,
    /// seek (Δη = 0) or funnel, then rests on the accurate η.
    #[default]
    Lookup,
    /// The paper: Fig. 7's own Δη, from the arc ends' η.
    Fig7,
}

/// Settings of the relaxed controller (the μ bound is the shared
/// [`FunnelConfig`]'s).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "camelCase")]
pub struct RelaxedConfig {
    /// Where to aim.
    pub aim: RelaxedAim,
    /// Fraction of the disk radius searched ([`RelaxedAim::PaperArc`]) for the relaxed point (0, 1].
    pub disk_margin: f32,
    /// Fraction of τ used for the interval T searched (0, 1]. Default
    /// 0.25, like the standard controller's seek threshold: with a margin
    /// near 1 (0.8) the prediction sits at T's edge and entries fall just
    /// outside it (chosen on the envelope study's tune seed 1).
    pub orientation_margin: f32,
    /// η at the arc ends.
    pub end_eta: EndEta,
    /// The Δη funnelled with ([`RelaxedDeltaEta`]).
    pub delta_eta: RelaxedDeltaEta,
}

impl Default for RelaxedConfig {
    fn default() -> Self {
        Self {
            aim: RelaxedAim::Entry,
            disk_margin: 0.8,
            orientation_margin: 0.25,
            end_eta: EndEta::Linear,
            delta_eta: RelaxedDeltaEta::Lookup,
        }
    }
}

impl RelaxedConfig {
    /// Paper 001 §4 exactly, nothing of ours added: the relaxed point on
    /// the arc 𝒜 of Fig. 7, the whole tolerance disk and the whole interval
    /// T searched (margins 1), η at the arc ends by the plain linear
    /// interpolation the paper names, and Fig. 7's Δη funnelled with. Run
    /// it with [`FunnelConfig::paper_000`], the standard funnelling the
    /// paper builds on (`docs/READINGS.md`).
    #[must_use]
    pub fn paper_001() -> Self {
        Self {
            aim: RelaxedAim::PaperArc,
            disk_margin: 1.0,
            orientation_margin: 1.0,
            end_eta: EndEta::Linear,
            delta_eta: RelaxedDeltaEta::Fig7,
        }
    }
}

/// Which branch of paper 001 Fig. 7 decided α_r.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "camelCase")]
#[repr(u8)]
pub enum Fig7Branch {
    /// Not computed (inside the disk, no goal, or the standard controller).
    #[default]
    None = 0,
    /// Centres of F and T of opposite signs, straight ahead (α = 0) valid:
    /// Δη = 0, α_r = 0.
    OppositeStraight = 1,
    /// Centres of opposite signs, overlap of F with T or T ± 2π: Δη = 0,
    /// α_r the overlap point of smallest |α|.
    OppositeOverlap = 2,
    /// Centres of opposite signs, no overlap: α_r the 𝒜 end of smallest gap.
    OppositeGap = 3,
    /// Centres of the same sign, straight ahead valid: Δη = 0, α_r = 0.
    SameStraight = 4,
    /// Same sign, overlap: Δη = 0, α_r the overlap point of smallest |α|.
    SameOverlap = 5,
    /// Same sign, no overlap: α_r the 𝒜 end of smallest gap.
    SameGap = 6,
    /// No η available at the arc ends, or closer than `D_η`: the standard
    /// controller's update was used.
    Fallback = 7,
    /// Not searched: [`RelaxedAim::Entry`] aims at the disk's entry point
    /// (𝒜 degenerates to its direction).
    EntryPoint = 8,
}

/// The outcome of [`relaxed_direction`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choice {
    /// Relaxed direction α_r ∈ 𝒜, rad (vehicle frame).
    pub alpha_r: f32,
    /// Δη = (nearest orientation of T) − (predicted final orientation at
    /// α_r), rad; 0 when F overlaps T.
    pub delta_eta: f32,
    /// The branch taken.
    pub branch: Fig7Branch,
}

/// Signed Δη of a predicted final orientation `f` against the interval
/// T = [tc − τ, tc + τ] modulo 2π: 0 inside, else the signed distance to
/// the nearest bound (target − prediction, like the standard Δη).
#[inline]
#[must_use]
pub fn interval_delta(f: f32, tc: f32, tau: f32) -> f32 {
    let d = wrap(f - tc);
    if d > tau {
        tau - d
    } else if d < -tau {
        -tau - d
    } else {
        0.0
    }
}

/// Paper 001 Fig. 7: the optimal relaxed direction from boundaries only.
///
/// Inputs, all in the vehicle frame (angles relative to the heading θ):
/// the arc 𝒜 = [`a_min`, `a_max`] ⊂ [−π, π], the predicted final
/// orientations at its ends `f_min` = α_min + η(α_min) and `f_max` =
/// α_max + η(α_max) (unwrapped so that `f_max − f_min` is the span, which
/// may cross ±π), and T = [`tc` − `tau`, `tc` + `tau`].
///
/// Under the monotonic hypothesis α + η is taken linear between the ends
/// ("mapped 𝒜 value" of Fig. 7). Fig. 7's early exits ("Δη = 0, α_r = 0"
/// for opposite-sign centres with partial overlap, and for same-sign
/// centres with boundaries of opposite signs) both mean that straight
/// ahead is a valid choice; we test that exactly (0 ∈ 𝒜 and F(0) ∈ T mod
/// 2π) instead of through the centres' signs, which is only a proxy, and
/// keep the signs to label the branch. Otherwise F is compared with T
/// and its 2π-translates (T ± 2π, T ± 4π since F spans up to [−3π, 3π]):
/// an overlap gives Δη = 0 and α_r the point of the overlap's pre-image
/// closest to 0; without overlap, F lies within one gap of the periodic
/// set, where the distance is a tent, so the best point is an 𝒜 end:
/// the end with the smallest |gap| (ties: smallest |α|). O(1).
#[must_use]
pub fn relaxed_direction(
    a_min: f32,
    a_max: f32,
    f_min: f32,
    f_max: f32,
    tc: f32,
    tau: f32,
) -> Choice {
    let tc = wrap(tc);
    let centre_f = wrap(0.5 * (f_min + f_max));
    let opposite = (centre_f < 0.0) != (tc < 0.0);
    let span = f_max - f_min;
    let da = a_max - a_min;
    let flat = span.abs() < 1e-7;
    // α of a final orientation f on 𝒜 (linear map, monotonic hypothesis).
    let to_alpha = |f: f32| -> f32 {
        if flat {
            a_min
        } else {
            (a_min + (f - f_min) / span * da).clamp(a_min, a_max)
        }
    };
    // Early exit: straight ahead valid.
    if a_min <= 0.0 && 0.0 <= a_max {
        let f0 = if da > 0.0 {
            f_min + (0.0 - a_min) / da * span
        } else {
            f_min
        };
        if interval_delta(f0, tc, tau) == 0.0 {
            return Choice {
                alpha_r: 0.0,
                delta_eta: 0.0,
                branch: if opposite {
                    Fig7Branch::OppositeStraight
                } else {
                    Fig7Branch::SameStraight
                },
            };
        }
    }
    // Overlaps of F with T + 2πk.
    let (lo_f, hi_f) = if span >= 0.0 {
        (f_min, f_max)
    } else {
        (f_max, f_min)
    };
    let mut best = f32::INFINITY;
    for k in -2i32..=2 {
        let shift = TAU * k as f32;
        let lo = lo_f.max(tc - tau + shift);
        let hi = hi_f.min(tc + tau + shift);
        if lo <= hi {
            let (x, y) = if flat {
                (a_min, a_max)
            } else {
                let (x, y) = (to_alpha(lo), to_alpha(hi));
                (x.min(y), x.max(y))
            };
            let c = 0.0f32.clamp(x, y);
            if c.abs() < best.abs() {
                best = c;
            }
        }
    }
    if best.is_finite() {
        return Choice {
            alpha_r: best,
            delta_eta: 0.0,
            branch: if opposite {
                Fig7Branch::OppositeOverlap
            } else {
                Fig7Branch::SameOverlap
            },
        };
    }
    // Gaps: the best end of 𝒜.
    let g0 = interval_delta(f_min, tc, tau);
    let g1 = interval_delta(f_max, tc, tau);
    let take_max = g1.abs() < g0.abs() || (g1.abs() == g0.abs() && a_max.abs() < a_min.abs());
    let (alpha_r, delta_eta) = if take_max { (a_max, g1) } else { (a_min, g0) };
    Choice {
        alpha_r,
        delta_eta,
        branch: if opposite {
            Fig7Branch::OppositeGap
        } else {
            Fig7Branch::SameGap
        },
    }
}

/// Everything the relaxed search computed in one update, for the front
/// end. Angles are radians in the **vehicle frame** (relative to the
/// heading θ at the update); add θ for world angles. F may extend past ±π.
#[derive(Clone, Copy, Debug, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct RelaxedInternals {
    /// Fig. 7 branch taken (`None` when not searched this update).
    pub branch: Fig7Branch,
    /// Radius of the ring used, m.
    pub ring: f32,
    /// Whether that ring is a table sample (false: it missed the disk and
    /// the centre-distance ring was used).
    pub ring_sampled: bool,
    /// 𝒜 lower end α_min.
    pub arc_min: f32,
    /// 𝒜 upper end α_max.
    pub arc_max: f32,
    /// F at α_min: α_min + η(α_min).
    pub f_min: f32,
    /// F at α_max: α_max + η(α_max) (unwrapped relative to `f_min`).
    pub f_max: f32,
    /// T lower bound (searched interval, margin applied).
    pub t_min: f32,
    /// T upper bound.
    pub t_max: f32,
    /// Relaxed direction α_r.
    pub alpha_r: f32,
    /// Δη of Fig. 7 (from the arc-end values).
    pub delta_eta: f32,
    /// Relaxed point, world x, m.
    pub point_x: f32,
    /// Relaxed point, world y, m.
    pub point_y: f32,
}

impl RelaxedConfig {
    /// Rejects out-of-range margins.
    ///
    /// # Errors
    /// The offending field.
    pub fn validate(&self) -> Result<(), ParamError> {
        use crate::base::ranges as r;
        r::DISK_MARGIN.check(self.disk_margin)?;
        r::ORIENTATION_MARGIN.check(self.orientation_margin)?;
        Ok(())
    }

    /// Chooses the mode and seek command for one step (no motion).
    /// `ri` receives the relaxed internals; the returned [`Internals`] are
    /// those of the standard controller with `d`, `alpha` measured to the
    /// disk centre and `eta`, `delta_eta`, `mu`, `gamma` to the relaxed
    /// point (Δη re-measured against T with the full lookup's η).
    #[must_use]
    pub fn plan(
        &self,
        funnel: &FunnelConfig,
        u: &mut Update<'_>,
        ri: &mut RelaxedInternals,
    ) -> Internals {
        *ri = RelaxedInternals::default();
        // The relaxed controller approaches near goals as paper 001 does;
        // its fallbacks to the standard update must not choose otherwise
        // (crate::funnelling::short_range).
        u.memory.short_range.decided = true;
        let (a, mut out) = match Approach::begin(u, funnel.deviations()) {
            ControlFlow::Break(done) => return done,
            ControlFlow::Continue(begun) => begun,
        };
        let (table, s) = (a.table, a.s);
        // Aim at the goal as the vehicle will meet it (approach::lead).
        let led = a.goal;
        let g = &led;
        let (d, alpha_c) = (a.d, a.alpha);
        // A goal that follows an agent: the paper's relaxed point, as the
        // standard aims at its centre (FunnelMemory::goal_follows_agent).
        if self.aim == RelaxedAim::Entry && !a.follows_agent {
            return self.plan_entry(funnel, &a, g, out, ri);
        }
        if d < table.d_eta() {
            // Inside the first sampled ring 𝒜 is a wide arc on a ring of
            // radius D, whose ends the vehicle keeps circling: seek the
            // centre at the orbit-free speed, as the standard does.
            ri.branch = Fig7Branch::Fallback;
            return funnel.plan(u);
        }
        // 1. The restricted arc 𝒜 on the ring nearest the disk centre.
        let r = self.disk_margin * g.d_tol;
        let mut ring_i = 0;
        for (i, &x) in table.distances().iter().enumerate() {
            if (x - d).abs() < (table.distances()[ring_i] - d).abs() {
                ring_i = i;
            }
        }
        let mut ring = table.distances()[ring_i];
        ri.ring_sampled = (ring - d).abs() <= r;
        if !ri.ring_sampled {
            ring = d;
        }
        let cos_h = ((ring * ring + d * d - r * r) / (2.0 * ring * d)).clamp(-1.0, 1.0);
        // acos from the deterministic atan2 (libm's acos differs per target).
        let h = crate::base::trig::atan2((1.0 - cos_h * cos_h).max(0.0).sqrt(), cos_h);
        let a_min = (alpha_c - h).max(-PI);
        let a_max = (alpha_c + h).min(PI);
        // 2. F from η at the two arc ends.
        let v_q = a.v_query();
        let ends = if self.end_eta == EndEta::Linear && ri.ring_sampled {
            (
                table.eta_ring_linear(ring_i, a_min, s.omega, s.v, v_q),
                table.eta_ring_linear(ring_i, a_max, s.omega, s.v, v_q),
            )
        } else {
            (
                table.eta(ring, a_min, s.omega, s.v, v_q),
                table.eta(ring, a_max, s.omega, s.v, v_q),
            )
        };
        let (Some(e0), Some(e1)) = ends else {
            ri.branch = Fig7Branch::Fallback;
            return funnel.plan(&mut u.towards(&led));
        };
        let f_min = a_min + e0;
        let f_max = f_min + wrap(a_max + e1 - f_min);
        // 3. Fig. 7.
        let tc = diff(g.beta, s.theta);
        let tau = self.orientation_margin * g.eps_tol;
        let c = relaxed_direction(a_min, a_max, f_min, f_max, tc, tau);
        let dir = s.theta + c.alpha_r;
        let point = s.pos + crate::base::trig::unit(dir) * ring;
        *ri = RelaxedInternals {
            branch: c.branch,
            ring,
            ring_sampled: ri.ring_sampled,
            arc_min: a_min,
            arc_max: a_max,
            f_min,
            f_max,
            t_min: tc - tau,
            t_max: tc + tau,
            alpha_r: c.alpha_r,
            delta_eta: c.delta_eta,
            point_x: point.x,
            point_y: point.y,
        };
        // 4. Funnel towards the relaxed point.
        let lk = a.look(ring, c.alpha_r, &mut out);
        out.delta_eta = if lk.eta_valid && self.delta_eta == RelaxedDeltaEta::Lookup {
            interval_delta(c.alpha_r + lk.eta, tc, tau)
        } else {
            c.delta_eta
        };
        out.gamma = wrap(dir);
        if ring < table.d_eta() || out.delta_eta == 0.0 || !lk.eta_valid {
            out.mode = Mode::PositionOnly;
            return out;
        }
        a.funnel(funnel, &lk, ring, dir, out)
    }

    /// [`RelaxedAim::Entry`] once the position tolerance is not met: the
    /// standard update aimed at the disk's entry point
    /// ([`FunnelConfig::aim_and_funnel`] with [`crate::funnelling::config::Aim::Entry`]),
    /// with the orientation interval T shrunk to `orientation_margin`·τ as
    /// its seek threshold: no correction while the predicted heading lies
    /// inside it, else a correction towards β itself (correcting only to
    /// T's edge leaves entries just outside it; envelope study, tune seed
    /// 1). The standard controller aims at the entry point by default as
    /// well, so on a disk goal the two coincide; the paper's relaxed point
    /// is [`RelaxedAim::PaperArc`].
    fn plan_entry(
        &self,
        funnel: &FunnelConfig,
        a: &Approach<'_>,
        g: &Goal,
        out: Internals,
        ri: &mut RelaxedInternals,
    ) -> Internals {
        let cfg = FunnelConfig {
            aim: crate::funnelling::config::Aim::Entry,
            seek_threshold: self.orientation_margin,
            ..*funnel
        };
        let out = cfg.aim_and_funnel(a, g, out);
        let aim = a.entry_point(g);
        let (dist, _, alpha) = a.seen(aim);
        let tc = diff(g.beta, a.s.theta);
        let tau = self.orientation_margin * g.eps_tol;
        let f = alpha + out.eta;
        *ri = RelaxedInternals {
            branch: Fig7Branch::EntryPoint,
            ring: dist,
            ring_sampled: false,
            arc_min: alpha,
            arc_max: alpha,
            f_min: f,
            f_max: f,
            t_min: tc - tau,
            t_max: tc + tau,
            alpha_r: alpha,
            delta_eta: out.delta_eta,
            point_x: aim.x,
            point_y: aim.y,
        };
        out
    }

    /// One relaxed update: plan, then one seek step.
    pub fn step(
        &self,
        funnel: &FunnelConfig,
        u: &mut Update<'_>,
        ri: &mut RelaxedInternals,
    ) -> Internals {
        let out = self.plan(funnel, u, ri);
        funnel.seek_step(u.params, u.state, out.gamma, out.v_dt);
        out
    }
}
