//! The funnelling world's instruction count under callgrind: the same
//! bits on every run of one build, so a cost figure a loaded machine
//! cannot blur (a time can only be a same-run ratio there). Counted on
//! the workload `examples/world_bench.rs` times (the lab's performance
//! world: 10,000 agents, seed 1, 16 goals each, metrics off), on one
//! thread (`RAYON_NUM_THREADS=1`: the serial step; several threads under
//! valgrind add scheduling that differs from run to run).
//!
//! Two runs: `world_bench 10000 20 1` (20 warm-up steps and 20 more) and
//! `world_bench 10000 20 2` (20 more); their difference over the 200,000
//! agent updates between them is the count per update, without the
//! table's loading and the spawning. Each run's state hash must be the
//! one the other builds print (the same work).
//!
//! Two runs of one build differ by some tens of instructions (the
//! thread pool's start), so the whole run is shown in millions; the
//! difference per update is exact to its decimal.
//!
//! A count holds for one toolchain and build only, so the figures name
//! the toolchain, and the record is of the full mode: `make icount`
//! builds `world_bench` in release and runs this with `FIGURES_DIR` set
//! (`make figures-full` runs it), which writes a record of kind `counted`
//! (`tests/common/figures.rs`). Needs valgrind (Debian's `valgrind`).
//! Under `cargo test` it does nothing.

use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "../tests/common/figures.rs"]
mod figures;

/// Agents and steps of the counted runs (`world_bench N STEPS ROUNDS`).
const AGENTS: usize = 10_000;
const STEPS: usize = 20;

/// The command `make icount` runs.
const COMMAND: &str = "make icount";

/// `target/release/examples/world_bench` (`CARGO_TARGET_DIR` honoured).
fn world_bench() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
        PathBuf::from,
    );
    target.join("release/examples/world_bench")
}

/// One line of a tool's output: its first line, trimmed.
fn version(program: &str) -> String {
    Command::new(program)
        .arg("--version")
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map_or_else(
            || format!("{program}: unknown"),
            |o| {
                String::from_utf8_lossy(&o.stdout)
                    .lines()
                    .next()
                    .unwrap_or("")
                    .trim()
                    .to_string()
            },
        )
}

/// Instructions and state hash of `world_bench AGENTS STEPS rounds` on one
/// thread under callgrind.
fn count(bin: &Path, rounds: usize) -> (u64, String) {
    let out_file = std::env::temp_dir().join(format!("icount-{}.cg", std::process::id()));
    let out = Command::new("valgrind")
        .arg("--tool=callgrind")
        .arg(format!("--callgrind-out-file={}", out_file.display()))
        .arg(bin)
        .args([AGENTS, STEPS, rounds].map(|n| n.to_string()))
        // Nothing of the caller's environment (its size moves the count
        // by some thousands): one thread, nothing else.
        .env_clear()
        .env("RAYON_NUM_THREADS", "1")
        .output()
        .expect("valgrind runs (Debian: apt-get install valgrind)");
    let _ = std::fs::remove_file(&out_file);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "valgrind failed:\n{stderr}");
    // `==pid== Collected : 736239482`
    let collected = stderr
        .lines()
        .find_map(|l| {
            l.split_once("Collected :")
                .map(|(_, n)| n.trim().to_string())
        })
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no `Collected :` line from callgrind:\n{stderr}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let hash = stdout
        .lines()
        .find_map(|l| l.strip_prefix("hash "))
        .unwrap_or_else(|| panic!("no `hash` line from world_bench:\n{stdout}"))
        .trim()
        .to_string();
    (collected, hash)
}

fn main() {
    // `cargo bench` passes `--bench`; `cargo test --all-targets` does not,
    // and a test run has neither valgrind's minutes nor its binary.
    if !std::env::args().any(|a| a == "--bench") {
        println!("icount: counted by `make icount` only");
        return;
    }
    let bin = world_bench();
    assert!(
        bin.exists(),
        "{} is missing: `make icount` builds it (cargo build --release --example world_bench)",
        bin.display()
    );
    let (one, hash) = count(&bin, 1);
    let (two, hash2) = count(&bin, 2);
    let rustc = version("rustc");
    let valgrind = version("valgrind");
    println!("world_bench {AGENTS} {STEPS} 1: {one} instructions, hash {hash}");
    println!("world_bench {AGENTS} {STEPS} 2: {two} instructions, hash {hash2}");
    let per = (two.saturating_sub(one)) as f64 / (AGENTS * STEPS) as f64;
    println!("per agent update: {per:.1} ({rustc}, {valgrind})");
    if std::env::var_os("FIGURES_DIR").is_none() {
        return;
    }
    let built = format!("{rustc}, release build, {valgrind}");
    let figs = [
        figures::Figure::new(
            "world.icount.10k.whole_run",
            &format!(
                "instructions of `RAYON_NUM_THREADS=1 world_bench {AGENTS} {STEPS} 1` under callgrind \
                 (the whole process: table load, spawn, {} steps; state hash {hash}; {built})",
                2 * STEPS
            ),
            one as f64 / 1e6,
            "M instructions",
            1,
        ),
        figures::Figure::new(
            "world.icount.10k.per_update",
            &format!(
                "instructions per agent update, steps {}–{} of the same world (`world_bench {AGENTS} \
                 {STEPS} 2` less `… 1`, over {} updates; state hash {hash2}; {built})",
                2 * STEPS + 1,
                3 * STEPS,
                AGENTS * STEPS
            ),
            per,
            "instructions",
            1,
        ),
    ];
    figures::record(
        "benches/icount.rs",
        COMMAND,
        figures::Kind::Counted,
        &figures::Seeds {
            tuning: vec![],
            report: vec![1],
        },
        &figs,
    );
}
