//! Figures as records: the JSON a test, a study (`steer … --record`) or a
//! benchmark writes for each thing it measured, and what `steer report`
//! reads to build `docs/FIGURES.md` and the presets' `measured` strings, so
//! no figure is typed by hand.
//!
//! One file per source, named after it (`tests/fidelity.rs::p001_fig10` →
//! `tests_fidelity.rs__p001_fig10.json`); the tests write the same format
//! with `tests/common/figures.rs`:
//!
//! ```json
//! { "source": "steer reach --n 1000 --seed 2",
//!   "command": "cargo run --release --features cli --bin steer -- reach --n 1000 --seed 2 --record",
//!   "kind": "deterministic",
//!   "seeds": { "tuning": [1], "report": [2] },
//!   "commit": "4dd0f3d…", "date": "2026-12-04", "cores": 2,
//!   "figures": [ { "id": "reach.radius8-g2-t0.25.oriented", "what": "…",
//!                  "value": 96.1, "unit": "%", "digits": 1 } ] }
//! ```
//!
//! A fidelity test adds `"claim": { "paper", "place", "claim", "reading":
//! "paper"|"ours", "verdict": "reproduced"|"partly"|"refuted" }`. `kind` is
//! `deterministic` (the same bits on every machine), `timed` (a ratio of
//! times measured in one run) or `counted` (instructions under callgrind,
//! the same for one toolchain and build). `commit`, `date` and `cores` say where the
//! record was made; the report keeps them out of the deterministic rows so
//! that those rows are byte-stable.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Deserializer, Serialize};

/// One measured number.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Figure {
    /// Stable dotted key (`p001.fig10.beta45.relaxed.length`); presets and
    /// the report refer to figures by it.
    pub id: String,
    /// One line: what is measured, on which input.
    pub what: String,
    /// The value (finite: a NaN or an infinity is written as `null`, which
    /// reading refuses).
    #[serde(deserialize_with = "finite")]
    pub value: f64,
    /// Its unit (`m`, `°`, `%`, `runs`, `×`; empty for a pure number).
    pub unit: String,
    /// Decimals shown.
    pub digits: u8,
}

fn finite<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    match Option::<f64>::deserialize(d)? {
        Some(v) if v.is_finite() => Ok(v),
        _ => Err(serde::de::Error::custom(
            "`value` is null: the source measured NaN or an infinity",
        )),
    }
}

impl Figure {
    /// A figure with `digits` decimals shown.
    #[must_use]
    pub fn new(id: &str, what: &str, value: f64, unit: &str, digits: u8) -> Self {
        Self {
            id: id.into(),
            what: what.into(),
            value,
            unit: unit.into(),
            digits,
        }
    }

    /// The value with its decimals and unit, as the report and the presets
    /// show it: `0.22 m`, `4.7°`, `96.1 %`, `3` (a space before every unit
    /// but the degree sign).
    #[must_use]
    pub fn shown(&self) -> String {
        let n = self.number();
        match self.unit.as_str() {
            "" => n,
            "°" => n + "°",
            u => format!("{n} {u}"),
        }
    }

    /// The value with its decimals, without the unit.
    #[must_use]
    pub fn number(&self) -> String {
        format!("{:.*}", usize::from(self.digits), self.value)
    }
}

/// The seeds a record was measured on: those its parameters were chosen on
/// (`tuning`) and those it reports (`report`). Both empty for a fixed preset.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Seeds {
    /// Seeds the parameters behind the figures were tuned on.
    pub tuning: Vec<u64>,
    /// Seeds the figures are reported on.
    pub report: Vec<u64>,
}

/// A fidelity record's conclusion.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Verdict {
    /// The claim holds, asserted by the test.
    Reproduced,
    /// Part of it holds; the test asserts which part.
    Partly,
    /// It does not hold; the test asserts the refutation.
    Refuted,
}

impl Verdict {
    /// As the report writes it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Reproduced => "reproduced",
            Self::Partly => "partly",
            Self::Refuted => "refuted",
        }
    }
}

/// The claim of one of the four texts a fidelity test checks.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Claim {
    /// `000`, `001`, `003` or `004`.
    pub paper: String,
    /// Where in the text: `Fig. 10`, `§5`, `Table 1`.
    pub place: String,
    /// The claim in a sentence.
    pub claim: String,
    /// `paper` (the text's literal algorithm) or `ours`.
    pub reading: String,
    /// The conclusion.
    pub verdict: Verdict,
}

/// Deterministic figures or same-run timing ratios.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Kind {
    /// The same bits on every machine.
    Deterministic,
    /// A ratio of times measured in one run.
    Timed,
    /// Instructions counted under callgrind: the same on every run of one
    /// toolchain and build, not across them (the figures name the
    /// toolchain).
    Counted,
}

