//! Fidelity of paper 003 (crowded path following) beyond the preset runs
//! of `tests/fidelity.rs`: claims measured over several seeds, the side of
//! the path each seek rides, the shape of the ideal path, and Test IV at
//! every separation weight from ours (0.05) to the text's literal rule (1).
//! Each test asserts its claim, or its refutation with the numbers, and
//! writes one row of the fidelity table (`common::figures`).
//!
//! Seeds: the presets use seed = test number (1–4); the presets' settings,
//! among them the separation weight 0.05, were chosen by looking at those
//! runs. The figures here are reported on seeds 11–15, on which nothing of
//! the crowd was chosen (the preset seed beside them where the test also
//! reads the preset). The thresholds of the assertions are not fitted to
//! either: each sits far from the values on both sides of it, which vary by
//! under half a point between seeds where shares are compared.

mod common;

use common::figures::{record_claim, Claim, Figure, Seeds, Verdict};
use glam::Vec2;
use steering::crowd::boid_seek::Seek;
use steering::crowd::config::{CrowdConfig, PaperTest};
use steering::crowd::metrics::{CrowdMetrics, OffsetProfile};
use steering::crowd::world::Crowd;

const VARIANTS: [(&str, Seek); 5] = [
    ("reynolds", Seek::Reynolds),
    ("parker100", Seek::Parker { fraction: 1.0 }),
    ("parker10", Seek::Parker { fraction: 0.1 }),
    ("parker1", Seek::Parker { fraction: 0.01 }),
    ("parker0_1", Seek::Parker { fraction: 0.001 }),
];

fn command(test: &str) -> String {
    format!("cargo test --release --features cli --test fidelity_crowd {test}")
}

fn source(test: &str) -> String {
    format!("tests/fidelity_crowd.rs::{test}")
}

fn claim(place: &str, text: &str, reading: &str, verdict: Verdict) -> Claim {
    Claim {
        paper: "003".into(),
        place: place.into(),
        claim: text.into(),
        reading: reading.into(),
        verdict,
    }
}

fn mean(v: &[f32]) -> f32 {
    v.iter().sum::<f32>() / v.len().max(1) as f32
}

/// The preset of `test` with `seek` on `seed`, warm-up 1,500 and 3,000
/// measured steps (the presets measure 6,000; half is enough for shares
/// and offsets, which vary by under 0.5 points between seeds).
fn config(test: PaperTest, seek: Seek, seed: u64) -> CrowdConfig {
    let mut cfg = CrowdConfig::paper(test, seek);
    cfg.seed = seed;
    cfg.warmup_steps = 1500;
    cfg.measure_steps = 3000;
    cfg
}

fn measured(cfg: &CrowdConfig) -> CrowdMetrics {
    Crowd::new(cfg).unwrap().run_measured()
}

/// Each boid's offset profile over the next `steps` steps of `c`.
fn profiles(c: &mut Crowd, steps: u32) -> Vec<OffsetProfile> {
    let mut out = vec![OffsetProfile::new(c.path().length()); c.len()];
    for _ in 0..steps {
        c.step();
        for (i, prof) in out.iter_mut().enumerate() {
            let p = Vec2::new(c.positions()[2 * i], c.positions()[2 * i + 1]);
            let n = c.path().normal_point(p);
            prof.record(n.s, c.path().lateral_offset(p, &n));
        }
    }
    out
}

/// The Test I boid's ideal path on `seed`: its profile over the preset's
/// measurement window (6,000 steps after 1,500 of warm-up).
fn ideal_path(seek: Seek, seed: u64) -> OffsetProfile {
    let mut c = Crowd::new(&config(PaperTest::I, seek, seed)).unwrap();
    c.run(1500);
    profiles(&mut c, 6000).remove(0)
}

const PARKER_SIDES: &str = "p003_parker_100_percent_and_reynolds_differ_only_in_the_side_they_ride";

