//! Paper 001 §5 and Figs. 10–12, like for like: the paper's relaxed
//! funnelling against the paper's standard funnelling, both exactly as
//! written ([`Reading::Paper`]: `FunnelConfig::paper_000`,
//! `RelaxedConfig::paper_001`), and our relaxed controller against our
//! standard one ([`Reading::Ours`], the defaults). Each claim is one test
//! per reading that asserts the claim or asserts its refutation, with the
//! figures recorded (`tests/common/figures.rs`).
//!
//! Inputs: the paper 001 presets (nine entities entering from the left)
//! with every start moved by a seeded jitter (±0.3 m, ±5°), so that a
//! verdict does not rest on one picture. The thresholds below were chosen
//! looking at the tuning seeds [`TUNING`] only; the tests assert on the
//! report seeds [`REPORT`], which were never looked at while choosing.

use glam::Vec2;
use steering::base::rng::Rng;
use steering::base::vehicle::VehicleState;
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::controller::{Controller, ControllerKind, Reading};
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::funnelling::relaxed::RelaxedInternals;
use steering::funnelling::seek::seek_step;
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::{Mode, Update};
use steering::world::scenario::Scenario;

mod common;
use common::figures::{record_claim, Claim, Figure, Seeds, Verdict};
use common::paths::distance_to_middle_path;
use common::table;

/// Seeds the thresholds were chosen on.
const TUNING: [u64; 3] = [1, 2, 3];
/// Seeds the tests assert on (held out).
const REPORT: [u64; 3] = [101, 102, 103];

