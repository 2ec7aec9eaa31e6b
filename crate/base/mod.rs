//! The shared base: what every paper's code builds on, and nothing
//! paper-specific. Each is written once so that two controllers never
//! disagree on an angle, a rounding or a random draw.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`angle`] | — | one definition of angle wrapping and differences |
//! | [`trig`] | — | bit-reproducible `sin_cos` / `atan2`: the same trajectory natively and in wasm |
//! | [`rng`] | — | seeded PCG32: the same sequence natively and in wasm |
//! | [`metrics`] | DESIGN §9 | path length, integrated \|curvature\|, per-step limit checks, percentiles |
//! | [`dubins`] | 000 §2 | Dubins shortest paths, the lower bound for an oriented reach |
//! | [`range`] | — | one error for a number out of range or not finite, one check: every paper's validation speaks it |
//! | [`minmax`] | — | `f32` max / min as comparisons: no `fmaxf` / `fminf` calls per agent in wasm, the same numbers |
//! | [`parallel`] | — | seeded cases mapped over an index range: rayon natively, sequential on wasm32, same results |

pub mod angle;
pub mod dubins;
pub mod grid;
pub mod metrics;
pub mod minmax;
pub mod parallel;
pub mod range;
pub mod ranges;
pub mod rng;
pub mod trig;
pub mod vehicle;
