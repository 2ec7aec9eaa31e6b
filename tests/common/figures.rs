//! Figures as records: what a test or a study measured, written as JSON
//! where the figures report (`steer report`, `make figures`) reads them, so
//! no figure in `docs/FIGURES.md`, the README or a preset's `measured`
//! string is typed by hand.
//!
//! One file per source, `target/figures/<source>.json`, rewritten each time
//! the source runs (a test that is renamed leaves a stale file behind, which
//! `make figures` clears first):
//!
//! ```json
//! { "source": "tests/fidelity.rs::p001_fig10_relaxed_paths",
//!   "command": "cargo test --release --features cli --test fidelity p001_fig10",
//!   "kind": "deterministic",
//!   "seeds": { "tuning": [], "report": [] },
//!   "commit": "4dd0f3d…", "date": "2026-12-04", "cores": 2,
//!   "claim": { "paper": "001", "place": "Fig. 10", "claim": "…",
//!              "reading": "paper", "verdict": "refuted" },
//!   "figures": [ { "id": "p001.fig10.beta45.relaxed.length", "what": "…",
//!                  "value": 55.9, "unit": "m", "digits": 1 } ] }
//! ```
//!
//! `kind` is `deterministic` (the same bits on every machine: counts,
//! simulated outcomes) or `timed` (a ratio of times measured in the same
//! run). Only deterministic figures are compared byte for byte by
//! `make figures`' check; `commit`, `date` and `cores` say where a record
//! was made and are not part of that comparison.
#![allow(dead_code)]

use std::path::PathBuf;

use serde::Serialize;

/// One measured number.
#[derive(Clone, Debug, Serialize)]
pub struct Figure {
    /// Stable key, dotted: paper, figure, case, quantity
    /// (`p001.fig10.beta45.relaxed.length`). Presets and the report refer
    /// to figures by it.
    pub id: String,
    /// One line: what is measured, on which input.
    pub what: String,
    /// The value.
    pub value: f64,
    /// Its unit (`m`, `°`, `%`, `runs`, `×`; empty for a pure number).
    pub unit: String,
    /// Decimals the report shows.
    pub digits: u8,
}

impl Figure {
    /// A figure with `digits` decimals shown.
    pub fn new(id: &str, what: &str, value: f64, unit: &str, digits: u8) -> Self {
        Self {
            id: id.into(),
            what: what.into(),
            value,
            unit: unit.into(),
            digits,
        }
    }
}

/// The seeds a figure was measured on: the ones its parameters were chosen
/// on (`tuning`) and the held-out ones it reports (`report`). Both empty for
/// a fixed preset.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Seeds {
    /// Seeds the parameters behind the figure were tuned on.
    pub tuning: Vec<u64>,
    /// Seeds the figure is reported on (never tuned on).
    pub report: Vec<u64>,
}

/// What a fidelity record concludes about a paper's claim.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub enum Verdict {
    /// The claim holds on our measurement, asserted by the test.
    Reproduced,
    /// Part of the claim holds; the test asserts which part, with numbers.
    Partly,
    /// The claim does not hold; the test asserts the refutation, with numbers.
    Refuted,
}

/// A claim of one of the four texts and what the test that writes the
/// record concludes (the fidelity table's row).
#[derive(Clone, Debug, Serialize)]
pub struct Claim {
    /// `000`, `001`, `003` or `004`.
    pub paper: String,
    /// Where in the text: `Fig. 10`, `§5`, `Table 1`.
    pub place: String,
    /// The claim in a sentence, as the text makes it.
    pub claim: String,
    /// Which reading of the algorithm was measured: `paper` (the text's
    /// literal algorithm against its literal baseline) or `ours`.
    pub reading: String,
    /// The conclusion, asserted by the test.
    pub verdict: Verdict,
}

/// Deterministic, a same-run timing ratio, or an instruction count.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub enum Kind {
    /// The same bits on every machine.
    Deterministic,
    /// A ratio of times measured in one run.
    Timed,
    /// Instructions counted under callgrind: the same for one toolchain
    /// and build (`benches/icount.rs`).
    Counted,
}

#[derive(Serialize)]
struct Record<'a> {
    source: &'a str,
    command: &'a str,
    kind: Kind,
    seeds: &'a Seeds,
    commit: String,
    date: String,
    cores: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    claim: Option<&'a Claim>,
    figures: &'a [Figure],
}

/// Where records go: `$FIGURES_DIR`, else `target/figures`.
pub fn dir() -> PathBuf {
    std::env::var_os("FIGURES_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/figures"))
}

fn commit() -> String {
    std::process::Command::new("git")
        .args(["rev-parse", "HEAD"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map_or_else(
            || "unknown".into(),
            |o| String::from_utf8_lossy(&o.stdout).trim().to_string(),
        )
}

/// Today's date (UTC), `YYYY-MM-DD`, from the system clock (days since the
/// epoch to a civil date, H. Hinnant's algorithm).
fn date() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

/// Writes the record of `source` (`tests/fidelity.rs::test_name`), run by
/// `command`, replacing the previous one atomically (a temporary file
/// renamed over it). Figures are also printed, for `--nocapture` readers.
pub fn record(source: &str, command: &str, kind: Kind, seeds: &Seeds, figures: &[Figure]) {
    write(source, command, kind, seeds, None, figures);
}

/// [`record`] for a benchmark's same-run ratios, one record per claim:
/// source `benches/<bench>.rs::<name>`, kind `timed`, the inputs' seeds
/// fixed (none reported). Written only when `FIGURES_DIR` is set (by
/// `make figures-full`), so a plain `cargo bench` leaves no record behind.
pub fn record_timed(bench: &str, name: &str, figures: &[Figure]) {
    if std::env::var_os("FIGURES_DIR").is_none() {
        return;
    }
    record(
        &format!("benches/{bench}.rs::{name}"),
        &format!("FIGURES_DIR=target/figures cargo bench --features cli,counters --bench {bench}"),
        Kind::Timed,
        &Seeds::default(),
        figures,
    );
}

/// [`record`] for a fidelity test: the claim it checks and its verdict too
/// (one row of the fidelity table).
pub fn record_claim(source: &str, command: &str, seeds: &Seeds, claim: &Claim, figures: &[Figure]) {
    write(
        source,
        command,
        Kind::Deterministic,
        seeds,
        Some(claim),
        figures,
    );
}

fn write(
    source: &str,
    command: &str,
    kind: Kind,
    seeds: &Seeds,
    claim: Option<&Claim>,
    figures: &[Figure],
) {
    for f in figures {
        println!(
            "{}: {:.*} {} ({})",
            f.id, f.digits as usize, f.value, f.unit, f.what
        );
    }
    // In the browser there is no file system and no clock to stamp a
    // record with: the same tests' native run writes the records.
    if cfg!(target_arch = "wasm32") {
        return;
    }
    let rec = Record {
        source,
        command,
        kind,
        seeds,
        commit: commit(),
        date: date(),
        cores: std::thread::available_parallelism().map_or(1, usize::from),
        claim,
        figures,
    };
    let dir = dir();
    std::fs::create_dir_all(&dir).expect("figures directory");
    let name = source.replace(['/', ':'], "_");
    let path = dir.join(format!("{name}.json"));
    let tmp = dir.join(format!(".{name}.json.tmp"));
    let text = serde_json::to_string_pretty(&rec).expect("record serialises");
    std::fs::write(&tmp, text + "\n").expect("record written");
    std::fs::rename(&tmp, &path).expect("record in place");
}
