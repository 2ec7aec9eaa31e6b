//! `--threads N`: the size of the rayon pool a study or the table generator
//! runs on ([`crate::base::parallel`]). Results never depend on it; it only
//! trades wall time against sharing the machine.

use clap::Args;

/// Most threads `--threads` accepts.
pub const MAX_THREADS: usize = 256;

/// The `--threads` flag, shared by every command that runs a study.
#[derive(Args, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PoolArgs {
    /// Worker threads (default: one per core; results do not depend on it).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u16).range(1..=MAX_THREADS as i64))]
    pub threads: Option<u16>,
}

impl PoolArgs {
    /// Runs `f` on a pool of `--threads` threads, or on the global pool.
    ///
    /// # Errors
    /// If the operating system refuses to start the threads.
    pub fn install<T: Send>(&self, f: impl FnOnce() -> T + Send) -> Result<T, String> {
        match self.threads {
            None => Ok(f()),
            Some(n) => rayon::ThreadPoolBuilder::new()
                .num_threads(usize::from(n))
                .build()
                .map(|pool| pool.install(f))
                .map_err(|e| format!("cannot start {n} threads: {e}")),
        }
    }
}
