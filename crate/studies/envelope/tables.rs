//! The envelope report as people read it: markdown tables per cell, the
//! targets the controllers are held to, and the per-cell JSON.

use core::fmt::Write as _;

use super::report::missed;
use super::report::{summarise, CellSummary, EnvelopeReport, MISSES_KEPT};
use super::{GoalKind, RunRecord, BANDS, D_TOLS, EPS_TOLS_DEG, SPEEDS};

/// The static cells of `runs` in distance band `band` (`None`: all D):
/// (ε_tol in degrees, column, column value, summary) for every ε_tol ×
/// D_tol and ε_tol × desired-speed cell, in that order.
fn static_cells(
    runs: &[RunRecord],
    band: Option<usize>,
) -> Vec<(f32, &'static str, f32, CellSummary)> {
    type Column = (&'static str, &'static [f32], fn(&RunRecord) -> f32);
    let columns: [Column; 2] = [
        ("dTol", &D_TOLS, |r| r.d_tol),
        ("speed", &SPEEDS, |r| r.speed),
    ];
    let mut out = Vec::new();
    for e in EPS_TOLS_DEG {
        for (key, values, f) in columns {
            for &c in values {
                let sum = summarise(runs.iter().filter(|r| {
                    band.is_none_or(|b| band_of(r.d0) == b)
                        && r.eps_tol_deg.round() == e
                        && f(r) == c
                }));
                out.push((e, key, c, sum));
            }
        }
    }
    out
}

fn band_of(d: f32) -> usize {
    BANDS
        .iter()
        .position(|&(_, hi)| d < hi)
        .unwrap_or(BANDS.len() - 1)
}

fn pct(x: f32) -> String {
    if x.is_nan() {
        "—".into()
    } else {
        format!("{:.1}", 100.0 * x)
    }
}

/// The summary row of a group, markdown.
fn summary_row(name: &str, kind: GoalKind, s: &CellSummary) -> String {
    format!(
        "| {name} | {} | {} ({} inside) | {} % | {} % | {:.1} / {:.1} | {} % | {} % ({}) | {} % | {:.3} / {:.3} | {} | {} | {} |",
        kind.name(),
        s.n,
        s.n_inside,
        pct(s.reach),
        pct(s.oriented),
        s.entry_err_deg.0,
        s.entry_err_deg.1,
        pct(s.eos_ok),
        pct(s.rest_ok),
        s.n_halting,
        pct(s.finished),
        s.length_ratio.0,
        s.length_ratio.1,
        s.nan,
        s.violations,
        s.orbits
    )
}

const SUMMARY_HEAD: &str = "| variant | group | n | reach | oriented on entry (of runs starting outside) | entry err med / p90 (°) | EoS in both tol | halting at rest in both tol (n) | finished | length/Dubins med / p90 | NaN | violations | orbits |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|";

/// Oriented-on-entry matrix of static runs in `band` (`None`: all D):
/// rows ε_tol, columns from `col` (D_tol or desired speed).
fn matrix(
    runs: &[RunRecord],
    band: Option<usize>,
    col_name: &str,
    cols: &[f32],
    col: fn(&RunRecord) -> f32,
) -> String {
    let mut s = format!("| ε_tol \\ {col_name} |");
    for c in cols {
        let _ = write!(s, " {c} |");
    }
    s.push_str(" all |\n|---|");
    for _ in 0..=cols.len() {
        s.push_str("---|");
    }
    s.push('\n');
    let in_band = |r: &&RunRecord| band.is_none_or(|b| band_of(r.d0) == b);
    let cell = |f: &dyn Fn(&RunRecord) -> bool| {
        let c = summarise(runs.iter().filter(in_band).filter(|r| f(r)));
        format!(" {} ({}) |", pct(c.oriented), c.n - c.n_inside)
    };
    for e in EPS_TOLS_DEG {
        let _ = write!(s, "| {e}° |");
        for &c in cols {
            s.push_str(&cell(&|r| r.eps_tol_deg.round() == e && col(r) == c));
        }
        s.push_str(&cell(&|r| r.eps_tol_deg.round() == e));
        s.push('\n');
    }
    s.push_str("| all |");
    for &c in cols {
        s.push_str(&cell(&|r| col(r) == c));
    }
    s.push_str(&cell(&|_| true));
    s.push('\n');
    s
}

