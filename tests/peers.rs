//! Ours beside the peers a user would install instead, natively (the
//! figures report's Peers section; `benches/peers.rs` times the same
//! pieces in one run):
//!
//! - our Dubins solve ([`steering::base::dubins`]) against dubins_paths on
//!   seeded random queries: the shortest lengths agree within 1e-4·R;
//! - our avoidance (ORCA on the forward-only unicycle, funnelling to
//!   oriented targets) against dodgy_2d (ORCA on holonomic discs with no
//!   heading) on the avoidance benchmarks, the same scenarios and seeds.
//!
//! Each record names the peer's version as `Cargo.lock` pins it.
#![cfg(not(target_arch = "wasm32"))]

mod common;
#[path = "common/peers.rs"]
mod peers;

use common::figures::{record, Figure, Kind, Seeds};
use common::table;

use steering::avoidance::config::AvoidanceMethod;
use steering::base::dubins::{shortest_length, DubinsPath};
use steering::base::rng::Rng;
use steering::studies::avoidance::{run, Bench, RunReport};

use peers::{dubins_query, locked_version, peer_length, PeerRun};

/// Queries of the Dubins agreement.
const DUBINS_QUERIES: usize = 100_000;
/// Its seed (nothing is tuned on it).
const DUBINS_SEED: u64 = 50;
/// Agreement bound, in turning radii.
const DUBINS_TOLERANCE: f64 = 1e-4;

#[test]
fn our_dubins_lengths_agree_with_dubins_paths() {
    let mut r = Rng::new(DUBINS_SEED);
    let (mut worst_len, mut worst_path) = (0.0f64, 0.0f64);
    let (mut over_len, mut over_path) = (0usize, 0usize);
    let mut worst_query = None;
    for _ in 0..DUBINS_QUERIES {
        let (s, g, rho) = dubins_query(&mut r);
        let theirs = peer_length(s, g, rho);
        let len = (f64::from(shortest_length(s, g, rho)) - theirs).abs() / f64::from(rho);
        let path = DubinsPath::shortest(s, g, rho).expect("finite query");
        let path = (f64::from(path.length()) - theirs).abs() / f64::from(rho);
        if len > worst_len {
            worst_query = Some((s, g, rho, theirs));
        }
        worst_len = worst_len.max(len);
        worst_path = worst_path.max(path);
        over_len += usize::from(len > DUBINS_TOLERANCE);
        over_path += usize::from(path > DUBINS_TOLERANCE);
    }
    println!("worst query (start, goal, R, dubins_paths' length): {worst_query:?}");
    let v = locked_version("dubins_paths");
    let figs = [
        Figure::new(
            "peers.dubins.queries",
            &format!("seeded random queries, ours against dubins_paths {v} (its f64 solve): R log-uniform in 0.1–100 m, start in a 200 m square, goal within 4 R (half) or 4–40 R, any headings"),
            DUBINS_QUERIES as f64,
            "queries",
            0,
        ),
        Figure::new(
            "peers.dubins.length.max_error",
            "largest |ours − dubins_paths| of the shortest length (`dubins::shortest_length`, what the studies compare paths with), in millionths of R",
            worst_len * 1e6,
            "× 10⁻⁶ R",
            2,
        ),
        Figure::new(
            "peers.dubins.length.over_tolerance",
            "queries where `dubins::shortest_length` differs from dubins_paths by more than 1e-4·R",
            over_len as f64,
            "queries",
            0,
        ),
        Figure::new(
            "peers.dubins.path.max_error",
            "largest |ours − dubins_paths| of the length of the path a car-like agent follows (`DubinsPath::shortest`, rounded to f32 per segment), in millionths of R",
            worst_path * 1e6,
            "× 10⁻⁶ R",
            2,
        ),
        Figure::new(
            "peers.dubins.path.over_tolerance",
            "queries where `DubinsPath::shortest`'s length differs from dubins_paths by more than 1e-4·R",
            over_path as f64,
            "queries",
            0,
        ),
    ];
    record(
        "tests/peers.rs::our_dubins_lengths_agree_with_dubins_paths",
        "cargo test --release --features cli,counters --test peers our_dubins -- --nocapture",
        Kind::Deterministic,
        &Seeds {
            tuning: vec![],
            report: vec![DUBINS_SEED],
        },
        &figs,
    );
    assert_eq!(over_len, 0, "worst {worst_len} R");
    assert_eq!(over_path, 0, "worst {worst_path} R");
}

