//! What `steer reach / relaxed / envelope / avoid --record` write: each
//! printed summary row as figures with stable ids, and the seeds the
//! settings were tuned on beside the seeds reported.
//!
//! The tuning seeds are those the defaults were chosen on, as the code
//! that holds each default says: the funnelling and relaxed settings on
//! the envelope study's seed 1 (`crate/funnelling/config.rs`,
//! `crate/funnelling/relaxed.rs`), the avoidance rules on the benchmarks'
//! seeds 1000–1099, 2000–2099 and 3000–3999 (`crate/avoidance/passing.rs`,
//! `patience.rs`).

use super::records::{Figure, Seeds};
use crate::studies::avoidance::CellSummary as AvoidCell;
use crate::studies::envelope::report::{summarise, EnvelopeReport};
use crate::studies::envelope::GoalKind;
use crate::studies::reach::Summary as ReachSummary;
use crate::studies::region::Comparison;

/// Seeds the funnelling and relaxed defaults were tuned on (the envelope
/// study's tune seed).
pub const FUNNEL_TUNING: [u64; 1] = [1];

/// The seed ranges the avoidance rules were tuned on.
pub const AVOID_TUNING: [std::ops::Range<u64>; 3] = [1000..1100, 2000..2100, 3000..4000];

/// A funnelling study's seeds: tuned on [`FUNNEL_TUNING`], reporting `seed`.
#[must_use]
pub fn funnel_seeds(seed: u64) -> Seeds {
    Seeds {
        tuning: FUNNEL_TUNING.to_vec(),
        report: vec![seed],
    }
}

/// The avoidance study's seeds: tuned on [`AVOID_TUNING`], reporting
/// `first .. first + n`.
#[must_use]
pub fn avoid_seeds(first: u64, n: usize) -> Seeds {
    Seeds {
        tuning: AVOID_TUNING.iter().cloned().flatten().collect(),
        report: (first..first + n as u64).collect(),
    }
}

/// Collects figures, leaving out values that are not finite (a share of
/// an empty group): a record holds only numbers.
#[derive(Default)]
struct Figures(Vec<Figure>);

impl Figures {
    fn add(&mut self, id: String, what: String, value: f64, unit: &str, digits: u8) {
        if value.is_finite() {
            self.0.push(Figure::new(&id, &what, value, unit, digits));
        }
    }
}

/// `steer reach`: one variant's row (`variant` names it in ids, `label`
/// in words).
#[must_use]
pub fn reach(variant: &str, label: &str, s: &ReachSummary) -> Vec<Figure> {
    let mut f = Figures::default();
    let id = |q: &str| format!("reach.{variant}.{q}");
    let what = |q: &str| format!("reach study, {label}: {q}");
    let pct = |v: f32| 100.0 * f64::from(v);
    f.add(
        id("reach"),
        what("runs reaching End_of_Steering"),
        pct(s.reach_rate),
        "%",
        2,
    );
    f.add(
        id("oriented"),
        what("entries into the tolerance disk already within ε_tol"),
        pct(s.oriented_rate),
        "%",
        1,
    );
    f.add(
        id("entry-error.median"),
        what("heading error on entry, median"),
        f64::from(s.entry_err_deg.0),
        "°",
        1,
    );
    f.add(
        id("entry-error.p95"),
        what("heading error on entry, 95th percentile"),
        f64::from(s.entry_err_deg.1),
        "°",
        1,
    );
    f.add(
        id("length-over-dubins.median"),
        what("path length / Dubins shortest path, median"),
        f64::from(s.length_ratio.0),
        "×",
        3,
    );
    f.add(
        id("violations"),
        what("steps over a vehicle limit"),
        f64::from(s.violations),
        "steps",
        0,
    );
    f.0
}

/// `steer relaxed`: one comparison row (`row` names the preset or the
/// random study; `variant` the relaxed settings, e.g. `paper-arc`).
#[must_use]
pub fn relaxed(variant: &str, row: &str, c: &Comparison) -> Vec<Figure> {
    let mut f = Figures::default();
    let id = |q: &str| format!("relaxed.{variant}.{}.{q}", id_segment(row));
    let what = |q: &str| format!("{row}, standard vs relaxed ({variant}): {q}");
    let pct = |v: f32| 100.0 * f64::from(v);
    for (side, k) in [("standard", 0), ("relaxed", 1)] {
        let pick = |p: (f32, f32)| f64::from(if k == 0 { p.0 } else { p.1 });
        f.add(
            id(&format!("length.{side}")),
            what(&format!("mean path length, {side}")),
            pick(c.length),
            "m",
            2,
        );
        f.add(
            id(&format!("curvature.{side}")),
            what(&format!("mean integrated |curvature|, {side}")),
            pick(c.curvature),
            "rad",
            2,
        );
        f.add(
            id(&format!("reach.{side}")),
            what(&format!("runs finishing every goal, {side}")),
            pct(if k == 0 { c.reach.0 } else { c.reach.1 }),
            "%",
            1,
        );
    }
    f.add(
        id("shorter"),
        what("agents whose relaxed path is shorter"),
        pct(c.relaxed_shorter),
        "%",
        1,
    );
    f.add(
        id("less-curved"),
        what("agents whose relaxed path is less curved"),
        pct(c.relaxed_less_curved),
        "%",
        1,
    );
    f.add(id("n"), what("agents compared"), c.n as f64, "", 0);
    f.0
}