/// One source's record.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Record {
    /// What measured: `tests/<file>.rs::<test>`, `steer <subcommand> …`,
    /// `benches/<file>.rs`.
    pub source: String,
    /// The command that writes this record again.
    pub command: String,
    /// Deterministic or timed.
    pub kind: Kind,
    /// Tuning and report seeds.
    pub seeds: Seeds,
    /// `git rev-parse HEAD` when written.
    pub commit: String,
    /// UTC date when written, `YYYY-MM-DD`.
    pub date: String,
    /// Cores of the machine that wrote it.
    pub cores: usize,
    /// A fidelity record's claim.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub claim: Option<Claim>,
    /// The figures.
    pub figures: Vec<Figure>,
}

/// The file a source's record lives in: every character but ASCII letters,
/// digits, `.`, `-` and `_` becomes `_` (`tests/fidelity.rs::x` →
/// `tests_fidelity.rs__x.json`, as `tests/common/figures.rs` names it).
#[must_use]
pub fn file_name(source: &str) -> String {
    let stem: String = source
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '_') {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{stem}.json")
}

/// Whether `id` is dotted segments of ASCII letters, digits, `_` and `-`.
fn valid_id(id: &str) -> bool {
    !id.is_empty()
        && id.split('.').all(|s| {
            !s.is_empty()
                && s.chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-'))
        })
}

impl Record {
    /// What is wrong with the record, naming the field; `None` if nothing.
    #[must_use]
    pub fn problem(&self) -> Option<String> {
        if self.source.trim().is_empty() {
            return Some("`source` is empty".into());
        }
        if self.command.trim().is_empty() {
            return Some("`command` is empty".into());
        }
        if let Some(c) = &self.claim {
            if !["000", "001", "003", "004"].contains(&c.paper.as_str()) {
                return Some(format!(
                    "`claim.paper` is `{}`, not one of 000, 001, 003, 004",
                    c.paper
                ));
            }
            if !["paper", "ours"].contains(&c.reading.as_str()) {
                return Some(format!(
                    "`claim.reading` is `{}`, neither paper nor ours",
                    c.reading
                ));
            }
            for (name, v) in [("place", &c.place), ("claim", &c.claim)] {
                if v.trim().is_empty() {
                    return Some(format!("`claim.{name}` is empty"));
                }
            }
        }
        let mut seen = std::collections::BTreeSet::new();
        for (i, f) in self.figures.iter().enumerate() {
            if !valid_id(&f.id) {
                return Some(format!(
                    "`figures[{i}].id` `{}` is not dotted segments of letters, digits, _ and -",
                    f.id
                ));
            }
            if !seen.insert(f.id.as_str()) {
                return Some(format!("`figures[{i}].id` `{}` appears twice", f.id));
            }
            if f.what.trim().is_empty() {
                return Some(format!("`figures[{i}].what` ({}) is empty", f.id));
            }
            if f.digits > 9 {
                return Some(format!(
                    "`figures[{i}].digits` ({}) is {}, more than 9",
                    f.id, f.digits
                ));
            }
        }
        None
    }

    /// Reads and checks the record in `path`.
    ///
    /// # Errors
    /// Unreadable, not a record (the message names the field and the line),
    /// a field out of range, or a file not named after its source.
    pub fn read(path: &Path) -> Result<Self, String> {
        let shown = path.display();
        let text =
            std::fs::read_to_string(path).map_err(|e| format!("cannot read {shown}: {e}"))?;
        let r: Self = serde_json::from_str(&text).map_err(|e| format!("{shown}: {e}"))?;
        if let Some(p) = r.problem() {
            return Err(format!("{shown}: {p}"));
        }
        let want = file_name(&r.source);
        if path.file_name().and_then(|n| n.to_str()) != Some(want.as_str()) {
            return Err(format!(
                "{shown}: its `source` `{}` belongs in a file named {want}",
                r.source
            ));
        }
        Ok(r)
    }

    /// Pretty JSON, with the seed lists on one line each.
    ///
    /// # Errors
    /// Never in practice (serde_json on plain data).
    pub fn to_json(&self) -> Result<String, String> {
        let text = serde_json::to_string_pretty(self).map_err(|e| e.to_string())?;
        Ok(fold_number_lists(&text))
    }

    /// Writes the record into `dir` (created if missing), replacing the
    /// previous one atomically: a temporary file renamed over it, so no
    /// half-written record is ever read.
    ///
    /// # Errors
    /// The folder or the file cannot be written.
    pub fn write(&self, dir: &Path) -> Result<PathBuf, String> {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        let path = dir.join(file_name(&self.source));
        write_atomically(&path, &(self.to_json()? + "\n"))?;
        Ok(path)
    }

    /// The record without where and when it was made (commit, date,
    /// cores): what a regenerated record must equal to leave its stored
    /// copy untouched.
    #[must_use]
    pub fn content(&self) -> Self {
        Self {
            commit: String::new(),
            date: String::new(),
            cores: 0,
            ..self.clone()
        }
    }
}

/// Writes `text` to `path` through a temporary file in the same folder
/// renamed over it.
///
/// # Errors
/// Either step fails (the temporary file is removed).
pub fn write_atomically(path: &Path, text: &str) -> Result<(), String> {
    let name = path
        .file_name()
        .map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned());
    let tmp = path.with_file_name(format!(".{name}.tmp"));
    std::fs::write(&tmp, text).map_err(|e| format!("cannot write {}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("cannot write {}: {e}", path.display())
    })
}

