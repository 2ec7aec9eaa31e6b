//! One record as the report shows it: its source, command and seeds, then
//! a table of its figures (shared by every section of `docs/FIGURES.md`).

use std::fmt::Write as _;

use super::records::Record;

/// Markdown table cell: `|` escaped, line breaks as spaces.
pub(crate) fn cell(s: &str) -> String {
    s.replace('|', "\\|").replace('\n', " ")
}

/// Seeds as ranges: `1000–1099, 2000–2099`; `—` for none.
#[must_use]
pub fn seed_ranges(seeds: &[u64]) -> String {
    let mut v = seeds.to_vec();
    v.sort_unstable();
    v.dedup();
    let mut parts = Vec::new();
    let mut i = 0;
    while i < v.len() {
        let mut j = i;
        while j + 1 < v.len() && v[j + 1] == v[j] + 1 {
            j += 1;
        }
        parts.push(if j == i {
            v[i].to_string()
        } else {
            format!("{}–{}", v[i], v[j])
        });
        i = j + 1;
    }
    if parts.is_empty() {
        "—".into()
    } else {
        parts.join(", ")
    }
}

/// The seeds line of a source: tuning and report seeds, flagged when a
/// report seed was also tuned on.
pub(crate) fn seeds_line(r: &Record) -> String {
    let s = &r.seeds;
    let overlap = s.report.iter().any(|x| s.tuning.contains(x));
    format!(
        "seeds: tuning {} / report {}{}",
        seed_ranges(&s.tuning),
        seed_ranges(&s.report),
        if overlap {
            " (reported on a tuning seed)"
        } else {
            ""
        }
    )
}

/// One source's figures as a subsection: source, command, seeds, then a
/// table of id, what, value.
pub(crate) fn source_table(out: &mut String, r: &Record, when: bool) {
    let _ = writeln!(out, "### `{}`\n", r.source);
    let _ = writeln!(out, "`{}`  ", r.command);
    let _ = write!(out, "{}", seeds_line(r));
    if when {
        let _ = write!(
            out,
            "; measured {} at commit {} on {} cores",
            r.date,
            &r.commit[..r.commit.len().min(12)],
            r.cores
        );
    }
    out.push_str("\n\n| id | what | value |\n|---|---|---|\n");
    for f in &r.figures {
        let _ = writeln!(
            out,
            "| `{}` | {} | {} |",
            f.id,
            cell(&f.what),
            cell(&f.shown())
        );
    }
    out.push('\n');
}