/// `steer envelope`: per variant and goal family, the summary row (ids
/// start with `prefix`: `envelope`, or `envelope-car` for a vehicle file).
#[must_use]
pub fn envelope(prefix: &str, report: &EnvelopeReport) -> Vec<Figure> {
    let mut f = Figures::default();
    let pct = |v: f32| 100.0 * f64::from(v);
    for v in &report.variants {
        for kind in GoalKind::ALL {
            let s = summarise(v.runs(kind));
            let group = format!("{kind:?}").to_lowercase();
            let id = |q: &str| format!("{prefix}.{}.{group}.{q}", v.name);
            let what = |q: &str| format!("envelope study, {} on {group} goals: {q}", v.name);
            f.add(id("runs"), what("runs"), s.n as f64, "", 0);
            f.add(
                id("reach"),
                what("runs entering the first disk"),
                pct(s.reach),
                "%",
                1,
            );
            f.add(
                id("oriented"),
                what("entries already within ε_tol (runs starting outside the disk)"),
                pct(s.oriented),
                "%",
                1,
            );
            f.add(
                id("eos-inside"),
                what("End_of_Steering declared inside both tolerances"),
                pct(s.eos_ok),
                "%",
                1,
            );
            f.add(
                id("rest-inside"),
                what("halting runs at rest inside both tolerances"),
                pct(s.rest_ok),
                "%",
                1,
            );
            f.add(
                id("finished"),
                what("runs finishing every goal"),
                pct(s.finished),
                "%",
                1,
            );
            f.add(
                id("length-over-dubins.median"),
                what("path length / Dubins, median of finished runs"),
                f64::from(s.length_ratio.0),
                "×",
                3,
            );
            f.add(
                id("orbits"),
                what("runs still circling at the time limit"),
                s.orbits as f64,
                "runs",
                0,
            );
        }
    }
    f.0
}

/// `steer avoid`: one benchmark and method's row.
#[must_use]
pub fn avoid(bench: &str, method: &str, c: &AvoidCell) -> Vec<Figure> {
    let mut f = Figures::default();
    let id = |q: &str| format!("avoid.{bench}.{method}.{q}");
    let what = |q: &str| format!("avoidance benchmark {bench}, {method}: {q}");
    let share = |k: f64, of: f64| if of > 0.0 { 100.0 * k / of } else { f64::NAN };
    f.add(id("runs"), what("runs"), c.runs as f64, "", 0);
    f.add(
        id("reach"),
        what("agents reaching their goal"),
        share(c.reached as f64, c.agents as f64),
        "%",
        2,
    );
    f.add(
        id("oriented"),
        what("entries oriented within ε_tol"),
        share(c.oriented as f64, c.entries as f64),
        "%",
        1,
    );
    f.add(
        id("finished-runs"),
        what("runs where every agent finished"),
        c.finished_runs as f64,
        "runs",
        0,
    );
    f.add(
        id("min-distance"),
        what("smallest centre distance between two agents (bodies 0.6 m)"),
        f64::from(c.min_distance),
        "m",
        3,
    );
    f.add(
        id("overlap-runs"),
        what("runs with two bodies overlapping"),
        c.runs_with_overlap as f64,
        "runs",
        0,
    );
    f.add(
        id("deadlocked"),
        what("deadlocked agents"),
        c.deadlocks as f64,
        "agents",
        0,
    );
    f.add(
        id("violations"),
        what("steps over a vehicle limit"),
        c.violations as f64,
        "steps",
        0,
    );
    f.0
}

/// An id segment from free text: ASCII letters, digits, `_` and `-` kept,
/// `.` written `p` (`0.25` → `0p25`), anything else a `-`.
#[must_use]
pub fn id_segment(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        let c = match c {
            '.' => 'p',
            c if c.is_ascii_alphanumeric() || c == '_' || c == '-' => c.to_ascii_lowercase(),
            _ => '-',
        };
        if !(c == '-' && (out.is_empty() || out.ends_with('-'))) {
            out.push(c);
        }
    }
    out.trim_end_matches('-').to_string()
}

/// A reach variant's id segment and label: `radius8-g2-t0p25`,
/// "μ bound TurningRadius { factor: 8.0 }, gain 2, seek threshold 0.25".
#[must_use]
pub fn reach_variant(
    bound: &crate::funnelling::config::MuBound,
    gain: f32,
    threshold: f32,
) -> (String, String) {
    use crate::funnelling::config::MuBound;
    let b = match bound {
        MuBound::Literal => "literal".to_string(),
        MuBound::ScaledLiteral { gain } => format!("scaled{gain}"),
        MuBound::TurningRadius { factor } => format!("radius{factor}"),
        MuBound::Constant => "constant".to_string(),
    };
    (
        id_segment(&format!("{b}-g{gain}-t{threshold}")),
        format!("μ bound {bound:?}, gain {gain}, seek threshold {threshold}"),
    )
}

/// The relaxed settings' id segment: the aim (`entry`, `paper-arc`), and
/// the margins where they are not the defaults (`paper-arc-dm1-om1`).
#[must_use]
pub fn relaxed_variant(c: &crate::funnelling::relaxed::RelaxedConfig) -> String {
    use crate::funnelling::relaxed::{RelaxedAim, RelaxedConfig};
    let d = RelaxedConfig::default();
    let mut s = match c.aim {
        RelaxedAim::Entry => "entry".to_string(),
        RelaxedAim::PaperArc => "paper-arc".to_string(),
    };
    if c.disk_margin != d.disk_margin {
        s += &format!("-dm{}", c.disk_margin);
    }
    if c.orientation_margin != d.orientation_margin {
        s += &format!("-om{}", c.orientation_margin);
    }
    if c.end_eta != d.end_eta {
        s += &format!("-{:?}", c.end_eta);
    }
    id_segment(&s)
}