/// Joins the lines of arrays that hold only numbers (`"tuning": [\n 1,\n
/// 2\n ]` → `"tuning": [1, 2]`): a report seed range of 100 stays one line.
fn fold_number_lists(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        if line.trim_end().ends_with('[') {
            let mut items = Vec::new();
            let mut close = None;
            let mut ahead = lines.clone();
            for l in ahead.by_ref() {
                let t = l.trim();
                if t.starts_with(']') {
                    close = Some(t.to_string());
                    break;
                }
                let v = t.trim_end_matches(',');
                if v.parse::<f64>().is_err() {
                    break;
                }
                items.push(v.to_string());
            }
            if let Some(close) = close {
                let _ = writeln!(out, "{}{}{close}", line.trim_end(), items.join(", "));
                lines = ahead;
                continue;
            }
        }
        out.push_str(line);
        out.push('\n');
    }
    out.pop();
    out
}

/// Every record in `dir` (`*.json`, not descending into subfolders), keyed
/// by file name; an empty map if `dir` does not exist.
///
/// # Errors
/// The first file that is not a valid record, named.
pub fn read_dir(dir: &Path) -> Result<BTreeMap<String, Record>, String> {
    let mut out = BTreeMap::new();
    let entries = match std::fs::read_dir(dir) {
        Ok(e) => e,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(out),
        Err(e) => return Err(format!("cannot read {}: {e}", dir.display())),
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    for p in paths {
        let r = Record::read(&p)?;
        out.insert(file_name(&r.source), r);
    }
    Ok(out)
}

/// Where records go: `$FIGURES_DIR`, else `target/figures` (relative to
/// the working folder, the repository root for the Makefile).
#[must_use]
pub fn dir() -> PathBuf {
    std::env::var_os("FIGURES_DIR").map_or_else(|| PathBuf::from("target/figures"), PathBuf::from)
}

/// `git rev-parse HEAD`, or `unknown` outside a repository.
#[must_use]
pub fn commit() -> String {
    std::process::Command::new("git")
        .args(["rev-parse", "HEAD"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map_or_else(
            || "unknown".into(),
            |o| String::from_utf8_lossy(&o.stdout).trim().to_string(),
        )
}

/// Today's date (UTC), `YYYY-MM-DD`, from the system clock (days since the
/// epoch to a civil date, H. Hinnant's algorithm; no date crate needed).
#[must_use]
pub fn date() -> String {
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

/// A shell word: as is when plain, else in single quotes.
fn shell_word(a: &str) -> String {
    let plain = !a.is_empty()
        && a.chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+@%".contains(c));
    if plain {
        a.to_string()
    } else {
        format!("'{}'", a.replace('\'', r"'\''"))
    }
}

/// `steer`'s own arguments as a record's source and command: the source
/// is `steer` and the arguments without `--record`, `--threads` and `--brief`
/// (none changes a figure); the command is the cargo line that writes
/// the record again.
#[must_use]
pub fn steer_source_and_command(args: &[String]) -> (String, String) {
    let mut kept = Vec::new();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        if a == "--record" || a == "--brief" || a.starts_with("--threads=") {
            continue;
        }
        if a == "--threads" {
            it.next();
            continue;
        }
        kept.push(shell_word(a));
    }
    let joined = kept.join(" ");
    (
        format!("steer {joined}"),
        format!("cargo run --release --features cli --bin steer -- {joined} --record"),
    )
}

/// A record made by this process now (commit, date and cores filled in).
#[must_use]
pub fn make(
    source: String,
    command: String,
    kind: Kind,
    seeds: Seeds,
    figures: Vec<Figure>,
) -> Record {
    Record {
        source,
        command,
        kind,
        seeds,
        commit: commit(),
        date: date(),
        cores: std::thread::available_parallelism().map_or(1, usize::from),
        claim: None,
        figures,
    }
}

/// `--record`, shared by the `steer` subcommands that measure.
#[derive(clap::Args, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RecordArgs {
    /// Also write the printed summary as a figures record into
    /// `$FIGURES_DIR` (default `target/figures`), for `steer report`.
    #[arg(long)]
    pub record: bool,
}

impl RecordArgs {
    /// With `--record`: writes a deterministic record of `figures`, its
    /// source and command taken from this process's arguments, and says
    /// where on standard error.
    ///
    /// # Errors
    /// A record that does not validate, or a failed write.
    pub fn write(&self, seeds: Seeds, figures: Vec<Figure>) -> Result<(), String> {
        if !self.record {
            return Ok(());
        }
        let args: Vec<String> = std::env::args().skip(1).collect();
        let (source, command) = steer_source_and_command(&args);
        let r = make(source, command, Kind::Deterministic, seeds, figures);
        if let Some(p) = r.problem() {
            return Err(format!("record of `{}`: {p}", r.source));
        }
        let path = r.write(&dir())?;
        eprintln!("steer: record -> {}", path.display());
        Ok(())
    }
}