#[test]
fn p003_parker_100_percent_and_reynolds_differ_only_in_the_side_they_ride() {
    // "By observation of the two first illustrations we can conclude that
    // Conrad Parker's seek with 100% steering is equivalent to Craig
    // Reynolds' seek algorithm" (Tests I–II), and Test III "should produce
    // similar results using these algorithms. [...] this is indeed the
    // case".
    //
    // They are not the same update: Reynolds' velocity becomes the desired
    // one (towards the target at max speed; the preset's force limit never
    // binds), Parker 100 % adds the whole offset to the current velocity and
    // then clamps the speed, so part of the old heading survives each
    // correction and the boid turns later. Alone on the counter-clockwise
    // loop that puts it on the outer side (negative offset) where Reynolds
    // rides the inner one; in a crowd of 100 the neighbours even it out.
    let solo: Vec<u64> = vec![1, 11, 12, 13, 14, 15];
    let crowd: Vec<u64> = vec![3, 11, 12];
    let mut figs = Vec::new();
    // Laps and widths compare as means over the seeds: one boid's p95
    // distance varies between seeds by about as much as the two seeks
    // differ, so a per-seed ratio would compare two seeds' noise.
    let (mut lap_dev, mut p95_dev, mut out_max) = (0.0f32, 0.0f32, 0.0f32);
    let (mut p95_seed_dev, mut lap_seed_dev) = (0.0f32, 0.0f32);
    let mut gaps = [Vec::new(), Vec::new()];
    let mut sides = [[Vec::new(), Vec::new()], [Vec::new(), Vec::new()]];
    for (k, (test, seeds)) in [(PaperTest::I, &solo), (PaperTest::III, &crowd)]
        .into_iter()
        .enumerate()
    {
        let mut laps = [Vec::new(), Vec::new()];
        let mut p95s = [Vec::new(), Vec::new()];
        for &seed in seeds {
            let r = measured(&config(test, Seek::Reynolds, seed));
            let p = measured(&config(test, Seek::Parker { fraction: 1.0 }, seed));
            let (lr, lp) = (r.mean_lap_steps.unwrap(), p.mean_lap_steps.unwrap());
            let (dr, dp) = (r.p95_distance.unwrap(), p.p95_distance.unwrap());
            let (or, op) = (r.mean_offset.unwrap(), p.mean_offset.unwrap());
            lap_seed_dev = lap_seed_dev.max((lr / lp - 1.0).abs());
            p95_seed_dev = p95_seed_dev.max((dr / dp - 1.0).abs());
            laps[0].push(lr);
            laps[1].push(lp);
            p95s[0].push(dr);
            p95s[1].push(dp);
            out_max = out_max
                .max(r.outside_share.unwrap())
                .max(p.outside_share.unwrap());
            println!("003 {test:?} seed {seed}: Reynolds / Parker 100 %: lap {lr:.0} / {lp:.0} steps, p95 distance {dr:.1} / {dp:.1}, mean signed offset {or:+.1} / {op:+.1}");
            sides[k][0].push(or);
            sides[k][1].push(op);
            gaps[k].push(or - op);
        }
        lap_dev = lap_dev.max((mean(&laps[0]) / mean(&laps[1]) - 1.0).abs());
        p95_dev = p95_dev.max((mean(&p95s[0]) / mean(&p95s[1]) - 1.0).abs());
    }
    let min = |v: &[f32]| v.iter().copied().fold(f32::INFINITY, f32::min);
    let max = |v: &[f32]| v.iter().copied().fold(f32::NEG_INFINITY, f32::max);
    for (k, t) in ["test1", "test3"].iter().enumerate() {
        let n = if k == 0 {
            "Test I (1 boid)"
        } else {
            "Test III (100 boids)"
        };
        figs.push(Figure::new(&format!("p003.{t}.reynolds.offset"), &format!("{n}: Reynolds' mean signed lateral offset (+ = inner side of the loop; radius 24), mean over seeds"), f64::from(mean(&sides[k][0])), "", 1));
        figs.push(Figure::new(
            &format!("p003.{t}.parker100.offset"),
            &format!("{n}: Parker 100 %'s mean signed lateral offset, mean over seeds"),
            f64::from(mean(&sides[k][1])),
            "",
            1,
        ));
        figs.push(Figure::new(
            &format!("p003.{t}.offset_gap.min"),
            &format!("{n}: smallest Reynolds − Parker 100 % offset over seeds"),
            f64::from(min(&gaps[k])),
            "",
            1,
        ));
        figs.push(Figure::new(
            &format!("p003.{t}.offset_gap.max"),
            &format!("{n}: largest Reynolds − Parker 100 % offset over seeds"),
            f64::from(max(&gaps[k])),
            "",
            1,
        ));
    }
    figs.push(Figure::new("p003.test1_3.reynolds_parker100.lap_dev", "Tests I and III, the larger: relative difference of the mean lap time over seeds, Reynolds vs Parker 100 %", f64::from(100.0 * lap_dev), "%", 1));
    figs.push(Figure::new("p003.test1_3.reynolds_parker100.p95_dev", "Tests I and III, the larger: relative difference of the mean over seeds of the 95th-percentile distance from the centre line", f64::from(100.0 * p95_dev), "%", 1));
    figs.push(Figure::new(
        "p003.test1_3.reynolds_parker100.lap_dev.seed_max",
        "Tests I and III: largest relative difference of lap time on one seed",
        f64::from(100.0 * lap_seed_dev),
        "%",
        1,
    ));
    figs.push(Figure::new(
        "p003.test1_3.reynolds_parker100.p95_dev.seed_max",
        "Tests I and III: largest relative difference of the p95 distance on one seed",
        f64::from(100.0 * p95_seed_dev),
        "%",
        1,
    ));
    figs.push(Figure::new(
        "p003.test1_3.reynolds_parker100.outside.max",
        "Tests I and III: largest share of boid-steps outside the path, either seek",
        f64::from(100.0 * out_max),
        "%",
        1,
    ));
    record_claim(
        &source(PARKER_SIDES),
        &command(PARKER_SIDES),
        &Seeds {
            tuning: vec![],
            report: {
                let mut s = [solo.clone(), crowd.clone()].concat();
                s.sort_unstable();
                s.dedup();
                s
            },
        },
        &claim(
            "Tests I–III (illus. 3–4, 8–9)",
            "Parker's seek at 100 % is equivalent to Reynolds' seek",
            "paper",
            Verdict::Partly,
        ),
        &figs,
    );
    // Equivalent in what the illustrations show of a lap: its time, its
    // width and staying on the path…
    assert!(
        lap_dev < 0.05 && p95_dev < 0.10 && out_max < 0.01,
        "lap {lap_dev}, p95 {p95_dev}, outside {out_max}"
    );
    // …but alone they ride opposite sides, on every seed…
    assert!(
        min(&sides[0][0]) > 1.0 && max(&sides[0][1]) < -2.0 && min(&gaps[0]) > 4.0,
        "{sides:?}"
    );
    // …which 100 boids even out.
    assert!(
        max(&gaps[1]).abs() < 1.5 && min(&gaps[1]).abs() < 1.5,
        "{gaps:?}"
    );
}

