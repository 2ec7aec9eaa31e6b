//! Cost of the core pieces, measured side by side in one run: one seek
//! step (the baseline), one η-table lookup (target: ≤ 10× seek) and
//! one funnelling update — plan plus the committed seek step — for near
//! (1–4 m) and far (20–30 m) targets, for the default μ bound and the two
//! literal ones (target: ≤ 4× seek); and `crate::base::trig::atan2`
//! against std's `atan2`.
//!
//! `cargo bench --bench core` (add `-- --warm-up-time 1 --measurement-time 2`
//! for a quick run). Criterion times each piece; then a plain timing loop
//! measures every piece in turn, seven rounds, and prints the ratios of the
//! per-piece minima: interleaving the rounds keeps a busy machine from
//! favouring whichever piece ran in a quiet moment. With `FIGURES_DIR`
//! set, the ratios are written as timed records for the figures report
//! (`tests/common/figures.rs` documents the format), one per claim: paper
//! 000 §7's far / near cost in the paper's reading and ours, the lookup
//! and the update against the seek step, the paper-size table against ours.

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, Criterion};
use glam::Vec2;
use steering::base::rng::Rng;
use steering::base::trig::unit;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::{FunnelConfig, MuBound};
use steering::funnelling::goal::{FunnelMemory, Goal};
use steering::funnelling::seek::seek_point;
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::update::Update;
use steering::studies::cost::{
    oriented_goals, start_states, PAPER_SIZE_COUNTS, SEC7_FAR_CLAIM, SEC7_FAR_NEAR,
};

#[path = "../tests/common/figures.rs"]
mod figures;
use figures::{record_timed, Figure};

/// Interleaved rounds of [`ratio`]'s timing loop, each piece timed over
/// 1,000,000 iterations per round; the minimum over the rounds is kept.
const ROUNDS: usize = 7;

fn table() -> EtaTable {
    EtaTable::for_vehicle(&VehicleParams::default()).unwrap()
}

/// 1,024 random queries, cycled, so the lookup is not measured on one hot cell.
fn queries() -> Vec<[f32; 5]> {
    let p = VehicleParams::default();
    let mut r = Rng::new(9);
    (0..1024)
        .map(|_| {
            let v = r.range(0.0, p.v_max);
            [
                r.range(0.5, 30.0),
                r.range(-3.1, 3.1),
                r.range(-1.0, 1.0) * p.omega_limit(v),
                v,
                r.range(0.3, 2.0),
            ]
        })
        .collect()
}

/// The measured pieces, each a closure over iteration `k`.
struct Pieces {
    p: VehicleParams,
    t: EtaTable,
    qs: Vec<[f32; 5]>,
    /// The queries' relative target positions, precomputed so that the
    /// seek baseline times the seek step alone.
    offsets: Vec<Vec2>,
    st: Vec<VehicleState>,
    near: Vec<Goal>,
    far: Vec<Goal>,
}

impl Pieces {
    fn new() -> Self {
        let qs = queries();
        Self {
            p: VehicleParams::default(),
            t: table(),
            offsets: qs.iter().map(|q| unit(q[1]) * q[0]).collect(),
            qs,
            st: start_states(),
            near: oriented_goals(1.0, 4.0),
            far: oriented_goals(20.0, 30.0),
        }
    }

    fn seek(&self, s: &mut VehicleState, k: usize) {
        let target = s.pos + self.offsets[k & 1023];
        seek_point(&self.p, s, black_box(target), 1.3);
        black_box(&s);
    }

    /// The seek step on the funnelling update's own inputs: from the same
    /// random state towards the same goal's position (paper 000 §3's seek,
    /// which the funnelling update plans the heading of). The `seek`
    /// baseline instead follows one continuous trajectory, whose heading
    /// and speed change little from one step to the next (its branches
    /// predictable, its data hot); this one pays what a fresh agent state
    /// costs, as the funnelling update does.
    fn seek_like(&self, far: bool, k: usize) {
        let mut s = self.st[k & 1023];
        let g = if far { &self.far } else { &self.near }[k & 1023];
        seek_point(&self.p, &mut s, black_box(g.pos), black_box(g.speed));
        black_box(s);
    }

