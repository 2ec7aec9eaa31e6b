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
use common::table;

fn preset(name: &str) -> Scenario {
    let path = format!("{}/scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scenario::from_json(&text).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Runs `sc` for its duration, calling `visit(world)` after every step.
fn run(t: &EtaTable, sc: &Scenario, mut visit: impl FnMut(&World)) -> World {
    let mut w = sc.world().expect("preset builds");
    let steps = (sc.duration / w.params.dt).round() as u32;
    for _ in 0..steps {
        w.step(t);
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
            .agents
            .iter()
            .filter(|a| matches!(a.internals.mode, Mode::Funnelling | Mode::OrientationOnly))
            .count();
    });
    for (i, a) in w.agents.iter().enumerate() {
        let g = a.goals[0].goal;
        let d = a.state.pos.distance(g.pos);
        println!(
            "fig1 seek agent {i}: rest {d:.3} m from the target, finished {:?}",
            a.finished_at
        );
        assert!(a.done() && d < g.d_tol, "agent {i}: {d} m");
    }
    assert_eq!(funnelled, 0, "plain seek funnelled");
    // The old reading (standard controller, ε_tol 180°) funnels the agent
    // whose target lies behind it towards β.
    let mut old = sc.clone();
    old.controller = ControllerKind::Standard;
    let mut old_funnel = 0;
    run(&t, &old, |w| {
        old_funnel += usize::from(w.agents[2].internals.mode == Mode::Funnelling);
    });
    println!(
        "fig1 under the standard controller with ε_tol 180°: agent 2 funnels {old_funnel} steps"
    );
    assert!(old_funnel > 0);
}

#[test]
fn p000_fig3_funnelling_reaches_position_and_orientation() {
    let t = table();
    let w = run(&t, &preset("p000_fig3_funnel"), |_| {});
    for (i, a) in w.agents.iter().enumerate() {
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
    }
}

#[test]
fn p000_fig6_pairs_meet_face_to_face() {
    let t = table();
    let w = run(&t, &preset("p000_fig6_face_to_face"), |_| {});
    for k in 0..w.agents.len() / 2 {
        let (a, b) = (&w.agents[2 * k], &w.agents[2 * k + 1]);
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
    }
}

/// Mean |μ| (the heading's offset from the seek direction, degrees) of
/// Fig. 7's runs per distance band to the current goal: D > 10 m, 4–10 m,
/// 1–4 m.
fn fig7_mu_by_distance(t: &EtaTable, sc: &Scenario) -> ([f32; 3], usize) {
    let mut bands: [Vec<f32>; 3] = Default::default();
    let w = run(t, sc, |w| {
        for a in w.agents.iter().filter(|a| !a.done()) {
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
        w.agents.iter().filter(|a| a.done()).count(),
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
            prev = w.agents.iter().map(|a| a.state).collect();
            return;
        }
        for (i, a) in w.agents.iter().enumerate() {
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
}

// ---------------------------------------------------------------- paper 001

/// Mean |curvature| (rad/m) over the last `l` metres of each agent's path
/// before it first meets its position tolerance.
fn curvature_near_the_end(t: &EtaTable, sc: &Scenario, l: f32) -> Vec<f32> {
    let n = sc.agents.len();
    let mut paths: Vec<Vec<(Vec2, f32)>> = vec![Vec::new(); n];
    let mut met = vec![false; n];
    run(t, sc, |w| {
        for (i, a) in w.agents.iter().enumerate() {
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
        }
    }
}

/// (length, ∫|κ|) per agent over the whole run.
fn path_metrics(t: &EtaTable, sc: &Scenario) -> Vec<(f32, f32)> {
    run(t, sc, |_| {})
        .agents
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

#[test]
fn p001_fig10_relaxed_is_less_curved_and_shorter() {
    let t = table();
    for beta in [0, 45, 120] {
        let (ls, lr, ks, kr, sh, st) = compare(&t, &format!("p001_fig10_beta{beta}"));
        println!("fig10 β {beta}°: length {ls:.1} → {lr:.1} m (shorter {sh}/9), ∫|κ| {ks:.2} → {kr:.2} rad (less curved {st}/9)");
        assert!(kr < ks && st >= 7, "β {beta}: ∫|κ| {ks} vs {kr}, {st}/9");
        assert!(lr < ls && sh >= 5, "β {beta}: length {ls} vs {lr}, {sh}/9");
    }
}

/// Where each agent first enters goal `k`'s disk (None if it never does).
fn entries(t: &EtaTable, sc: &Scenario) -> Vec<Vec<Option<Vec2>>> {
    let n = sc.agents.len();
    let k = sc.agents[0].goals.len();
    let mut e = vec![vec![None; k]; n];
    run(t, sc, |w| {
        for (i, a) in w.agents.iter().enumerate() {
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
        for (i, a) in w.agents.iter().enumerate() {
            out[i].push(a.state.pos);
        }
    });
    out
}

/// Distance of each agent's trace, sampled every `step` metres of travel
/// up to `until` m, from the nearest point of the middle agent's trace:
/// mean over the agents at each sample.
fn distance_to_middle_path(tr: &[Vec<Vec2>], step: f32, until: f32) -> Vec<f32> {
    let mid = &tr[tr.len() / 2];
    let n = (until / step) as usize;
    let mut sums = vec![Vec::new(); n + 1];
    for (i, t) in tr.iter().enumerate() {
        if i == tr.len() / 2 {
            continue;
        }
        let mut s = 0.0;
        let mut k = 0;
        for w in t.windows(2) {
            s += w[0].distance(w[1]);
            while k <= n && s >= step * k as f32 {
                let d = mid
                    .iter()
                    .map(|m| m.distance(w[1]))
                    .fold(f32::INFINITY, f32::min);
                sums[k].push(d);
                k += 1;
            }
        }
    }
    sums.iter().map(|v| mean(v)).collect()
}

/// The paper's full literal reading of relaxed funnelling (gain 1, literal
/// bound, centre aim; relaxed point on the arc, T searched over 0.8 τ).
fn literal_relaxed(mut sc: Scenario) -> Scenario {
    sc.controller = ControllerKind::Relaxed;
    sc.funnel = steering::studies::envelope::literal_config();
    sc.relaxed = steering::studies::envelope::literal_relaxed_config();
    sc
}

#[test]
fn p001_fig11_relaxed_entry_points_spread_with_tolerance() {
    // Fig. 11: "a minor impact on the trajectories produced with the
    // standard funnelling (a) compared to the much wider spread of
    // trajectories achieved with the relaxed one (b)".
    let t = table();
    let mut rows = Vec::new();
    for tol in [5, 15, 30, 45] {
        let base = format!("p001_fig11_tol{tol}");
        let mut line = format!("fig11 ε_tol {tol}°:");
        for (label, sc) in [
            ("standard", preset(&format!("{base}_standard"))),
            (
                "relaxed paper arc",
                paper_arc(preset(&format!("{base}_relaxed"))),
            ),
            (
                "relaxed literal",
                literal_relaxed(preset(&format!("{base}_relaxed"))),
            ),
        ] {
            let e = entries(&t, &sc);
            let pts: Vec<Vec2> = e.iter().filter_map(|x| x[0]).collect();
            let d = distance_to_middle_path(&traces(&t, &sc), 1.0, 40.0);
            line += &format!(
                " {label}: entry spread {:.2} m, {:.2?} m from the middle path at 10/20/30 m;",
                spread(&pts),
                [d[10], d[20], d[30]]
            );
            rows.push((tol, label, spread(&pts)));
        }
        println!("{line}");
    }
    // Refuted: the spread does not widen with the tolerance (the paper
    // arc's relaxed point funnels every agent to one entry point whatever
    // τ; the literal reading widens 0.20 → 0.24 m). If this starts to
    // fail, the claim may hold now: update the README row.
    let at = |tol, label| {
        rows.iter()
            .find(|r| r.0 == tol && r.1 == label)
            .map_or(f32::NAN, |r| r.2)
    };
    for label in ["relaxed paper arc", "relaxed literal"] {
        assert!(at(45, label) < 2.0 * at(5, label), "{label}: {rows:?}");
    }
    assert!(at(45, "standard") < 0.05, "{rows:?}");
}

#[test]
fn p001_fig12_successive_relaxed_goals_converge_to_one_path() {
    let t = table();
    for (label, sc) in [
        ("standard", preset("p001_fig12_successive_standard")),
        (
            "relaxed paper arc",
            paper_arc(preset("p001_fig12_successive_relaxed")),
        ),
        (
            "relaxed literal",
            literal_relaxed(preset("p001_fig12_successive_relaxed")),
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
    }
}

#[test]
fn p001_sec5_curvature_by_tolerance_band() {
    let t = table();
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
    }
}

#[test]
fn p001_fig6_a_better_point_of_the_disk_gives_a_smoother_path() {
    let t = table();
    let (b, c) = (preset("p001_fig6b_centre"), preset("p001_fig6c_relaxed"));
    let until_met = |sc: &Scenario| {
        let mut m = None;
        let w = run(&t, sc, |w| {
            let a = &w.agents[0];
            if m.is_none() && a.memory.position_met {
                m = Some((a.metrics.length, a.metrics.curvature));
            }
        });
        (m, w.agents[0].done())
    };
    let ((mb, db), (mc, dc)) = (until_met(&b), until_met(&c));
    let ((lb, kb), (lc, kc)) = (mb.unwrap(), mc.unwrap());
    println!("fig6: up to the disk, centre aim (6b) {lb:.1} m and ∫|κ| {kb:.2} rad; relaxed point (6c) {lc:.1} m and {kc:.2} rad");
    assert!(db && dc);
    assert!(kc < 0.95 * kb && lc < lb, "6b {mb:?} 6c {mc:?}");
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
    assert!(s
        .iter()
        .all(|x| x.4 == 0.0 && x.1.abs() <= x.2.abs().max(x.3.abs())));
    assert!(inner * 2 > s.len(), "{inner}");
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
}

// ---------------------------------------------------------------- paper 003

mod crowd {
    use steering::crowd::boid_seek::Seek;
    use steering::crowd::config::{CrowdConfig, PaperTest};
    use steering::crowd::metrics::CrowdMetrics;
    use steering::crowd::world::Crowd;

    fn short(test: PaperTest, seek: Seek) -> CrowdMetrics {
        let mut cfg = CrowdConfig::paper(test, seek);
        cfg.warmup_steps = 1500;
        cfg.measure_steps = 3000;
        Crowd::new(&cfg).unwrap().run_measured()
    }

    const VARIANTS: [(&str, Seek); 5] = [
        ("Reynolds", Seek::Reynolds),
        ("Parker 100 %", Seek::Parker { fraction: 1.0 }),
        ("Parker 10 %", Seek::Parker { fraction: 0.1 }),
        ("Parker 1 %", Seek::Parker { fraction: 0.01 }),
        ("Parker 0.1 %", Seek::Parker { fraction: 0.001 }),
    ];

    #[test]
    fn p003_test_one_and_test_two_give_the_same_result() {
        // "Since test I and test II yields the exact same result only
        // illustrative data from test I is presented."
        for (label, seek) in VARIANTS {
            let (a, b) = (short(PaperTest::I, seek), short(PaperTest::II, seek));
            let (la, lb) = (a.mean_lap_steps.unwrap(), b.mean_lap_steps.unwrap());
            let (pa, pb) = (a.p95_distance.unwrap(), b.p95_distance.unwrap());
            let (oa, ob) = (a.outside_share.unwrap(), b.outside_share.unwrap());
            println!("003 Test I vs II, {label}: lap {la:.0} / {lb:.0} steps, p95 distance {pa:.1} / {pb:.1}, outside {:.1} / {:.1} %", 100.0 * oa, 100.0 * ob);
            assert!((la / lb - 1.0).abs() < 0.03, "{label}: laps {la} {lb}");
            assert!((pa / pb - 1.0).abs() < 0.05, "{label}: p95 {pa} {pb}");
            assert!((oa - ob).abs() < 0.02, "{label}: outside {oa} {ob}");
        }
    }

    #[test]
    fn p003_test_two_boids_converge_on_a_common_path() {
        // "all boids follows the same path pattern after an arbitrary
        // amount of time" (Test II). Trace spread: the standard deviation
        // of the boids' lateral offsets per path stretch (path radius 24).
        for (label, seek) in VARIANTS {
            let mut cfg = CrowdConfig::paper(PaperTest::II, seek);
            cfg.warmup_steps = 0;
            cfg.measure_steps = 700;
            let early = Crowd::new(&cfg)
                .unwrap()
                .run_measured()
                .trace_spread
                .unwrap();
            let late = short(PaperTest::II, seek).trace_spread.unwrap();
            let alone = short(PaperTest::I, seek).trace_spread.unwrap();
            println!("003 Test II {label}: trace spread first lap {early:.1}, after 1,500 steps {late:.1} (one boid lap to lap: {alone:.1})");
            if seek != (Seek::Parker { fraction: 0.001 }) {
                assert!(
                    late < 0.5 * 24.0 && late < 2.0 * alone.max(2.0),
                    "{label}: {late} vs alone {alone}"
                );
            } else {
                // Refuted for the weakest seek: ten boids keep ten paths.
                assert!(late > 2.0 * alone, "{label}: {late} vs {alone}");
            }
        }
    }

    #[test]
    fn p003_ten_percent_and_above_keep_the_crowd_on_the_path() {
        // Conclusion: "the steering must be at least above 10%" (Test IV,
        // separation on); Test III alike.
        for test in [PaperTest::III, PaperTest::IV] {
            for (label, seek) in VARIANTS {
                let out = short(test, seek).outside_share.unwrap();
                println!(
                    "003 {test:?} {label}: {:.1} % of boid-steps outside the path",
                    100.0 * out
                );
                match seek {
                    Seek::Parker { fraction } if fraction < 0.1 => {
                        assert!(out > 0.03, "{label}: {out}")
                    }
                    _ => assert!(out < 0.01, "{test:?} {label}: {out}"),
                }
            }
        }
    }

    #[test]
    fn p003_weaker_parker_rides_along_the_outer_wall() {
        // "as the steering loosens the boid moves more and more alongside
        // the outer wall of the path" (Test I). Mean signed offset,
        // positive to the left of travel = the inside of the
        // counter-clockwise loop; the outer wall is at −24.
        let mut offs = Vec::new();
        for (label, seek) in VARIANTS {
            let m = short(PaperTest::I, seek);
            let o = m.mean_offset.unwrap();
            println!("003 Test I {label}: mean signed offset {o:+.1} (outer wall −24), mean distance from centre line {:.1}", m.mean_distance.unwrap());
            offs.push(o);
        }
        assert!(
            offs[0] > -6.0 && offs[1] > -6.0 && offs[2] > -6.0,
            "{offs:?}"
        );
        assert!(offs[3] < -12.0 && offs[4] < -12.0, "{offs:?}");
    }
}

// ---------------------------------------------------------------- paper 004

mod wander {
    use core::f32::consts::TAU;

    use steering::base::angle::diff;
    use steering::wander::{config::WanderConfig, pipeline::WanderPreset, pipeline::Wanderer};

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

    /// The longest run of same-signed turning, in turns.
    fn longest_spin(p: &[[f32; 3]]) -> f32 {
        let (mut best, mut run, mut sign) = (0.0f32, 0.0f32, 0.0f32);
        for w in p.windows(2) {
            let d = diff(w[1][2], w[0][2]);
            if d.signum() != sign && d != 0.0 {
                run = 0.0;
                sign = d.signum();
            }
            run += d;
            best = best.max(run.abs());
        }
        best / TAU
    }

    fn with(cfg: &WanderConfig, seed: u64, edit: impl Fn(&mut serde_json::Value)) -> WanderConfig {
        let mut v = serde_json::to_value(cfg).unwrap();
        v["seed"] = seed.into();
        edit(&mut v);
        serde_json::from_value(v).unwrap()
    }

    /// Seeds (of 20) whose agent ends trapped: the last 1,000 of 3,000
    /// steps stay within one field cell (radius of gyration < 60).
    fn trapped(cfg: &WanderConfig, acc: f32, vel: f32, fields: u32) -> u32 {
        (1..=20)
            .filter(|&seed| {
                let c = with(cfg, seed, |v| {
                    v["control"]["max_acceleration_deg"] = acc.into();
                    v["control"]["max_velocity_deg"] = vel.into();
                    v["source"]["field"]["count"] = fields.into();
                    v["source"]["field"]["switch_every"] = 100.into();
                });
                gyration(&poses(&c, 3000)[2000..]) < 60.0
            })
            .count() as u32
    }

    #[test]
    fn p004_sec3_a_sink_traps_and_switching_fields_frees_only_sometimes() {
        // "Random vector field can have sinks from which the agent cannot
        // escape [...] especially when the acceleration is set from a
        // vector field. One way of resolving this problem is to switch
        // between two or even three vector field at regular intervals."
        let sink = variant("fields", "screenshot124");
        let p = poses(&sink, 3000);
        let g = gyration(&p[2000..]);
        let mut rows = Vec::new();
        for (acc, vel) in [(2.0, 15.0), (1.0, 5.0)] {
            let t = [1, 2, 3].map(|n| trapped(&sink, acc, vel, n));
            println!("004 §3 acceleration from a field, clamps {acc}° / {vel}°: trapped in {} / {} / {} of 20 seeds with 1 / 2 / 3 fields (switching every 100 steps)", t[0], t[1], t[2]);
            rows.push(t);
        }
        println!("004 §3 the sink preset (seed 3): gyration {g:.1} over the last 1,000 steps");
        assert!(g < 60.0);
        // A sink traps: every seed at both clamp settings.
        assert!(rows.iter().all(|t| t[0] == 20), "{rows:?}");
        // Switching frees nobody at the preset's clamps (2°, 15°: refuted)…
        assert!(rows[0][1] >= 18 && rows[0][2] >= 18, "{rows:?}");
        // …and some with three fields at low clamps (1°, 5°).
        assert!(rows[1][2] <= 15, "{rows:?}");
    }

    #[test]
    fn p004_sec1_too_high_an_acceleration_clamp_spins() {
        // "If the acceleration is not clamped to a suitably low value, the
        // agent might go off on a spin for a long time" (figure 118).
        // Velocity clamp 30°; 20 seeds × 1,000 steps per acceleration clamp.
        let base = variant("control", "screenshot118");
        let mut at_clamp = Vec::new();
        let mut spin = Vec::new();
        for acc in [0.5f32, 1.0, 2.0, 5.0, 10.0] {
            let (mut spins, mut sat) = (Vec::new(), 0usize);
            for seed in 1..=20 {
                let c = with(&base, seed, |v| {
                    v["control"]["max_acceleration_deg"] = acc.into()
                });
                let p = poses(&c, 1000);
                spins.push(longest_spin(&p));
                sat += p
                    .windows(2)
                    .filter(|w| diff(w[1][2], w[0][2]).abs() > 0.95 * 30f32.to_radians())
                    .count();
            }
            spins.sort_by(f32::total_cmp);
            let share = sat as f32 / 20_000.0;
            println!("004 §1 velocity clamp 30°, acceleration clamp {acc}°: {:.1} % of steps spinning at the velocity clamp; longest same-way turn median {:.1} turns", 100.0 * share, spins[10]);
            at_clamp.push(share);
            spin.push(spins[10]);
        }
        assert!(at_clamp.windows(2).all(|w| w[1] > w[0]), "{at_clamp:?}");
        assert!(at_clamp[0] < 0.001 && at_clamp[4] > 0.1, "{at_clamp:?}");
        assert!(spin[2] > 2.0 * spin[0], "{spin:?}");
    }

    /// Mean |Δ²θ| per step, degrees: how abruptly the turn rate changes.
    fn roughness(p: &[[f32; 3]]) -> f32 {
        let d: Vec<f32> = p.windows(2).map(|w| diff(w[1][2], w[0][2])).collect();
        d.windows(2)
            .map(|w| (w[1] - w[0]).abs().to_degrees())
            .sum::<f32>()
            / (d.len() - 1) as f32
    }

    #[test]
    fn p004_sec1_velocity_is_smoother_than_displacement_and_acceleration_smoother_still() {
        // "Changing the velocity results in smoother behaviour. The
        // smoothness depends on the maximum allowed velocity. [...]
        // Changing the acceleration is even smoother".
        let r = |fig: &str| roughness(&poses(&variant("control", fig), 1000));
        let rows = [
            ("101 displacement 180°", r("screenshot101")),
            ("102 displacement 10°", r("screenshot102")),
            ("106 velocity 10°", r("screenshot106")),
            ("108 velocity 40°", r("screenshot108")),
            ("109 velocity 80°", r("screenshot109")),
            ("111 acceleration 0.5°, velocity 10°", r("screenshot111")),
        ];
        for (l, v) in &rows {
            println!("004 §1 {l}: mean |Δ²θ| {v:.2}° per step");
        }
        let v: Vec<f32> = rows.iter().map(|x| x.1).collect();
        assert!(
            v[0] > v[1] && v[1] > v[2] && v[2] < v[3] && v[3] < v[4] && v[5] < 0.2 * v[2],
            "{v:?}"
        );
    }

    #[test]
    fn p004_sec5_long_hold_intervals_give_loops() {
        // "The presence of many circular loops indicate long times of
        // constant velocity [...] when the intervals are too long in
        // relation to the max angular velocity." Velocity clamp 10°.
        let base = variant("timed", "screenshot141");
        let mut counts = Vec::new();
        for hold in [1u32, 5, 10, 20, 40, 80] {
            let lp: u32 = (1..=20)
                .map(|seed| {
                    let c = with(&base, seed, |v| {
                        v["hold"] = serde_json::json!({"kind": "fixed", "every": hold})
                    });
                    loops(&poses(&c, 1500))
                })
                .sum();
            println!("004 §5 velocity 10°, hold {hold} steps: {lp} loops in 20 × 1,500 steps");
            counts.push(lp);
        }
        assert!(
            counts.windows(2).all(|w| w[1] > w[0]) || counts[0] == counts[1],
            "{counts:?}"
        );
        assert!(counts[0] == 0 && counts[5] > 200, "{counts:?}");
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
        // Ours is the more accurate and orients more runs on entry.
        assert!(rows[0].1 < rows[1].1 && rows[0].0 < rows[1].0, "{rows:?}");
        assert!(rows[0].2 > rows[1].2 && rows[0].3 >= rows[1].3, "{rows:?}");
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
    assert!((below - above).abs() < 0.01 && step > 0.7);
    // Draws follow the curve's distribution (20,000 draws at 20°).
    let mut rng = Rng::new(6);
    let draws: Vec<f32> = (0..20_000).map(|_| c.sample(r(20.0), &mut rng)).collect();
    for x in [5.0f32, 10.0, 15.0, 22.5, 30.0, 40.0] {
        let emp = draws.iter().filter(|&&d| d < r(x)).count() as f32 / 20_000.0;
        let want = c.cdf(r(20.0), r(x));
        assert!((emp - want).abs() < 0.015, "x {x}: {emp} vs {want}");
    }
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
}
