//! Cost of the core pieces, measured side by side in one run: one seek
//! step (the baseline), one η-table lookup (issue: lookup ≤ 10× seek) and
//! one funnelling update for near (1–4 m) and far (20–30 m) targets
//! (issue: funnelling ≤ 4× seek). `cargo bench --bench core`; same-run
//! ratios are printed at the end.

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, Criterion};
use glam::Vec2;
use steering::funnel::{FunnelConfig, FunnelMemory, Goal, MuBound};
use steering::rng::Rng;
use steering::seek::seek_point;
use steering::table::EtaTable;
use steering::vehicle::{VehicleParams, VehicleState};

fn table() -> EtaTable {
    EtaTable::from_bytes(
        &std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin")).unwrap(),
    )
    .unwrap()
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

fn bench(c: &mut Criterion) {
    let p = VehicleParams::default();
    let t = table();
    let qs = queries();
    let mut g = c.benchmark_group("core");
    g.bench_function("seek_step", |b| {
        let mut s = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
        let mut k = 0usize;
        b.iter(|| {
            k = (k + 1) & 1023;
            let q = qs[k];
            let target = s.pos + Vec2::from_angle(q[1]) * q[0];
            seek_point(&p, &mut s, black_box(target), 1.3);
            black_box(&s);
        });
    });
    g.bench_function("table_lookup", |b| {
        let mut k = 0usize;
        b.iter(|| {
            k = (k + 1) & 1023;
            let q = qs[k];
            black_box(t.lookup(black_box(q[0]), q[1], q[2], q[3], q[4]))
        });
    });
    for (name, lo, hi) in [
        ("funnel_update_near", 1.0, 4.0),
        ("funnel_update_far", 20.0, 30.0),
    ] {
        let goals = goals(lo, hi);
        let states = states();
        let cfg = FunnelConfig::default();
        g.bench_function(name, |b| {
            let mut k = 0usize;
            b.iter(|| {
                k = (k + 1) & 1023;
                let mut s = states[k];
                let mut m = FunnelMemory::default();
                black_box(cfg.step(&t, &p, &mut s, black_box(&goals[k]), &mut m));
                black_box(s);
            });
        });
    }
    g.finish();
}

/// 1,024 random oriented goals at distances in [lo, hi] from the origin.
fn goals(lo: f32, hi: f32) -> Vec<Goal> {
    let mut r = Rng::new(17);
    (0..1024)
        .map(|_| Goal {
            pos: glam::Vec2::from_angle(r.range(-3.1, 3.1)) * r.range(lo, hi),
            beta: r.range(-3.1, 3.1),
            ..Default::default()
        })
        .collect()
}

/// 1,024 random admissible start states at the origin.
fn states() -> Vec<VehicleState> {
    let p = VehicleParams::default();
    let mut r = Rng::new(23);
    (0..1024)
        .map(|_| {
            let v = r.range(0.0, p.v_max);
            VehicleState::new(Vec2::ZERO, 0.0, v, r.range(-1.0, 1.0) * p.omega_limit(v))
        })
        .collect()
}

/// Same-run ratio with a plain timing loop (criterion reports absolute times).
fn ratio() {
    let p = VehicleParams::default();
    let t = table();
    let qs = queries();
    let n = 2_000_000;
    let time = |f: &mut dyn FnMut(usize)| {
        let t0 = Instant::now();
        for i in 0..n {
            f(i);
        }
        t0.elapsed().as_secs_f64() * 1e9 / n as f64
    };
    let mut s = VehicleState::new(Vec2::ZERO, 0.0, 1.0, 0.0);
    let seek = time(&mut |i| {
        let q = qs[i & 1023];
        let target = s.pos + Vec2::from_angle(q[1]) * q[0];
        seek_point(&p, &mut s, black_box(target), 1.3);
        black_box(&s);
    });
    let look = time(&mut |i| {
        let q = qs[i & 1023];
        black_box(t.lookup(black_box(q[0]), q[1], q[2], q[3], q[4]));
    });
    println!(
        "same-run ratio: seek step {seek:.1} ns, table lookup {look:.1} ns, lookup/seek = {:.2}",
        look / seek
    );
    let st = states();
    for bound in [
        MuBound::default(),
        MuBound::Literal,
        MuBound::TurningRadius { factor: 12.0 },
    ] {
        let cfg = FunnelConfig {
            bound,
            ..Default::default()
        };
        for (name, lo, hi) in [("near 1-4 m", 1.0, 4.0), ("far 20-30 m", 20.0, 30.0)] {
            let gs = goals(lo, hi);
            let f = time(&mut |i| {
                let mut s = st[i & 1023];
                let mut m = FunnelMemory::default();
                black_box(cfg.step(&t, &p, &mut s, black_box(&gs[i & 1023]), &mut m));
                black_box(s);
            });
            println!("same-run ratio: funnelling update ({bound:?}, {name}) {f:.1} ns, funnel/seek = {:.2}", f / seek);
        }
    }
}

criterion_group!(benches, bench);

fn main() {
    benches();
    ratio();
    Criterion::default().configure_from_args().final_summary();
}
