//! The η table `Tη` (paper 000 §3, paper 001 §3 and Fig. 3; DESIGN §3):
//! the seek controller's final radial-tangential angle η, sampled once over
//! five axes so that funnelling can predict where plain seek would arrive at
//! constant cost per update.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [format](mod@format) | 000 §3 | the file: header, [`BuildParams`], [`TableError`], CRC-32, validation, to/from bytes |
//! | [`lookup`] | 000 §3, 001 Fig. 3 | [`EtaTable`] in memory: cells, the multilinear blend, [`Lookup`] |
//! | [`grid`] | — | where a query falls on a sampled axis, in constant time |
//! | [`generate`] | 000 §3 | the generator: the same seek code, anisotropic axes, mirror symmetry |

pub mod format;
pub mod generate;
pub mod grid;
pub mod lookup;

pub use format::*;
pub use lookup::{EtaTable, Lookup};
