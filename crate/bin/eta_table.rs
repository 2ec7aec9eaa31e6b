//! `eta-table`: generates the η table from the committed default parameters
//! (arguments: [`steering::cli::eta_table`]; `eta-table --help`).
//!
//! ```text
//! eta-table [--out tables/eta.bin] [--vehicle VEHICLE.json] [--threads N] [--counts ND,NA,NS,NV,NVD]
//! ```
//! Deterministic: the same parameters give the same bytes, whatever the
//! thread count (entries run on rayon and are collected in order).

// `wasm-pack test` builds every binary for wasm32, where clap and rayon
// are not dependencies: there this binary is empty.
#![cfg_attr(target_arch = "wasm32", no_main)]
#![cfg(not(target_arch = "wasm32"))]

use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use steering::cli::eta_table::EtaTableCli;
use steering::funnelling::table::spec::TableSpec;

fn main() -> ExitCode {
    match generate(&EtaTableCli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("eta-table: {e}");
            ExitCode::FAILURE
        }
    }
}

fn generate(cli: &EtaTableCli) -> Result<(), String> {
    let out = cli.out.display();
    let spec = TableSpec::for_vehicle(cli.vehicle_params()?, cli.counts)?;
    let t0 = Instant::now();
    let (table, threads) = cli
        .pool
        .install(|| (spec.generate(), rayon::current_num_threads()))?;
    let table = table.map_err(|e| e.to_string())?;
    let secs = t0.elapsed().as_secs_f64();
    let bytes = table.to_bytes();
    let reachable = (0..table.len())
        .filter(|&i| table.entry(spec.unravel(i)).2 & 1 != 0)
        .count();
    std::fs::write(&cli.out, &bytes).map_err(|e| format!("cannot write {out}: {e}"))?;
    println!(
        "eta-table: {} entries ({} reachable, {:.1} %) in {secs:.2} s on {threads} threads -> {out} ({} bytes, crc32 {:#010x}, key {})",
        table.len(),
        reachable,
        100.0 * reachable as f64 / table.len() as f64,
        bytes.len(),
        steering::funnelling::table::codec::crc32(&bytes[..bytes.len() - 4]),
        spec.key(),
    );
    Ok(())
}