const TEN_PERCENT: &str =
    "p003_ten_percent_changes_the_ideal_path_as_much_as_reynolds_differs_from_parker";

#[test]
fn p003_ten_percent_changes_the_ideal_path_as_much_as_reynolds_differs_from_parker() {
    // "At 10%, see footnote five, a relatively major change in the ideal
    // path is made by the boid" (Test I), where 100 % is "equivalent" to
    // Reynolds. The ideal path of a seek on a seed: its Test I boid's mean
    // signed offset per stretch of the loop. How far two seeks' paths lie
    // apart is the mean RMS difference over all pairs of seeds, divided by
    // how far the same seek's paths lie apart between seeds (the run's own
    // variation): 1 = no change, larger = a change.
    let seeds = [1u64, 11, 12, 13, 14, 15];
    let paths: Vec<Vec<OffsetProfile>> = VARIANTS
        .iter()
        .map(|&(_, s)| seeds.iter().map(|&k| ideal_path(s, k)).collect())
        .collect();
    let apart = |a: usize, b: usize| {
        let mut d = Vec::new();
        for i in 0..seeds.len() {
            for j in 0..seeds.len() {
                if a != b || i < j {
                    d.push(paths[a][i].rms_difference(&paths[b][j]).unwrap());
                }
            }
        }
        mean(&d)
    };
    let change = |a: usize, b: usize| apart(a, b) / (0.5 * (apart(a, a) + apart(b, b)));
    let (r, p100, p10, p1) = (0, 1, 2, 3);
    let rows = [
        (
            "reynolds_parker100",
            "Reynolds vs Parker 100 % (the text: equivalent)",
            change(r, p100),
        ),
        (
            "parker10_parker100",
            "Parker 10 % vs 100 % (the text: a relatively major change)",
            change(p10, p100),
        ),
        (
            "parker1_parker10",
            "Parker 1 % vs 10 % (the text: more and more along the outer wall)",
            change(p1, p10),
        ),
    ];
    let mut figs = Vec::new();
    for (k, (tag, _)) in VARIANTS.iter().enumerate().take(4) {
        figs.push(Figure::new(&format!("p003.test1.{tag}.path_between_seeds"), "Test I: mean RMS difference of the ideal path (mean offset per 1 % of the loop) between two seeds of the same seek", f64::from(apart(k, k)), "", 1));
    }
    for (id, what, v) in rows {
        println!("003 Test I ideal paths, {what}: {v:.2}× the seed-to-seed difference");
        figs.push(Figure::new(&format!("p003.test1.change.{id}"), &format!("Test I: {what}: RMS difference of the ideal paths over the seed-to-seed difference"), f64::from(v), "×", 2));
    }
    record_claim(
        &source(TEN_PERCENT),
        &command(TEN_PERCENT),
        &Seeds {
            tuning: vec![],
            report: seeds.to_vec(),
        },
        &claim(
            "Test I (illus. 5)",
            "at 10 % a relatively major change in the ideal path is made by the boid",
            "paper",
            Verdict::Partly,
        ),
        &figs,
    );
    let (eq, ten, one) = (rows[0].2, rows[1].2, rows[2].2);
    // The 10 % path does change (beyond the seed-to-seed variation)…
    assert!(ten > 1.5, "10 % vs 100 %: {ten}");
    // …but by no more than Reynolds differs from 100 %, which the text
    // calls equivalent; the major change comes at 1 %.
    assert!(ten < 1.25 * eq, "10 %: {ten}, Reynolds vs 100 %: {eq}");
    assert!(one > 2.0 * ten, "1 % vs 10 %: {one}, 10 % vs 100 %: {ten}");
}

