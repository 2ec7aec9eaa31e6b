//! The figures report's sections beyond the papers' claims and the
//! studies: the Peers section (ours beside the libraries a user would pick
//! instead; its checked part and its timed costs) and the instruction
//! counts (records of kind [`Kind::Counted`]). `report.rs` renders the
//! report around them.

use std::collections::BTreeMap;

use super::records::{Kind, Record};
use super::report_table::source_table;

/// Whether a record belongs to the Peers section: every figure id starts
/// with `peers.` (a test, study, benchmark or browser run that measures a
/// peer beside ours joins the section by naming its figures so).
#[must_use]
pub fn is_peers(r: &Record) -> bool {
    !r.figures.is_empty() && r.figures.iter().all(|f| f.id.starts_with("peers."))
}

/// The Peers section's checked part: what it is, then the deterministic
/// peers records of the fast mode.
pub(crate) fn peers_checked(out: &mut String, fast: &BTreeMap<String, Record>) {
    out.push_str("## Peers\n\n");
    out.push_str(
        "Ours beside the libraries a user would install instead, on the same scenarios and seeds, \
         in one run. Every comparison is a count or a ratio; each table names its source and the \
         command that measures it again, and its rows name the peer's version (as the lock file \
         pins it) and settings. A row where a peer is ahead says so, and why (less work, another \
         model). The peers are dev-dependencies: none is in the library's dependency tree \
         (`cargo tree -e normal`) or in the npm package. Quality rows (below) are deterministic and \
         checked by `make test`; the costs, timed, follow the checked part. A record joins this \
         section when every one of its figure ids starts with `peers.`.\n\n",
    );
    let mut any = false;
    for r in fast
        .values()
        .filter(|r| r.kind == Kind::Deterministic && r.claim.is_none() && is_peers(r))
    {
        source_table(out, r, false);
        any = true;
    }
    if !any {
        out.push_str("No deterministic peers record yet.\n\n");
    }
}

/// The Peers section's measured part, outside the checked part: the
/// timed peers records (either mode) and the full mode's deterministic
/// ones, with where and when each was measured.
pub(crate) fn peers_measured(
    out: &mut String,
    fast: &BTreeMap<String, Record>,
    full: &BTreeMap<String, Record>,
) {
    let rs: Vec<&Record> = fast
        .values()
        .filter(|r| r.kind == Kind::Timed)
        .chain(full.values())
        .filter(|r| is_peers(r))
        .collect();
    if rs.is_empty() {
        return;
    }
    out.push_str("\n\n## Peers: costs measured in one run\n\n");
    out.push_str(
        "Ratios of times measured in the same run (ours and the peer interleaved in one process), \
         never absolute times: the commit, date and core count of the run are given, and the load of \
         the machine weighs on both sides alike.\n\n",
    );
    for r in rs {
        source_table(out, r, true);
    }
    // The next section opens with its own blank line.
    while out.ends_with('\n') {
        out.pop();
    }
}

/// The cost part's instruction counts ([`Kind::Counted`]), after the
/// timed ratios.
pub(crate) fn counted(out: &mut String, full: &BTreeMap<String, Record>) {
    let mut counted = full.values().filter(|r| r.kind == Kind::Counted).peekable();
    if counted.peek().is_none() {
        return;
    }
    out.push_str(
        "## Counted: instructions under callgrind

",
    );
    out.push_str(
        "Instructions counted by valgrind's callgrind, not timed: the same on every run of one \
         toolchain and build, and not across them, so each figure names its toolchain, and the \
         commit and date of the run are given (`make icount`).\n\n",
    );
    for r in counted {
        source_table(out, r, true);
    }
}
