//! What the η table samples (paper 000 §3; docs/DESIGN.md §8): the axes, scaled
//! with the vehicle, and one entry's simulation, which runs the very seek
//! controller of [`crate::funnelling::seek`] from a sampled relative target
//! and records η, reachability and the fallback speed. The whole table is
//! built by [`crate::funnelling::table::generate`].
//!
//! # Axes, and why
//! Every axis is dimensionless, scaled with the vehicle ([`VehicleScale`]):
//! distances in units of the vehicle's turning radius at full
//! speed, speeds in fractions of `v_max`, the reach radius with the
//! distances and the simulated-time cap with distance over speed. The
//! pedestrian of [`VehicleParams::default`] is the unit (scale exactly 1,
//! so its table is the committed `tables/eta.bin`); a car with 21 times its turning
//! radius gets rings from 10.5 m to 675 m, one generator serves both. The
//! figures below are the pedestrian's.
//! - **Distance D**: 16 samples, geometric from 0.5 m to 32 m (ratio ≈ 1.32).
//!   η changes fast near the vehicle (the turn-in dominates) and slowly far
//!   away (η → 0 as the path becomes a straight line), so the rings are
//!   dense near and sparse far, as in paper 000 Fig. 2. `D_η = 0.5 m`, the
//!   first ring, is where the mode logic switches to plain seek.
//! - **Radial angle α**: 56 samples over [−π, π), periodic and anisotropic
//!   ([`anisotropic_alphas`]): 10° in front, 5° from 120°, 2.5° from 160°,
//!   where the seek controller's turn direction flips.
//! - **Angular speed**: 5 samples of the *fraction* `ω_c / min(ω_max, A/v_c)`
//!   in [−1, 1], so every sample is an admissible state.
//! - **Current speed v_c**: 9 samples, 0 to `v_max`, u² spacing (dense
//!   where turns are tight).
//! - **Desired speed v_d**: 9 samples, 0.25 m/s to `v_max`, u² spacing.
//!
//! 16 × 56 × 5 × 9 × 9 = 362,880 entries (the paper has 43,200), generated
//! in parallel (rayon, [`crate::base::parallel`]).
//!
//! # Time step
//! The simulations step at the vehicle's `dt`, or coarser for a vehicle
//! slower for its size than the pedestrian ([`generator_dt`]: the car's
//! table in a third of the steps, η error against its own `dt` measured).
//!
//! # Entries
//! Reachable: η at `v_d`. Unreachable: the largest desired speed among
//! `v_d·k/10`, k = 9..1, that reaches (the "closest desired speed ensuring
//! reachability"), with the η obtained at that speed (paper 001 Fig. 3c
//! stores and displays it); 0 with no η when none reaches.

use core::f32::consts::PI;

use glam::Vec2;

use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::seek::{simulate_reach, ReachLimits, ReachOutcome};
use crate::funnelling::table::format::{BuildParams, AXES, FLAG_ETA_VALID, FLAG_REACHABLE};

/// One generated entry: (η, desired-or-fallback speed, flags).
pub type Entry = (f32, f32, u8);

/// The sample counts of the committed table's layout, per axis: D, α, ω
/// fraction, v_c, v_d. Each is the number of samples on its axis except
/// α's: 36 is the number of *front* steps in a full turn (10°, so
/// `anisotropic_alphas(360° / 36)`), which the denser spacing behind gives
/// 56 samples ([`anisotropic_alphas`]); the table has
/// 16 × 56 × 5 × 9 × 9 = 362,880 entries.
pub const DEFAULT_COUNTS: [usize; AXES] = [16, 36, 5, 9, 9];

/// The anisotropic α axis (paper 001 Fig. 3a): spacing `step` degrees in
/// front (|α| ≤ 120°), `step/2` to 160° and `step/4` behind, where the
/// seek controller's turn direction flips and η jumps. Symmetric about 0
/// (so η(α, ω) = −η(−α, −ω) can halve the generation), periodic, with −π.
#[must_use]
pub fn anisotropic_alphas(step: f64) -> Vec<f32> {
    let mut pos = Vec::new();
    let mut a = 0.0f64;
    loop {
        a += if a < 120.0 - 1e-9 {
            step
        } else if a < 160.0 - 1e-9 {
            step / 2.0
        } else {
            step / 4.0
        };
        if a >= 180.0 - 1e-6 {
            break;
        }
        pos.push(a);
    }
    let mut out = vec![-PI];
    out.extend(pos.iter().rev().map(|d| (-d).to_radians() as f32));
    out.push(0.0);
    out.extend(pos.iter().map(|d| d.to_radians() as f32));
    out
}

