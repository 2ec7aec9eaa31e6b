//! The figures report's sources and its promises:
//!
//! - the fast studies (`steer reach / relaxed / envelope / avoid --record`
//!   at small sizes on their report seeds) and the paper-figure presets
//!   run to their end write their records, so `cargo test` leaves in
//!   `target/figures` every deterministic record `steer report --check`
//!   compares with `docs/FIGURES.md` (`make test` runs that check after
//!   the native tests; `make figures` rewrites the report);
//! - every preset's `claim` and `measured` strings equal the captions of
//!   `docs/presets.json` rendered from the committed records
//!   (`docs/figures/`): the lab's preset menu, the report and the tests
//!   cannot disagree;
//! - the record format the tests write is the one the report reads, and
//!   the report refuses a bad record naming the file and the field.
#![cfg(all(feature = "cli", not(target_arch = "wasm32")))]

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use steering::base::angle::diff;
use steering::cli::records::{self, Record};
use steering::cli::report::{self, Captions};
use steering::world::scenario::Scenario;

mod common;
use common::figures::{record, Figure, Kind, Seeds};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The fast studies: each a few seconds, on the report seeds (the
/// defaults were tuned on the envelope's seed 1 and the avoidance
/// benchmarks' 1000–3999). `make figures-full` runs them at report size.
pub const FAST_STUDIES: &[&[&str]] = &[
    &["reach", "--n", "1000", "--seed", "2"],
    &["relaxed", "--n", "200"],
    &["relaxed", "--n", "200", "--aim", "paper-arc"],
    &["envelope", "--n", "200", "--seed", "2", "--brief"],
    &["avoid", "--seeds", "2", "--seed", "0"],
];

#[test]
fn fast_studies_write_their_records() {
    let dir = common::figures::dir();
    for args in FAST_STUDIES {
        let out = Command::new(env!("CARGO_BIN_EXE_steer"))
            .args(*args)
            .arg("--record")
            .env("FIGURES_DIR", &dir)
            .current_dir(root())
            .output()
            .expect("steer runs");
        assert!(
            out.status.success(),
            "steer {}: {}",
            args.join(" "),
            String::from_utf8_lossy(&out.stderr)
        );
        let (source, _) = records::steer_source_and_command(
            &args.iter().map(|s| (*s).to_string()).collect::<Vec<_>>(),
        );
        let r = Record::read(&dir.join(records::file_name(&source))).expect("record reads back");
        assert_eq!(r.source, source);
        assert!(!r.figures.is_empty(), "{source}: no figures");
        assert!(!r.seeds.report.is_empty(), "{source}: no report seeds");
    }
}

/// Every paper-figure preset (`scenarios/p0*.json`).
fn paper_presets() -> Vec<(String, Scenario)> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("scenarios"))
        .expect("scenarios/")
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.starts_with("p0") && n.ends_with(".json"))
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|n| {
            let path = root().join("scenarios").join(&n);
            let text = std::fs::read_to_string(&path).expect("preset reads");
            let sc = Scenario::from_json(&text).unwrap_or_else(|e| panic!("{n}: {e}"));
            (n.trim_end_matches(".json").to_string(), sc)
        })
        .collect()
}

fn min_max(v: &[f32]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(f64::from(x)), hi.max(f64::from(x)))
        })
}

