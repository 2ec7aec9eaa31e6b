//! `steer report`: `docs/FIGURES.md` built from the figures records
//! ([`super::records`]), and its check.
//!
//! Records live in two places: fresh ones where the tests, studies and
//! benchmarks write them (`target/figures`, and `target/figures-full` for
//! the full mode), and the committed ones (`docs/figures/`, the full
//! mode's in `docs/figures/full/`) from which the presets' `measured`
//! strings are rendered without running anything. Writing merges the
//! fresh records into the committed ones (a fresh record replaces its
//! source's), then writes the report.
//!
//! The report's *checked part* holds everything the fast mode measures
//! again in minutes and that is the same on every machine: the fidelity
//! table, the presets' captions, the deterministic figures. It carries no
//! commit or date, so `--check` can demand it byte for byte. The studies
//! at report size and the timed ratios follow it, with where and when
//! they were measured.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::Args;
use serde::Deserialize;

use super::records::{self, Figure, Kind, Record, Verdict};
use super::report_sections::{counted, is_peers, peers_checked, peers_measured};
use super::report_table::{cell, source_table};

/// First line of the checked part.
pub const CHECKED_BEGIN: &str = "<!-- checked part: begin (steer report --check) -->";
/// Last line of the checked part.
pub const CHECKED_END: &str = "<!-- checked part: end -->";

/// `steer report`.
#[derive(Args, Clone, Debug, PartialEq)]
pub struct ReportArgs {
    /// Fresh records of the fast mode (fidelity tests, fast studies).
    #[arg(long, value_name = "DIR", default_value = "target/figures")]
    pub records: PathBuf,
    /// Fresh records of the full mode (studies at report size, benchmarks).
    #[arg(long, value_name = "DIR")]
    pub full_records: Option<PathBuf>,
    /// The committed records (the full mode's in its `full/` subfolder).
    #[arg(long, value_name = "DIR", default_value = "docs/figures")]
    pub store: PathBuf,
    /// The report.
    #[arg(long, value_name = "FILE", default_value = "docs/FIGURES.md")]
    pub out: PathBuf,
    /// The claims no test can check, with the reason (hand-kept).
    #[arg(long, value_name = "FILE", default_value = "docs/not-testable.json")]
    pub not_testable: PathBuf,
    /// The presets' claims and `measured` templates.
    #[arg(long, value_name = "FILE", default_value = "docs/presets.json")]
    pub captions: PathBuf,
    /// Write nothing: rebuild the checked part from the fresh and committed
    /// records and fail, naming the first differing row, if the report's
    /// differs or a committed record has no fresh counterpart.
    #[arg(long)]
    pub check: bool,
    /// Drop committed fast-mode records that have no fresh one (their
    /// source was renamed or removed); `make figures` runs every source.
    #[arg(long, conflicts_with = "check")]
    pub prune: bool,
}

/// A claim no test can check.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NotTestable {
    /// `000`, `001`, `003` or `004`.
    pub paper: String,
    /// Where in the text.
    pub place: String,
    /// The claim.
    pub claim: String,
    /// Why no test can check it.
    pub why: String,
}

/// The caption of one or more presets: the text's claim, and what we
/// measure as a template over figure ids ([`render_template`]).
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Caption {
    /// Preset names (`scenarios/<name>.json`) the caption is shown on.
    pub presets: Vec<String>,
    /// What the text claims.
    pub claim: String,
    /// What we measure, with `{figure.id}` (value and unit),
    /// `{figure.id:num}` (value only) and `{verdict:SOURCE}` placeholders.
    pub measured: String,
}

/// The presets' captions file.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Captions {
    /// What the file is (kept for its readers).
    pub about: String,
    /// One entry per figure of the texts.
    pub captions: Vec<Caption>,
}

/// Reads a JSON file of type `T`, naming the file in every error.
///
/// # Errors
/// Unreadable or not a `T` (serde names the field and line).
pub fn read_json<T: for<'de> Deserialize<'de>>(path: &Path) -> Result<T, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Every figure of `records` by id.
///
/// # Errors
/// An id measured by two sources, naming both.
pub fn figures_by_id<'a>(
    records: impl IntoIterator<Item = &'a Record>,
) -> Result<BTreeMap<&'a str, &'a Figure>, String> {
    let mut out: BTreeMap<&str, (&Figure, &str)> = BTreeMap::new();
    for r in records {
        for f in &r.figures {
            if let Some((_, other)) = out.insert(&f.id, (f, &r.source)) {
                return Err(format!(
                    "figure id `{}` is measured by two sources: `{other}` and `{}`",
                    f.id, r.source
                ));
            }
        }
    }
    Ok(out.into_iter().map(|(k, (f, _))| (k, f)).collect())
}