/// The avoidance benchmarks both sides run (the paper figures' presets
/// are left out: several of their agents share a target, which a disc
/// that must reach the point itself cannot share).
const BENCHES: [Bench; 5] = [
    Bench::CircleSwap(8),
    Bench::CircleSwap(32),
    Bench::CircleSwap(100),
    Bench::Corridor,
    Bench::Doorway,
];
/// Report seeds of the avoidance comparison (the avoidance defaults were
/// tuned on 1000–1099, 2000–2099 and 3000–3999; dodgy_2d's settings are
/// the scenario's, tuned on nothing).
const AVOID_SEEDS: std::ops::Range<u64> = 0..4;

/// Which side a comparison favours: `Some(true)` ours, `Some(false)` the
/// peer, `None` a tie.
fn ahead(ours: f64, peer: f64, lower_is_better: bool) -> Option<bool> {
    if (ours - peer).abs() <= 1e-9 * ours.abs().max(peer.abs()) {
        None
    } else {
        Some((ours < peer) == lower_is_better)
    }
}

/// The verdict of a comparison as the report shows it: who is ahead, and
/// when the peer is, why.
fn verdict(ours: f64, peer: f64, lower_is_better: bool, why_peer: &str) -> String {
    match ahead(ours, peer, lower_is_better) {
        None => "tie".into(),
        Some(true) => "ours ahead".into(),
        Some(false) => format!("**dodgy_2d ahead**: {why_peer}"),
    }
}

const WHY_HOLONOMIC: &str =
    "another model: a holonomic disc takes the avoiding velocity at once, in any direction";
const WHY_POSITION_ONLY: &str =
    "less work: it arrives at a position only; ours must also face the target (ε_tol 10°)";
const WHY_STRAIGHT: &str = "another model, less work: a holonomic disc goes straight at full speed from the first step and arrives with no heading; ours accelerates within 1.5 m/s², turns within ω_max and funnels into the target's heading";
const WHY_CLEARANCE: &str =
    "with our margin it avoids at 0.9 m between centres and holds it exactly (holonomic)";

fn median(mut v: Vec<f32>) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    Some(f64::from(steering::base::metrics::percentile(&mut v, 0.5)))
}

/// One comparison: a measure of both sides, and which way is better.
struct Row<'a> {
    measure: &'a str,
    what: String,
    ours: f64,
    peer: f64,
    unit: &'a str,
    digits: u8,
    lower_is_better: bool,
    why_peer: &'a str,
    /// dodgy_2d avoiding with our margin added to its radius, where measured.
    peer_margin: Option<f64>,
}

/// A comparison's two figures, `peers.avoid.<bench>.<measure>.ours` and
/// `….dodgy_2d`, the peer's saying who is ahead.
fn push_row(figs: &mut Vec<Figure>, name: &str, r: Row<'_>) {
    let id = |side: &str| format!("peers.avoid.{name}.{}.{side}", r.measure);
    figs.push(Figure::new(
        &id("ours"),
        &format!("{name}, {}: ours", r.what),
        r.ours,
        r.unit,
        r.digits,
    ));
    figs.push(Figure::new(
        &id("dodgy_2d"),
        &format!(
            "{name}, {}: dodgy_2d — {}",
            r.what,
            verdict(r.ours, r.peer, r.lower_is_better, r.why_peer)
        ),
        r.peer,
        r.unit,
        r.digits,
    ));
    if let Some(m) = r.peer_margin {
        figs.push(Figure::new(
            &id("dodgy_2d_margin"),
            &format!(
                "{name}, {}: dodgy_2d avoiding with our 0.15 m margin added to its radius — {}",
                r.what,
                verdict(r.ours, m, r.lower_is_better, r.why_peer)
            ),
            m,
            r.unit,
            r.digits,
        ));
    }
}