const PREDICTABLE: &str = "p003_test_three_weaker_steering_is_less_predictable";

#[test]
fn p003_test_three_weaker_steering_is_less_predictable() {
    // Test III: illustration three (10 %) "is also similar to one and two,
    // but as the steering loosens the shape of the lap changes
    // unpredictably. A conclusion can be made, the weaker the steering is
    // the more unpredictable the boid's traversal route is." Trace spread:
    // the standard deviation of the lateral offset between passages through
    // a stretch of the path (`crowd::metrics`), separation weight 0.05.
    let seeds = [3u64, 11, 12, 13];
    let mut spread = vec![Vec::new(); 5];
    for &seed in &seeds {
        for (k, &(_, s)) in VARIANTS.iter().enumerate() {
            spread[k].push(
                measured(&config(PaperTest::III, s, seed))
                    .trace_spread
                    .unwrap(),
            );
        }
    }
    let mut figs = vec![Figure::new(
        "p003.test3.separation_weight",
        "separation weight of the runs (ours; the text's literal rule is 1)",
        0.05,
        "",
        2,
    )];
    for (k, (tag, _)) in VARIANTS.iter().enumerate() {
        println!("003 Test III {tag}: trace spread {:.1?}", spread[k]);
        figs.push(Figure::new(
            &format!("p003.test3.{tag}.trace_spread"),
            "Test III (100 boids): trace spread, mean over seeds (path radius 24)",
            f64::from(mean(&spread[k])),
            "",
            1,
        ));
    }
    record_claim(
        &source(PREDICTABLE),
        &command(PREDICTABLE),
        &Seeds { tuning: vec![3], report: seeds[1..].to_vec() },
        &claim(
            "Test III (illus. 8–12)",
            "10 % is similar to 100 % and Reynolds; the weaker the steering, the more unpredictable the route (separation weight 0.05, ours)",
            "ours",
            Verdict::Reproduced,
        ),
        &figs,
    );
    for i in 0..seeds.len() {
        let s: Vec<f32> = spread.iter().map(|v| v[i]).collect();
        // 10 % like 100 % and Reynolds…
        assert!(
            s[2] >= s[1] && s[2] < 1.15 * s[1].min(s[0]),
            "seed {}: {s:?}",
            seeds[i]
        );
        // …then ever less predictable.
        assert!(
            s[3] > 1.25 * s[2] && s[4] > 1.5 * s[3],
            "seed {}: {s:?}",
            seeds[i]
        );
    }
}