/// Renders a `measured` template: `{id}` becomes the figure's value with
/// its decimals and unit, `{id:num}` the value alone, `{verdict:SOURCE}`
/// the verdict of the claim record of that source.
///
/// # Errors
/// An unclosed brace, an unknown figure id or source, naming it.
pub fn render_template(
    template: &str,
    records: &BTreeMap<String, Record>,
) -> Result<String, String> {
    let figures = figures_by_id(records.values())?;
    let mut out = String::with_capacity(template.len());
    let mut rest = template;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        let close = after
            .find('}')
            .ok_or_else(|| format!("an unclosed `{{` in `{template}`"))?;
        let key = &after[..close];
        out.push_str(&placeholder(key, &figures, records)?);
        rest = &after[close + 1..];
    }
    if rest.contains('}') {
        return Err(format!("a `}}` without `{{` in `{template}`"));
    }
    out.push_str(rest);
    Ok(out)
}

fn placeholder(
    key: &str,
    figures: &BTreeMap<&str, &Figure>,
    records: &BTreeMap<String, Record>,
) -> Result<String, String> {
    if let Some(source) = key.strip_prefix("verdict:") {
        let r = records
            .values()
            .find(|r| r.source == source)
            .ok_or_else(|| format!("`{{{key}}}`: no record from source `{source}`"))?;
        let c = r
            .claim
            .as_ref()
            .ok_or_else(|| format!("`{{{key}}}`: the record of `{source}` has no claim"))?;
        return Ok(c.verdict.name().into());
    }
    let (id, how) = key.split_once(':').unwrap_or((key, ""));
    let f = figures
        .get(id)
        .ok_or_else(|| format!("`{{{key}}}`: no figure `{id}` in the records"))?;
    match how {
        "" => Ok(f.shown()),
        "num" => Ok(f.number()),
        _ => Err(format!(
            "`{{{key}}}`: `{how}` is not a format (none, or `num`)"
        )),
    }
}

/// The fidelity section: counts, one row per claim record, the claims no
/// test can check.
fn fidelity(out: &mut String, claims: &[&Record], not_testable: &[NotTestable]) {
    out.push_str("## Fidelity: the texts' claims\n\n");
    let count = |v: Verdict| {
        claims
            .iter()
            .filter(|r| r.claim.as_ref().is_some_and(|c| c.verdict == v))
            .count()
    };
    let _ = writeln!(
        out,
        "{} claims checked by a test: {} reproduced, {} partly, {} refuted; {} not testable (below). \
         Each row is one test, which asserts the claim or asserts its refutation with the numbers shown; \
         *reading* says whether the text's literal algorithm (`paper`) or ours was measured.\n",
        claims.len(),
        count(Verdict::Reproduced),
        count(Verdict::Partly),
        count(Verdict::Refuted),
        not_testable.len()
    );
    out.push_str("| paper | place | claim | reading | our figures | verdict | test |\n");
    out.push_str("|---|---|---|---|---|---|---|\n");
    for r in claims {
        let Some(c) = &r.claim else { continue };
        let figs: Vec<String> = r
            .figures
            .iter()
            .map(|f| format!("{}: {} (`{}`)", cell(&f.what), cell(&f.shown()), f.id))
            .collect();
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} | `{}` |",
            c.paper,
            cell(&c.place),
            cell(&c.claim),
            c.reading,
            figs.join("<br>"),
            c.verdict.name(),
            r.source
        );
    }
    out.push_str("\n### Not testable\n\n");
    if not_testable.is_empty() {
        out.push_str("None.\n\n");
        return;
    }
    out.push_str("| paper | place | claim | why |\n|---|---|---|---|\n");
    for n in not_testable {
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} |",
            n.paper,
            cell(&n.place),
            cell(&n.claim),
            cell(&n.why)
        );
    }
    out.push('\n');
}

/// The presets section: each caption's claim and its rendered `measured`.
fn presets(
    out: &mut String,
    captions: &Captions,
    fast: &BTreeMap<String, Record>,
) -> Result<(), String> {
    out.push_str("## The lab's presets\n\n");
    out.push_str(
        "What the lab's side panel shows for each paper-figure preset: the text's claim, and what we \
         measure, rendered from the figures above (`scenarios/make_presets.py` writes the same strings \
         into the preset files; `tests/figures.rs` checks that they agree).\n\n",
    );
    out.push_str("| presets | claim | measured |\n|---|---|---|\n");
    for c in &captions.captions {
        let measured = render_template(&c.measured, fast)
            .map_err(|e| format!("caption of {}: {e}", c.presets.join(", ")))?;
        let _ = writeln!(
            out,
            "| {} | {} | {} |",
            c.presets
                .iter()
                .map(|p| format!("`{p}`"))
                .collect::<Vec<_>>()
                .join(" "),
            cell(&c.claim),
            cell(&measured)
        );
    }
    out.push('\n');
    Ok(())
}

