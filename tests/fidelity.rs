//! Fidelity: what each figure of the four texts *claims*,
//! measured on its preset and asserted, so a claim that stops holding
//! fails a test. Every test prints its figures (`--nocapture`); the README's
//! table "figure | preset | claim | our measurement | agrees?" quotes them,
//! and each preset's `claim` / `measured` fields (shown in the lab's side
//! panel) carry the same sentence. Fast: the whole file runs in seconds in
//! release; long studies live in `steer`.

use core::f32::consts::{FRAC_PI_2, PI, TAU};

use glam::Vec2;
use steering::base::angle::diff;
use steering::funnelling::controller::ControllerKind;
use steering::funnelling::relaxed::{Fig7Branch, RelaxedAim};
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::Mode;
use steering::world::scenario::Scenario;
use steering::world::World;

mod common;
use common::figures::{record_claim, Claim, Figure, Seeds, Verdict};
use common::paths::distance_to_middle_path;
use common::table;

/// Writes the record of a paper 000 / 001 test (fixed presets: no seeds):
/// the claim, which reading was measured, the verdict the test asserts and
/// the figures it asserts on, for the figures report and the presets'
/// `measured` strings.
fn record_fig(
    test: &str,
    paper: &str,
    place: &str,
    claim: &str,
    reading: &str,
    verdict: Verdict,
    figs: &[Figure],
) {
    record_claim(
        &format!("tests/fidelity.rs::{test}"),
        &format!("cargo test --release --features cli --test fidelity {test}"),
        &Seeds::default(),
        &Claim {
            paper: paper.into(),
            place: place.into(),
            claim: claim.into(),
            reading: reading.into(),
            verdict,
        },
        figs,
    );
}

/// Smallest and largest.
fn min_max(v: &[f32]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(f64::from(x)), hi.max(f64::from(x)))
        })
}

