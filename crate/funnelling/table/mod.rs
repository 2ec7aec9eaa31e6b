//! The η table `Tη` (paper 000 §3, paper 001 §3 and Fig. 3; docs/DESIGN.md §8):
//! the seek controller's final radial-tangential angle η, sampled once over
//! five axes so that funnelling can predict where plain seek would arrive at
//! constant cost per update.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [format](mod@format) | 000 §3 | the file's header: [`BuildParams`](format::BuildParams), [`TableError`](format::TableError), layout constants |
//! | [`codec`] | 000 §3 | the bytes: CRC-32, validation of every field, to/from bytes |
//! | [`lookup`] | 000 §3, 001 Fig. 3 | [`EtaTable`](lookup::EtaTable) in memory: cells, the multilinear blend, [`Lookup`](lookup::Lookup) |
//! | [`grid`] | — | where a query falls on a sampled axis, in constant time |
//! | [`gpu_table`] | — | the table's arrays as a GPU kernel reads them (the same cells, samples and reciprocal widths) |
//! | [`key`] | — | the parameter key (hash of build parameters and axes) that table caches are keyed by |
//! | [`spec`] | 000 §3 | what the table samples: anisotropic axes scaled with the vehicle, one entry's reach simulation (the same seek code), mirror symmetry |
//! | [`batch`] | 000 §3 | the entries' reach simulations interleaved several at a time, the same bits |
//! | [`generate`] | 000 §3 | the whole table in parallel, and a browser worker's slice of it |
//! | [`embedded`] | — | the table of any vehicle for a library user ([`EtaTable::for_vehicle`](lookup::EtaTable::for_vehicle)): the pedestrian's compiled in (feature `embedded-table`), others generated |

pub mod batch;
pub mod codec;
pub mod embedded;
pub mod format;
pub mod generate;
pub mod gpu_table;
pub mod grid;
pub mod key;
pub mod lookup;
pub mod spec;