/// The report's text from the fast-mode and full-mode records.
///
/// # Errors
/// A figure id measured twice, or a caption that does not render.
pub fn render(
    fast: &BTreeMap<String, Record>,
    full: &BTreeMap<String, Record>,
    not_testable: &[NotTestable],
    captions: &Captions,
) -> Result<String, String> {
    figures_by_id(fast.values())?;
    figures_by_id(full.values())?;
    let mut out = String::new();
    out.push_str(HEADER);
    out.push_str(CHECKED_BEGIN);
    out.push_str("\n\n");
    let mut claims: Vec<&Record> = fast.values().filter(|r| r.claim.is_some()).collect();
    claims.sort_by(|a, b| {
        let key = |r: &Record| r.claim.as_ref().map(|c| c.paper.clone());
        key(a).cmp(&key(b)).then_with(|| a.source.cmp(&b.source))
    });
    fidelity(&mut out, &claims, not_testable);
    presets(&mut out, captions, fast)?;
    out.push_str("## Deterministic figures\n\n");
    out.push_str("The same bits on every machine; `make test` checks them.\n\n");
    for r in fast
        .values()
        .filter(|r| r.claim.is_none() && r.kind == Kind::Deterministic && !is_peers(r))
    {
        source_table(&mut out, r, false);
    }
    peers_checked(&mut out, fast);
    out.push_str(CHECKED_END);
    peers_measured(&mut out, fast, full);
    out.push_str("\n\n## Studies at report size\n\n");
    out.push_str(
        "Deterministic too, but minutes to hours of computing: `make figures-full` measures them again \
         (not part of `make test`).\n\n",
    );
    for r in full
        .values()
        .filter(|r| r.kind == Kind::Deterministic && !is_peers(r))
    {
        source_table(&mut out, r, true);
    }
    out.push_str("## Timed: ratios of times measured in the same run\n\n");
    out.push_str(
        "Each figure is a ratio of times measured in the same run (a baseline beside the measured \
         operation, one process), never an absolute time: it depends on the machine and its load, so \
         the commit, date and core count of the run are given.\n\n",
    );
    for r in fast
        .values()
        .chain(full.values())
        .filter(|r| r.kind == Kind::Timed && !is_peers(r))
    {
        source_table(&mut out, r, true);
    }
    counted(&mut out, full);
    Ok(out.trim_end().to_string() + "\n")
}

const HEADER: &str = "# Figures

Generated by `steer report` from the records in `docs/figures/`: do not edit by hand.
`make figures` measures the fast part again in a few minutes (the fidelity tests and the
fast studies) and rewrites this file; `make figures-full` adds the studies at their report
sizes and the benchmarks' timings; `make test` fails when the checked part below differs
from what the tests measure.

Every figure comes from a record: what was measured, the command that measures it again, and
its seeds. *Tuning* seeds are those the defaults were chosen on, *report* seeds those the
figure is measured on; a figure measured on a tuning seed says so.

";

/// The lines of `text` between the checked part's markers.
fn checked_part(text: &str) -> Option<Vec<&str>> {
    let mut lines = text.lines();
    lines.by_ref().find(|l| *l == CHECKED_BEGIN)?;
    let part: Vec<&str> = lines.by_ref().take_while(|l| *l != CHECKED_END).collect();
    Some(part)
}

/// Compares the checked parts of the committed report and the rebuilt one.
///
/// # Errors
/// The first differing row, both versions shown.
pub fn compare_checked(committed: &str, rebuilt: &str, name: &str) -> Result<(), String> {
    let fix = "run `make figures` and commit docs/FIGURES.md and docs/figures/";
    let ours = checked_part(rebuilt).ok_or("the rebuilt report has no checked part")?;
    let theirs = checked_part(committed)
        .ok_or_else(|| format!("{name} has no checked part (`{CHECKED_BEGIN}`): {fix}"))?;
    let offset = committed
        .lines()
        .position(|l| l == CHECKED_BEGIN)
        .unwrap_or(0)
        + 2;
    for (i, (a, b)) in theirs.iter().zip(&ours).enumerate() {
        if a != b {
            return Err(format!(
                "{name} line {} differs from the records:\n  committed: {a}\n  measured:  {b}\n{fix}",
                offset + i
            ));
        }
    }
    if theirs.len() != ours.len() {
        let (which, row) = if theirs.len() > ours.len() {
            ("only in the committed report", theirs[ours.len()])
        } else {
            ("only in the measured records", ours[theirs.len()])
        };
        return Err(format!(
            "{name} line {}: a row {which}:\n  {row}\n{fix}",
            offset + theirs.len().min(ours.len())
        ));
    }
    Ok(())
}