/// Runs (of those given) with something at some step.
fn runs_with<T>(runs: &[T], f: impl Fn(&T) -> bool) -> f64 {
    runs.iter().filter(|r| f(r)).count() as f64
}

/// The figures of one benchmark: both sides' measures, who is ahead, and
/// the ratios.
fn bench_figures(
    name: &str,
    ours: &[RunReport],
    peer: &[PeerRun],
    margin: &[PeerRun],
) -> Vec<Figure> {
    let id = |m: &str, side: &str| format!("peers.avoid.{name}.{m}.{side}");
    let runs = ours.len();
    let mut figs = Vec::new();
    push_row(
        &mut figs,
        name,
        Row {
            measure: "overlap-runs",
            what: format!(
                "runs (of {runs}) with two bodies overlapping (centres closer than 0.6 m) at some step (how deep: the smallest distance below)"
            ),
            ours: runs_with(ours, |r| r.overlap_pair_steps > 0),
            peer: runs_with(peer, |r| r.overlap_pair_steps > 0),
            unit: "runs",
            digits: 0,
            lower_is_better: true,
            why_peer: WHY_HOLONOMIC,
            peer_margin: Some(runs_with(margin, |r| r.overlap_pair_steps > 0)),
        },
    );
    // Walls only in the corridor and the doorway.
    if matches!(name, "corridor" | "doorway") {
        push_row(
            &mut figs,
            name,
            Row {
                measure: "wall-contact-runs",
                what: format!(
                    "runs (of {runs}) with a body closer than its radius to a wall at some step"
                ),
                ours: runs_with(ours, |r| r.obstacle_contacts > 0),
                peer: runs_with(peer, |r| r.obstacle_contacts > 0),
                unit: "runs",
                digits: 0,
                lower_is_better: true,
                why_peer: WHY_HOLONOMIC,
                peer_margin: Some(runs_with(margin, |r| r.obstacle_contacts > 0)),
            },
        );
    }
    let agents: usize = ours.iter().map(|r| r.agents).sum();
    let share = |n: usize| 100.0 * n as f64 / agents as f64;
    push_row(
        &mut figs,
        name,
        Row {
            measure: "reach",
            what: format!("agents arrived (of {agents}; ours: done, inside D_tol 0.3 m and ε_tol 10°; dodgy_2d: inside D_tol)"),
            ours: share(ours.iter().map(|r| r.reached).sum()),
            peer: share(peer.iter().map(|r| r.reached).sum()),
            unit: "%",
            digits: 1,
            lower_is_better: false,
            why_peer: WHY_POSITION_ONLY,
            peer_margin: Some(share(margin.iter().map(|r| r.reached).sum())),
        },
    );
    let fin_o: Vec<f32> = ours.iter().filter_map(|r| r.finish_time).collect();
    let fin_p: Vec<f32> = peer.iter().filter_map(|r| r.finish_time).collect();
    let fin_m: Vec<f32> = margin.iter().filter_map(|r| r.finish_time).collect();
    push_row(
        &mut figs,
        name,
        Row {
            measure: "finished-runs",
            what: format!("runs (of {runs}) in which every agent arrived"),
            ours: fin_o.len() as f64,
            peer: fin_p.len() as f64,
            unit: "runs",
            digits: 0,
            lower_is_better: false,
            why_peer: WHY_POSITION_ONLY,
            peer_margin: Some(fin_m.len() as f64),
        },
    );
    if let (Some(o), Some(p)) = (median(fin_o), median(fin_p)) {
        push_row(
            &mut figs,
            name,
            Row {
                measure: "time-all-arrived",
                what: "time until all arrived, median over the runs in which all did".into(),
                ours: o,
                peer: p,
                unit: "s",
                digits: 1,
                lower_is_better: true,
                why_peer: WHY_STRAIGHT,
                peer_margin: median(fin_m.clone()),
            },
        );
        figs.push(Figure::new(
            &id("time-all-arrived", "ratio"),
            &format!("{name}, time until all arrived, ours / dodgy_2d (the medians above)"),
            o / p,
            "×",
            2,
        ));
    }
    let len_o: f64 = ours.iter().map(|r| f64::from(r.path_length)).sum();
    let len_p: f64 = peer.iter().map(|r| f64::from(r.path_length)).sum();
    figs.push(Figure::new(
        &id("path-length", "ratio"),
        &format!(
            "{name}, Σ path length over all runs, ours / dodgy_2d — {}",
            verdict(len_o, len_p, true, WHY_STRAIGHT)
        ),
        len_o / len_p,
        "×",
        3,
    ));
    let smallest = |v: &mut dyn Iterator<Item = f32>| f64::from(v.fold(f32::INFINITY, f32::min));
    push_row(
        &mut figs,
        name,
        Row {
            measure: "min-distance",
            what:
                "smallest centre distance between two agents over all runs (bodies touch at 0.6 m)"
                    .into(),
            ours: smallest(&mut ours.iter().map(|r| r.min_distance)),
            peer: smallest(&mut peer.iter().map(|r| r.min_distance)),
            unit: "m",
            digits: 3,
            lower_is_better: false,
            why_peer: WHY_CLEARANCE,
            peer_margin: Some(smallest(&mut margin.iter().map(|r| r.min_distance))),
        },
    );
    let entries: u64 = ours.iter().map(|r| u64::from(r.entries)).sum();
    let oriented: u64 = ours.iter().map(|r| u64::from(r.oriented)).sum();
    figs.push(Figure::new(
        &id("oriented", "ours"),
        &format!("{name}, goal entries oriented within ε_tol 10°: ours (dodgy_2d has no heading)"),
        100.0 * oriented as f64 / entries.max(1) as f64,
        "%",
        1,
    ));
    let steps_p: u64 = peer.iter().map(|r| r.agent_steps).sum();
    let beyond: u64 = peer.iter().map(|r| r.beyond_limits).sum();
    figs.push(Figure::new(
        &id("limit-steps", "ours"),
        &format!("{name}, agent-steps over a vehicle limit: ours"),
        ours.iter().map(|r| r.violations).sum::<u64>() as f64,
        "steps",
        0,
    ));
    figs.push(Figure::new(
        &id("limit-steps", "dodgy_2d"),
        &format!("{name}, agent-steps whose change of velocity is more than our vehicle may make in a step (√(a_max² + A²)·dt): dodgy_2d, share of its agent-steps"),
        100.0 * beyond as f64 / steps_p.max(1) as f64,
        "%",
        2,
    ));
    figs
}