/// How a vehicle's table axes scale against the reference pedestrian
/// ([`VehicleParams::default`]): lengths with the turning radius at full
/// speed `v_max / min(ω_max, A/v_max)`, speeds with `v_max`, times with
/// length over speed. Exactly 1, 1, 1 for the pedestrian.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VehicleScale {
    /// Turning radius over the pedestrian's (2.67 m).
    pub length: f32,
    /// `v_max` over the pedestrian's (2 m/s).
    pub speed: f32,
}

impl VehicleScale {
    /// The scale of vehicle `p`.
    #[must_use]
    pub fn of(p: &VehicleParams) -> Self {
        let r = VehicleParams::default();
        Self {
            length: turn_radius(p) / turn_radius(&r),
            speed: p.v_max / r.v_max,
        }
    }

    /// Time scale: length over speed.
    #[must_use]
    pub fn time(&self) -> f32 {
        self.length / self.speed
    }
}

/// The turning radius at full speed, m: `v_max / min(ω_max, A/v_max)`.
/// (`v_max` is not negative in valid limits: the limit at it is
/// [`VehicleParams::omega_limit_ahead`]'s, which the μ bound reads every
/// update.)
#[must_use]
pub fn turn_radius(p: &VehicleParams) -> f32 {
    p.v_max / p.omega_limit_ahead(p.v_max)
}

/// The time step of the generator's reach simulations for vehicle `p`:
/// its own `dt`, scaled up by its time scale when that is above 1 (a
/// vehicle slower for its size than the pedestrian, such as the car:
/// 2.8), so that a table costs about as many steps as the pedestrian's;
/// kept where the discrete PD seek is well damped (`kd·dt ≤ 1/2`,
/// `kp·dt² ≤ 1/4`) and a step is at most R/4. Exactly `dt` for the
/// pedestrian and every vehicle at or below its time scale, so their
/// tables are unchanged.
///
/// Why: at its own `dt` the car's table is 75 M simulation steps (the
/// pedestrian's 42 M), too slow for a build in the page; at its
/// time-scaled step (2.81 × 1/60 s) it is 27 M, and the η error against
/// direct simulation at the car's own `dt` stays well inside the targets
/// of 0.2° median and 2° p95 (`steer envelope --vehicle
/// scenarios/vehicles/car.json --queries 10000 --seed 2`: median 0.052°,
/// p95 0.33° over 10,000 queries at D ≥ 4 R). The table's
/// header still records the vehicle's `dt` (the controller it serves);
/// the key ([`super::key`]) includes this step when it differs.
#[must_use]
pub fn generator_dt(p: &VehicleParams) -> f32 {
    let t = VehicleScale::of(p).time();
    if t.is_nan() || t <= 1.0 {
        return p.dt;
    }
    let dt = (p.dt * t)
        .min(0.5 / p.kd)
        .min((0.25 / p.kp).sqrt())
        .min(0.25 * turn_radius(p) / p.v_max);
    dt.max(p.dt)
}

/// Largest build cost of a table relative to the pedestrian's (steps per
/// entry scale with the time scale over the time step).
pub const MAX_COST_RATIO: f32 = 20.0;
/// Largest ratio of a response time (reaching `v_max`, reaching `ω_max`)
/// to the time to cross one turning radius at full speed.
pub const MAX_RESPONSE_RATIO: f32 = 50.0;