/// `fresh` over `stored`: a fresh record replaces its source's.
#[must_use]
pub fn merge(
    stored: &BTreeMap<String, Record>,
    fresh: &BTreeMap<String, Record>,
) -> BTreeMap<String, Record> {
    let mut out = stored.clone();
    out.extend(fresh.iter().map(|(k, v)| (k.clone(), v.clone())));
    out
}

/// Writes `records` into `dir`, leaving a file untouched when only its
/// commit, date or cores would change (so a rerun does not churn the
/// committed records), and removes the `*.json` records not in the set.
fn sync_store(
    dir: &Path,
    records: &BTreeMap<String, Record>,
    stored: &BTreeMap<String, Record>,
) -> Result<(), String> {
    for (name, r) in records {
        if stored.get(name).is_some_and(|s| s.content() == r.content()) {
            continue;
        }
        r.write(dir)?;
    }
    for name in stored.keys().filter(|n| !records.contains_key(*n)) {
        let p = dir.join(name);
        std::fs::remove_file(&p).map_err(|e| format!("cannot remove {}: {e}", p.display()))?;
    }
    Ok(())
}

/// Runs `steer report`: writes the report and the committed records, or
/// with `--check` compares. Returns what to print.
///
/// # Errors
/// A bad record, captions or not-testable file (named), a caption naming
/// an unknown figure, a failed write, or a failed check.
pub fn run(args: &ReportArgs) -> Result<String, String> {
    let full_dir = args.store.join("full");
    let stored = records::read_dir(&args.store)?;
    let stored_full = records::read_dir(&full_dir)?;
    let fresh = records::read_dir(&args.records)?;
    let fresh_full = match &args.full_records {
        Some(d) => records::read_dir(d)?,
        None => BTreeMap::new(),
    };
    let not_testable: Vec<NotTestable> = read_json(&args.not_testable)?;
    let captions: Captions = read_json(&args.captions)?;
    if args.check {
        return check(
            args,
            &stored,
            &fresh,
            &stored_full,
            &not_testable,
            &captions,
        );
    }
    if fresh.is_empty() && fresh_full.is_empty() {
        return Err(format!(
            "no records in {}{}: run what writes them first (`make figures`)",
            args.records.display(),
            args.full_records
                .as_ref()
                .map_or(String::new(), |d| format!(" or {}", d.display()))
        ));
    }
    let fast = if args.prune {
        fresh.clone()
    } else {
        merge(&stored, &fresh)
    };
    let full = merge(&stored_full, &fresh_full);
    let text = render(&fast, &full, &not_testable, &captions)?;
    sync_store(&args.store, &fast, &stored)?;
    sync_store(&full_dir, &full, &stored_full)?;
    records::write_atomically(&args.out, &text)?;
    Ok(format!(
        "steer report: {} fast-mode and {} full-mode records -> {}",
        fast.len(),
        full.len(),
        args.out.display()
    ))
}

/// Where the browser suites' records come from (their `source` prefix).
const BROWSER_SOURCES: &str = "web/test/";

fn check(
    args: &ReportArgs,
    stored: &BTreeMap<String, Record>,
    fresh: &BTreeMap<String, Record>,
    stored_full: &BTreeMap<String, Record>,
    not_testable: &[NotTestable],
    captions: &Captions,
) -> Result<String, String> {
    let fix = "run `make figures` and commit docs/FIGURES.md and docs/figures/";
    // Timed records come from benchmarks, which the fast mode does not run;
    // the browser suites' records (sources in web/test/) are measured after
    // the native tests, and each suite compares its own with the committed
    // ones (web/test/records.mjs `committedFigures`): absent here, they are
    // taken as committed.
    let deterministic = stored.iter().filter(|(_, s)| s.kind == Kind::Deterministic);
    for (name, s) in deterministic {
        match fresh.get(name) {
            None if s.source.starts_with(BROWSER_SOURCES) => {}
            None => {
                return Err(format!(
                    "{}: no fresh record of `{}` in {} (its source did not run, or was renamed or removed): {fix}",
                    args.store.join(name).display(),
                    s.source,
                    args.records.display()
                ))
            }
            Some(f) if f.kind == Kind::Deterministic && f.content() != s.content() => {
                return Err(format!(
                    "{}: `{}` now measures other figures than the committed record: {fix}",
                    args.store.join(name).display(),
                    s.source
                ))
            }
            Some(_) => {}
        }
    }
    let rebuilt = render(&merge(stored, fresh), stored_full, not_testable, captions)?;
    let committed = std::fs::read_to_string(&args.out)
        .map_err(|e| format!("cannot read {}: {e}", args.out.display()))?;
    compare_checked(&committed, &rebuilt, &args.out.display().to_string())?;
    Ok(format!(
        "steer report --check: {} records agree with {}",
        fresh.len(),
        args.out.display()
    ))
}
