//! The native η-table cache: `steer run` on a scenario whose
//! vehicle is not the committed table's builds the matching table once and
//! keeps it, keyed by [`TableSpec::key`] (the hash of every build
//! parameter and axis value, the same key the browser's IndexedDB cache
//! uses).
//!
//! Where: `$STEER_TABLE_CACHE` if set, else
//! `$XDG_CACHE_HOME/steering-lab/tables`, else
//! `$HOME/.cache/steering-lab/tables`, else `target/eta-cache`; one file
//! `eta-<key>.bin` per vehicle (3 MB at the default size).
//!
//! Never silent: a cached file is used only if it loads (CRC, every field)
//! and its own header hashes to the key asked for and its parameters
//! equal the vehicle's bit for bit; anything else is rebuilt and
//! overwritten (written to a temporary name, then renamed, so a
//! concurrent reader never sees half a file).

use std::path::{Path, PathBuf};

use crate::base::vehicle::VehicleParams;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::{TableSpec, DEFAULT_COUNTS};

/// Where a table came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Source {
    /// Read from the cache file.
    Cached(PathBuf),
    /// Built now and written to the cache file.
    Built(PathBuf),
}

/// The cache directory (see the module documentation).
#[must_use]
pub fn cache_dir() -> PathBuf {
    let var = |k: &str| std::env::var_os(k).filter(|v| !v.is_empty());
    if let Some(d) = var("STEER_TABLE_CACHE") {
        return PathBuf::from(d);
    }
    if let Some(d) = var("XDG_CACHE_HOME") {
        return PathBuf::from(d).join("steering-lab/tables");
    }
    if let Some(h) = var("HOME") {
        return PathBuf::from(h).join(".cache/steering-lab/tables");
    }
    PathBuf::from("target/eta-cache")
}

/// The cache file of `spec` in `dir`.
#[must_use]
pub fn cache_path(dir: &Path, spec: &TableSpec) -> PathBuf {
    dir.join(format!("eta-{}.bin", spec.key()))
}

/// Reads `path` if it holds exactly `spec`'s table.
fn read_cached(path: &Path, spec: &TableSpec, p: &VehicleParams) -> Option<EtaTable> {
    let bytes = std::fs::read(path).ok()?;
    let t = EtaTable::from_bytes(&bytes).ok()?;
    (t.key() == spec.key() && t.check_params(p).is_ok()).then_some(t)
}

/// The default-size table for vehicle `p`: from the cache in `dir`, or
/// built (on the current rayon pool) and stored there.
///
/// # Errors
/// A vehicle the generator refuses (field named), or a cache directory
/// that cannot be written.
pub fn table_for(p: &VehicleParams, dir: &Path) -> Result<(EtaTable, Source), String> {
    let spec = TableSpec::for_vehicle(*p, DEFAULT_COUNTS)?;
    let path = cache_path(dir, &spec);
    if let Some(t) = read_cached(&path, &spec, p) {
        return Ok((t, Source::Cached(path)));
    }
    let t = spec.generate().map_err(|e| e.to_string())?;
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("cannot create the table cache {}: {e}", dir.display()))?;
    let tmp = path.with_extension(format!("tmp{}", std::process::id()));
    std::fs::write(&tmp, t.to_bytes())
        .and_then(|()| std::fs::rename(&tmp, &path))
        .map_err(|e| format!("cannot write the table cache {}: {e}", path.display()))?;
    Ok((t, Source::Built(path)))
}
