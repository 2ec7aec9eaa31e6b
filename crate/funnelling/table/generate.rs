//! The whole η table from a [`TableSpec`]: entries computed in parallel
//! natively (several reach simulations interleaved, [`super::batch`]), in
//! order, mirrored where the vehicle is symmetric; and the browser's share
//! of it (a worker's slice, encoded; the slices assembled).

#[cfg(not(target_arch = "wasm32"))]
use crate::funnelling::table::batch;
use crate::funnelling::table::format::TableError;
use crate::funnelling::table::lookup::EtaTable;
use crate::funnelling::table::spec::{Entry, TableSpec};

/// Entries per parallel task of [`TableSpec::generate`] (a few hundred
/// tasks for the default table, so the threads balance).
pub const GENERATE_CHUNK: usize = 1024;

impl TableSpec {
    /// Computes entries `range` on the calling thread; entries that
    /// [`TableSpec::is_mirrored`] are left as `None` (filled by
    /// [`TableSpec::fill_mirrors`]).
    /// Natively several simulations run interleaved ([`super::batch`]);
    /// in wasm one at a time, which V8 runs at least as fast as two or
    /// four lanes (natively the lanes win). The result is the same bits
    /// either way.
    #[must_use]
    pub fn entries(&self, range: core::ops::Range<usize>) -> Vec<Option<Entry>> {
        #[cfg(not(target_arch = "wasm32"))]
        {
            batch::entries(self, range)
        }
        #[cfg(target_arch = "wasm32")]
        {
            range.map(|i| self.unless_mirrored(i)).collect()
        }
    }

    /// Generates the whole table: in parallel on the current rayon pool
    /// natively, sequentially on wasm32 ([`crate::base::parallel`]). Entries are
    /// computed independently and collected in index order, so the bytes do
    /// not depend on the thread count.
    ///
    /// # Errors
    /// If the spec itself is invalid.
    pub fn generate(&self) -> Result<EtaTable, TableError> {
        let n = self.len();
        let chunks = n.div_ceil(GENERATE_CHUNK);
        let parts = crate::base::parallel::map_indices(chunks, |c| {
            self.entries(c * GENERATE_CHUNK..((c + 1) * GENERATE_CHUNK).min(n))
        });
        let partial: Vec<Option<Entry>> = parts.into_iter().flatten().collect();
        self.assemble(self.fill_mirrors(&partial))
    }

    /// Entries `range` encoded for a worker (the browser splits the
    /// generation across Web Workers): three f32 per entry, η, the
    /// desired-or-fallback speed and the flags, with flags −1 for an entry
    /// left to its mirror ([`TableSpec::is_mirrored`]).
    #[must_use]
    pub fn encode_slice(&self, range: core::ops::Range<usize>) -> Vec<f32> {
        let mut out = Vec::with_capacity(3 * range.len());
        for e in self.entries(range) {
            match e {
                Some((eta, v, f)) => out.extend([eta, v, f32::from(f)]),
                None => out.extend([0.0, 0.0, -1.0]),
            }
        }
        out
    }

    /// Assembles the table from the encoded slices of every entry, in
    /// index order ([`TableSpec::encode_slice`] over `0..len`, possibly in
    /// pieces). The bytes equal [`TableSpec::generate`]'s.
    ///
    /// # Errors
    /// A wrong length, a flag that is not one a slice writes, or an
    /// invalid table.
    pub fn assemble_encoded(&self, data: &[f32]) -> Result<EtaTable, TableError> {
        if data.len() != 3 * self.len() {
            return Err(TableError::Invalid(format!(
                "{} encoded values for {} entries (3 per entry expected)",
                data.len(),
                self.len()
            )));
        }
        let mut partial = Vec::with_capacity(self.len());
        for (i, c) in data.chunks_exact(3).enumerate() {
            let f = c[2];
            partial.push(if f == -1.0 {
                if !self.is_mirrored(i) {
                    return Err(TableError::Invalid(format!("entry {i} missing")));
                }
                None
            } else if f == f.trunc() && (0.0..=3.0).contains(&f) {
                Some((c[0], c[1], f as u8))
            } else {
                return Err(TableError::Invalid(format!("entry {i} has flags {f}")));
            });
        }
        self.assemble(self.fill_mirrors(&partial))
    }

    /// Builds the table from computed entries.
    ///
    /// # Errors
    /// If the spec or entries are invalid.
    pub fn assemble(&self, entries: Vec<Entry>) -> Result<EtaTable, TableError> {
        let eta = entries.iter().map(|e| e.0).collect();
        let vfb = entries.iter().map(|e| e.1).collect();
        let flags = entries.iter().map(|e| e.2).collect();
        EtaTable::from_parts(self.params, self.axes.clone(), eta, vfb, flags)
    }
}