/// Checks that a table can be built for `p`: every field in its range
/// ([`VehicleParams::validate`], the scenarios' validation), then the
/// ratios that make a vehicle absurd for the generator, each message
/// starting with the fields it names:
/// - a step at most a quarter of the turning radius (`vMax·dt ≤ R/4`),
/// - build cost at most [`MAX_COST_RATIO`] × the pedestrian's,
/// - reaching `v_max` and `ω_max` within [`MAX_RESPONSE_RATIO`] × `R/v_max`,
/// - a stable discrete PD seek (`kd·dt ≤ 1`, `kp·dt² ≤ 1`).
///
/// # Errors
/// The first refused field or ratio, named.
pub fn check_vehicle(p: &VehicleParams) -> Result<(), String> {
    p.validate().map_err(|e| format!("vehicle: {e}"))?;
    let r = turn_radius(p);
    let step = p.v_max * p.dt;
    if step > 0.25 * r {
        return Err(format!(
            "vehicle: vMax·dt = {step} m per step is more than a quarter of the turning radius \
             vMax / min(omegaMax, normalAccelMax/vMax) = {r} m: lower vMax or dt, or raise omegaMax / normalAccelMax"
        ));
    }
    let reference = VehicleParams::default();
    let cost = VehicleScale::of(p).time() * reference.dt / p.dt;
    if cost > MAX_COST_RATIO {
        return Err(format!(
            "vehicle: turning radius / vMax / dt is {cost:.1} times the pedestrian's (at most {MAX_COST_RATIO}): \
             the table would take that much longer to build; raise dt or vMax, or lower the turning radius"
        ));
    }
    let cross = r / p.v_max;
    let speed_up = p.v_max / p.accel_max;
    if speed_up > MAX_RESPONSE_RATIO * cross {
        return Err(format!(
            "vehicle: accelMax = {} m/s² takes {speed_up} s to reach vMax, more than {MAX_RESPONSE_RATIO} × the {cross} s to cross one turning radius",
            p.accel_max
        ));
    }
    let turn_up = p.omega_max / p.omega_accel_max;
    if turn_up > MAX_RESPONSE_RATIO * cross {
        return Err(format!(
            "vehicle: omegaAccelMax = {} rad/s² takes {turn_up} s to reach omegaMax, more than {MAX_RESPONSE_RATIO} × the {cross} s to cross one turning radius",
            p.omega_accel_max
        ));
    }
    if p.kd * p.dt > 1.0 {
        return Err(format!(
            "vehicle: kd·dt = {} exceeds 1: the discrete seek controller oscillates; lower kd or dt",
            p.kd * p.dt
        ));
    }
    if p.kp * p.dt * p.dt > 1.0 {
        return Err(format!(
            "vehicle: kp·dt² = {} exceeds 1: the discrete seek controller oscillates; lower kp or dt",
            p.kp * p.dt * p.dt
        ));
    }
    Ok(())
}

/// What to generate: build parameters and the five axes.
#[derive(Clone, Debug, PartialEq)]
pub struct TableSpec {
    /// Vehicle, controller and reach-simulation parameters.
    pub params: BuildParams,
    /// Axis samples in storage order (see [`crate::funnelling::table::format::AXIS_NAMES`]).
    pub axes: [Vec<f32>; AXES],
}

impl TableSpec {
    /// The committed default: pedestrian vehicle, axes as documented above.
    #[must_use]
    pub fn default_for(vehicle: VehicleParams) -> Self {
        Self::with_counts(vehicle, DEFAULT_COUNTS)
    }

    /// The default layout for vehicle `p`, after [`check_vehicle`].
    ///
    /// # Errors
    /// [`check_vehicle`]'s message.
    pub fn for_vehicle(p: VehicleParams, counts: [usize; AXES]) -> Result<Self, String> {
        check_vehicle(&p)?;
        Ok(Self::with_counts(p, counts))
    }

    /// The default layout with other sample counts per axis (for studies of
    /// accuracy against size; speed axes stay uniform).
    #[must_use]
    pub fn with_counts(vehicle: VehicleParams, counts: [usize; AXES]) -> Self {
        let [nd, na, ns, nv, nvd] = counts;
        let lim = ReachLimits::default();
        let scale = VehicleScale::of(&vehicle);
        let params = BuildParams {
            vehicle,
            reach_radius: lim.reach_radius * scale.length,
            orbit_turns: lim.orbit_turns,
            max_time: lim.max_time * scale.time(),
        };
        let d0 = 0.5 * scale.length;
        let distances: Vec<f32> = (0..nd)
            .map(|i| d0 * (64.0f64).powf(i as f64 / (nd - 1) as f64) as f32)
            .collect();
        let alphas = anisotropic_alphas(360.0 / na as f64);
        let fractions: Vec<f32> = (0..ns)
            .map(|k| -1.0 + 2.0 * k as f32 / (ns - 1) as f32)
            .collect();
        let vm = vehicle.v_max;
        // Speeds are dense where η changes fastest, at low speed: u² spacing.
        let g = |u: f32| u * u;
        let speeds: Vec<f32> = (0..nv)
            .map(|k| vm * g(k as f32 / (nv - 1) as f32))
            .collect();
        // The slowest desired speed, an eighth of v_max (0.25 m/s walking).
        let v0 = 0.125 * vm;
        let desired: Vec<f32> = (0..nvd)
            .map(|k| v0 + (vm - v0) * g(k as f32 / (nvd - 1) as f32))
            .collect();
        Self {
            params,
            axes: [distances, alphas, fractions, speeds, desired],
        }
    }

    /// Number of entries.
    #[must_use]
    pub fn len(&self) -> usize {
        self.axes.iter().map(Vec::len).product()
    }

