//! The JavaScript boundary (WebAssembly builds only): the one place that
//! knows about wasm-bindgen. Thin by rule: conversion only, every value from
//! JavaScript checked by the core, every error a `JsError`, never a panic.
//!
//! | module | page | what |
//! |---|---|---|
//! | [`lab`] | `index.html` | `Lab`: a funnelling [`World`](crate::world::World) and its η table |
//! | [`crowd`] | `crowd.html` | `CrowdLab`: crowded path following (paper 003) |
//! | [`wander`] | `wander.html` | `WanderLab`: the random steering toolkit (paper 004) |
//! | [`boundary`] | — | `from_js` / `to_js` / `js_err`: decoding that names the field at fault |
//! | [`layout`] | all | `Mode`, `StateField`: the core's numbers by name, checked at compile time |

mod boundary;
pub mod crowd;
pub mod lab;
pub mod layout;
pub mod wander;