/// One preset run to its duration, as figures: agents, finished, the final
/// distance and heading error to the last goal, finish times, mean path
/// length and integrated |curvature|, limit violations.
fn preset_figures(
    name: &str,
    sc: &Scenario,
    table: &steering::funnelling::table::lookup::EtaTable,
) -> Vec<Figure> {
    let mut w = sc.world().expect("preset builds");
    for _ in 0..sc.steps() {
        w.step(table).unwrap();
    }
    let a = w.agents();
    let n = a.len() as f64;
    let dist: Vec<f32> = a
        .iter()
        .map(|a| (a.goal_now.pos - a.state.pos).length())
        .collect();
    let head: Vec<f32> = a
        .iter()
        .map(|a| diff(a.goal_now.beta, a.state.theta).abs().to_degrees())
        .collect();
    let times: Vec<f32> = a.iter().filter_map(|a| a.finished_at).collect();
    let finished = a.iter().filter(|a| a.done()).count();
    let (d0, d1) = min_max(&dist);
    let (h0, h1) = min_max(&head);
    let id = |q: &str| format!("preset.{name}.{q}");
    let what = |q: &str| format!("preset {name} run to its end: {q}");
    let mut f = vec![
        Figure::new(&id("agents"), &what("agents"), n, "", 0),
        Figure::new(
            &id("finished"),
            &what("agents that completed every goal"),
            finished as f64,
            "",
            0,
        ),
        Figure::new(
            &id("distance.min"),
            &what("final distance to the last goal, smallest"),
            d0,
            "m",
            2,
        ),
        Figure::new(
            &id("distance.max"),
            &what("final distance to the last goal, largest"),
            d1,
            "m",
            2,
        ),
        Figure::new(
            &id("heading.min"),
            &what("final heading error to the last goal's β, smallest"),
            h0,
            "°",
            1,
        ),
        Figure::new(
            &id("heading.max"),
            &what("final heading error to the last goal's β, largest"),
            h1,
            "°",
            1,
        ),
        Figure::new(
            &id("length.mean"),
            &what("path length, mean"),
            a.iter().map(|a| f64::from(a.metrics.length)).sum::<f64>() / n,
            "m",
            1,
        ),
        Figure::new(
            &id("curvature.mean"),
            &what("integrated |curvature|, mean"),
            a.iter()
                .map(|a| f64::from(a.metrics.curvature))
                .sum::<f64>()
                / n,
            "rad",
            2,
        ),
        Figure::new(
            &id("violations"),
            &what("steps over a vehicle limit"),
            a.iter()
                .map(|a| f64::from(a.metrics.violations))
                .sum::<f64>(),
            "steps",
            0,
        ),
    ];
    if !times.is_empty() {
        let (t0, t1) = min_max(&times);
        f.push(Figure::new(
            &id("time.min"),
            &what("time to complete every goal, earliest"),
            t0,
            "s",
            1,
        ));
        f.push(Figure::new(
            &id("time.max"),
            &what("time to complete every goal, latest"),
            t1,
            "s",
            1,
        ));
    }
    f
}

#[test]
fn paper_presets_write_their_record() {
    let table = common::table();
    let mut figures = Vec::new();
    for (name, sc) in paper_presets() {
        figures.extend(preset_figures(&name, &sc, &table));
    }
    let source = "tests/figures.rs::paper_presets_write_their_record";
    record(
        source,
        "cargo test --features cli --test figures paper_presets",
        Kind::Deterministic,
        &Seeds::default(),
        &figures,
    );
    // What the tests write is what the report reads.
    let back = Record::read(&common::figures::dir().join(records::file_name(source)))
        .expect("the test's record reads as a report record");
    assert_eq!(back.figures.len(), figures.len());
    for (a, b) in back.figures.iter().zip(&figures) {
        // serde_json reads a float back to within an ulp, not always to
        // the same bits: what the report shows is what must survive.
        let shown = format!("{:.*}", usize::from(b.digits), b.value);
        assert_eq!((a.id.as_str(), a.number()), (b.id.as_str(), shown));
    }
}

/// The committed fast-mode records.
fn store() -> BTreeMap<String, Record> {
    records::read_dir(&root().join("docs/figures")).expect("docs/figures reads")
}

#[test]
fn presets_show_the_captions_rendered_from_the_committed_records() {
    let captions: Captions =
        report::read_json(&root().join("docs/presets.json")).expect("captions");
    let store = store();
    let mut covered = Vec::new();
    for c in &captions.captions {
        let measured = report::render_template(&c.measured, &store)
            .unwrap_or_else(|e| panic!("caption of {}: {e}", c.presets.join(", ")));
        for p in &c.presets {
            let path = root().join("scenarios").join(format!("{p}.json"));
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            let sc = Scenario::from_json(&text).unwrap_or_else(|e| panic!("{p}: {e}"));
            assert_eq!(
                sc.claim, c.claim,
                "{p}: `claim` is not docs/presets.json's (python3 scenarios/make_presets.py)"
            );
            assert_eq!(
                sc.measured, measured,
                "{p}: `measured` is not its caption rendered from docs/figures (python3 scenarios/make_presets.py)"
            );
            covered.push(p.clone());
        }
    }
    for (name, sc) in paper_presets() {
        assert!(
            sc.measured.is_empty() || covered.contains(&name),
            "{name} has a `measured` string that no caption of docs/presets.json renders"
        );
    }
}

/// A scratch folder of this test binary.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("steering-figures-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("scratch folder");
    d
}

fn sample(source: &str) -> Record {
    records::make(
        source.into(),
        "cargo test".into(),
        records::Kind::Deterministic,
        records::Seeds::default(),
        vec![
            records::Figure::new("x.length", "a length", 55.925, "m", 1),
            records::Figure::new("x.angle", "an angle", 4.71, "°", 1),
            records::Figure::new("x.share", "a share", 96.05, "%", 1),
        ],
    )
}