    /// Never true for a sensible spec.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Grid index of linear entry `i` (last axis fastest).
    #[must_use]
    pub fn unravel(&self, mut i: usize) -> [usize; AXES] {
        let mut idx = [0usize; AXES];
        for k in (0..AXES).rev() {
            let n = self.axes[k].len();
            idx[k] = i % n;
            i /= n;
        }
        idx
    }

    /// The vehicle the reach simulations run: the table's, at
    /// [`generator_dt`].
    #[must_use]
    pub fn sim_vehicle(&self) -> VehicleParams {
        VehicleParams {
            dt: generator_dt(&self.params.vehicle),
            ..self.params.vehicle
        }
    }

    fn limits(&self) -> ReachLimits {
        ReachLimits {
            reach_radius: self.params.reach_radius,
            orbit_turns: self.params.orbit_turns,
            max_time: self.params.max_time,
        }
    }

    /// The start state and target of grid sample `idx`, in the vehicle frame.
    #[must_use]
    pub fn sample(&self, idx: [usize; AXES]) -> (VehicleState, Vec2, f32) {
        let d = self.axes[0][idx[0]];
        let a = self.axes[1][idx[1]];
        let v = self.axes[3][idx[3]];
        let w = self.axes[2][idx[2]] * self.params.vehicle.omega_limit(v);
        let start = VehicleState::new(Vec2::ZERO, 0.0, v, w);
        (start, crate::base::trig::unit(a) * d, self.axes[4][idx[4]])
    }

    /// Computes one entry: (η, fallback speed, flags).
    #[must_use]
    pub fn entry(&self, i: usize) -> Entry {
        let (start, target, v_d) = self.sample(self.unravel(i));
        let p = &self.sim_vehicle();
        let lim = self.limits();
        if let ReachOutcome::Reached { eta, .. } = simulate_reach(p, start, target, v_d, &lim) {
            return (eta, v_d, FLAG_REACHABLE | FLAG_ETA_VALID);
        }
        for k in (1..=9).rev() {
            let v = v_d * k as f32 / 10.0;
            if let ReachOutcome::Reached { eta, .. } = simulate_reach(p, start, target, v, &lim) {
                return (eta, v, FLAG_ETA_VALID);
            }
        }
        (0.0, 0.0, 0)
    }

    /// Linear index of the mirror image of entry `i`: α → −α and
    /// ω → −ω. The controller is left/right symmetric, so
    /// η(mirror) = −η and the rest of the entry is equal.
    #[must_use]
    pub fn mirror(&self, i: usize) -> usize {
        let mut idx = self.unravel(i);
        let na = self.axes[1].len();
        let ns = self.axes[2].len();
        idx[1] = (na - idx[1]) % na;
        idx[2] = ns - 1 - idx[2];
        let mut j = 0;
        for (k, x) in idx.iter().enumerate() {
            j = j * self.axes[k].len() + x;
        }
        j
    }

    /// True when the α and ω-fraction axes are mirror-symmetric, so only
    /// half of the entries need simulating.
    #[must_use]
    pub fn is_symmetric(&self) -> bool {
        let a = &self.axes[1];
        let f = &self.axes[2];
        let na = a.len();
        (a[0] + PI).abs() < 1e-6
            && (1..na).all(|k| (a[k] + a[na - k]).abs() < 1e-5)
            && (0..f.len()).all(|k| (f[k] + f[f.len() - 1 - k]).abs() < 1e-6)
    }

    /// Whether entry `i` is filled from its mirror instead of simulated:
    /// symmetric spec, mirror with a lower index, and not on the α = −π
    /// column (a target exactly behind lies on the symmetry axis, where the
    /// (−π, π] wrap convention makes the controller itself asymmetric).
    #[must_use]
    pub fn is_mirrored(&self, i: usize) -> bool {
        self.is_symmetric() && self.unravel(i)[1] != 0 && self.mirror(i) < i
    }

    /// Entry `i`, or `None` when it [`TableSpec::is_mirrored`].
    #[must_use]
    pub fn unless_mirrored(&self, i: usize) -> Option<Entry> {
        (!self.is_mirrored(i)).then(|| self.entry(i))
    }

    /// Completes the mirrored half of a symmetric generation.
    #[must_use]
    pub fn fill_mirrors(&self, partial: &[Option<Entry>]) -> Vec<Entry> {
        (0..partial.len())
            .map(|i| match partial[i] {
                Some(e) => e,
                None => {
                    let (eta, v, f) = partial[self.mirror(i)].unwrap_or((0.0, 0.0, 0));
                    (crate::base::angle::wrap(-eta), v, f)
                }
            })
            .collect()
    }
}