    fn lookup(&self, k: usize) {
        let q = self.qs[k & 1023];
        black_box(self.t.lookup(black_box(q[0]), q[1], q[2], q[3], q[4]));
    }

    /// Each query's memory as a world holds it after the goal's first
    /// update: the once-per-goal short-range choice
    /// (`steering::funnelling::short_range::decide`, a few simulated
    /// approaches for a near goal) made, so that [`Self::funnel`] times the
    /// per-update cost and not that one-off.
    fn decided(&self, cfg: &FunnelConfig, far: bool) -> Vec<FunnelMemory> {
        (0..1024)
            .map(|k| {
                let mut s = self.st[k];
                let g = if far { &self.far } else { &self.near }[k];
                let mut m = FunnelMemory::default();
                let _ = cfg.plan(&mut Update {
                    table: &self.t,
                    params: &self.p,
                    state: &mut s,
                    goal: &g,
                    memory: &mut m,
                });
                FunnelMemory {
                    short_range: m.short_range,
                    ..FunnelMemory::default()
                }
            })
            .collect()
    }

    fn funnel(&self, cfg: &FunnelConfig, mems: &[FunnelMemory], far: bool, k: usize) {
        let mut s = self.st[k & 1023];
        let g = if far { &self.far } else { &self.near }[k & 1023];
        let mut m = mems[k & 1023];
        black_box(cfg.step(&mut Update {
            table: &self.t,
            params: &self.p,
            state: &mut s,
            goal: black_box(&g),
            memory: &mut m,
        }));
        black_box(s);
    }
}