#[test]
fn templates_render_values_units_and_verdicts_and_name_what_is_missing() {
    let mut r = sample("tests/x.rs::t");
    r.claim = Some(records::Claim {
        paper: "001".into(),
        place: "Fig. 12".into(),
        claim: "shorter".into(),
        reading: "paper".into(),
        verdict: records::Verdict::Partly,
    });
    let recs = BTreeMap::from([(records::file_name(&r.source), r)]);
    let text = report::render_template(
        "{x.length} ({x.length:num}), {x.angle}, {x.share}: {verdict:tests/x.rs::t}",
        &recs,
    )
    .expect("renders");
    assert_eq!(text, "55.9 m (55.9), 4.7°, 96.0 %: partly");
    let err = report::render_template("{x.nope}", &recs).unwrap_err();
    assert!(err.contains("no figure `x.nope`"), "{err}");
    let err = report::render_template("{x.length", &recs).unwrap_err();
    assert!(err.contains("unclosed"), "{err}");
    let err = report::render_template("{verdict:tests/y.rs::t}", &recs).unwrap_err();
    assert!(
        err.contains("no record from source `tests/y.rs::t`"),
        "{err}"
    );
}

#[test]
fn bad_records_are_refused_naming_the_file_and_the_field() {
    let d = scratch("bad");
    let good = sample("steer reach --n 5");
    let path = good.write(&d).expect("writes");
    assert_eq!(
        Record::read(&path).expect("reads back").content(),
        good.content()
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let cases = [
        (
            text.replacen("\"value\": 55.925", "\"value\": null", 1),
            "`value` is null",
        ),
        (
            text.replacen("\"unit\": \"m\",", "", 1),
            "missing field `unit`",
        ),
        (
            text.replacen("\"deterministic\"", "\"fast\"", 1),
            "unknown variant `fast`",
        ),
        (
            text.replacen("\"x.angle\"", "\"x.length\"", 1),
            "`figures[1].id` `x.length` appears twice",
        ),
        (
            text.replacen("\"x.angle\"", "\"x angle\"", 1),
            "`figures[1].id`",
        ),
        (
            text.replacen("\"cores\"", "\"core\"", 1),
            "unknown field `core`",
        ),
    ];
    for (bad, want) in cases {
        std::fs::write(&path, bad).unwrap();
        let err = Record::read(&path).unwrap_err();
        assert!(
            err.contains(&path.display().to_string()) && err.contains(want),
            "{want}: {err}"
        );
    }
    // A record copied under another file name.
    std::fs::write(d.join("other.json"), &text).unwrap();
    std::fs::remove_file(&path).unwrap();
    let err = records::read_dir(&d).unwrap_err();
    assert!(
        err.contains("other.json") && err.contains("belongs in a file named"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn the_check_names_the_first_differing_row() {
    let a = format!(
        "# F\n{}\n| `x` | a | 1.0 m |\n| `y` | b | 2.0 m |\n{}\nrest\n",
        report::CHECKED_BEGIN,
        report::CHECKED_END
    );
    assert!(report::compare_checked(&a, &a.replace("rest", "other timings"), "F.md").is_ok());
    let err = report::compare_checked(&a, &a.replace("2.0 m", "2.1 m"), "F.md").unwrap_err();
    assert!(
        err.contains("F.md line 4") && err.contains("| `y` | b | 2.1 m |"),
        "{err}"
    );
    let longer = a.replace(
        "| `y` | b | 2.0 m |\n",
        "| `y` | b | 2.0 m |\n| `z` | c | 3 |\n",
    );
    let err = report::compare_checked(&a, &longer, "F.md").unwrap_err();
    assert!(
        err.contains("only in the measured records") && err.contains("`z`"),
        "{err}"
    );
}

#[test]
fn the_report_is_the_same_text_for_the_same_records() {
    let fast = BTreeMap::from([(records::file_name("tests/x.rs::t"), sample("tests/x.rs::t"))]);
    let caps = Captions {
        about: String::new(),
        captions: vec![report::Caption {
            presets: vec!["p".into()],
            claim: "c".into(),
            measured: "{x.length}".into(),
        }],
    };
    let mut later = fast.clone();
    for r in later.values_mut() {
        r.commit = "another".into();
        r.date = "2099-01-01".into();
        r.cores = 64;
    }
    let one = report::render(&fast, &BTreeMap::new(), &[], &caps).unwrap();
    let two = report::render(&later, &BTreeMap::new(), &[], &caps).unwrap();
    assert!(report::compare_checked(&one, &two, "F.md").is_ok());
    assert!(one.contains("| `p` | c | 55.9 m |"), "{one}");
    assert!(
        !one.contains("2099")
            && !two
                .split(report::CHECKED_END)
                .next()
                .unwrap()
                .contains("2099")
    );
}

#[test]
fn instruction_counts_are_reported_after_the_checked_part_under_their_own_heading() {
    let caps = Captions {
        about: String::new(),
        captions: vec![],
    };
    let mut counted = sample("benches/icount.rs");
    counted.kind = records::Kind::Counted;
    let full = BTreeMap::from([(records::file_name(&counted.source), counted)]);
    let text = report::render(&BTreeMap::new(), &full, &[], &caps).unwrap();
    let (checked, rest) = text.split_once(report::CHECKED_END).unwrap();
    assert!(!checked.contains("benches/icount.rs"), "{text}");
    let heading = rest
        .find("## Counted: instructions under callgrind")
        .expect("the counted heading");
    assert!(
        rest.find("## Timed").unwrap() < heading
            && rest[heading..].contains("### `benches/icount.rs`"),
        "{text}"
    );
    let none = report::render(&BTreeMap::new(), &BTreeMap::new(), &[], &caps).unwrap();
    assert!(!none.contains("## Counted"), "{none}");
}

/// Where test `name` starts in `text`: the `fn name(` line right after a
/// `#[test]` line, inside `mod m {` when the source names module `m`.
fn test_fn(text: &str, path: &str) -> Result<usize, String> {
    let mut parts: Vec<&str> = path.split("::").collect();
    let name = parts.pop().ok_or("no test name")?;
    let mut from = 0;
    for m in parts {
        from += text[from..]
            .find(&format!("mod {m} {{"))
            .ok_or(format!("no `mod {m}`"))?;
    }
    let at = from
        + text[from..]
            .find(&format!("fn {name}("))
            .ok_or(format!("no `fn {name}(`"))?;
    let attr = text[..at].trim_end().lines().last().unwrap_or("").trim();
    if attr == "#[test]" {
        Ok(at)
    } else {
        Err(format!(
            "`fn {name}` is not a #[test] (preceded by `{attr}`)"
        ))
    }
}

#[test]
fn every_claim_row_names_an_existing_test_that_asserts() {
    // Each row of the fidelity table is a committed claim record; its
    // `source` is the test that measured it. That test must exist as a
    // #[test] fn of the file (and module) named, spell the record's name
    // (so it is the one writing it), and assert something: a row whose
    // test was renamed or deleted, or that records without asserting,
    // fails here.
    let store = store();
    let mut rows = 0;
    let mut bad = Vec::new();
    for r in store.values() {
        if r.claim.is_none() {
            continue;
        }
        rows += 1;
        let Some((file, path)) = r.source.split_once("::") else {
            bad.push(format!("{}: source names no test (`file::test`)", r.source));
            continue;
        };
        let text = match std::fs::read_to_string(root().join(file)) {
            Ok(t) => t,
            Err(e) => {
                bad.push(format!("{}: {file}: {e}", r.source));
                continue;
            }
        };
        let name = path.rsplit("::").next().unwrap_or(path);
        match test_fn(&text, path) {
            Err(e) => bad.push(format!("{}: {e}", r.source)),
            Ok(at) => {
                let rest = &text[at..];
                let body = &rest[..rest[1..].find("#[test]").map_or(rest.len(), |e| e + 1)];
                if !text.contains(&format!("\"{name}\"")) {
                    bad.push(format!("{}: the file never spells \"{name}\"", r.source));
                }
                if !body.contains("assert") {
                    bad.push(format!("{}: the test asserts nothing", r.source));
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "claim rows without their test:\n{}",
        bad.join("\n")
    );
    // The fidelity tests' rows: 000, 001 (both readings), 003, 004.
    assert!(rows >= 38, "{rows} claim records in docs/figures");
}

#[test]
fn the_test_finder_refuses_a_missing_or_plain_fn() {
    let text = "#[test]\nfn a() {}\nfn b() {}\nmod m {\n    #[test]\n    fn c() {}\n}\n";
    assert_eq!(test_fn(text, "a"), Ok(text.find("fn a(").unwrap()));
    assert!(test_fn(text, "b").unwrap_err().contains("not a #[test]"));
    assert!(test_fn(text, "m::c").is_ok());
    assert!(test_fn(text, "m::a").is_err());
    assert!(test_fn(text, "n::c").unwrap_err().contains("no `mod n`"));
    assert!(test_fn(text, "z").unwrap_err().contains("no `fn z(`"));
}
