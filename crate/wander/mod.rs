//! The random steering toolkit (paper 004, "Random Steering – 7 Components
//! for a Toolkit"; docs/DESIGN.md §16).
//!
//! Forward speed is constant; components control the angular displacement,
//! velocity or acceleration directly, under clamps. One idea per module:
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`control`] | §1 | modes, clamps, discrete sets, the constant-speed agent |
//! | [`distribution`] | §2 | uniform, smooth noise, Perlin, hand-drawn curve |
//! | [`noise`] | §2, §4 | smooth (value) noise, 1D/2D Perlin noise |
//! | [`field`] | §3 | interpolated random vector fields, bias, switching |
//! | [`time_fn`] | §4 | sums of sines, noise envelopes and blends |
//! | [`timed`] | §5 | fixed or random hold intervals |
//! | [`markov`] | §6 | transition tables, two-table variant |
//! | [`response`] | §6 | a transition table read as a smooth 2D response curve |
//! | [`generated_path`] | §7 | fractal and circle-with-sines paths, following |
//! | [`config`] | all | [`WanderConfig`](config::WanderConfig): the JSON configuration of a pipeline and its validation |
//! | [`pipeline`] | all | [`Wanderer`](pipeline::Wanderer): the pipeline built from a config, stepped, traced; presets |
//! | [`error`] | — | [`WanderError`](error::WanderError) |

pub mod config;
pub mod control;
pub mod distribution;
pub mod error;
pub mod field;
pub mod generated_path;
pub mod markov;
pub mod noise;
pub mod pipeline;
pub mod response;
pub mod time_fn;
pub mod timed;