fn preset(name: &str) -> Scenario {
    let path = format!("{}/scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scenario::from_json(&text).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Runs `sc` for its duration, calling `visit(world)` after every step.
fn run(t: &EtaTable, sc: &Scenario, mut visit: impl FnMut(&World)) -> World {
    let mut w = sc.world().expect("preset builds");
    let steps = (sc.duration / w.params().dt).round() as u32;
    for _ in 0..steps {
        w.step(t).unwrap();
        visit(&w);
    }
    w
}

/// The paper's relaxed point (paper 001 Fig. 7 literally: `aim: paperArc`).
fn paper_arc(mut sc: Scenario) -> Scenario {
    sc.controller = ControllerKind::Relaxed;
    sc.relaxed.aim = RelaxedAim::PaperArc;
    sc
}

fn mean(v: &[f32]) -> f32 {
    v.iter().sum::<f32>() / v.len().max(1) as f32
}

/// Circular standard deviation of angles, rad.
fn circ_std(a: &[f32]) -> f32 {
    let (s, c) = a
        .iter()
        .fold((0.0f32, 0.0f32), |(s, c), x| (s + x.sin(), c + x.cos()));
    let r = (s * s + c * c).sqrt() / a.len().max(1) as f32;
    (-2.0 * r.max(1e-9).ln()).sqrt()
}

// ---------------------------------------------------------------- paper 000

#[test]
fn p000_fig1_plain_seek_never_funnels_and_reaches_every_target() {
    let t = table();
    let sc = preset("p000_fig1_seek");
    assert_eq!(sc.controller, ControllerKind::Seek);
    let mut funnelled = 0;
    let w = run(&t, &sc, |w| {
        funnelled += w
            .agents()
            .iter()
            .filter(|a| matches!(a.internals.mode, Mode::Funnelling | Mode::OrientationOnly))
            .count();
    });
    for (i, a) in w.agents().iter().enumerate() {
        let g = a.goals[0].goal;
        let d = a.state.pos.distance(g.pos);
        println!(
            "fig1 seek agent {i}: rest {d:.3} m from the target, finished {:?}",
            a.finished_at
        );
        assert!(a.done() && d < g.d_tol, "agent {i}: {d} m");
    }
    assert_eq!(funnelled, 0, "plain seek funnelled");
    let dist: Vec<f32> = w
        .agents()
        .iter()
        .map(|a| a.state.pos.distance(a.goals[0].goal.pos))
        .collect();
    let times: Vec<f32> = w.agents().iter().filter_map(|a| a.finished_at).collect();
    let (t0, t1) = min_max(&times);
    // The old reading (standard controller, ε_tol 180°) funnels the agent
    // whose target lies behind it towards β.
    let mut old = sc.clone();
    old.controller = ControllerKind::Standard;
    let mut old_funnel = 0;
    run(&t, &old, |w| {
        old_funnel += usize::from(w.agents()[2].internals.mode == Mode::Funnelling);
    });
    println!(
        "fig1 under the standard controller with ε_tol 180°: agent 2 funnels {old_funnel} steps"
    );
    assert!(old_funnel > 0);
    record_fig(
        "p000_fig1_plain_seek_never_funnels_and_reaches_every_target",
        "000",
        "Fig. 1",
        "plain seek reaches position targets without a prescribed orientation",
        "paper",
        Verdict::Reproduced,
        &[
            Figure::new("p000.fig1.reached", "agents at rest inside their target", w.agents().iter().filter(|a| a.done()).count() as f64, "of 3", 0),
            Figure::new("p000.fig1.distance.max", "final distance to the target's centre, largest", min_max(&dist).1, "m", 2),
            Figure::new("p000.fig1.time.min", "time to rest, earliest", t0, "s", 1),
            Figure::new("p000.fig1.time.max", "time to rest, latest", t1, "s", 1),
            Figure::new("p000.fig1.funnelled", "agent-steps in a funnelling mode", funnelled as f64, "", 0),
            Figure::new("p000.fig1.standard-eps180.funnelled", "steps the agent whose target lies behind funnels under the standard controller with ε_tol 180°", old_funnel as f64, "steps", 0),
        ],
    );
}

#[test]
fn p000_fig3_funnelling_reaches_position_and_orientation() {
    let t = table();
    let w = run(&t, &preset("p000_fig3_funnel"), |_| {});
    let (mut dist, mut head) = (Vec::new(), Vec::new());
    for (i, a) in w.agents().iter().enumerate() {
        let g = a.goals[0].goal;
        let (d, e) = (
            a.state.pos.distance(g.pos),
            diff(g.beta, a.state.theta).abs(),
        );
        println!(
            "fig3 agent {i}: rest {d:.3} m, heading error {:.2}°",
            e.to_degrees()
        );
        assert!(
            a.done() && d < g.d_tol && e < g.eps_tol,
            "agent {i}: {d} m, {e} rad"
        );
        dist.push(d);
        head.push(e.to_degrees());
    }
    let (h0, h1) = min_max(&head);
    record_fig(
        "p000_fig3_funnelling_reaches_position_and_orientation",
        "000",
        "Fig. 3",
        "funnelling reaches the same targets with the prescribed orientations",
        "ours",
        Verdict::Reproduced,
        &[
            Figure::new(
                "p000.fig3.distance.max",
                "final distance to the target's centre, largest",
                min_max(&dist).1,
                "m",
                2,
            ),
            Figure::new(
                "p000.fig3.heading.min",
                "final heading error to β, smallest",
                h0,
                "°",
                1,
            ),
            Figure::new(
                "p000.fig3.heading.max",
                "final heading error to β, largest",
                h1,
                "°",
                1,
            ),
        ],
    );
}

#[test]
fn p000_fig6_pairs_meet_face_to_face() {
    let t = table();
    let w = run(&t, &preset("p000_fig6_face_to_face"), |_| {});
    let (mut gaps, mut facings) = (Vec::new(), Vec::new());
    for k in 0..w.agents().len() / 2 {
        let (a, b) = (&w.agents()[2 * k], &w.agents()[2 * k + 1]);
        let gap = a.state.pos.distance(b.state.pos);
        let facing = diff(a.state.theta + PI, b.state.theta).abs().to_degrees();
        let ab = b.state.pos - a.state.pos;
        let look = diff(ab.y.atan2(ab.x), a.state.theta).abs().to_degrees();
        println!("fig6 pair {k}: {gap:.2} m apart, headings {facing:.1}° from opposite, A looks {look:.1}° off B; done {} {}", a.done(), b.done());
        assert!(a.done() && b.done(), "pair {k} not done");
        assert!(
            gap < 2.0 * 1.2 && facing < 20.0,
            "pair {k}: {gap} m, {facing}°"
        );
        gaps.push(gap);
        facings.push(facing);
    }
    let (g0, g1) = min_max(&gaps);
    record_fig(
        "p000_fig6_pairs_meet_face_to_face",
        "000",
        "Fig. 6",
        "pairs attracted to each other's pose meet face to face",
        "ours",
        Verdict::Reproduced,
        &[
            Figure::new(
                "p000.fig6.pairs",
                "pairs, both done",
                gaps.len() as f64,
                "",
                0,
            ),
            Figure::new(
                "p000.fig6.gap.min",
                "final distance between the two of a pair, smallest",
                g0,
                "m",
                2,
            ),
            Figure::new(
                "p000.fig6.gap.max",
                "final distance between the two of a pair, largest",
                g1,
                "m",
                2,
            ),
            Figure::new(
                "p000.fig6.facing.max",
                "final headings' difference from opposite, largest",
                min_max(&facings).1,
                "°",
                1,
            ),
        ],
    );
}

/// Mean |μ| (the heading's offset from the seek direction, degrees) of
/// Fig. 7's runs per distance band to the current goal: D > 10 m, 4–10 m,
/// 1–4 m.
fn fig7_mu_by_distance(t: &EtaTable, sc: &Scenario) -> ([f32; 3], usize) {
    let mut bands: [Vec<f32>; 3] = Default::default();
    let w = run(t, sc, |w| {
        for a in w.agents().iter().filter(|a| !a.done()) {
            let i = a.internals;
            if matches!(i.mode, Mode::EndOfSteering | Mode::OrientationOnly) {
                continue;
            }
            let b = if i.d > 10.0 {
                0
            } else if i.d > 4.0 {
                1
            } else if i.d > 1.0 {
                2
            } else {
                continue;
            };
            bands[b].push(i.mu.abs().to_degrees());
        }
    });
    (
        [mean(&bands[0]), mean(&bands[1]), mean(&bands[2])],
        w.agents().iter().filter(|a| a.done()).count(),
    )
}

#[test]
fn p000_fig7_distant_targets_are_first_sought_then_funnelled() {
    // "for distant targets the behavior is first similar to a seek
    // trajectory prior to smoothly starting to enforce the final
    // orientation goal when arriving closer to the target". Fig. 7's goals
    // lie 3–16 m apart; the asymptotic seek at 20–90 m is
    // `tests/funnel.rs` (`distant`).
    let t = table();
    let sc = preset("p000_fig7_variety");
    let (ours, done) = fig7_mu_by_distance(&t, &sc);
    let mut lit = sc.clone();
    lit.funnel = steering::studies::envelope::literal_config();
    let (paper, done_lit) = fig7_mu_by_distance(&t, &lit);
    println!(
        "fig7: mean |μ| at D > 10 m / 4–10 m / 1–4 m: ours {:.1}° / {:.1}° / {:.1}° ({done}/8 finish); paper's literal bound {:.1}° / {:.1}° / {:.1}° ({done_lit}/8 finish)",
        ours[0], ours[1], ours[2], paper[0], paper[1], paper[2]
    );
    assert_eq!(done, sc.agents.len());
    // The literal reading is seek-like far away and funnels near; ours
    // modulates from the start (bound atan(8·R/D): 38° at 10 m).
    assert!(paper[0] < 0.5 * paper[2], "literal {paper:?}");
    assert!(ours[0] > 0.8 * ours[2], "ours {ours:?}");
    let mut figs = vec![Figure::new(
        "p000.fig7.finished",
        "agents finishing their three goals (ours)",
        done as f64,
        "of 8",
        0,
    )];
    for (reading, v) in [("ours", ours), ("literal", paper)] {
        for (band, x) in ["far", "mid", "near"].iter().zip(v) {
            let what = format!(
                "mean |μ| at D {} ({reading} bound)",
                match *band {
                    "far" => "> 10 m",
                    "mid" => "4–10 m",
                    _ => "1–4 m",
                }
            );
            figs.push(Figure::new(
                &format!("p000.fig7.{reading}.mu.{band}"),
                &what,
                f64::from(x),
                "°",
                1,
            ));
        }
    }
    record_fig(
        "p000_fig7_distant_targets_are_first_sought_then_funnelled",
        "000",
        "Fig. 7",
        "distant targets are first approached like a seek, the orientation enforced when closer (holds for the literal bound; ours modulates from the start)",
        "paper",
        Verdict::Reproduced,
        &figs,
    );
}

/// Per agent of Fig. 8: the three sections of its trace (turning to the
/// target, quasi straight, final curve) and the heading samples of each.
#[test]
fn p000_fig8_traces_show_three_sections() {
    let t = table();
    let sc = preset("p000_fig8_eighty");
    let n = sc.agents.len();
    // section 0: until |α| < 10° first; 2: D < 6 m; 1: between.
    let mut sec = vec![0usize; n];
    let mut headings: Vec<[Vec<f32>; 3]> = vec![Default::default(); n];
    let mut turn = vec![[0.0f32; 3]; n];
    let mut len = vec![[0.0f32; 3]; n];
    let mut prev: Vec<_> = Vec::new();
    run(&t, &sc, |w| {
        if prev.is_empty() {
            prev = w.agents().iter().map(|a| a.state).collect();
            return;
        }
        for (i, a) in w.agents().iter().enumerate() {
            if a.done() {
                continue;
            }
            let it = a.internals;
            if sec[i] == 0 && it.alpha.abs() < 10f32.to_radians() {
                sec[i] = 1;
            }
            if it.d < 6.0 {
                sec[i] = 2;
            }
            let s = sec[i];
            headings[i][s].push(a.state.theta);
            turn[i][s] += diff(a.state.theta, prev[i].theta).abs();
            len[i][s] += a.state.pos.distance(prev[i].pos);
            prev[i] = a.state;
        }
    });
    let mut disp = [Vec::new(), Vec::new(), Vec::new()];
    let mut kappa = [Vec::new(), Vec::new(), Vec::new()];
    let mut three = 0;
    for i in 0..n {
        if headings[i].iter().all(|h| h.len() > 5) {
            three += 1;
        }
        for s in 0..3 {
            if headings[i][s].len() > 5 && len[i][s] > 0.5 {
                disp[s].push(circ_std(&headings[i][s]).to_degrees());
                kappa[s].push(turn[i][s] / len[i][s]);
            }
        }
    }
    let d: Vec<f32> = disp.iter().map(|v| mean(v)).collect();
    let k: Vec<f32> = kappa.iter().map(|v| mean(v)).collect();
    println!("fig8: {three}/{n} traces have all three sections; heading dispersion within a section (circular std, mean over agents) turn {:.1}°, straight {:.1}°, final {:.1}°; mean |κ| {:.3} / {:.3} / {:.3} rad/m", d[0], d[1], d[2], k[0], k[1], k[2]);
    // The others start already facing their target (no turning section).
    assert!(three * 10 >= n * 6, "{three} of {n}");
    assert!(d[1] < 0.6 * d[0] && d[1] < 0.6 * d[2], "{d:?}");
    assert!(k[1] < 0.3 * k[0] && k[1] < 0.5 * k[2], "{k:?}");
    let mut figs = vec![
        Figure::new(
            "p000.fig8.three-sections",
            "traces showing all three sections",
            three as f64,
            "",
            0,
        ),
        Figure::new("p000.fig8.traces", "traces", n as f64, "", 0),
    ];
    for (s, name) in ["turn", "straight", "final"].iter().enumerate() {
        figs.push(Figure::new(
            &format!("p000.fig8.{name}.curvature"),
            &format!("mean |κ|, {name} section"),
            f64::from(k[s]),
            "rad/m",
            2,
        ));
        figs.push(Figure::new(
            &format!("p000.fig8.{name}.dispersion"),
            &format!("heading dispersion (circular std), {name} section"),
            f64::from(d[s]),
            "°",
            1,
        ));
    }
    record_fig(
        "p000_fig8_traces_show_three_sections",
        "000",
        "Fig. 8",
        "trace bundles show three sections: turn to the target, quasi straight, final curve",
        "ours",
        Verdict::Reproduced,
        &figs,
    );
}

// ---------------------------------------------------------------- paper 001

/// Mean |curvature| (rad/m) over the last `l` metres of each agent's path
/// before it first meets its position tolerance.
fn curvature_near_the_end(t: &EtaTable, sc: &Scenario, l: f32) -> Vec<f32> {
    let n = sc.agents.len();
    let mut paths: Vec<Vec<(Vec2, f32)>> = vec![Vec::new(); n];
    let mut met = vec![false; n];
    run(t, sc, |w| {
        for (i, a) in w.agents().iter().enumerate() {
            if !met[i] {
                paths[i].push((a.state.pos, a.state.theta));
                met[i] = a.memory.position_met || a.done();
            }
        }
    });
    assert!(met.iter().all(|&m| m), "every walker meets its disk");
    paths
        .iter()
        .map(|p| {
            let (mut s, mut turn) = (0.0f32, 0.0f32);
            for k in (1..p.len()).rev() {
                let ds = (p[k].0 - p[k - 1].0).length();
                if s + ds > l {
                    break;
                }
                s += ds;
                turn += diff(p[k].1, p[k - 1].1).abs();
            }
            turn / s.max(1e-3)
        })
        .collect()
}

/// Paper 001 Fig. 5 and §1: funnelling resembles measured human gait
/// [ALHB06] (not measurable here: no recordings), and "their local
/// curvature near the destination appears to be independent of the
/// distance for distances over 4 meters" [B05b]. Measured on the preset
/// (one start pose, bearings ±20° and ±45°, targets 4, 8, 12 m away) at
/// the preset's β (north) and at β 45° and 0°: the paper's literal reading
/// keeps the curvature of the last 1.5 m within 2× across 4–12 m in every
/// cell (agrees); ours lines up early and arrives nearly straight from
/// afar (refuted for ours: at 12 m under a quarter of its 4 m value).
#[test]
fn p001_fig5_curvature_near_the_destination_by_distance() {
    let t = table();
    let base = preset("p001_fig5_gait");
    let mut figs = Vec::new();
    for beta in [90.0f32, 45.0, 0.0] {
        let mut sc = base.clone();
        for a in &mut sc.agents {
            a.goals[0].beta_deg = beta;
        }
        let mut lit = sc.clone();
        lit.funnel = steering::studies::envelope::literal_config();
        let (ours, paper) = (
            curvature_near_the_end(&t, &sc, 1.5),
            curvature_near_the_end(&t, &lit, 1.5),
        );
        // Agents come in threes: one bearing, distances 4, 8, 12 m.
        for (cell, bearing) in [-45, -20, 20, 45].into_iter().enumerate() {
            let o = &ours[3 * cell..3 * cell + 3];
            let p = &paper[3 * cell..3 * cell + 3];
            println!(
                "fig5 β {beta}° bearing {bearing}°: mean |κ| over the last 1.5 m at 4 / 8 / 12 m: literal {:.3} / {:.3} / {:.3}, ours {:.3} / {:.3} / {:.3} rad/m",
                p[0], p[1], p[2], o[0], o[1], o[2]
            );
            let (lo, hi) = p
                .iter()
                .fold((f32::INFINITY, 0.0f32), |(l, h), &x| (l.min(x), h.max(x)));
            assert!(
                hi <= 2.0 * lo || hi - lo < 0.05,
                "literal β {beta} bearing {bearing}: {p:?}"
            );
            if o[0] > 0.05 {
                assert!(o[2] < 0.25 * o[0], "ours β {beta} bearing {bearing}: {o:?}");
            }
            // The preset's own β, bearings 20° and 45°, in the report.
            if beta == 90.0 && bearing > 0 {
                for (reading, v) in [("literal", p), ("ours", o)] {
                    for (d, x) in [4, 8, 12].iter().zip(v) {
                        figs.push(Figure::new(
                            &format!("p001.fig5.bearing{bearing}.{reading}.d{d}"),
                            &format!("mean |κ| over the last 1.5 m, target {d} m away at bearing {bearing}° ({reading})"),
                            f64::from(*x),
                            "rad/m",
                            2,
                        ));
                    }
                }
            }
        }
    }
    record_fig(
        "p001_fig5_curvature_near_the_destination_by_distance",
        "001",
        "Fig. 5, §1",
        "the curvature near the destination appears independent of the distance over 4 m (the literal reading within 2× at 4–12 m; ours arrives nearly straight from afar)",
        "paper",
        Verdict::Reproduced,
        &figs,
    );
}

/// (length, ∫|κ|) per agent over the whole run.
fn path_metrics(t: &EtaTable, sc: &Scenario) -> Vec<(f32, f32)> {
    run(t, sc, |_| {})
        .agents()
        .iter()
        .map(|a| (a.metrics.length, a.metrics.curvature))
        .collect()
}

fn compare(t: &EtaTable, base: &str) -> (f32, f32, f32, f32, usize, usize) {
    let s = path_metrics(t, &preset(&format!("{base}_standard")));
    let r = path_metrics(t, &paper_arc(preset(&format!("{base}_relaxed"))));
    let shorter = s.iter().zip(&r).filter(|(s, r)| r.0 < s.0).count();
    let straighter = s.iter().zip(&r).filter(|(s, r)| r.1 < s.1).count();
    let m = |v: &[(f32, f32)], k: usize| {
        mean(
            &v.iter()
                .map(|x| if k == 0 { x.0 } else { x.1 })
                .collect::<Vec<_>>(),
        )
    };
    (m(&s, 0), m(&r, 0), m(&s, 1), m(&r, 1), shorter, straighter)
}

/// [`compare`]'s result as figures `{prefix}.length.standard` … (`label`
/// says which preset in words).
fn compare_figures(
    prefix: &str,
    label: &str,
    c: (f32, f32, f32, f32, usize, usize),
) -> Vec<Figure> {
    let (ls, lr, ks, kr, sh, st) = c;
    let f = |q: &str, what: &str, v: f64, unit: &str, digits: u8| {
        Figure::new(
            &format!("{prefix}.{q}"),
            &format!("{label}: {what}"),
            v,
            unit,
            digits,
        )
    };
    vec![
        f(
            "length.standard",
            "mean path length, standard",
            f64::from(ls),
            "m",
            1,
        ),
        f(
            "length.relaxed",
            "mean path length, relaxed (paper arc)",
            f64::from(lr),
            "m",
            1,
        ),
        f(
            "curvature.standard",
            "mean ∫|κ|, standard",
            f64::from(ks),
            "rad",
            2,
        ),
        f(
            "curvature.relaxed",
            "mean ∫|κ|, relaxed (paper arc)",
            f64::from(kr),
            "rad",
            2,
        ),
        f(
            "shorter",
            "agents whose relaxed path is shorter",
            sh as f64,
            "of 9",
            0,
        ),
        f(
            "less-curved",
            "agents whose relaxed path is less curved",
            st as f64,
            "of 9",
            0,
        ),
    ]
}

#[test]
fn p001_fig10_relaxed_is_less_curved_and_shorter() {
    let t = table();
    let mut figs = Vec::new();
    for beta in [0, 45, 120] {
        let c = compare(&t, &format!("p001_fig10_beta{beta}"));
        let (ls, lr, ks, kr, sh, st) = c;
        println!("fig10 β {beta}°: length {ls:.1} → {lr:.1} m (shorter {sh}/9), ∫|κ| {ks:.2} → {kr:.2} rad (less curved {st}/9)");
        assert!(kr < ks && st >= 7, "β {beta}: ∫|κ| {ks} vs {kr}, {st}/9");
        assert!(lr < ls && sh >= 5, "β {beta}: length {ls} vs {lr}, {sh}/9");
        figs.extend(compare_figures(
            &format!("p001.fig10.beta{beta}"),
            &format!("β {beta}°"),
            c,
        ));
    }
    record_fig(
        "p001_fig10_relaxed_is_less_curved_and_shorter",
        "001",
        "Fig. 10",
        "relaxed funnelling gives less curved and frequently shorter paths than standard",
        "ours",
        Verdict::Reproduced,
        &figs,
    );
}

/// Where each agent first enters goal `k`'s disk (None if it never does).
fn entries(t: &EtaTable, sc: &Scenario) -> Vec<Vec<Option<Vec2>>> {
    let n = sc.agents.len();
    let k = sc.agents[0].goals.len();
    let mut e = vec![vec![None; k]; n];
    run(t, sc, |w| {
        for (i, a) in w.agents().iter().enumerate() {
            if a.current < k && e[i][a.current].is_none() {
                let g = a.goal_now;
                if a.state.pos.distance(g.pos) < g.d_tol {
                    e[i][a.current] = Some(a.state.pos);
                }
            }
        }
    });
    e
}

/// RMS distance of points from their centroid, m.
fn spread(p: &[Vec2]) -> f32 {
    let c = p.iter().copied().sum::<Vec2>() / p.len() as f32;
    (p.iter().map(|q| q.distance_squared(c)).sum::<f32>() / p.len() as f32).sqrt()
}

fn mean_pairwise(p: &[Vec2]) -> f32 {
    let mut s = Vec::new();
    for i in 0..p.len() {
        for j in i + 1..p.len() {
            s.push(p[i].distance(p[j]));
        }
    }
    mean(&s)
}

/// Every agent's trajectory, every step.
fn traces(t: &EtaTable, sc: &Scenario) -> Vec<Vec<Vec2>> {
    let mut out: Vec<Vec<Vec2>> = sc
        .agents
        .iter()
        .map(|a| vec![Vec2::new(a.x, a.y)])
        .collect();
    run(t, sc, |w| {
        for (i, a) in w.agents().iter().enumerate() {
            out[i].push(a.state.pos);
        }
    });
    out
}

#[test]
fn p001_fig11_relaxed_entry_points_spread_with_tolerance() {
    // Fig. 11: "a minor impact on the trajectories produced with the
    // standard funnelling (a) compared to the much wider spread of
    // trajectories achieved with the relaxed one (b)".
    // The paper's relaxed controller against the paper's standard one:
    // tests/fidelity_literal.rs.
    let t = table();
    let (mut rows, mut dist) = (Vec::new(), Vec::new());
    for tol in [5, 15, 30, 45] {
        let base = format!("p001_fig11_tol{tol}");
        let mut line = format!("fig11 ε_tol {tol}°:");
        for (label, sc) in [
            ("standard", preset(&format!("{base}_standard"))),
            (
                "relaxed paper arc",
                paper_arc(preset(&format!("{base}_relaxed"))),
            ),
        ] {
            let e = entries(&t, &sc);
            let pts: Vec<Vec2> = e.iter().filter_map(|x| x[0]).collect();
            let d = distance_to_middle_path(&traces(&t, &sc), 1.0, 40.0);
            dist.push((tol, label, (d[10] + d[20] + d[30]) / 3.0));
            line += &format!(
                " {label}: entry spread {:.2} m, {:.2?} m from the middle path at 10/20/30 m;",
                spread(&pts),
                [d[10], d[20], d[30]]
            );
            rows.push((tol, label, spread(&pts)));
        }
        println!("{line}");
    }
    // Refuted: neither the entry points nor the trajectories spread with
    // the tolerance (the paper arc's relaxed point with our funnel leads
    // every agent to one entry point whatever τ; mean distance from the
    // middle path at 10/20/30 m of travel 0.28 m at 5°, 0.26 m at 45°).
    // If this starts to fail, the claim may hold now: update the README row.
    let at = |v: &[(u32, &str, f32)], tol, label| {
        v.iter()
            .find(|r| r.0 == tol && r.1 == label)
            .map_or(f32::NAN, |r| r.2)
    };
    let label = "relaxed paper arc";
    assert!(at(&rows, 45, label) < 2.0 * at(&rows, 5, label), "{rows:?}");
    assert!(at(&dist, 45, label) < 1.2 * at(&dist, 5, label), "{dist:?}");
    assert!(at(&rows, 45, "standard") < 0.05, "{rows:?}");
    let key = |label: &str| {
        if label == "standard" {
            "standard"
        } else {
            "paper-arc"
        }
    };
    let mut figs: Vec<Figure> = rows
        .iter()
        .map(|(tol, label, v)| {
            Figure::new(
                &format!("p001.fig11.tol{tol}.{}.spread", key(label)),
                &format!("spread of the entry points, ε_tol {tol}°, {label}"),
                f64::from(*v),
                "m",
                2,
            )
        })
        .collect();
    figs.extend(dist.iter().map(|(tol, label, v)| {
        Figure::new(
            &format!("p001.fig11.tol{tol}.{}.middle-distance", key(label)),
            &format!(
                "mean distance from the middle path at 10/20/30 m of travel, ε_tol {tol}°, {label}"
            ),
            f64::from(*v),
            "m",
            2,
        )
    }));
    record_fig(
        "p001_fig11_relaxed_entry_points_spread_with_tolerance",
        "001",
        "Fig. 11",
        "a wider orientation tolerance spreads relaxed trajectories much wider; standard barely changes",
        "ours",
        Verdict::Refuted,
        &figs,
    );
}

#[test]
fn p001_fig12_successive_relaxed_goals_converge_to_one_path() {
    let t = table();
    let mut figs = Vec::new();
    for (label, sc) in [
        ("standard", preset("p001_fig12_successive_standard")),
        (
            "relaxed paper arc",
            paper_arc(preset("p001_fig12_successive_relaxed")),
        ),
    ] {
        let d = distance_to_middle_path(&traces(&t, &sc), 5.0, 60.0);
        let e = entries(&t, &sc);
        // Converged within 20 m of travel, and every goal entered by all.
        assert!(d[0] > 2.0 && d[4] < 0.1 && d[8] < 0.1, "{label}: {d:?}");
        assert!(e.iter().all(|x| x.iter().all(Option::is_some)), "{label}");
        let mut line = format!("fig12 {label}: mean distance from the middle agent's path every 5 m of travel {d:.2?}; pairwise at goal entries");
        for k in 0..e[0].len() {
            let p: Vec<Vec2> = e.iter().filter_map(|x| x[k]).collect();
            line += &format!(" {:.2} m ({}/9)", mean_pairwise(&p), p.len());
            assert!(mean_pairwise(&p) < 0.6, "{label}: goal {k}");
        }
        println!("{line}");
        let key = match label {
            "standard" => "standard",
            "relaxed paper arc" => "paper-arc",
            _ => "literal",
        };
        for (i, at) in [(0, 0), (2, 10), (3, 15)] {
            figs.push(Figure::new(
                &format!("p001.fig12.{key}.middle-distance.at{at}"),
                &format!(
                    "mean distance from the middle agent's path after {at} m of travel, {label}"
                ),
                f64::from(d[i]),
                "m",
                2,
            ));
        }
    }
    // "the longer and more curved path produced by the standard funnelling
    // compared to the more globally smoother and shorter one obtained with
    // the relaxed algorithm": the paper arc's relaxed point on our funnel
    // against our standard funnelling.
    let s = path_metrics(&t, &preset("p001_fig12_successive_standard"));
    let r = path_metrics(&t, &paper_arc(preset("p001_fig12_successive_relaxed")));
    let m = |v: &[(f32, f32)], k: usize| {
        mean(
            &v.iter()
                .map(|x| if k == 0 { x.0 } else { x.1 })
                .collect::<Vec<_>>(),
        )
    };
    let shorter = s.iter().zip(&r).filter(|(s, r)| r.0 < s.0).count();
    println!(
        "fig12 length {:.1} → {:.1} m ({shorter}/9 shorter), ∫|κ| {:.2} → {:.2} rad",
        m(&s, 0),
        m(&r, 0),
        m(&s, 1),
        m(&r, 1)
    );
    assert!(m(&r, 0) < 0.95 * m(&s, 0) && shorter >= 8, "{s:?} {r:?}");
    assert!(m(&r, 1) < m(&s, 1), "{s:?} {r:?}");
    figs.extend(compare_figures(
        "p001.fig12",
        "successive goals",
        compare(&t, "p001_fig12_successive"),
    ));
    record_fig(
        "p001_fig12_successive_relaxed_goals_converge_to_one_path",
        "001",
        "Fig. 12",
        "relaxed paths are smoother and shorter, and converge to one path whatever the start",
        "ours",
        Verdict::Reproduced,
        &figs,
    );
}

#[test]
fn p001_sec5_curvature_by_tolerance_band() {
    let t = table();
    let mut figs = Vec::new();
    for (base, band) in [
        ("p001_fig11_tol5", "5°"),
        ("p001_fig10_beta0", "10° β0"),
        ("p001_fig10_beta45", "10° β45"),
        ("p001_fig10_beta120", "10° β120"),
        ("p001_fig12_successive", "10° chain"),
        ("p001_fig11_tol15", "15°"),
        ("p001_fig11_tol30", "30°"),
        ("p001_fig11_tol45", "45°"),
    ] {
        let (ls, lr, ks, kr, sh, st) = compare(&t, base);
        println!("§5 {band}: ∫|κ| {ks:.2} → {kr:.2} rad ({st}/9 less curved), length {ls:.1} → {lr:.1} m ({sh}/9 shorter)");
        // Every band: less curved on average and for at least 8 of 9.
        assert!(kr < 0.95 * ks && st >= 8, "{band}: {ks} vs {kr}, {st}/9");
        let c = compare_figures(
            &format!(
                "p001.sec5.{}",
                base.trim_start_matches("p001_").replace('_', "-")
            ),
            &format!("ε_tol {band}"),
            (ls, lr, ks, kr, sh, st),
        );
        figs.extend(
            c.into_iter()
                .filter(|f| f.id.contains("curvature") || f.id.ends_with("less-curved")),
        );
    }
    record_fig(
        "p001_sec5_curvature_by_tolerance_band",
        "001",
        "§5",
        "relaxed funnelling gives less curved paths at every orientation tolerance",
        "ours",
        Verdict::Reproduced,
        &figs,
    );
}

#[test]
fn p001_fig6_a_better_point_of_the_disk_gives_a_smoother_path() {
    let t = table();
    let (b, c) = (preset("p001_fig6b_centre"), preset("p001_fig6c_relaxed"));
    let until_met = |sc: &Scenario| {
        let mut m = None;
        let w = run(&t, sc, |w| {
            let a = &w.agents()[0];
            if m.is_none() && a.memory.position_met {
                m = Some((a.metrics.length, a.metrics.curvature));
            }
        });
        (m, w.agents()[0].done())
    };
    let ((mb, db), (mc, dc)) = (until_met(&b), until_met(&c));
    let ((lb, kb), (lc, kc)) = (mb.unwrap(), mc.unwrap());
    println!("fig6: up to the disk, centre aim (6b) {lb:.1} m and ∫|κ| {kb:.2} rad; relaxed point (6c) {lc:.1} m and {kc:.2} rad");
    assert!(db && dc);
    assert!(kc < 0.95 * kb && lc < lb, "6b {mb:?} 6c {mc:?}");
    record_fig(
        "p001_fig6_a_better_point_of_the_disk_gives_a_smoother_path",
        "001",
        "Fig. 6",
        "aiming at the disk centre gives an artificially curved path; a better point of the disk a smoother one",
        "ours",
        Verdict::Reproduced,
        &[
            Figure::new("p001.fig6.centre.length", "path length up to the disk, centre aim (6b)", f64::from(lb), "m", 1),
            Figure::new("p001.fig6.centre.curvature", "∫|κ| up to the disk, centre aim (6b)", f64::from(kb), "rad", 2),
            Figure::new("p001.fig6.relaxed.length", "path length up to the disk, relaxed point (6c)", f64::from(lc), "m", 1),
            Figure::new("p001.fig6.relaxed.curvature", "∫|κ| up to the disk, relaxed point (6c)", f64::from(kc), "rad", 2),
        ],
    );
}

/// The relaxed direction's branch at every step of a preset's run where
/// the arc was searched: (branch, α_r, arc ends, Δη).
fn searched(t: &EtaTable, name: &str) -> Vec<(Fig7Branch, f32, f32, f32, f32)> {
    let mut out = Vec::new();
    run(t, &preset(name), |w| {
        let r = *w.relaxed_internals(0).unwrap();
        if !matches!(
            r.branch,
            Fig7Branch::None | Fig7Branch::Fallback | Fig7Branch::EntryPoint
        ) {
            out.push((r.branch, r.alpha_r, r.arc_min, r.arc_max, r.delta_eta));
        }
    });
    out
}

/// The relaxed internals at every step of a preset's run where the arc was
/// searched with Δη = 0.
fn searched_arcs(t: &EtaTable, name: &str) -> Vec<steering::funnelling::relaxed::RelaxedInternals> {
    let mut out = Vec::new();
    run(t, &preset(name), |w| {
        let r = *w.relaxed_internals(0).unwrap();
        if r.delta_eta == 0.0
            && !matches!(
                r.branch,
                Fig7Branch::None | Fig7Branch::Fallback | Fig7Branch::EntryPoint
            )
        {
            out.push(r);
        }
    });
    out
}

#[test]
fn p001_fig8_delta_eta_zero_takes_the_smallest_alpha_r() {
    // "The relaxed funnelling minimizes |Δη|, and |α_r| in case Δη is null."
    use Fig7Branch::*;
    let t = table();
    let s = searched(&t, "p001_fig8_zero_delta_eta_relaxed");
    let zero = s
        .iter()
        .filter(|x| {
            matches!(
                x.0,
                OppositeStraight | OppositeOverlap | SameStraight | SameOverlap
            )
        })
        .count();
    let inner = s
        .iter()
        .filter(|x| x.4 == 0.0 && x.1 > x.2 + 1e-4 && x.1 < x.3 - 1e-4)
        .count();
    println!("fig8: {} searched steps, {zero} with Δη = 0 (straight or overlap branch), {inner} of them with α_r strictly inside the arc; first α_r {:.1}° in [{:.1}°, {:.1}°]", s.len(), s[0].1.to_degrees(), s[0].2.to_degrees(), s[0].3.to_degrees());
    assert!(s.len() > 100 && zero == s.len(), "{zero} of {}", s.len());
    assert!(s.iter().all(|x| x.4 == 0.0));
    // α_r is the smallest |α| of the arc whose final direction F(α) =
    // α + η(α) lies in T, F read linearly between the arc ends as the
    // paper does: a brute-force search of 2,001 points of the arc finds no
    // smaller one (within one search step), and F(α_r) is in T.
    let arcs = searched_arcs(&t, "p001_fig8_zero_delta_eta_relaxed");
    let mut worst = 0.0f32;
    for r in &arcs {
        let f = |a: f32| r.f_min + (a - r.arc_min) / (r.arc_max - r.arc_min) * (r.f_max - r.f_min);
        let (c, h) = (0.5 * (r.t_min + r.t_max), 0.5 * (r.t_max - r.t_min));
        let in_t = |a: f32| diff(f(a), c).abs() <= h + 1e-4;
        let step = (r.arc_max - r.arc_min) / 2000.0;
        let best = (0..=2000)
            .map(|k| r.arc_min + step * k as f32)
            .filter(|&a| in_t(a))
            .map(f32::abs)
            .fold(f32::INFINITY, f32::min);
        assert!(in_t(r.alpha_r), "F(α_r) outside T: {r:?}");
        assert!(
            r.alpha_r.abs() <= best + step + 1e-5,
            "α_r {} but |α| {best} is valid: {r:?}",
            r.alpha_r
        );
        worst = worst.max(r.alpha_r.abs() - best);
    }
    println!("fig8: |α_r| minus the smallest valid |α| of a 2,001-point search, largest over {} steps: {:.5} rad", arcs.len(), worst);
    assert!(inner * 2 > s.len(), "{inner}");
    let deg = |x: f32| f64::from(x.to_degrees());
    record_fig(
        "p001_fig8_delta_eta_zero_takes_the_smallest_alpha_r",
        "001",
        "Fig. 8",
        "when some point of the arc gives Δη = 0, the one of smallest |α_r| is taken",
        "ours",
        Verdict::Reproduced,
        &[
            Figure::new(
                "p001.fig8.searched",
                "steps where the arc was searched",
                s.len() as f64,
                "",
                0,
            ),
            Figure::new(
                "p001.fig8.zero",
                "searched steps with Δη = 0",
                zero as f64,
                "",
                0,
            ),
            Figure::new(
                "p001.fig8.inner",
                "searched steps with α_r strictly inside the arc",
                inner as f64,
                "",
                0,
            ),
            Figure::new(
                "p001.fig8.first.alpha-r",
                "first searched step: α_r",
                deg(s[0].1),
                "°",
                1,
            ),
            Figure::new(
                "p001.fig8.first.arc-min",
                "first searched step: the arc's lower end",
                deg(s[0].2),
                "°",
                1,
            ),
            Figure::new(
                "p001.fig8.first.arc-max",
                "first searched step: the arc's upper end",
                deg(s[0].3),
                "°",
                1,
            ),
        ],
    );
}

#[test]
fn p001_fig9_no_zero_delta_eta_takes_an_arc_end() {
    // "no relaxed direction can produce a null Δη. In that case the
    // boundary of 𝒜 minimizing |Δη| is retained for α_r."
    use Fig7Branch::*;
    let t = table();
    let s = searched(&t, "p001_fig9_arc_end_relaxed");
    let gap = s
        .iter()
        .filter(|x| matches!(x.0, OppositeGap | SameGap))
        .count();
    let at_end = s
        .iter()
        .filter(|x| x.4 != 0.0 && (x.1 == x.2 || x.1 == x.3))
        .count();
    println!("fig9: {} searched steps, {gap} in a gap branch, {at_end} with Δη ≠ 0 and α_r at an arc end; first Δη {:.1}°", s.len(), s[0].4.to_degrees());
    assert!(
        s.len() > 100 && gap * 100 >= s.len() * 99,
        "{gap} of {}",
        s.len()
    );
    assert!(at_end * 100 >= s.len() * 99, "{at_end} of {}", s.len());
    record_fig(
        "p001_fig9_no_zero_delta_eta_takes_an_arc_end",
        "001",
        "Fig. 9",
        "when no point gives Δη = 0, the arc end of smallest |Δη| is taken",
        "ours",
        Verdict::Reproduced,
        &[
            Figure::new(
                "p001.fig9.searched",
                "steps where the arc was searched",
                s.len() as f64,
                "",
                0,
            ),
            Figure::new(
                "p001.fig9.gap",
                "searched steps in a gap branch",
                gap as f64,
                "",
                0,
            ),
            Figure::new(
                "p001.fig9.at-end",
                "searched steps with Δη ≠ 0 and α_r at an arc end",
                at_end as f64,
                "",
                0,
            ),
        ],
    );
}

// ---------------------------------------------------------------- paper 003

mod crowd {
    use glam::Vec2;
    use steering::crowd::boid_seek::Seek;
    use steering::crowd::config::{CrowdConfig, PaperTest};
    use steering::crowd::metrics::{CrowdMetrics, OffsetProfile};
    use steering::crowd::world::Crowd;

    use super::common::figures::{record_claim, Claim, Figure, Seeds, Verdict};

    fn short(test: PaperTest, seek: Seek) -> CrowdMetrics {
        let mut cfg = CrowdConfig::paper(test, seek);
        cfg.warmup_steps = 1500;
        cfg.measure_steps = 3000;
        Crowd::new(&cfg).unwrap().run_measured()
    }

    const VARIANTS: [(&str, Seek); 5] = [
        ("reynolds", Seek::Reynolds),
        ("parker100", Seek::Parker { fraction: 1.0 }),
        ("parker10", Seek::Parker { fraction: 0.1 }),
        ("parker1", Seek::Parker { fraction: 0.01 }),
        ("parker0_1", Seek::Parker { fraction: 0.001 }),
    ];

    fn record(
        test: &str,
        seeds: Seeds,
        place: &str,
        claim: &str,
        reading: &str,
        verdict: Verdict,
        figs: &[Figure],
    ) {
        record_claim(
            &format!("tests/fidelity.rs::crowd::{test}"),
            &format!("cargo test --release --features cli --test fidelity crowd::{test}"),
            &seeds,
            &Claim {
                paper: "003".into(),
                place: place.into(),
                claim: claim.into(),
                reading: reading.into(),
                verdict,
            },
            figs,
        );
    }

    /// Each boid's `(arc length, signed lateral offset)` at every step of
    /// `steps` steps of `c`.
    fn samples(c: &mut Crowd, steps: u32) -> Vec<Vec<(f32, f32)>> {
        let mut out = vec![Vec::with_capacity(steps as usize); c.len()];
        for _ in 0..steps {
            c.step();
            for (i, v) in out.iter_mut().enumerate() {
                let p = Vec2::new(c.positions()[2 * i], c.positions()[2 * i + 1]);
                let n = c.path().normal_point(p);
                v.push((n.s, c.path().lateral_offset(p, &n)));
            }
        }
        out
    }

    fn profile(c: &Crowd, s: &[(f32, f32)]) -> OffsetProfile {
        let mut p = OffsetProfile::new(c.path().length());
        for &(arc, off) in s {
            p.record(arc, off);
        }
        p
    }

    /// The preset's measurement window (steps 1,500–7,500) of every boid,
    /// as the profiles of its two halves: a boid's own two halves differ by
    /// its lap-to-lap variation, the yardstick for "the same path".
    fn halves(test: PaperTest, seek: Seek, seed: u64) -> Vec<(OffsetProfile, OffsetProfile)> {
        let mut cfg = CrowdConfig::paper(test, seek);
        cfg.seed = seed;
        let mut c = Crowd::new(&cfg).unwrap();
        c.run(1500);
        samples(&mut c, 6000)
            .iter()
            .map(|s| (profile(&c, &s[..3000]), profile(&c, &s[3000..])))
            .collect()
    }

    fn median(mut v: Vec<f32>) -> f32 {
        v.sort_by(f32::total_cmp);
        v[v.len() / 2]
    }

    /// Two paths are the same when their profiles (one boid's first half
    /// against the other's second) differ by less than twice the boids'
    /// median lap-to-lap variation (own first half against own second).
    const SAME: f32 = 2.0;

    #[test]
    fn p003_test_one_and_test_two_give_the_same_result() {
        // "Since test I and test II yields the exact same result only
        // illustrative data from test I is presented."
        //
        // Without separation the ten boids of Test II never act on each
        // other, so Test II *is* ten Test I runs from ten starts (asserted
        // bit for bit below): comparing the two tests' lap statistics only
        // compares spawn points. What can differ is the start: the claim
        // holds when the ideal path a lone boid settles on does not depend
        // on where it starts, i.e. when every Test II boid rides the path
        // of the Test I illustration (the preset, seed 1).
        let mut figs = Vec::new();
        let mut matched = Vec::new();
        for (tag, seek) in VARIANTS {
            // Ten lone boids started in Test II's ten spawn states.
            let mut two = Crowd::new(&CrowdConfig::paper(PaperTest::II, seek)).unwrap();
            let (pos, vel) = (two.positions().to_vec(), two.velocities().to_vec());
            let mut alone: Vec<Crowd> = (0..10)
                .map(|i| {
                    let mut c = Crowd::new(&CrowdConfig::paper(PaperTest::I, seek)).unwrap();
                    c.set_state(&pos[2 * i..2 * i + 2], &vel[2 * i..2 * i + 2], 0)
                        .unwrap();
                    c
                })
                .collect();
            for step in 0..1500 {
                two.step();
                for (i, c) in alone.iter_mut().enumerate() {
                    c.step();
                    let (a, b) = (&c.positions()[..2], &two.positions()[2 * i..2 * i + 2]);
                    assert!(
                        a[0].to_bits() == b[0].to_bits() && a[1].to_bits() == b[1].to_bits(),
                        "{tag}: boid {i} at step {step}: {a:?} alone vs {b:?} in Test II"
                    );
                }
            }
            // The Test I boid's path against each Test II boid's.
            let (one, two) = (
                halves(PaperTest::I, seek, 1),
                halves(PaperTest::II, seek, 2),
            );
            let noise = median(
                one.iter()
                    .chain(&two)
                    .map(|(a, b)| a.rms_difference(b).unwrap())
                    .collect(),
            );
            let same = two
                .iter()
                .filter(|(_, b)| one[0].0.rms_difference(b).unwrap() < SAME * noise)
                .count();
            println!("003 Test I vs II, {tag}: 10 of 10 boids move as alone, bit for bit; {same} of 10 ride the Test I boid's path (lap-to-lap variation {noise:.1})");
            figs.push(Figure::new(&format!("p003.test1_2.{tag}.same_path"), "Test II boids (seed 2) whose ideal path is the Test I boid's (seed 1): profiles within twice the lap-to-lap variation", same as f64, "of 10", 0));
            figs.push(Figure::new(&format!("p003.test1_2.{tag}.lap_to_lap"), "median lap-to-lap variation of a boid's ideal path (RMS difference of its mean offset per 1 % of the loop between the two halves of 6,000 steps)", f64::from(noise), "", 1));
            matched.push(same);
        }
        figs.push(Figure::new("p003.test1_2.bitwise", "Test II boids moving bit for bit as a lone boid from the same state (1,500 steps, five seeks)", 50.0, "of 50", 0));
        record(
            "p003_test_one_and_test_two_give_the_same_result",
            Seeds {
                tuning: vec![],
                report: vec![1, 2],
            },
            "Tests I & II (illus. 3–7)",
            "Test I and Test II give the exact same result",
            "paper",
            Verdict::Partly,
            &figs,
        );
        // Every boid of Reynolds, 100 %, 10 % and 1 % rides the lone boid's
        // path (at most one per seek strays out of the band)…
        assert!(matched[..4].iter().all(|&m| m >= 9), "{matched:?}");
        // …at 0.1 % most boids settle on another loop than the lone one.
        assert!(matched[4] <= 5, "{matched:?}");
    }

    #[test]
    fn p003_test_two_boids_converge_on_a_common_path() {
        // "all boids follows the same path pattern after an arbitrary
        // amount of time" (Test II). Same pattern: the share of pairs of
        // boids whose paths are the same (`SAME`). Convergence: the boids'
        // mean distance from their common path (all ten pooled, steps
        // 1,500–7,500) over the first 100 steps, against the same distance
        // over that window.
        let seeds = [2u64, 11, 12];
        let mut figs = Vec::new();
        let (mut pairs_share, mut ratio) = (Vec::new(), Vec::new());
        for (tag, seek) in VARIANTS {
            let (mut sh, mut ra) = (Vec::new(), Vec::new());
            for &seed in &seeds {
                let h = halves(PaperTest::II, seek, seed);
                let noise = median(
                    h.iter()
                        .map(|(a, b)| a.rms_difference(b).unwrap())
                        .collect(),
                );
                let (mut same, mut all) = (0, 0);
                for (i, (a, _)) in h.iter().enumerate() {
                    for (j, (_, b)) in h.iter().enumerate() {
                        if i != j {
                            all += 1;
                            same += usize::from(a.rms_difference(b).unwrap() < SAME * noise);
                        }
                    }
                }
                let mut cfg = CrowdConfig::paper(PaperTest::II, seek);
                cfg.seed = seed;
                let mut c = Crowd::new(&cfg).unwrap();
                let s = samples(&mut c, 7500);
                let pooled: Vec<(f32, f32)> =
                    s.iter().flat_map(|b| b[1500..].iter().copied()).collect();
                let common = profile(&c, &pooled).means();
                let st = |arc: f32| ((arc / c.path().length() * 100.0) as usize).min(99);
                let dist = |r: core::ops::Range<usize>| {
                    let d: Vec<f32> = s
                        .iter()
                        .flat_map(|b| b[r.clone()].iter())
                        .filter_map(|&(arc, off)| common[st(arc)].map(|m| (off - m).abs()))
                        .collect();
                    super::mean(&d)
                };
                let (early, late) = (dist(0..100), dist(1500..7500));
                println!("003 Test II {tag}, seed {seed}: {same} of {all} pairs on the same path; distance from the common path {early:.1} over the first 100 steps, {late:.1} over steps 1,500–7,500");
                sh.push(same as f32 / all as f32);
                ra.push(early / late);
            }
            figs.push(Figure::new(&format!("p003.test2.{tag}.same_pairs"), "Test II: share of pairs of boids on the same path (within twice the lap-to-lap variation), mean over seeds", f64::from(100.0 * super::mean(&sh)), "%", 0));
            figs.push(Figure::new(&format!("p003.test2.{tag}.early_over_late"), "Test II: distance from the common path over the first 100 steps over that after 1,500 steps, mean over seeds", f64::from(super::mean(&ra)), "×", 2));
            pairs_share.push(sh);
            ratio.push(ra);
        }
        record(
            "p003_test_two_boids_converge_on_a_common_path",
            Seeds {
                tuning: vec![2],
                report: seeds[1..].to_vec(),
            },
            "Test II",
            "all boids follow the same path pattern after an arbitrary amount of time",
            "paper",
            Verdict::Partly,
            &figs,
        );
        let min = |v: &[f32]| v.iter().copied().fold(f32::INFINITY, f32::min);
        let max = |v: &[f32]| v.iter().copied().fold(f32::NEG_INFINITY, f32::max);
        // The same pattern for Reynolds, 100 %, 10 % and 1 % on every seed
        // (three pairs in four or more on the same path)…
        assert!(
            pairs_share[..4].iter().all(|s| min(s) >= 0.75),
            "{pairs_share:?}"
        );
        // …no farther from it than at the start; a clear convergence at
        // 1 %, where the band is narrow…
        assert!(ratio[..4].iter().all(|r| min(r) >= 1.0), "{ratio:?}");
        assert!(min(&ratio[3]) > 2.5, "{ratio:?}");
        // …and at 0.1 % the boids keep different loops on every seed.
        assert!(max(&pairs_share[4]) < 0.75, "{pairs_share:?}");
    }

    #[test]
    fn p003_ten_percent_and_above_keep_the_crowd_on_the_path() {
        // Conclusion: "Test case four suggests that the steering must be at
        // least above 10%"; 0.1 % shows "irregular, unpredictable traversal
        // [...] the relatively overwhelmingly powerful separation velocity".
        // The presets' separation weight, 0.05 (ours; the text's rule is
        // weight 1, `tests/fidelity_crowd.rs` sweeps it). Test III alike.
        let weight = CrowdConfig::paper(PaperTest::IV, Seek::Reynolds).separation_weight;
        let mut figs = vec![Figure::new(
            "p003.test3_4.separation_weight",
            "separation weight of the presets (ours; the text's literal rule is 1)",
            f64::from(weight),
            "",
            2,
        )];
        let mut out = Vec::new();
        let mut force = Vec::new();
        for test in [PaperTest::III, PaperTest::IV] {
            for (tag, seek) in VARIANTS {
                let m = short(test, seek);
                let o = m.outside_share.unwrap();
                let f = m.mean_separation.unwrap() / m.mean_steer.unwrap();
                println!("003 {test:?} {tag}: {:.1} % of boid-steps outside the path; separation / steering {f:.2}", 100.0 * o);
                let t = test.number();
                figs.push(Figure::new(
                    &format!("p003.test{t}.preset.{tag}.outside"),
                    &format!(
                        "Test {test:?} preset (seed {t}): share of boid-steps outside the path"
                    ),
                    f64::from(100.0 * o),
                    "%",
                    1,
                ));
                figs.push(Figure::new(&format!("p003.test{t}.preset.{tag}.separation_over_steer"), &format!("Test {test:?} preset: mean separation over mean seek steering per boid-step"), f64::from(f), "×", 2));
                out.push(o);
                force.push(f);
            }
        }
        record(
            "p003_ten_percent_and_above_keep_the_crowd_on_the_path",
            Seeds::default(),
            "Test IV (illus. 13–17), conclusion",
            "the steering must be at least above 10 % (separation weight 0.05, ours); at 0.1 % separation overwhelms the steering",
            "ours",
            Verdict::Reproduced,
            &figs,
        );
        assert!((weight - 0.05).abs() < 1e-6, "{weight}");
        for (k, o) in out.iter().enumerate() {
            match k % 5 {
                0..=2 => assert!(*o < 0.01, "{k}: {out:?}"),
                3 => assert!(*o > 0.03, "{k}: {out:?}"),
                _ => assert!(*o > 0.5, "{k}: {out:?}"),
            }
        }
        // With 300 boids separation outweighs the 0.1 % seek's steering,
        // not the 100 %'s. (The ratio alone does not decide: Reynolds'
        // steering acts only on the steps its prediction leaves the path,
        // so its mean is small too, and it stays on the path.)
        assert!(
            force[9] > 2.0 && force[6] < 1.0 && force[1] < 1.0,
            "{force:?}"
        );
    }

    #[test]
    fn p003_weaker_parker_rides_along_the_outer_wall() {
        // "As the steering loosens we can observe that the boid covers more
        // space. [...] as the steering loosens the boid moves more and more
        // alongside the outer wall of the path" (Test I). Mean signed
        // offset, positive to the left of travel = the inside of the
        // counter-clockwise loop; the outer wall is at −24.
        let mut offs = Vec::new();
        let mut dist = Vec::new();
        let mut figs = Vec::new();
        for (tag, seek) in VARIANTS {
            let m = short(PaperTest::I, seek);
            let (o, d) = (m.mean_offset.unwrap(), m.mean_distance.unwrap());
            println!("003 Test I {tag}: mean signed offset {o:+.1} (outer wall −24), mean distance from centre line {d:.1}");
            figs.push(Figure::new(&format!("p003.test1.preset.{tag}.offset"), "Test I preset (seed 1): mean signed lateral offset (+ = inner side; the outer wall is at −24)", f64::from(o), "", 1));
            figs.push(Figure::new(
                &format!("p003.test1.preset.{tag}.distance"),
                "Test I preset: mean distance from the centre line",
                f64::from(d),
                "",
                1,
            ));
            offs.push(o);
            dist.push(d);
        }
        record(
            "p003_weaker_parker_rides_along_the_outer_wall",
            Seeds::default(),
            "Test I (illus. 4–7)",
            "as Parker's steering loosens the boid covers more space and rides more and more along the outer wall",
            "paper",
            Verdict::Reproduced,
            &figs,
        );
        // More space from 100 % down to 0.1 %…
        assert!(
            dist[1] < dist[2] && dist[2] < dist[3] && dist[3] < dist[4],
            "{dist:?}"
        );
        // …and at 1 % and 0.1 % along the outer wall, which Reynolds, 100 %
        // and 10 % keep away from.
        assert!(offs[..3].iter().all(|&o| o > -6.0), "{offs:?}");
        assert!(offs[3] < -12.0 && offs[4] < -12.0, "{offs:?}");
    }
}

// ---------------------------------------------------------------- paper 004

mod wander {
    use core::f32::consts::TAU;

    use steering::base::angle::diff;
    use steering::wander::{config::WanderConfig, pipeline::WanderPreset, pipeline::Wanderer};

    use super::common::figures::{record_claim, Claim, Figure, Seeds, Verdict};

    fn record(
        test: &str,
        seeds: Seeds,
        place: &str,
        claim: &str,
        reading: &str,
        verdict: Verdict,
        figs: &[Figure],
    ) {
        record_claim(
            &format!("tests/fidelity.rs::wander::{test}"),
            &format!("cargo test --release --features cli --test fidelity wander::{test}"),
            &seeds,
            &Claim {
                paper: "004".into(),
                place: place.into(),
                claim: claim.into(),
                reading: reading.into(),
                verdict,
            },
            figs,
        );
    }

    fn variant(file: &str, figure_or_label: &str) -> WanderConfig {
        let path = format!(
            "{}/scenarios/wander/{file}.json",
            env!("CARGO_MANIFEST_DIR")
        );
        let p = WanderPreset::from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
        p.variants
            .into_iter()
            .find(|v| {
                v.figure.as_deref() == Some(figure_or_label) || v.label.starts_with(figure_or_label)
            })
            .unwrap_or_else(|| panic!("{file}: no variant {figure_or_label}"))
            .config
    }

    /// Poses `[x, y, θ]` of `steps` steps.
    fn poses(cfg: &WanderConfig, steps: u32) -> Vec<[f32; 3]> {
        let mut w = Wanderer::new(cfg.clone()).unwrap();
        (0..steps)
            .map(|_| {
                w.step();
                w.pose()
            })
            .collect()
    }

    /// The turn of every step, radians.
    fn turns(p: &[[f32; 3]]) -> Vec<f32> {
        p.windows(2).map(|w| diff(w[1][2], w[0][2])).collect()
    }

    /// Radius of gyration of the positions, world units.
    fn gyration(p: &[[f32; 3]]) -> f32 {
        let n = p.len() as f32;
        let (cx, cy) = (
            p.iter().map(|q| q[0]).sum::<f32>() / n,
            p.iter().map(|q| q[1]).sum::<f32>() / n,
        );
        (p.iter()
            .map(|q| (q[0] - cx).powi(2) + (q[1] - cy).powi(2))
            .sum::<f32>()
            / n)
            .sqrt()
    }

    /// Full turns made within runs of same-signed turning: Σ ⌊|Σ Δθ| / 2π⌋.
    fn loops(p: &[[f32; 3]]) -> u32 {
        let (mut total, mut run, mut sign) = (0, 0.0f32, 0.0f32);
        for w in p.windows(2) {
            let d = diff(w[1][2], w[0][2]);
            if d.signum() != sign && d != 0.0 {
                total += (run.abs() / TAU) as u32;
                run = 0.0;
                sign = d.signum();
            }
            run += d;
        }
        total + (run.abs() / TAU) as u32
    }

    /// Full turns made while turning one way at `fast` or more per step:
    /// Σ over such runs of ⌊|Σ Δθ| / 2π⌋.
    fn fast_turns(d: &[f32], fast: f32) -> u32 {
        let (mut total, mut run) = (0, 0.0f32);
        for &x in d {
            if x.abs() >= fast && (run == 0.0 || x.signum() == run.signum()) {
                run += x;
            } else {
                total += (run.abs() / TAU) as u32;
                run = if x.abs() >= fast { x } else { 0.0 };
            }
        }
        total + (run.abs() / TAU) as u32
    }

    fn with(cfg: &WanderConfig, seed: u64, edit: impl Fn(&mut serde_json::Value)) -> WanderConfig {
        let mut v = serde_json::to_value(cfg).unwrap();
        v["seed"] = seed.into();
        edit(&mut v);
        serde_json::from_value(v).unwrap()
    }

    fn median(mut v: Vec<f32>) -> f32 {
        v.sort_by(f32::total_cmp);
        v[v.len() / 2]
    }

    /// What holds an agent that stays put: `trapped` when its last 1,000 of
    /// 3,000 steps keep within one field cell (radius of gyration < 60),
    /// and of those `circling` when it turns the same way by the same angle
    /// on 95 % of those steps or more — a turn pinned at the velocity
    /// clamp, which traps an agent wherever the field's sign holds it, as
    /// against a sink, where the field's flow itself brings it back.
    #[derive(Clone, Copy, Debug, Default, PartialEq)]
    struct Held {
        trapped: u32,
        circling: u32,
    }

    fn held(
        cfg: &WanderConfig,
        seeds: core::ops::RangeInclusive<u64>,
        edit: impl Fn(&mut serde_json::Value),
    ) -> Held {
        let mut h = Held::default();
        for seed in seeds {
            let p = poses(&with(cfg, seed, &edit), 3000);
            if gyration(&p[2000..]) >= 60.0 {
                continue;
            }
            h.trapped += 1;
            let d = turns(&p[2000..]);
            let pinned = d
                .windows(2)
                .filter(|w| w[1].abs() > 1e-3 && (w[1] - w[0]).abs() < 1e-4)
                .count();
            h.circling += u32::from(pinned as f32 >= 0.95 * (d.len() - 1) as f32);
        }
        h
    }

    /// The field presets of figures 122 (displacement), 123 (velocity),
    /// 126 (acceleration, 1° / 10°) and 124 (the sink: acceleration, 2° / 15°).
    const FIELDS: [(&str, &str); 4] = [
        ("screenshot122", "displacement"),
        ("screenshot123", "velocity"),
        ("screenshot126", "acceleration_1_10"),
        ("screenshot124", "acceleration_2_15"),
    ];

    #[test]
    fn p004_sec3_fields_trap_by_sinks_and_by_saturated_circling() {
        // "Random vector field can have sinks from which the agent cannot
        // escape. This is especially true when the acceleration is set from
        // a vector field." 20 seeds per preset (122–126, one field each).
        let mut figs = Vec::new();
        let mut h = Vec::new();
        for (fig, tag) in FIELDS {
            let x = held(&variant("fields", fig), 1..=20, |_| {});
            println!("004 §3 {fig} ({tag} from a field): trapped {} of 20, {} of them circling at a pinned turn", x.trapped, x.circling);
            figs.push(Figure::new(&format!("p004.sec3.{tag}.trapped"), &format!("{fig} ({tag} from one field): seeds whose last 1,000 of 3,000 steps stay within one field cell (radius of gyration < 60)"), f64::from(x.trapped), "of 20", 0));
            figs.push(Figure::new(&format!("p004.sec3.{tag}.circling"), &format!("{fig}: of those, turning the same way by the same angle on ≥ 95 % of the steps (saturated circling, not a sink)"), f64::from(x.circling), "of 20", 0));
            h.push(x);
        }
        record(
            "p004_sec3_fields_trap_by_sinks_and_by_saturated_circling",
            Seeds { tuning: vec![], report: (1..=20).collect() },
            "§3 (122–126)",
            "a random vector field can have sinks the agent cannot escape, especially when the acceleration is set from the field",
            "paper",
            Verdict::Partly,
            &figs,
        );
        // Displacement from a field: sinks, every seed (the heading follows
        // the flow into a point; nothing circles)…
        assert_eq!(
            h[0],
            Held {
                trapped: 20,
                circling: 0
            },
            "{h:?}"
        );
        // …velocity from a field: free…
        assert!(h[1].trapped <= 2, "{h:?}");
        // …acceleration from a field: trapped on every seed too, but every
        // one circling with its turn pinned at the velocity clamp: held by a
        // patch of one sign, not by a sink.
        assert!(
            h[2..].iter().all(|x| *x
                == Held {
                    trapped: 20,
                    circling: 20
                }),
            "{h:?}"
        );
    }

    #[test]
    fn p004_sec3_switching_fields_frees_only_sometimes() {
        // "One way of resolving this problem is to switch between two or
        // even three vector field at regular intervals." Every 100 steps,
        // 20 seeds: the sinks of displacement from a field (122), and the
        // circling of acceleration from a field at the sink preset's clamps
        // (124: 2° / 15°) and at low ones (1° / 5°).
        let cases = [
            ("screenshot122", "displacement", None),
            (
                "screenshot124",
                "acceleration_2_15",
                Some((2.0f32, 15.0f32)),
            ),
            ("screenshot124", "acceleration_1_5", Some((1.0, 5.0))),
        ];
        let mut figs = Vec::new();
        let mut t = Vec::new();
        for (fig, tag, clamps) in cases {
            let row = [1u32, 2, 3].map(|n| {
                held(&variant("fields", fig), 1..=20, |v| {
                    if let Some((acc, vel)) = clamps {
                        v["control"]["max_acceleration_deg"] = acc.into();
                        v["control"]["max_velocity_deg"] = vel.into();
                    }
                    v["source"]["field"]["count"] = n.into();
                    v["source"]["field"]["switch_every"] = 100.into();
                })
            });
            println!("004 §3 {tag} from a field, switching every 100 steps: trapped {} / {} / {} of 20 with 1 / 2 / 3 fields (circling {} / {} / {})", row[0].trapped, row[1].trapped, row[2].trapped, row[0].circling, row[1].circling, row[2].circling);
            for (n, h) in row.iter().enumerate() {
                figs.push(Figure::new(&format!("p004.sec3.switch.{tag}.fields{}.trapped", n + 1), &format!("{fig} ({tag}) with {} field(s) switched every 100 steps: seeds still trapped (radius of gyration < 60 over the last 1,000 of 3,000 steps)", n + 1), f64::from(h.trapped), "of 20", 0));
            }
            t.push(row.map(|h| h.trapped));
        }
        record(
            "p004_sec3_switching_fields_frees_only_sometimes",
            Seeds {
                tuning: vec![],
                report: (1..=20).collect(),
            },
            "§3 (122–126)",
            "switching between two or even three vector fields at regular intervals resolves sinks",
            "paper",
            Verdict::Partly,
            &figs,
        );
        // One field traps every seed; two free none of them…
        assert!(t.iter().all(|r| r[0] == 20 && r[1] >= 19), "{t:?}");
        // …three free some sinks and some of the circling at low clamps,
        // but at most half, and none at the sink preset's clamps.
        assert!(t[0][2] <= 17 && t[2][2] <= 15, "{t:?}");
        assert!(t[0][2] >= 10 && t[2][2] >= 8 && t[1][2] >= 18, "{t:?}");
    }

    #[test]
    fn p004_sec1_too_high_an_acceleration_clamp_spins() {
        // "If the acceleration is not clamped to a suitably low value, the
        // agent might go off on a spin for a long time" (figure 118:
        // acceleration 5°, velocity 30°). Velocity clamp 30°; 1,000 steps
        // per seed. A spin: full turns made while turning one way at half
        // the velocity clamp or more (the longest same-way turn, measured
        // before on seeds 1–20, peaks at 2° and cannot carry a margin).
        // Reported on seeds 21–40.
        let base = variant("control", "screenshot118");
        let clamps = [0.5f32, 1.0, 2.0, 5.0, 10.0, 30.0];
        let (mut at_clamp, mut spins) = (Vec::new(), Vec::new());
        let mut figs = Vec::new();
        for acc in clamps {
            let (mut fast, mut sat) = (Vec::new(), 0usize);
            for seed in 21..=40 {
                let c = with(&base, seed, |v| {
                    v["control"]["max_acceleration_deg"] = acc.into()
                });
                let d = turns(&poses(&c, 1000));
                fast.push(fast_turns(&d, 15f32.to_radians()) as f32);
                sat += d
                    .iter()
                    .filter(|x| x.abs() > 0.95 * 30f32.to_radians())
                    .count();
            }
            let share = sat as f32 / (20.0 * 999.0);
            let m = median(fast);
            println!("004 §1 velocity clamp 30°, acceleration clamp {acc}°: {:.1} % of steps turning at the velocity clamp; spins: median {m} full turns at ≥ 15° per step", 100.0 * share);
            let id = format!("{acc}").replace('.', "_");
            figs.push(Figure::new(&format!("p004.sec1.acc{id}.spin_turns"), &format!("velocity clamp 30°, acceleration clamp {acc}°: full turns made turning one way at ≥ 15° per step, per 1,000 steps, median of 20 seeds"), f64::from(m), "turns", 0));
            figs.push(Figure::new(&format!("p004.sec1.acc{id}.at_velocity_clamp"), &format!("velocity clamp 30°, acceleration clamp {acc}°: share of steps turning at the velocity clamp"), f64::from(100.0 * share), "%", 1));
            at_clamp.push(share);
            spins.push(m);
        }
        record(
            "p004_sec1_too_high_an_acceleration_clamp_spins",
            Seeds { tuning: (1..=20).collect(), report: (21..=40).collect() },
            "§1 (110–120, 118)",
            "if the acceleration is not clamped to a suitably low value the agent might go off on a spin for a long time",
            "paper",
            Verdict::Reproduced,
            &figs,
        );
        // A suitably low clamp (0.5°) never spins; 2°, 5° (figure 118) and
        // 10° spin for ten turns or more per 1,000 steps…
        assert!(spins[0] <= 1.0, "{spins:?}");
        assert!(spins[2..5].iter().all(|&s| s >= 10.0), "{spins:?}");
        // …and the time at the velocity clamp grows with the clamp. At 30°
        // the turn's sign flips too often to spin long (fewer turns than at
        // 5°): "for a long time" needs a clamp high, but not too high.
        assert!(at_clamp.windows(2).all(|w| w[1] > w[0]), "{at_clamp:?}");
        assert!(at_clamp[0] < 0.001 && at_clamp[4] > 0.1, "{at_clamp:?}");
        assert!(spins[5] < 0.5 * spins[3], "{spins:?}");
    }

    /// Scale-free shape of the turn signal Δθ: mean |Δ²θ| / mean |Δθ| (how
    /// abruptly the turn changes for the turning done: 0 for steady
    /// turning, 4/3 for independent uniform turns) and the lag-1
    /// autocorrelation of Δθ (−½ for a zigzag, 0 for independent turns,
    /// near 1 for a slowly varying turn). Neither is set by a clamp: the
    /// clamps only scale Δθ.
    fn shape(d: &[f32]) -> (f32, f32) {
        let m1 = d.iter().map(|x| x.abs()).sum::<f32>() / d.len() as f32;
        let m2 = d.windows(2).map(|w| (w[1] - w[0]).abs()).sum::<f32>() / (d.len() - 1) as f32;
        let mean = d.iter().sum::<f32>() / d.len() as f32;
        let var = d.iter().map(|x| (x - mean).powi(2)).sum::<f32>();
        let cov = d
            .windows(2)
            .map(|w| (w[0] - mean) * (w[1] - mean))
            .sum::<f32>();
        (m2 / m1, cov / var)
    }

    /// Net distance over 50 steps against the 50 steps' length, averaged:
    /// 1 when the agent keeps a direction, near 0 when it does not.
    fn straightness(p: &[[f32; 3]], speed: f32) -> f32 {
        let s: Vec<f32> = p
            .windows(51)
            .step_by(10)
            .map(|w| {
                ((w[50][0] - w[0][0]).powi(2) + (w[50][1] - w[0][1]).powi(2)).sqrt()
                    / (50.0 * speed)
            })
            .collect();
        s.iter().sum::<f32>() / s.len() as f32
    }

    #[test]
    fn p004_sec1_velocity_is_smoother_than_displacement_and_acceleration_smoother_still() {
        // "We can get a better impression of intent if we limit the angles
        // in a certain range" (101–105). "Changing the velocity results in
        // smoother behaviour. The smoothness depends on the maximum allowed
        // velocity. [...] Changing the acceleration is even smoother than
        // changing the velocity" (106–120). Seeds 1 (the presets) to 5,
        // 2,000 steps each; the shape of the turn signal, which no clamp
        // sets, beside its size (mean |Δθ|), which the clamp does.
        let rows: [(&str, &str); 15] = [
            ("screenshot101", "displacement 180°"),
            ("screenshot102", "displacement 10°"),
            ("screenshot103", "displacement 30°"),
            ("screenshot105", "displacement 90°"),
            ("screenshot106", "velocity 10°"),
            ("screenshot108", "velocity 40°"),
            ("screenshot109", "velocity 80°"),
            ("screenshot114", "acceleration 0.5°, velocity 5°"),
            ("screenshot115", "acceleration 1°, velocity 5°"),
            ("screenshot111", "acceleration 0.5°, velocity 10°"),
            ("screenshot110", "acceleration 1°, velocity 10°"),
            ("screenshot117", "acceleration 0.5°, velocity 15°"),
            ("screenshot120", "acceleration 1°, velocity 15°"),
            ("screenshot118", "acceleration 5°, velocity 30°"),
            ("unclamped", "acceleration unclamped (180°), velocity 10°"),
        ];
        let mut figs = Vec::new();
        let mut m = Vec::new();
        for (fig, what) in rows {
            let base = if fig == "unclamped" {
                with(&variant("control", "screenshot111"), 1, |v| {
                    v["control"]["max_acceleration_deg"] = 180.0.into()
                })
            } else {
                variant("control", fig)
            };
            let (mut r, mut rho, mut size, mut st) = (0.0, 0.0, 0.0, 0.0);
            for seed in 1..=5 {
                let p = poses(&with(&base, seed, |_| {}), 2000);
                let d = turns(&p);
                let (a, b) = shape(&d);
                r += a / 5.0;
                rho += b / 5.0;
                size += d.iter().map(|x| x.abs().to_degrees()).sum::<f32>() / d.len() as f32 / 5.0;
                st += straightness(&p, base.agent.speed) / 5.0;
            }
            println!("004 §1 {fig} {what}: mean |Δ²θ| / mean |Δθ| {r:.2}, lag-1 autocorrelation of Δθ {rho:+.2}, mean |Δθ| {size:.2}°, straightness over 50 steps {st:.2}");
            let id = fig.replace("screenshot", "s");
            figs.push(Figure::new(
                &format!("p004.sec1.{id}.roughness"),
                &format!("{what}: mean |Δ²θ| over mean |Δθ| (scale-free), 5 seeds × 2,000 steps"),
                f64::from(r),
                "",
                2,
            ));
            figs.push(Figure::new(
                &format!("p004.sec1.{id}.turn"),
                &format!("{what}: mean |Δθ| per step"),
                f64::from(size),
                "°",
                2,
            ));
            figs.push(Figure::new(
                &format!("p004.sec1.{id}.straightness"),
                &format!("{what}: net distance over 50 steps / their length"),
                f64::from(st),
                "",
                2,
            ));
            m.push((r, rho, size, st));
        }
        record(
            "p004_sec1_velocity_is_smoother_than_displacement_and_acceleration_smoother_still",
            Seeds { tuning: vec![], report: (1..=5).collect() },
            "§1 (101–120)",
            "limiting the displacement gives intent; changing the velocity is smoother, its smoothness depending on the maximum velocity; changing the acceleration is smoother still",
            "paper",
            Verdict::Partly,
            &figs,
        );
        let r = |k: usize| m[k].0;
        // Intent: the narrower the displacement limit, the straighter.
        assert!(
            m[1].3 > m[2].3 && m[2].3 > m[3].3 && m[3].3 > 2.0 * m[0].3,
            "{m:?}"
        );
        // Velocity smoother than limited displacement (a zigzag, ρ ≈ −½)…
        for v in 4..7 {
            for d in 1..4 {
                assert!(
                    r(v) < 0.85 * r(d) && m[v].1 > m[d].1 + 0.3,
                    "{v} vs {d}: {m:?}"
                );
            }
        }
        // …but not than unlimited displacement: a uniform random heading
        // has uniform independent changes, the same as a random velocity
        // of ±180°.
        assert!((r(0) - r(4)).abs() < 0.1, "{m:?}");
        // "Depends on the maximum velocity": only in size (mean |Δθ| = c/2
        // for a clamp c), not in shape.
        assert!(
            (r(5) - r(4)).abs() < 0.1 && (r(6) - r(4)).abs() < 0.1,
            "{m:?}"
        );
        assert!(
            (m[5].2 / m[4].2 - 4.0).abs() < 0.4 && (m[6].2 / m[4].2 - 8.0).abs() < 0.8,
            "{m:?}"
        );
        // Acceleration smoother still, at every clamped preset…
        for a in 7..14 {
            assert!(r(a) < 0.2 * r(4) && m[a].1 > 0.95, "{a}: {m:?}");
        }
        // …because of its clamp: unclamped, it is as abrupt as velocity.
        assert!(r(14) > 0.5 * r(4), "{m:?}");
    }

    #[test]
    fn p004_sec5_long_hold_intervals_give_loops() {
        // "The presence of many circular loops indicate long times of
        // constant velocity [...] when the intervals are too long in
        // relation to the max angular velocity." Velocity clamp 10°.
        let base = variant("timed", "screenshot141");
        let holds = [1u32, 5, 10, 20, 40, 80];
        let mut counts = Vec::new();
        let mut figs = Vec::new();
        for hold in holds {
            let lp: u32 = (1..=20)
                .map(|seed| {
                    let c = with(&base, seed, |v| {
                        v["hold"] = serde_json::json!({"kind": "fixed", "every": hold})
                    });
                    loops(&poses(&c, 1500))
                })
                .sum();
            println!("004 §5 velocity 10°, hold {hold} steps: {lp} loops in 20 × 1,500 steps");
            figs.push(Figure::new(&format!("p004.sec5.hold{hold}.loops"), &format!("velocity clamp 10°, each command held {hold} steps: full loops in 20 seeds × 1,500 steps"), f64::from(lp), "loops", 0));
            counts.push(lp);
        }
        record(
            "p004_sec5_long_hold_intervals_give_loops",
            Seeds { tuning: vec![], report: (1..=20).collect() },
            "§5 (140–152)",
            "many circular loops indicate long times of constant velocity: intervals too long for the maximum angular velocity",
            "paper",
            Verdict::Reproduced,
            &figs,
        );
        // No loops when the command changes every step; more loops the
        // longer it is held.
        assert!(counts[0] == 0 && counts[5] > 200, "{counts:?}");
        assert!(counts.windows(2).all(|w| w[1] > w[0]), "{counts:?}");
    }
}

// ------------------------------------------------ the table at the paper's size

mod paper_size_table {
    use steering::base::vehicle::VehicleParams;
    use steering::funnelling::config::FunnelConfig;
    use steering::funnelling::table::spec::{turn_radius, TableSpec};
    use steering::studies::reach::{summarise, ReachStudy};
    use steering::studies::vehicle::accuracy;

    /// Axis counts of a 43,200-entry table (paper 000 §3's size): 10
    /// distances, 36 radial angles (nominal 24: 15° in front, finer
    /// behind), 5 ω fractions, 4 current and 6 desired speeds. Also
    /// `eta-table --counts 10,24,5,4,6 --out FILE` (0.1 s; not committed).
    pub const PAPER_COUNTS: [usize; 5] = [10, 24, 5, 4, 6];

    #[test]
    fn a_table_of_the_papers_size_beside_ours() {
        let ours = super::table();
        let small = TableSpec::with_counts(VehicleParams::default(), PAPER_COUNTS)
            .generate()
            .unwrap();
        assert_eq!(small.len(), 43_200);
        let p = VehicleParams::default();
        let study = ReachStudy {
            n: 1000,
            seed: 19,
            ..ReachStudy::default()
        };
        let mut rows = Vec::new();
        // The same queries for both: uniform from our table's first ring.
        let d_min_radii = ours.distances()[0] / turn_radius(&p);
        for (name, t) in [("ours (362,880)", &ours), ("paper size (43,200)", &small)] {
            let a = accuracy(t, &p, 2000, 19, d_min_radii);
            let (med, p95, agree) = (a.median_deg, a.p95_deg, a.agreement);
            let s = summarise(&study.run_all(t, &p, &FunnelConfig::default()));
            println!(
                "η table {name}: {:.1} MB in memory cells; η error median {med:.2}°, p95 {p95:.2}° (2,000 uniform queries, seed 19), reachability agreement {:.1} %; reach study (1,000 runs, seed 19): reach {:.1} %, oriented on entry {:.1} %, entry error median {:.1}°",
                t.len() as f32 * 16.0 / 1e6,
                100.0 * agree,
                100.0 * s.reach_rate,
                100.0 * s.oriented_rate,
                s.entry_err_deg.0
            );
            rows.push((med, p95, s.oriented_rate, s.reach_rate));
        }
        // Ours is the more accurate and orients at least as many runs on
        // entry (near goals, both turn first where funnelling would not
        // enter oriented: steering::funnelling::short_range).
        assert!(rows[0].1 < rows[1].1 && rows[0].0 < rows[1].0, "{rows:?}");
        assert!(rows[0].2 >= rows[1].2 && rows[0].3 >= rows[1].3, "{rows:?}");
    }
}

#[test]
fn p004_sec6_response_curve_smooths_the_table() {
    // "We can smooth out the results by using a 2D response curve".
    use steering::base::rng::Rng;
    use steering::wander::response::ResponseCurve;
    let table = vec![
        vec![0.9, 0.07, 0.03],
        vec![0.15, 0.8, 0.05],
        vec![0.1, 0.2, 0.7],
    ];
    let edges: Vec<f32> = [0.0f32, 15.0, 30.0, 45.0]
        .iter()
        .map(|d| d.to_radians())
        .collect();
    let c = ResponseCurve::new(&edges, &table);
    let r = |deg: f32| deg.to_radians();
    let (below, above) = (c.cdf(r(14.9), r(15.0)), c.cdf(r(15.1), r(15.0)));
    let step = (table[0][0] - table[1][0]) as f32;
    println!("004 §6: P(next < 15°) at a current 14.9° / 15.1°: table {:.2} / {:.2} (jump {step:.2}), response curve {below:.3} / {above:.3} (jump {:.3})", table[0][0], table[1][0], (below - above).abs());
    // Draws follow the curve's distribution (20,000 draws at 20°).
    let mut rng = Rng::new(6);
    let draws: Vec<f32> = (0..20_000).map(|_| c.sample(r(20.0), &mut rng)).collect();
    let mut worst = 0.0f32;
    for x in [5.0f32, 10.0, 15.0, 22.5, 30.0, 40.0] {
        let emp = draws.iter().filter(|&&d| d < r(x)).count() as f32 / 20_000.0;
        worst = worst.max((emp - c.cdf(r(20.0), r(x))).abs());
    }
    use common::figures::{record_claim, Claim, Figure, Seeds, Verdict};
    let test = "p004_sec6_response_curve_smooths_the_table";
    record_claim(
        &format!("tests/fidelity.rs::{test}"),
        &format!("cargo test --release --features cli --test fidelity {test}"),
        &Seeds { tuning: vec![], report: vec![6] },
        &Claim {
            paper: "004".into(),
            place: "§6".into(),
            claim: "a 2D response curve smooths out the transition table".into(),
            reading: "ours".into(),
            verdict: Verdict::Reproduced,
        },
        &[
            Figure::new("p004.sec6.table.jump", "transition table: change of P(next < 15°) between a current angle of 14.9° and 15.1°", f64::from(step), "", 2),
            Figure::new("p004.sec6.curve.jump", "response curve: the same change", f64::from((below - above).abs()), "", 3),
            Figure::new("p004.sec6.curve.draws_vs_cdf", "response curve: largest gap between 20,000 draws at 20° and the curve's distribution, at 5–40°", f64::from(worst), "", 3),
        ],
    );
    assert!((below - above).abs() < 0.01 && step > 0.7);
    assert!(worst < 0.015, "{worst}");
    assert!(draws.iter().all(|d| (0.0..=r(45.0)).contains(d)));
}

#[test]
fn p001_fig3_eta_is_radial_at_low_speed_and_only_in_front_at_normal_speed() {
    // "In the first case [slow] the final tangential directions appear to
    // be oriented radially (Fig. 3b) whereas this is only the case for
    // sampled goals lying in front of the mobile entity for Fig. 3c."
    // ω = 0; mean |η| over targets 2–4 m away; and the share of targets
    // within 1.5 m unreachable at the desired speed (darker in Fig. 3c).
    let t = table();
    let mut rows = Vec::new();
    for (label, v) in [("slow 0.3 m/s", 0.3f32), ("normal 1.3 m/s", 1.3)] {
        let (mut front, mut back, mut near, mut unreach) = (Vec::new(), Vec::new(), 0, 0);
        for i in 0..72 {
            let a = -PI + TAU * (i as f32 + 0.5) / 72.0;
            for d in [2.0f32, 2.5, 3.0, 3.5, 4.0] {
                let e = t.lookup(d, a, 0.0, v, v).eta.abs().to_degrees();
                if a.abs() < FRAC_PI_2 {
                    front.push(e)
                } else {
                    back.push(e)
                }
            }
            for d in [0.6f32, 0.9, 1.2, 1.5] {
                near += 1;
                unreach += usize::from(!t.lookup(d, a, 0.0, v, v).reachable);
            }
        }
        let u = unreach as f32 / near as f32;
        println!("001 Fig. 3 {label}: mean |η| {:.1}° in front, {:.1}° behind (2–4 m); {:.0} % of targets within 1.5 m unreachable at that speed", mean(&front), mean(&back), 100.0 * u);
        rows.push((mean(&front), mean(&back), u));
    }
    let (slow, normal) = (rows[0], rows[1]);
    assert!(normal.1 > 2.0 * slow.1, "{rows:?}");
    assert!(normal.0 < 0.5 * normal.1, "{rows:?}");
    assert!(normal.2 > slow.2, "{rows:?}");
    let mut figs = Vec::new();
    for (key, label, r) in [("slow", "0.3 m/s", slow), ("normal", "1.3 m/s", normal)] {
        figs.push(Figure::new(
            &format!("p001.fig3.{key}.eta.front"),
            &format!("mean |η|, targets 2–4 m in front, {label}"),
            f64::from(r.0),
            "°",
            1,
        ));
        figs.push(Figure::new(
            &format!("p001.fig3.{key}.eta.behind"),
            &format!("mean |η|, targets 2–4 m behind, {label}"),
            f64::from(r.1),
            "°",
            1,
        ));
        figs.push(Figure::new(
            &format!("p001.fig3.{key}.unreachable"),
            &format!("targets within 1.5 m unreachable, {label}"),
            100.0 * f64::from(r.2),
            "%",
            0,
        ));
    }
    record_fig(
        "p001_fig3_eta_is_radial_at_low_speed_and_only_in_front_at_normal_speed",
        "001",
        "Fig. 3",
        "η is radial at low speed, and only for targets in front at normal speed",
        "ours",
        Verdict::Reproduced,
        &figs,
    );
}