const SIMILAR: &str = "p003_test_four_illustrations_13_to_16_are_quite_similar";

#[test]
fn p003_test_four_illustrations_13_to_16_are_quite_similar() {
    // "Illustration one to four, see footnote 13 to 16, are quite similar.
    // [...] there is no free space to move around in". 13–16 are Reynolds
    // and Parker at 100, 10 and 1 %. At our separation weight (0.05).
    let seeds = [4u64, 11, 12];
    let (mut out, mut spread) = (vec![Vec::new(); 4], vec![Vec::new(); 4]);
    for &seed in &seeds {
        for (k, &(_, s)) in VARIANTS.iter().enumerate().take(4) {
            let m = measured(&config(PaperTest::IV, s, seed));
            out[k].push(m.outside_share.unwrap());
            spread[k].push(m.trace_spread.unwrap());
        }
    }
    let mut figs = vec![Figure::new(
        "p003.test4.separation_weight",
        "separation weight of the runs (ours; the text's literal rule is 1)",
        0.05,
        "",
        2,
    )];
    for (k, (tag, _)) in VARIANTS.iter().enumerate().take(4) {
        println!(
            "003 Test IV {tag}: outside {:.1?} %, trace spread {:.1?}",
            out[k].iter().map(|x| 100.0 * x).collect::<Vec<_>>(),
            spread[k]
        );
        figs.push(Figure::new(
            &format!("p003.test4.{tag}.outside"),
            "Test IV (300 boids): share of boid-steps outside the path, mean over seeds",
            f64::from(100.0 * mean(&out[k])),
            "%",
            1,
        ));
        figs.push(Figure::new(
            &format!("p003.test4.{tag}.trace_spread"),
            "Test IV: trace spread, mean over seeds",
            f64::from(mean(&spread[k])),
            "",
            1,
        ));
    }
    record_claim(
        &source(SIMILAR),
        &command(SIMILAR),
        &Seeds { tuning: vec![4], report: seeds[1..].to_vec() },
        &claim(
            "Test IV (illus. 13–16)",
            "with 300 boids Reynolds and Parker at 100, 10 and 1 % are quite similar (separation weight 0.05, ours)",
            "ours",
            Verdict::Partly,
        ),
        &figs,
    );
    let worst = |k: usize| out[k].iter().copied().fold(0.0f32, f32::max);
    let best = |k: usize| out[k].iter().copied().fold(1.0f32, f32::min);
    // Reynolds, 100 % and 10 % alike: on the path, spreads within 15 %…
    for k in 0..3 {
        assert!(worst(k) < 0.01, "{k}: {:?}", out[k]);
        assert!(mean(&spread[k]) < 1.15 * mean(&spread[0]), "{spread:?}");
    }
    // …1 % not: five times as often off the path, and wider.
    assert!(
        best(3) > 0.05 && best(3) > 5.0 * worst(0).max(worst(1)).max(worst(2)),
        "{out:?}"
    );
    assert!(mean(&spread[3]) > 1.25 * mean(&spread[0]), "{spread:?}");
}

