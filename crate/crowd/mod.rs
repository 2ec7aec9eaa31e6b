//! Crowded path following (paper 003, "Crowded path following"; docs/DESIGN.md §15):
//! boids follow a polyline path with Reynolds' or Parker's seek, with or
//! without separation, from one boid to hundreds of thousands.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`path`] | "Path following – improved path" | polyline path with a radius; the normal-point rule |
//! | [`path_follow`] | "Path following" | predict ahead, find the normal point, target ahead on the path |
//! | [`boid_seek`] | "Seek" | Reynolds and Parker seeks as interchangeable strategies |
//! | [`separation`] | "Separation" | separation over the neighbour grid of [`crate::base::grid`] (not O(n²)), overlap counts |
//! | [`world`] | all | [`Crowd`](world::Crowd): the boid world stepped one paper frame at a time |
//! | [`config`] | "Testing" | [`CrowdConfig`](config::CrowdConfig) and the paper's Tests I–IV presets |
//! | [`metrics`] | "Results" | lap time, path deviation, overlaps: numbers on what the figures show |
//! | [`error`] | — | [`CrowdError`](error::CrowdError) |

pub mod boid_seek;
pub mod config;
pub mod error;
pub mod metrics;
pub mod path;
pub mod path_follow;
pub mod separation;
pub mod world;