fn preset(name: &str) -> Scenario {
    let path = format!("{}/scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scenario::from_json(&text).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Preset `base` (`p001_fig10_beta45`) with its starts jittered by `seed`,
/// run by `kind` of `reading`.
fn scenario(base: &str, seed: u64, reading: Reading, kind: ControllerKind) -> Scenario {
    let mut sc = preset(&format!("{base}_standard"));
    let mut r = Rng::new(seed);
    for a in &mut sc.agents {
        a.x += r.range(-0.3, 0.3);
        a.y += r.range(-0.3, 0.3);
        a.theta_deg += r.range(-5.0, 5.0);
    }
    sc.set_reading(reading);
    sc.controller = kind;
    sc
}

/// Every agent's trajectory, every step.
type Traces = Vec<Vec<Vec2>>;

/// Every agent's trajectory, every step, and its (length, ∫|κ|, finished).
fn run(t: &EtaTable, sc: &Scenario) -> (Traces, Vec<(f32, f32, bool)>) {
    let mut w = sc.world().expect("preset builds");
    let mut tr: Vec<Vec<Vec2>> = w.agents().iter().map(|a| vec![a.state.pos]).collect();
    for _ in 0..sc.steps() {
        w.step(t).unwrap();
        for (i, a) in w.agents().iter().enumerate() {
            tr[i].push(a.state.pos);
        }
    }
    let m = w
        .agents()
        .iter()
        .map(|a| (a.metrics.length, a.metrics.curvature, a.done()))
        .collect();
    (tr, m)
}

fn mean(v: &[f32]) -> f32 {
    v.iter().sum::<f32>() / v.len().max(1) as f32
}

/// Standard against relaxed of one reading over seeds: per agent
/// (length, ∫|κ|) of both, paired.
#[derive(Debug, Default)]
struct Paired {
    standard: Vec<(f32, f32)>,
    relaxed: Vec<(f32, f32)>,
    finished: (usize, usize),
}

impl Paired {
    fn of(t: &EtaTable, base: &str, reading: Reading, seeds: &[u64]) -> Self {
        let mut p = Self::default();
        for &seed in seeds {
            let (_, s) = run(t, &scenario(base, seed, reading, ControllerKind::Standard));
            let (_, r) = run(t, &scenario(base, seed, reading, ControllerKind::Relaxed));
            p.finished.0 += s.iter().filter(|x| x.2).count();
            p.finished.1 += r.iter().filter(|x| x.2).count();
            p.standard.extend(s.iter().map(|x| (x.0, x.1)));
            p.relaxed.extend(r.iter().map(|x| (x.0, x.1)));
        }
        p
    }
    fn n(&self) -> usize {
        self.standard.len()
    }
    fn mean(&self, relaxed: bool, k: usize) -> f32 {
        let v = if relaxed {
            &self.relaxed
        } else {
            &self.standard
        };
        mean(
            &v.iter()
                .map(|x| if k == 0 { x.0 } else { x.1 })
                .collect::<Vec<_>>(),
        )
    }
    /// Agents whose relaxed path is below the standard one on `k`
    /// (0 length, 1 ∫|κ|) by more than `eps`.
    fn below(&self, k: usize, eps: f32) -> usize {
        let at = |x: &(f32, f32)| if k == 0 { x.0 } else { x.1 };
        self.standard
            .iter()
            .zip(&self.relaxed)
            .filter(|(s, r)| at(r) < at(s) - eps)
            .count()
    }
}

fn command(name: &str) -> String {
    format!("cargo test --release --features cli --test fidelity_literal {name}")
}

fn seeds() -> Seeds {
    Seeds {
        tuning: TUNING.to_vec(),
        report: REPORT.to_vec(),
    }
}

fn claim(place: &str, text: &str, reading: Reading, verdict: Verdict) -> Claim {
    Claim {
        paper: "001".into(),
        place: place.into(),
        claim: text.into(),
        reading: reading.name().into(),
        verdict,
    }
}

const BETAS: [u32; 3] = [0, 45, 120];

/// Fig. 10 on the report seeds, per β: the paired comparison, printed with
/// the tuning seeds' for the reader.
fn fig10(t: &EtaTable, reading: Reading) -> Vec<(u32, Paired)> {
    BETAS
        .iter()
        .map(|&beta| {
            let base = format!("p001_fig10_beta{beta}");
            for (what, s) in [("tuning", &TUNING[..]), ("report", &REPORT[..])] {
                let p = Paired::of(t, &base, reading, s);
                println!(
                    "fig10 {} β {beta}° ({what} seeds {s:?}): length {:.2} → {:.2} m ({}/{} shorter by > 1 cm), ∫|κ| {:.2} → {:.2} rad ({}/{} less curved by > 0.01 rad), finished {:?}",
                    reading.name(),
                    p.mean(false, 0),
                    p.mean(true, 0),
                    p.below(0, 0.01),
                    p.n(),
                    p.mean(false, 1),
                    p.mean(true, 1),
                    p.below(1, 0.01),
                    p.n(),
                    p.finished
                );
            }
            (beta, Paired::of(t, &base, reading, &REPORT))
        })
        .collect()
}

fn fig10_figures(reading: Reading, rows: &[(u32, Paired)], k: usize, what: &str) -> Vec<Figure> {
    let r = reading.name();
    let q = if k == 0 { "length" } else { "curvature" };
    let unit = if k == 0 { "m" } else { "rad" };
    let mut f = Vec::new();
    for (beta, p) in rows {
        let id = |x: &str| format!("p001.fig10.beta{beta}.{r}.{q}.{x}");
        f.push(Figure::new(
            &id("standard"),
            &format!("{r}: standard, mean {what} per agent (report seeds)"),
            f64::from(p.mean(false, k)),
            unit,
            2,
        ));
        f.push(Figure::new(
            &id("relaxed"),
            &format!("{r}: relaxed, mean {what} per agent (report seeds)"),
            f64::from(p.mean(true, k)),
            unit,
            2,
        ));
        f.push(Figure::new(
            &id("below"),
            &format!(
                "{r}: agents whose relaxed {what} is the smaller, of {}",
                p.n()
            ),
            p.below(k, 0.01) as f64,
            "",
            0,
        ));
    }
    f
}

/// §5 / Fig. 10: "the relaxed steering produces less curved trajectories
/// for the same mobile entities". Reproduced when, at every β, the
/// relaxed mean ∫|κ| is below 0.95 × the standard one and at least 2/3
/// of the agents are less curved; refuted when at no β it is below 0.99 ×.
fn less_curved(name: &str, reading: Reading, verdict: Verdict) -> Vec<(u32, f32, usize, usize)> {
    fig10_claim(
        name,
        reading,
        verdict,
        (1, "∫|κ|"),
        "the relaxed steering produces less curved trajectories for the same mobile entities",
    )
}

/// §5 / Fig. 10: "the traveled distance also appears to be frequently
/// smaller". Reproduced when, at every β, at least half of the agents
/// travel less with the relaxed controller; refuted when at no β a third do.
fn shorter(name: &str, reading: Reading, verdict: Verdict) -> Vec<(u32, f32, usize, usize)> {
    fig10_claim(
        name,
        reading,
        verdict,
        (0, "length"),
        "the traveled distance also appears to be frequently smaller with the relaxed steering",
    )
}

/// One Fig. 10 claim on metric `k` (0 length, 1 ∫|κ|): records it and
/// returns per β the relaxed / standard mean ratio, the agents more than
/// 1 % below with the relaxed controller, and the agents compared.
fn fig10_claim(
    name: &str,
    reading: Reading,
    verdict: Verdict,
    (k, what): (usize, &str),
    sentence: &str,
) -> Vec<(u32, f32, usize, usize)> {
    let t = table();
    let rows = fig10(&t, reading);
    record_claim(
        &format!("tests/fidelity_literal.rs::{name}"),
        &command(name),
        &seeds(),
        &claim("§5, Fig. 10", sentence, reading, verdict),
        &fig10_figures(reading, &rows, k, what),
    );
    rows.iter()
        .map(|(b, p)| {
            (
                *b,
                p.mean(true, k) / p.mean(false, k),
                p.below(k, 0.01),
                p.n(),
            )
        })
        .collect()
}

#[test]
fn p001_sec5_fig10_relaxed_less_curved_paper() {
    // Refuted on the tuning seeds (∫|κ| relaxed / standard 1.41, 1.05 and
    // 18.7 at β 0°, 45°, 120°): the relaxed point on the arc turns the
    // entities earlier and harder than the centre aim; at 120° the literal
    // relaxed entities never finish (they circle the disk: Orientation_only
    // keeps the speed, the paper being silent on it, and Fig. 7's Δη from
    // the arc ends never reaches the tolerance; with Orientation_only
    // stopping, or Δη measured again at the relaxed point, all 9 finish).
    let rows = less_curved(
        "p001_sec5_fig10_relaxed_less_curved_paper",
        Reading::Paper,
        Verdict::Refuted,
    );
    for (beta, ratio, below, n) in rows {
        assert!(ratio >= 0.99, "β {beta}: ∫|κ| ratio {ratio}, {below}/{n}");
    }
}

#[test]
fn p001_sec5_fig10_relaxed_less_curved_ours() {
    // Ours aims the relaxed controller at the disk's entry point, as the
    // standard one: on these disk goals both ride the same path.
    let rows = less_curved(
        "p001_sec5_fig10_relaxed_less_curved_ours",
        Reading::Ours,
        Verdict::Refuted,
    );
    for (beta, ratio, _, _) in rows {
        assert!(ratio >= 0.99, "β {beta}: ∫|κ| ratio {ratio}");
    }
}

#[test]
fn p001_sec5_fig10_relaxed_frequently_shorter_paper() {
    // Partly, on the tuning seeds: shorter for 27/27 at β 45° (−2.9 %),
    // 12/27 at 0° (−0.1 %), 0/27 at 120° (the relaxed entities never
    // finish: see the curvature test).
    let rows = shorter(
        "p001_sec5_fig10_relaxed_frequently_shorter_paper",
        Reading::Paper,
        Verdict::Partly,
    );
    let at = |b: u32| rows.iter().find(|r| r.0 == b).copied().unwrap();
    let (b0, b45, b120) = (at(0), at(45), at(120));
    assert!(2 * b45.2 >= b45.3 && b45.1 < 0.99, "β 45: {b45:?}");
    assert!(3 * b0.2 >= b0.3 && 2 * b0.2 < b0.3, "β 0: {b0:?}");
    assert!(b120.2 == 0, "β 120: {b120:?}");
}

#[test]
fn p001_sec5_fig10_relaxed_frequently_shorter_ours() {
    let rows = shorter(
        "p001_sec5_fig10_relaxed_frequently_shorter_ours",
        Reading::Ours,
        Verdict::Refuted,
    );
    for (beta, ratio, below, n) in rows {
        assert!(3 * below < n, "β {beta}: length ratio {ratio}, {below}/{n}");
    }
}

const TOLS: [u32; 4] = [5, 15, 30, 45];

/// Fig. 11: per controller kind, the mean distance from the middle
/// agent's path over 5–35 m of travel (every metre, all seeds), at each
/// orientation tolerance.
fn fig11_spread(t: &EtaTable, reading: Reading, seeds: &[u64]) -> Vec<(u32, f32, f32)> {
    TOLS.iter()
        .map(|&tol| {
            let base = format!("p001_fig11_tol{tol}");
            let spread = |kind| {
                let v: Vec<f32> = seeds
                    .iter()
                    .flat_map(|&s| {
                        let (tr, _) = run(t, &scenario(&base, s, reading, kind));
                        distance_to_middle_path(&tr, 1.0, 35.0)[5..].to_vec()
                    })
                    .collect();
                mean(&v)
            };
            (
                tol,
                spread(ControllerKind::Standard),
                spread(ControllerKind::Relaxed),
            )
        })
        .collect()
}

/// Fig. 11: "increasing the orientation tolerance has a minor impact on
/// the trajectories produced with the standard funnelling compared to the
/// much wider spread of trajectories achieved with the relaxed one".
/// Reproduced when from 5° to 45° the relaxed spread grows by at least
/// 0.5 m and by at least twice the standard one's change; refuted when it
/// grows by less than the standard one's change or by less than 0.1 m.
fn fig11(name: &str, reading: Reading, verdict: Verdict) -> (f32, f32) {
    let t = table();
    let tune = fig11_spread(&t, reading, &TUNING);
    let rows = fig11_spread(&t, reading, &REPORT);
    println!("fig11 {}: mean distance from the middle path (5–35 m), (ε_tol°, standard m, relaxed m): tuning {tune:.2?}, report {rows:.2?}", reading.name());
    let r = reading.name();
    let mut figures = Vec::new();
    for (tol, s, x) in &rows {
        figures.push(Figure::new(
            &format!("p001.fig11.tol{tol}.{r}.standard"),
            &format!(
                "{r}: standard, mean distance from the middle agent's path over 5–35 m of travel"
            ),
            f64::from(*s),
            "m",
            2,
        ));
        figures.push(Figure::new(
            &format!("p001.fig11.tol{tol}.{r}.relaxed"),
            &format!(
                "{r}: relaxed, mean distance from the middle agent's path over 5–35 m of travel"
            ),
            f64::from(*x),
            "m",
            2,
        ));
    }
    record_claim(
        &format!("tests/fidelity_literal.rs::{name}"),
        &command(name),
        &seeds(),
        &claim("Fig. 11", "increasing the orientation tolerance has a minor impact on the standard funnelling's trajectories compared to the much wider spread achieved with the relaxed one", reading, verdict),
        &figures,
    );
    let (first, last) = (rows[0], rows[rows.len() - 1]);
    (last.1 - first.1, last.2 - first.2)
}

#[test]
fn p001_fig11_relaxed_spreads_with_tolerance_paper() {
    // Partly, on the tuning seeds: from 5° to 45° the relaxed spread grows
    // by 0.10 m, three times the standard one's 0.03 m, but not by the
    // 0.5 m of a "much wider spread".
    let (ds, dr) = fig11(
        "p001_fig11_relaxed_spreads_with_tolerance_paper",
        Reading::Paper,
        Verdict::Partly,
    );
    assert!(
        dr >= 2.0 * ds.abs() && dr < 0.5,
        "5° → 45°: standard {ds:+.2} m, relaxed {dr:+.2} m"
    );
}

#[test]
fn p001_fig11_relaxed_spreads_with_tolerance_ours() {
    let (ds, dr) = fig11(
        "p001_fig11_relaxed_spreads_with_tolerance_ours",
        Reading::Ours,
        Verdict::Refuted,
    );
    assert!(
        dr < ds.abs().max(0.1),
        "5° → 45°: standard {ds:+.2} m, relaxed {dr:+.2} m"
    );
}

/// Fig. 12 over seeds: paired paths, and the mean distance from the middle
/// path every 5 m of travel for each kind.
fn fig12(t: &EtaTable, reading: Reading, seeds: &[u64]) -> (Paired, [Vec<f32>; 2]) {
    let base = "p001_fig12_successive";
    let p = Paired::of(t, base, reading, seeds);
    let d = [ControllerKind::Standard, ControllerKind::Relaxed].map(|kind| {
        let per: Vec<Vec<f32>> = seeds
            .iter()
            .map(|&s| {
                distance_to_middle_path(&run(t, &scenario(base, s, reading, kind)).0, 5.0, 60.0)
            })
            .collect();
        (0..per[0].len())
            .map(|k| mean(&per.iter().map(|v| v[k]).collect::<Vec<_>>()))
            .collect()
    });
    (p, d)
}

/// Fig. 12: "the longer and more curved path produced by the standard
/// funnelling compared to the more globally smoother and shorter one
/// obtained with the relaxed algorithm". Reproduced when the relaxed mean
/// length and ∫|κ| are both below the standard ones (by 1 % or more);
/// refuted when neither is.
fn fig12_shorter(name: &str, reading: Reading, verdict: Verdict) -> (f32, f32) {
    let t = table();
    let (tune, _) = fig12(&t, reading, &TUNING);
    let (p, _) = fig12(&t, reading, &REPORT);
    let r = reading.name();
    println!(
        "fig12 {r}: length {:.2} → {:.2} m, ∫|κ| {:.2} → {:.2} rad (report; tuning {:.2} → {:.2} m, {:.2} → {:.2} rad); finished {:?}",
        p.mean(false, 0), p.mean(true, 0), p.mean(false, 1), p.mean(true, 1),
        tune.mean(false, 0), tune.mean(true, 0), tune.mean(false, 1), tune.mean(true, 1), p.finished
    );
    record_claim(
        &format!("tests/fidelity_literal.rs::{name}"),
        &command(name),
        &seeds(),
        &claim("Fig. 12", "successive goals: the standard funnelling's path is longer and more curved, the relaxed one globally smoother and shorter", reading, verdict),
        &[
            Figure::new(&format!("p001.fig12.{r}.standard.length"), &format!("{r}: standard, mean length per agent over four goals (report seeds)"), f64::from(p.mean(false, 0)), "m", 2),
            Figure::new(&format!("p001.fig12.{r}.relaxed.length"), &format!("{r}: relaxed, mean length per agent over four goals (report seeds)"), f64::from(p.mean(true, 0)), "m", 2),
            Figure::new(&format!("p001.fig12.{r}.standard.curvature"), &format!("{r}: standard, mean ∫|κ| per agent (report seeds)"), f64::from(p.mean(false, 1)), "rad", 2),
            Figure::new(&format!("p001.fig12.{r}.relaxed.curvature"), &format!("{r}: relaxed, mean ∫|κ| per agent (report seeds)"), f64::from(p.mean(true, 1)), "rad", 2),
        ],
    );
    (
        p.mean(true, 0) / p.mean(false, 0),
        p.mean(true, 1) / p.mean(false, 1),
    )
}

#[test]
fn p001_fig12_relaxed_shorter_and_smoother_paper() {
    // Partly, on the tuning seeds: shorter (53.9 → 51.7 m) but more curved
    // (3.02 → 3.48 rad).
    let (l, k) = fig12_shorter(
        "p001_fig12_relaxed_shorter_and_smoother_paper",
        Reading::Paper,
        Verdict::Partly,
    );
    assert!(
        l < 0.99 && k > 1.01,
        "relaxed / standard: length {l}, ∫|κ| {k}"
    );
}

#[test]
fn p001_fig12_relaxed_shorter_and_smoother_ours() {
    let (l, k) = fig12_shorter(
        "p001_fig12_relaxed_shorter_and_smoother_ours",
        Reading::Ours,
        Verdict::Refuted,
    );
    assert!(
        l >= 0.99 && k >= 0.99,
        "relaxed / standard: length {l}, ∫|κ| {k}"
    );
}

/// Fig. 12: "the tendency of trajectories to converge to a single path
/// independently of the initial conditions", for the relaxed controller.
/// Reproduced when the relaxed agents start more than 2 m from the middle
/// path on average and are within 0.25 m of it after 25 m of travel and
/// stay so to 60 m.
fn fig12_converge(name: &str, reading: Reading, verdict: Verdict) -> Vec<f32> {
    let t = table();
    let (_, [_, tune]) = fig12(&t, reading, &TUNING);
    let (_, [ds, dr]) = fig12(&t, reading, &REPORT);
    let r = reading.name();
    println!("fig12 {r}: mean distance from the middle path every 5 m: relaxed {dr:.2?} (tuning {tune:.2?}); standard {ds:.2?}");
    record_claim(
        &format!("tests/fidelity_literal.rs::{name}"),
        &command(name),
        &seeds(),
        &claim("Fig. 12", "the trajectories tend to converge to a single path independently of the initial conditions", reading, verdict),
        &[
            Figure::new(&format!("p001.fig12.{r}.relaxed.start"), &format!("{r}: relaxed, mean distance from the middle agent's path at the start"), f64::from(dr[0]), "m", 2),
            Figure::new(&format!("p001.fig12.{r}.relaxed.after25"), &format!("{r}: relaxed, largest mean distance from the middle agent's path from 25 to 60 m of travel"), f64::from(dr[5..].iter().copied().fold(0.0, f32::max)), "m", 2),
            Figure::new(&format!("p001.fig12.{r}.standard.after25"), &format!("{r}: standard, largest mean distance from the middle agent's path from 25 to 60 m of travel"), f64::from(ds[5..].iter().copied().fold(0.0, f32::max)), "m", 2),
        ],
    );
    dr
}

#[test]
fn p001_fig12_trajectories_converge_paper() {
    let d = fig12_converge(
        "p001_fig12_trajectories_converge_paper",
        Reading::Paper,
        Verdict::Reproduced,
    );
    assert!(d[0] > 2.0 && d[5..].iter().all(|&x| x < 0.25), "{d:?}");
}

#[test]
fn p001_fig12_trajectories_converge_ours() {
    let d = fig12_converge(
        "p001_fig12_trajectories_converge_ours",
        Reading::Ours,
        Verdict::Reproduced,
    );
    assert!(d[0] > 2.0 && d[5..].iter().all(|&x| x < 0.25), "{d:?}");
}

// ------------------------------------------------- paper 000 §3, Fig. 5

/// One random seek case: a start at rest or moving, turning or not, and a
/// target 0.3–4 m away in any direction (behind included).
fn seek_case(r: &mut Rng, p: &steering::base::vehicle::VehicleParams) -> (VehicleState, Goal) {
    let v = r.range(0.0, p.v_max);
    let w = r.range(-1.0, 1.0) * p.omega_limit(v);
    let (d, bearing) = (r.range(0.3, 4.0), r.range(-3.1, 3.1));
    (
        VehicleState::new(Vec2::ZERO, 0.0, v, w),
        Goal {
            pos: Vec2::from_angle(bearing) * d,
            beta: 0.0,
            d_tol: 0.1,
            eps_tol: f32::INFINITY,
            speed: 1.3,
            halting: false,
            vel: Vec2::ZERO,
        },
    )
}

/// Whether seek reaches (comes within `d_tol` of) the target within 30 s:
/// with the table's proactive speed (`cfg`'s plain seek, paper 000 §3), or
/// without it (`None`: the seek step towards the target at the desired
/// speed every step).
fn seek_reaches(t: &EtaTable, cfg: Option<FunnelConfig>, s: VehicleState, g: &Goal) -> bool {
    let p = t.params().vehicle;
    let (mut s, mut mem, mut ri) = (s, FunnelMemory::default(), RelaxedInternals::default());
    let steps = (30.0 / p.dt) as u32;
    for _ in 0..steps {
        if s.pos.distance(g.pos) < g.d_tol {
            return true;
        }
        match cfg {
            Some(c) => {
                Controller::Standard(c.plain_seek()).step(
                    &mut Update {
                        table: t,
                        params: &p,
                        state: &mut s,
                        goal: g,
                        memory: &mut mem,
                    },
                    &mut ri,
                );
            }
            None => {
                let to = g.pos - s.pos;
                seek_step(&p, &mut s, to.y.atan2(to.x), g.speed);
            }
        }
    }
    false
}

/// Seeded random seek cases reached: (without the table's speed, with
/// `cfg`'s) of `n`.
fn proactive_study(t: &EtaTable, cfg: FunnelConfig, seed: u64, n: usize) -> (usize, usize) {
    let p = t.params().vehicle;
    let mut r = Rng::new(seed);
    let mut k = (0, 0);
    for _ in 0..n {
        let (s, g) = seek_case(&mut r, &p);
        k.0 += usize::from(seek_reaches(t, None, s, &g));
        k.1 += usize::from(seek_reaches(t, Some(cfg), s, &g));
    }
    k
}

/// 000 §3's claim for one reading over 500 random starts, recorded as the
/// row of test `name`: (without the table's speed, with it) reached.
fn proactive(
    name: &str,
    reading: Reading,
    cfg: FunnelConfig,
    verdict: Verdict,
) -> (usize, usize, usize) {
    let t = table();
    let n = 500;
    let tune = proactive_study(&t, cfg, 1, n);
    let (without, k) = proactive_study(&t, cfg, 101, n);
    let who = reading.name();
    println!("000 §3, {who}: seek reaches within 30 s (of {n} random starts, targets 0.3–4 m in any direction, d_tol 0.1 m): without the table's speed / {who}: tuning seed 1 {tune:?}, report seed 101 ({without}, {k})");
    let figs = |id: &str, what: &str, k: usize| {
        Figure::new(
            &format!("p000.sec3.proactive.{who}.{id}"),
            &format!("seek cases reached within 30 s, {what}, of {n} random starts (seed 101)"),
            k as f64,
            "",
            0,
        )
    };
    record_claim(
        &format!("tests/fidelity_literal.rs::{name}"),
        &command(name),
        &Seeds {
            tuning: vec![1],
            report: vec![101],
        },
        &Claim {
            paper: "000".into(),
            place: "§3".into(),
            claim: "the table's stored speed makes the seek mode reach the target in all cases"
                .into(),
            reading: who.into(),
            verdict,
        },
        &[
            figs("without", "without the table's speed", without),
            figs("with", &format!("{who} seek, with the table's speed"), k),
        ],
    );
    (without, k, n)
}

// "Its first immediate benefit is to make the seek mode capable of
// adjusting the desired speed so that the target becomes reachable in all
// cases." Reproduced when, over random starts, seek with the table's
// speed reaches every target and seek without it misses some (it orbits
// targets inside its turning circle).

#[test]
fn p000_sec3_proactive_speed_makes_seek_reach_in_all_cases_paper() {
    // The paper's seek (the closest element's stored speed) reaches no
    // more than seek without the table (362 and 362 of 500 on the report
    // seed, 367 and 366 on the tuning seed): refuted.
    let (without, paper, n) = proactive(
        "p000_sec3_proactive_speed_makes_seek_reach_in_all_cases_paper",
        Reading::Paper,
        FunnelConfig::paper_000(),
        Verdict::Refuted,
    );
    assert!(
        without < n && paper < n && paper <= without + n / 100,
        "paper {paper}, without {without} of {n}"
    );
}

#[test]
fn p000_sec3_proactive_speed_makes_seek_reach_in_all_cases_ours() {
    // Ours reaches all 500 because of the orbit-free speed near the target
    // (`FunnelConfig::orbit_free`; without it ours reaches 363):
    // reproduced, by a step of ours.
    let (without, ours, n) = proactive(
        "p000_sec3_proactive_speed_makes_seek_reach_in_all_cases_ours",
        Reading::Ours,
        FunnelConfig::default(),
        Verdict::Reproduced,
    );
    assert!(
        ours == n && without < n,
        "ours {ours}, without {without} of {n}"
    );
    let no_orbit_free = FunnelConfig {
        orbit_free: false,
        ..FunnelConfig::default()
    };
    let t = table();
    let (_, ours_without_orbit_free) = proactive_study(&t, no_orbit_free, 101, n);
    assert!(
        ours_without_orbit_free < n,
        "ours without the orbit-free speed {ours_without_orbit_free} of {n}"
    );
}

/// The mode one update chooses for a vehicle at rest near the goal's
/// centre, heading `err` off β.
fn mode_at(t: &EtaTable, cfg: FunnelConfig, err: f32, eps: f32, halting: bool) -> Mode {
    let p = t.params().vehicle;
    let g = Goal {
        pos: Vec2::new(0.0, 0.0),
        beta: 0.5,
        d_tol: 0.25,
        eps_tol: eps,
        speed: 1.3,
        halting,
        vel: Vec2::ZERO,
    };
    let mut s = VehicleState::new(Vec2::new(0.05, -0.02), 0.5 + err, 0.0, 0.0);
    let mut mem = FunnelMemory::default();
    cfg.plan(&mut Update {
        table: t,
        params: &p,
        state: &mut s,
        goal: &g,
        memory: &mut mem,
    })
    .mode
}

#[test]
fn p000_fig5_end_of_steering_at_the_orientation_tolerance() {
    // Fig. 5: inside the position tolerance, End_of_Steering when
    // |β − θ| < ε_tol, else Orientation_only. At 0.9·ε_tol and 1.1·ε_tol,
    // either side of β, halting or not, for both readings and several
    // tolerances.
    let t = table();
    for cfg in [FunnelConfig::paper_000(), FunnelConfig::default()] {
        for eps_deg in [2.0f32, 5.0, 20.0] {
            let eps = eps_deg.to_radians();
            for (sign, halting) in [(-1.0, false), (1.0, false), (-1.0, true), (1.0, true)] {
                let inside = mode_at(&t, cfg, sign * 0.9 * eps, eps, halting);
                let outside = mode_at(&t, cfg, sign * 1.1 * eps, eps, halting);
                let case = format!("{cfg:?}, ε {eps_deg}°, halting {halting}, {sign}·");
                assert_eq!(inside, Mode::EndOfSteering, "{case}0.9");
                assert_eq!(outside, Mode::OrientationOnly, "{case}1.1");
            }
        }
    }
}