const SWEEP: &str = "p003_test_four_at_every_separation_weight";

#[test]
fn p003_test_four_at_every_separation_weight() {
    // The presets weight the paper's separation sum by 0.05
    // (`CrowdConfig::paper`); the text's rule is the plain sum (weight 1).
    // Test IV's share of boid-steps outside the path at each weight, and
    // what the text claims of Test IV read at its own weight: 13–16 "quite
    // similar", 0.1 % "irregular [...] the relatively overwhelmingly
    // powerful separation velocity", and "the steering must be at least
    // above 10%".
    let weights = [0.01f32, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0];
    let seeds = [11u64, 12, 13];
    let mut share = vec![[0.0f32; 5]; weights.len()];
    let mut figs = vec![
        Figure::new(
            "p003.test4.separation_weight.ours",
            "the presets' separation weight",
            0.05,
            "",
            2,
        ),
        Figure::new(
            "p003.test4.separation_weight.paper",
            "the text's separation weight (its rule, unweighted)",
            1.0,
            "",
            2,
        ),
    ];
    for (w, row) in weights.iter().zip(share.iter_mut()) {
        for (k, &(tag, s)) in VARIANTS.iter().enumerate() {
            let v: Vec<f32> = seeds
                .iter()
                .map(|&seed| {
                    let mut cfg = config(PaperTest::IV, s, seed);
                    cfg.separation_weight = *w;
                    measured(&cfg).outside_share.unwrap()
                })
                .collect();
            row[k] = mean(&v);
            let wid = format!("{w}").replace('.', "_");
            figs.push(Figure::new(&format!("p003.test4.weight{wid}.{tag}.outside"), &format!("Test IV at separation weight {w}: share of boid-steps outside the path, mean over seeds"), f64::from(100.0 * row[k]), "%", 1));
        }
        println!(
            "003 Test IV, separation weight {w}: outside Reynolds / 100 / 10 / 1 / 0.1 %: {:.1?} %",
            row.map(|x| 100.0 * x)
        );
    }
    record_claim(
        &source(SWEEP),
        &command(SWEEP),
        &Seeds { tuning: vec![4], report: seeds.to_vec() },
        &claim(
            "Test IV (illus. 13–17), conclusion",
            "at the text's own separation (weight 1): 13–16 quite similar, 0.1 % overwhelmed, the steering must be at least above 10 %",
            "paper",
            Verdict::Partly,
        ),
        &figs,
    );
    let literal = share[weights.len() - 1];
    // At weight 1: Reynolds and 100 % stay on the path and 0.1 % is the
    // most overwhelmed (the conclusion holds read as "above 10 %")…
    assert!(literal[0] < 0.05 && literal[1] < 0.05, "{literal:?}");
    assert!(literal[4] > 0.5 && literal[4] > literal[3], "{literal:?}");
    // …but 10 % and 1 % leave it: 13–16 are not similar.
    assert!(literal[2] > 0.1 && literal[3] > 0.3, "{literal:?}");
    // The 10 % seek holds the path only at weights of 0.1 and below.
    for (w, row) in weights.iter().zip(&share) {
        if *w <= 0.1 {
            assert!(row[2] < 0.02, "weight {w}: {row:?}");
        } else if *w >= 0.5 {
            assert!(row[2] > 0.1, "weight {w}: {row:?}");
        }
    }
}
