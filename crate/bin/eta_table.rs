//! `eta-table`: generates the η table from the committed default parameters.
//!
//! ```text
//! eta-table [--out tables/eta.bin] [--threads N] [--counts ND,NA,NS,NV,NVD]
//! ```
//! Deterministic: the same parameters give the same bytes, whatever the
//! thread count.

#![cfg_attr(target_arch = "wasm32", allow(unused_imports))]

use std::process::ExitCode;
use std::time::Instant;

use steering::table::generate::TableSpec;
use steering::vehicle::VehicleParams;

/// `wasm-pack test` builds every binary for wasm32, where the threaded
/// generator does not exist: there the binary is an empty stub.
#[cfg(target_arch = "wasm32")]
fn main() {}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> ExitCode {
    let mut out = String::from("tables/eta.bin");
    let mut threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let mut counts = steering::table::generate::DEFAULT_COUNTS;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = args.next().unwrap_or_default(),
            "--threads" => threads = args.next().and_then(|s| s.parse().ok()).unwrap_or(threads),
            "--counts" => {
                let v: Vec<usize> = args
                    .next()
                    .unwrap_or_default()
                    .split(',')
                    .filter_map(|x| x.parse().ok())
                    .collect();
                match <[usize; 5]>::try_from(v) {
                    Ok(c) if c.iter().all(|&n| n >= 2) => counts = c,
                    _ => {
                        eprintln!("eta-table: --counts wants five integers ≥ 2, e.g. 16,36,5,5,5");
                        return ExitCode::FAILURE;
                    }
                }
            }
            "-h" | "--help" => {
                println!("usage: eta-table [--out FILE] [--threads N] [--counts ND,NA,NS,NV,NVD]");
                return ExitCode::SUCCESS;
            }
            other => {
                eprintln!("eta-table: unknown argument `{other}` (try --help)");
                return ExitCode::FAILURE;
            }
        }
    }
    let spec = TableSpec::with_counts(VehicleParams::default(), counts);
    let t0 = Instant::now();
    let table = match spec.generate(threads) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("eta-table: {e}");
            return ExitCode::FAILURE;
        }
    };
    let secs = t0.elapsed().as_secs_f64();
    let bytes = table.to_bytes();
    let reachable = (0..table.len())
        .filter(|&i| table.entry(spec.unravel(i)).2 & 1 != 0)
        .count();
    if let Err(e) = std::fs::write(&out, &bytes) {
        eprintln!("eta-table: cannot write {out}: {e}");
        return ExitCode::FAILURE;
    }
    println!(
        "eta-table: {} entries ({} reachable, {:.1} %) in {secs:.2} s on {threads} threads -> {out} ({} bytes, crc32 {:#010x})",
        table.len(),
        reachable,
        100.0 * reachable as f64 / table.len() as f64,
        bytes.len(),
        steering::table::crc32(&bytes[..bytes.len() - 4]),
    );
    ExitCode::SUCCESS
}
