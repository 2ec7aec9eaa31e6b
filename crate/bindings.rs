//! The JavaScript boundary: the one module that knows about wasm-bindgen.
//!
//! Rules kept here (issue 5):
//! - thin: conversion only, no steering logic; every value is validated and
//!   turned into a `JsError` with a readable message, never a panic;
//! - typed: configuration objects cross via serde-wasm-bindgen and carry real
//!   TypeScript types (`typescript_custom_section` + `unchecked_*_type`);
//! - bulk per-agent state crosses as `Float32Array` views.

use wasm_bindgen::prelude::*;

use crate::rng::Rng;

/// The crate version, to show on the page and check the package loaded.
#[wasm_bindgen]
#[must_use]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_owned()
}

/// `n` uniform samples in `[0, 1)` from the shared PCG32 generator, seeded:
/// the same seed gives the same numbers natively and in the browser.
#[wasm_bindgen(js_name = randomSamples)]
#[must_use]
pub fn random_samples(seed: u32, n: u32) -> Vec<f32> {
    let mut rng = Rng::new(u64::from(seed));
    (0..n).map(|_| rng.next_f32()).collect()
}
