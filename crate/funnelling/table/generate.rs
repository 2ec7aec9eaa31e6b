//! The η table generator (paper 000 §3; DESIGN §3): runs the very seek
//! controller of [`crate::seek`] from every sampled relative target and
//! records η, reachability and the fallback speed.
//!
//! # Axes, and why
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
//! 16 × 56 × 5 × 9 × 9 = 362,880 entries (the paper has 43,200); 0.8 s on
//! two cores (rayon, [`crate::parallel`]).
//!
//! # Entries
//! Reachable: η at `v_d`. Unreachable: the largest desired speed among
//! `v_d·k/10`, k = 9..1, that reaches (the "closest desired speed ensuring
//! reachability"), with the η obtained at that speed (paper 001 Fig. 3c
//! stores and displays it); 0 with no η when none reaches.

use core::f32::consts::PI;

use glam::Vec2;

use crate::seek::{simulate_reach, ReachLimits, ReachOutcome};
use crate::table::{BuildParams, EtaTable, TableError, AXES, FLAG_ETA_VALID, FLAG_REACHABLE};
use crate::vehicle::{VehicleParams, VehicleState};

/// One generated entry: (η, desired-or-fallback speed, flags).
pub type Entry = (f32, f32, u8);

/// Samples per axis of the committed table: D, α, ω fraction, v_c, v_d.
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

/// What to generate: build parameters and the five axes.
#[derive(Clone, Debug, PartialEq)]
pub struct TableSpec {
    /// Vehicle, controller and reach-simulation parameters.
    pub params: BuildParams,
    /// Axis samples in storage order (see [`crate::table::AXIS_NAMES`]).
    pub axes: [Vec<f32>; AXES],
}

impl TableSpec {
    /// The committed default: pedestrian vehicle, axes as documented above.
    #[must_use]
    pub fn default_for(vehicle: VehicleParams) -> Self {
        Self::with_counts(vehicle, DEFAULT_COUNTS)
    }

    /// The default layout with other sample counts per axis (for studies of
    /// accuracy against size; speed axes stay uniform).
    #[must_use]
    pub fn with_counts(vehicle: VehicleParams, counts: [usize; AXES]) -> Self {
        let [nd, na, ns, nv, nvd] = counts;
        let lim = ReachLimits::default();
        let params = BuildParams {
            vehicle,
            reach_radius: lim.reach_radius,
            orbit_turns: lim.orbit_turns,
            max_time: lim.max_time,
        };
        let distances: Vec<f32> = (0..nd)
            .map(|i| 0.5 * (64.0f64).powf(i as f64 / (nd - 1) as f64) as f32)
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
        let desired: Vec<f32> = (0..nvd)
            .map(|k| 0.25 + (vm - 0.25) * g(k as f32 / (nvd - 1) as f32))
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
        (start, crate::trig::unit(a) * d, self.axes[4][idx[4]])
    }

    /// Computes one entry: (η, fallback speed, flags).
    #[must_use]
    pub fn entry(&self, i: usize) -> Entry {
        let (start, target, v_d) = self.sample(self.unravel(i));
        let p = &self.params.vehicle;
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

    /// Computes entries `range` on the calling thread; entries that
    /// [`TableSpec::is_mirrored`] are left as `None` (filled by
    /// [`TableSpec::fill_mirrors`]).
    #[must_use]
    pub fn entries(&self, range: core::ops::Range<usize>) -> Vec<Option<Entry>> {
        range.map(|i| self.unless_mirrored(i)).collect()
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
                    (crate::angle::wrap(-eta), v, f)
                }
            })
            .collect()
    }

    /// Generates the whole table: in parallel on the current rayon pool
    /// natively, sequentially on wasm32 ([`crate::parallel`]). Entries are
    /// computed independently and collected in index order, so the bytes do
    /// not depend on the thread count.
    ///
    /// # Errors
    /// If the spec itself is invalid.
    pub fn generate(&self) -> Result<EtaTable, TableError> {
        let partial = crate::parallel::map_indices(self.len(), |i| self.unless_mirrored(i));
        self.assemble(self.fill_mirrors(&partial))
    }

    /// Builds the table from computed entries.
    ///
    /// # Errors
    /// If the spec or entries are invalid.
    pub fn assemble(&self, entries: Vec<Entry>) -> Result<EtaTable, TableError> {
        let eta = entries.iter().map(|e| e.0).collect();
        let vfb = entries.iter().map(|e| e.1).collect();
        let flags = entries.iter().map(|e| e.2).collect();
        EtaTable::from_parts(self.params, self.axes.clone(), eta, vfb, flags)
    }
}