impl EnvelopeReport {
    /// The tables, markdown: one summary row per variant and group, then
    /// for each variant named in `detail` the oriented-on-entry share of
    /// the static group per cell (percent, with the run count): ε_tol ×
    /// D_tol and ε_tol × desired speed, for each distance band and all D.
    #[must_use]
    pub fn tables(&self, detail: &[&str]) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "envelope study: seed {}, limit {} s per goal",
            self.seed, self.max_time
        );
        s.push_str(SUMMARY_HEAD);
        s.push('\n');
        for v in &self.variants {
            for g in &v.groups {
                s.push_str(&summary_row(v.name, g.kind, &summarise(&g.runs)));
                s.push('\n');
            }
        }
        for v in self.variants.iter().filter(|v| detail.contains(&v.name)) {
            let runs = v.runs(GoalKind::Static);
            let bands = BANDS
                .iter()
                .enumerate()
                .map(|(i, &(lo, hi))| (Some(i), format!("D {lo}–{hi} m")))
                .chain(core::iter::once((None, "all D".to_string())));
            for (band, label) in bands {
                let _ = writeln!(
                    s,
                    "\n{}, static, {label}: oriented on entry, % (runs)",
                    v.name
                );
                s.push_str(&matrix(runs, band, "D_tol (m)", &D_TOLS, |r| r.d_tol));
                s.push('\n');
                s.push_str(&matrix(runs, band, "v_d (m/s)", &SPEEDS, |r| r.speed));
            }
        }
        s
    }

    /// The worst cell of `variant`'s static runs in distance band `band`
    /// (`None`: all D) whose ε_tol satisfies `eps`: (share oriented on
    /// entry, label), over the ε_tol × D_tol and ε_tol × speed cells.
    #[must_use]
    pub fn worst_cell(
        &self,
        variant: &str,
        band: Option<usize>,
        eps: fn(f32) -> bool,
    ) -> (f32, String) {
        let Some(v) = self.variants.iter().find(|v| v.name == variant) else {
            return (f32::NAN, String::new());
        };
        let mut worst = (f32::INFINITY, String::new());
        for (e, key, c, sum) in static_cells(v.runs(GoalKind::Static), band) {
            if eps(e) && sum.oriented < worst.0 {
                worst = (
                    sum.oriented,
                    format!("ε_tol {e}°, {key} {c} ({} runs)", sum.n - sum.n_inside),
                );
            }
        }
        worst
    }

    /// The targets against this report, markdown (standard = `standard`,
    /// relaxed = `relaxed`): oriented entries at D ≥ 5 m per cell and over
    /// all D, End_of_Steering inside both tolerances, halting runs at rest
    /// inside both, relaxed reach without orbits.
    #[must_use]
    pub fn targets(&self) -> String {
        let get = |name: &str, kind: GoalKind| {
            self.variants
                .iter()
                .find(|v| v.name == name)
                .map(|v| summarise(v.runs(kind)))
                .unwrap_or_default()
        };
        let far = Some(BANDS.len() - 1);
        let mut s = String::from("| target | measured | goal | met |\n|---|---|---|---|\n");
        let mut row = |what: &str, val: String, goal: &str, ok: bool| {
            let _ = writeln!(
                s,
                "| {what} | {val} | {goal} | {} |",
                if ok { "yes" } else { "NO" }
            );
        };
        let (w5, c5) = self.worst_cell("standard", far, |e| e >= 5.0);
        row(
            "standard, oriented on entry, D ≥ 5 m, worst cell ε_tol ≥ 5°",
            format!("{} % ({c5})", pct(w5)),
            "≥ 95 %",
            w5 >= 0.95,
        );
        let (w2, c2) = self.worst_cell("standard", far, |e| e < 5.0);
        row(
            "standard, oriented on entry, D ≥ 5 m, worst cell ε_tol 2°",
            format!("{} % ({c2})", pct(w2)),
            "≥ 90 %",
            w2 >= 0.9,
        );
        let st = get("standard", GoalKind::Static);
        row(
            "standard, oriented on entry, all D",
            format!("{} %", pct(st.oriented)),
            "≥ 80 %",
            st.oriented >= 0.8,
        );
        // End_of_Steering, static goals (single and chained) apart from
        // moving ones (led and never latched: approach::tolerance_phase).
        let (mut eos, mut eos_ok, mut rest, mut nh) = ([0.0f32; 2], [0.0f32; 2], 0.0, 0.0);
        let ours = ["standard", "relaxed"];
        for v in self.variants.iter().filter(|v| ours.contains(&v.name)) {
            for g in &v.groups {
                let c = summarise(&g.runs);
                let k = g.runs.iter().map(|r| r.eos).sum::<u32>() as f32;
                let m = usize::from(g.kind == GoalKind::Moving);
                eos[m] += k;
                eos_ok[m] += c.eos_ok * k;
                if c.n_halting > 0 {
                    rest += c.rest_ok * c.n_halting as f32;
                    nh += c.n_halting as f32;
                }
            }
        }
        row(
            "End_of_Steering with both tolerances met (standard and relaxed; static and chained goals)",
            format!("{} %", pct(eos_ok[0] / eos[0])),
            "≥ 99.5 %",
            eos_ok[0] / eos[0] >= 0.995,
        );
        row(
            "same, moving goals (led, never latched: declared only inside the moving disk)",
            format!("{} %", pct(eos_ok[1] / eos[1])),
            "≥ 99.5 %",
            eos_ok[1] / eos[1] >= 0.995,
        );
        row(
            "halting: rest pose inside both tolerances (standard and relaxed)",
            format!("{} % of {nh}", pct(rest / nh)),
            "100 %",
            rest >= nh,
        );
        let rx = get("relaxed", GoalKind::Static);
        row(
            "relaxed reach (enters the disk), orbits",
            format!("{} %, {} orbits", pct(rx.reach), rx.orbits),
            "≥ 99.5 %, 0",
            rx.reach >= 0.995 && rx.orbits == 0,
        );
        // Relaxed against standard, cell by cell.
        let mut worse = Vec::new();
        if let (Some(a), Some(b)) = (
            self.variants.iter().find(|v| v.name == "relaxed"),
            self.variants.iter().find(|v| v.name == "standard"),
        ) {
            let (ra, rb) = (a.runs(GoalKind::Static), b.runs(GoalKind::Static));
            for (bd, &(lo, hi)) in BANDS.iter().enumerate() {
                for e in EPS_TOLS_DEG {
                    for dt in D_TOLS {
                        let f = |r: &&RunRecord| {
                            band_of(r.d0) == bd && r.eps_tol_deg.round() == e && r.d_tol == dt
                        };
                        let (x, y) = (
                            summarise(ra.iter().filter(f)),
                            summarise(rb.iter().filter(f)),
                        );
                        if x.oriented < y.oriented {
                            worse.push(format!(
                                "D {lo}–{hi} m, ε {e}°, D_tol {dt}: {} vs {}",
                                pct(x.oriented),
                                pct(y.oriented)
                            ));
                        }
                    }
                }
            }
        }
        row(
            "relaxed, oriented on entry, cells below standard (band × ε_tol × D_tol)",
            format!(
                "{} of {} {}",
                worse.len(),
                BANDS.len() * 25,
                worse.join("; ")
            ),
            "0",
            worse.is_empty(),
        );
        for name in ["standard", "relaxed"] {
            for kind in [GoalKind::Moving, GoalKind::Chain] {
                let c = get(name, kind);
                row(
                    &format!("{name}, {} finish", kind.name()),
                    format!("{} %", pct(c.finished)),
                    "≥ 99 %",
                    c.finished >= 0.99,
                );
            }
        }
        row(
            "standard, static: length / Dubins median (p90)",
            format!("{:.3} ({:.3})", st.length_ratio.0, st.length_ratio.1),
            "≤ 1.15",
            st.length_ratio.0 <= 1.15,
        );
        let (nan, viol): (u32, u32) = self
            .variants
            .iter()
            .flat_map(|v| &v.groups)
            .flat_map(|g| &g.runs)
            .fold((0, 0), |(a, b), r| (a + r.nan, b + r.violations));
        row(
            "NaN, limit violations (all runs)",
            format!("{nan}, {viol}"),
            "0, 0",
            nan == 0 && viol == 0,
        );
        s
    }

    /// The per-cell JSON: every variant's group summaries, and for the
    /// static group one summary per (band, ε_tol, D_tol) and per (band,
    /// ε_tol, speed) cell; plus the records of every run that missed
    /// something (for regression cases).
    #[must_use]
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::json;
        let variants: Vec<serde_json::Value> = self
            .variants
            .iter()
            .map(|v| {
                let groups: Vec<serde_json::Value> = v
                    .groups
                    .iter()
                    .map(|g| json!({ "group": g.kind, "summary": summarise(&g.runs) }))
                    .collect();
                let runs = v.runs(GoalKind::Static);
                let mut cells = Vec::new();
                for (b, &(lo, hi)) in BANDS.iter().enumerate() {
                    for (e, key, c, sum) in static_cells(runs, Some(b)) {
                        cells.push(json!({
                            "band": [lo, hi], "epsTolDeg": e, key: c, "summary": sum
                        }));
                    }
                }
                let misses: Vec<serde_json::Value> = v
                    .groups
                    .iter()
                    .flat_map(|g| {
                        g.runs
                            .iter()
                            .filter(|r| missed(r))
                            .map(move |r| json!({ "group": g.kind, "run": r }))
                    })
                    .take(MISSES_KEPT)
                    .collect();
                json!({
                    "name": v.name, "settings": v.settings, "groups": groups,
                    "staticCells": cells, "misses": misses
                })
            })
            .collect();
        json!({ "seed": self.seed, "maxTime": self.max_time, "variants": variants })
    }
}