#[test]
fn our_avoidance_beside_dodgy_2d_on_the_benchmarks() {
    let t = table();
    let seeds: Vec<u64> = AVOID_SEEDS.collect();
    let jobs: Vec<(Bench, u64)> = BENCHES
        .iter()
        .flat_map(|&b| seeds.iter().map(move |&s| (b, s)))
        .collect();
    // Ours, dodgy_2d at the body radius, dodgy_2d with our margin added.
    let runs = steering::base::parallel::map_indices(3 * jobs.len(), |k| {
        let (b, s) = jobs[k / 3];
        let sc = b.scenario(s, AvoidanceMethod::Orca);
        match k % 3 {
            0 => (Some(run(&sc, &t)), None),
            1 => (None, Some(peers::run(&sc, 0.0))),
            _ => (None, Some(peers::run(&sc, sc.avoidance.margin))),
        }
    });
    let v = locked_version("dodgy_2d");
    let mut figs = vec![Figure::new(
        "peers.avoid.runs",
        &format!("runs per side and benchmark (seeds {}–{}); dodgy_2d {v}: holonomic discs, no heading, `Agent::compute_avoiding_velocity` each step (60 Hz) with the scenario's body radius (and again with our 0.15 m margin added, `dodgy_2d_margin`), speeds, step, horizons, reach and neighbour count; ours: the defaults (ORCA on the forward-only unicycle, planned at 30 Hz, funnelling to oriented targets)", seeds[0], seeds[seeds.len() - 1]),
        seeds.len() as f64,
        "runs",
        0,
    )];
    for (bi, b) in BENCHES.iter().enumerate() {
        let cell = &runs[3 * bi * seeds.len()..3 * (bi + 1) * seeds.len()];
        let ours: Vec<RunReport> = cell.iter().filter_map(|x| x.0).collect();
        let peer: Vec<PeerRun> = cell.iter().skip(1).step_by(3).filter_map(|x| x.1).collect();
        let margin: Vec<PeerRun> = cell.iter().skip(2).step_by(3).filter_map(|x| x.1).collect();
        for (s, ((o, p), m)) in seeds.iter().zip(ours.iter().zip(&peer).zip(&margin)) {
            println!(
                "{} seed {s}:\n  ours {o:?}\n  dodgy_2d {p:?}\n  dodgy_2d, margin {m:?}",
                b.name()
            );
            assert_eq!(o.nan, 0);
            assert_eq!(o.violations, 0);
            assert!(p.min_distance.is_finite() && p.path_length.is_finite());
        }
        figs.extend(bench_figures(&b.name(), &ours, &peer, &margin));
    }
    record(
        "tests/peers.rs::our_avoidance_beside_dodgy_2d_on_the_benchmarks",
        "cargo test --release --features cli,counters --test peers our_avoidance -- --nocapture",
        Kind::Deterministic,
        &Seeds {
            tuning: [1000..1100, 2000..2100, 3000..4000]
                .into_iter()
                .flatten()
                .collect(),
            report: seeds,
        },
        &figs,
    );
}