/// The μ bounds compared: the default and the paper's literal one, plain
/// and scaled (one interpolation more per update than the default bound:
/// 2–4 blends instead of 1–3).
fn bounds() -> [(&'static str, FunnelConfig); 4] {
    [
        (
            "default (TurningRadius ×8, entry aim, line pursuit)",
            FunnelConfig::default(),
        ),
        (
            "paper literal (centre aim, literal bound, gain 1)",
            steering::studies::envelope::literal_config(),
        ),
        (
            "ScaledLiteral ×6",
            FunnelConfig {
                bound: MuBound::ScaledLiteral { gain: 6.0 },
                ..Default::default()
            },
        ),
        (
            "Literal",
            FunnelConfig {
                bound: MuBound::Literal,
                ..Default::default()
            },
        ),
    ]
}

fn bench(c: &mut Criterion) {
    let x = Pieces::new();
    let mut g = c.benchmark_group("core");
    g.bench_function("seek_step", |b| {
        let mut s = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
        let mut k = 0usize;
        b.iter(|| {
            k += 1;
            x.seek(&mut s, k);
        });
    });
    for (dist, far) in [("near", false), ("far", true)] {
        g.bench_function(format!("seek_step_like_{dist}"), |b| {
            let mut k = 0usize;
            b.iter(|| {
                k += 1;
                x.seek_like(far, k);
            });
        });
    }
    g.bench_function("table_lookup", |b| {
        let mut k = 0usize;
        b.iter(|| {
            k += 1;
            x.lookup(k);
        });
    });
    // The deterministic atan2 every controller uses, against std's (libm).
    let pts: Vec<(f32, f32)> = queries()
        .iter()
        .map(|q| (q[1].sin(), q[1].cos() * q[0]))
        .collect();
    g.bench_function("atan2 trig", |b| {
        let mut k = 0usize;
        b.iter(|| {
            k += 1;
            let (y, x) = pts[k & 1023];
            black_box(steering::base::trig::atan2(black_box(y), black_box(x)))
        });
    });
    g.bench_function("atan2 std", |b| {
        let mut k = 0usize;
        b.iter(|| {
            k += 1;
            let (y, x) = pts[k & 1023];
            black_box(black_box(y).atan2(black_box(x)))
        });
    });
    for (name, cfg) in bounds() {
        for (dist, far) in [("near", false), ("far", true)] {
            let mems = x.decided(&cfg, far);
            g.bench_function(format!("funnel_update_{dist} {name}"), |b| {
                let mut k = 0usize;
                b.iter(|| {
                    k += 1;
                    x.funnel(&cfg, &mems, far, k);
                });
            });
        }
    }
    g.finish();
}

/// Same-run ratios from interleaved rounds (criterion reports absolute times).
fn ratio() {
    let x = Pieces::new();
    let n = 1_000_000;
    let time = |f: &mut dyn FnMut(usize)| {
        let t0 = Instant::now();
        for k in 0..n {
            f(k);
        }
        t0.elapsed().as_secs_f64() * 1e9 / n as f64
    };
    let cfgs = bounds();
    // best[0] seek, best[1] lookup, then funnel (bound, near/far).
    let mut best = [f64::INFINITY; 2 + 2 * 4];
    // The like-for-like seek, near and far.
    let mut like = [f64::INFINITY; 2];
    let mems: Vec<[Vec<FunnelMemory>; 2]> = cfgs
        .iter()
        .map(|(_, c)| [x.decided(c, false), x.decided(c, true)])
        .collect();
    let mut s = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
    for _ in 0..ROUNDS {
        best[0] = best[0].min(time(&mut |k| x.seek(&mut s, k)));
        for (j, far) in [false, true].into_iter().enumerate() {
            like[j] = like[j].min(time(&mut |k| x.seek_like(far, k)));
        }
        best[1] = best[1].min(time(&mut |k| x.lookup(k)));
        for (i, (_, cfg)) in cfgs.iter().enumerate() {
            for (j, far) in [false, true].into_iter().enumerate() {
                let slot = &mut best[2 + 2 * i + j];
                let m = &mems[i][usize::from(far)];
                *slot = slot.min(time(&mut |k| x.funnel(cfg, m, far, k)));
            }
        }
    }
    // A table at paper 000's own size (43,200 entries), generated here
    // (0.1 s), beside ours.
    let small = steering::funnelling::table::spec::TableSpec::with_counts(
        VehicleParams::default(),
        PAPER_SIZE_COUNTS,
    )
    .generate()
    .unwrap();
    let small_pieces = Pieces {
        t: small,
        ..Pieces::new()
    };
    let (mut ours, mut paper) = (f64::INFINITY, f64::INFINITY);
    let dflt = FunnelConfig::default();
    let (mut ours_f, mut paper_f) = (f64::INFINITY, f64::INFINITY);
    let ours_m = [x.decided(&dflt, false), x.decided(&dflt, true)];
    let paper_m = [
        small_pieces.decided(&dflt, false),
        small_pieces.decided(&dflt, true),
    ];
    let far = |k: usize| k & 1 == 0;
    for _ in 0..ROUNDS {
        ours = ours.min(time(&mut |k| x.lookup(k)));
        paper = paper.min(time(&mut |k| small_pieces.lookup(k)));
        ours_f = ours_f.min(time(&mut |k| {
            x.funnel(&dflt, &ours_m[usize::from(far(k))], far(k), k);
        }));
        paper_f = paper_f.min(time(&mut |k| {
            small_pieces.funnel(&dflt, &paper_m[usize::from(far(k))], far(k), k);
        }));
    }
    println!(
        "same-run ratio: lookup on the 43,200-entry table / ours (362,880): {paper:.1} / {ours:.1} ns = {:.2}; default funnelling update, near and far mixed: {paper_f:.1} / {ours_f:.1} ns = {:.2}",
        paper / ours,
        paper_f / ours_f
    );
    let seek = best[0];
    println!(
        "same-run ratio: seek step {seek:.1} ns, table lookup {:.1} ns, lookup/seek = {:.2}",
        best[1],
        best[1] / seek
    );
    for (i, (name, _)) in cfgs.iter().enumerate() {
        let (near, far) = (best[2 + 2 * i], best[3 + 2 * i]);
        println!(
            "same-run ratio: funnelling update, {name}: near 1-4 m {near:.1} ns ({:.2}× seek), far 20-30 m {far:.1} ns ({:.2}× seek)",
            near / seek,
            far / seek
        );
        println!(
            "same-run ratio, like for like: funnelling update, {name} / the seek step from the same states to the same goals ({:.1} / {:.1} ns): near {:.2}×, far {:.2}×",
            like[0],
            like[1],
            near / like[0],
            far / like[1]
        );
        println!("same-run ratio: funnelling update far / near, {name}: {:.2} (paper 000 §7: 9.5 / 12.5 = {SEC7_FAR_NEAR:.2})", far / near);
    }
    record(&cfgs, &best, like, [paper / ours, paper_f / ours_f]);
}

/// [`ratio`]'s minima as timed records, one per claim: `best` holds the
/// seek step, the lookup, then the update near and far per bound of
/// `cfgs`; `like` the like-for-like seek near and far; `paper_size` the
/// lookup and the update on the paper-size table over ours.
fn record(
    cfgs: &[(&str, FunnelConfig); 4],
    best: &[f64; 10],
    like: [f64; 2],
    paper_size: [f64; 2],
) {
    let seek = best[0];
    let f = |id: &str, what: &str, v: f64| Figure::new(id, what, v, "×", 2);
    // bounds()[0] is ours (the default), [1] the paper's literal controller.
    for (i, reading) in [(0, "ours"), (1, "paper")] {
        let (name, _) = &cfgs[i];
        record_timed(
            "core",
            &format!("p000_sec7_far_targets_cost_less_{reading}"),
            &[f(
                &format!("p000.sec7.far.{reading}.time_ratio"),
                &format!("000 §7 far targets cost less, {reading} reading ({name}): far (20–30 m) / near (1–4 m) time per funnelling update (paper {SEC7_FAR_NEAR:.2}: {SEC7_FAR_CLAIM})"),
                best[3 + 2 * i] / best[2 + 2 * i],
            )],
        );
    }
    let mut figs = vec![f(
        "core.lookup.over_seek",
        "η-table lookup / seek step (design target ≤ 10)",
        best[1] / seek,
    )];
    for (i, reading) in [(0, "ours"), (1, "paper")] {
        let name = cfgs[i].0;
        for (j, dist) in ["near", "far"].into_iter().enumerate() {
            let update = best[2 + 2 * i + j];
            figs.push(f(
                &format!("core.update.{reading}.{dist}.over_seek"),
                &format!("{reading} reading ({name}): funnelling update, {dist} targets / seek step (design target ≤ 4)"),
                update / seek,
            ));
            figs.push(f(
                &format!("core.update.{reading}.{dist}.over_seek_like"),
                &format!("{reading} reading ({name}): funnelling update, {dist} targets / the seek step from the same states to the same goals"),
                update / like[j],
            ));
        }
    }
    record_timed("core", "lookup_and_update_against_seek", &figs);
    record_timed(
        "core",
        "paper_size_table",
        &[
            f(
                "core.paper_size_table.lookup",
                "η-table lookup on a table at paper 000 §3's size (43,200 entries) / on ours (362,880)",
                paper_size[0],
            ),
            f(
                "core.paper_size_table.update",
                "default funnelling update, near and far mixed, on the 43,200-entry table / on ours",
                paper_size[1],
            ),
        ],
    );
}

criterion_group!(benches, bench);

fn main() {
    benches();
    // Not under `cargo test --all-targets` (criterion's test mode runs each
    // piece once; the same-run ratios are a benchmark's, minutes long).
    if std::env::args().any(|a| a == "--bench") {
        ratio();
    }
    Criterion::default().configure_from_args().final_summary();
}
