//! The shared base: what every paper's code builds on, and nothing
//! paper-specific. Each is written once so that two controllers never
//! disagree on an angle, a rounding or a random draw.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`angle`] | — | one definition of angle wrapping and differences |
//! | [`trig`] | — | bit-reproducible `sin_cos` / `atan2`: the same trajectory natively and in wasm |
//! | [`rng`] | — | seeded PCG32: the same sequence natively and in wasm |
//! | [`vehicle`] | 000 §3 | unicycle (forward only, or with a reverse gear), every limit enforced exactly; `VehicleParams`, `VehicleState` |
//! | [`metrics`] | docs/DESIGN.md §17 | path length, integrated \|curvature\|, per-step limit checks, percentiles |
//! | [`dubins`] | 000 §2 | Dubins shortest paths, the lower bound for an oriented reach |
//! | [`reeds_shepp`] | — | Reeds–Shepp shortest paths (forwards and backwards), every word for a caller's own cost, the lower bound with a reverse gear |
//! | [`field_error`] | — | JSON input read with the path of the field at fault (`agents[0].goals[1].x: expected a number, found a list`), for files and the page's objects alike |
//! | [`range`] | — | one error for a number out of range or not finite, one check: every paper's validation speaks it |
//! | [`ranges`] | — | one table of validation ranges (key, min, max, unit, integer, cross-field bound) that the core's checks and the page use |
//! | [`minmax`] | — | `f32` max / min as comparisons: no `fmaxf` / `fminf` calls per agent in wasm, the same numbers |
//! | [`parallel`] | — | seeded cases mapped over an index range: rayon natively, sequential on wasm32, same results |
//! | [`grid`] | 003 §3 | hashed uniform neighbour grid: every neighbour within a reach without an O(n²) scan, in a deterministic order (crowd separation, avoidance, proximity metrics) |

pub mod angle;
pub mod dubins;
pub mod field_error;
pub mod grid;
pub mod metrics;
pub mod minmax;
pub mod parallel;
pub mod range;
pub mod ranges;
pub mod reeds_shepp;
pub mod rng;
pub mod trig;
pub mod vehicle;