/// A record whose figure ids all start with `peers.` renders in the Peers
/// section: a deterministic one inside the checked part, a timed one after
/// it; neither in the generic sections.
#[cfg(feature = "cli")]
#[test]
fn peers_records_render_in_the_peers_section() {
    use std::collections::BTreeMap;
    use steering::cli::records::{self, Kind as K, Seeds as S};
    use steering::cli::report::{self, Captions, CHECKED_END};
    let rec = |source: &str, kind: K, id: &str| {
        records::make(
            source.into(),
            "cargo test".into(),
            kind,
            S::default(),
            vec![records::Figure::new(id, "a count", 3.0, "runs", 0)],
        )
    };
    let keyed = |r: records::Record| (records::file_name(&r.source), r);
    let fast = BTreeMap::from([
        keyed(rec("tests/a.rs::ours", K::Deterministic, "a.count")),
        keyed(rec("tests/b.rs::peer", K::Deterministic, "peers.b.count")),
        keyed(rec("benches/c.rs::fast_timed", K::Timed, "peers.c.ratio")),
    ]);
    let full = BTreeMap::from([keyed(rec("benches/d.rs::peer", K::Timed, "peers.d.ratio"))]);
    let caps = Captions {
        about: String::new(),
        captions: Vec::new(),
    };
    let text = report::render(&fast, &full, &[], &caps).unwrap();
    let at = |s: &str| {
        text.find(s)
            .unwrap_or_else(|| panic!("{s} not in:\n{text}"))
    };
    let (peers, end) = (at("## Peers\n"), at(CHECKED_END));
    let measured = at("## Peers: costs measured in one run");
    assert!(at("### `tests/a.rs::ours`") < peers);
    assert!((peers..end).contains(&at("### `tests/b.rs::peer`")));
    assert!(end < measured);
    assert!(measured < at("### `benches/c.rs::fast_timed`"));
    assert!(measured < at("### `benches/d.rs::peer`"));
    assert!(at("### `benches/d.rs::peer`") < at("## Studies at report size"));
    assert_eq!(text.matches("### `benches/d.rs::peer`").count(), 1);
}
