//! The JavaScript bindings in a real browser (`wasm-pack test --headless --chrome`).
#![cfg(target_arch = "wasm32")]

use steering::bindings;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn version_matches_the_crate() {
    assert_eq!(bindings::version(), env!("CARGO_PKG_VERSION"));
}

#[wasm_bindgen_test]
fn random_samples_are_seeded_and_in_range() {
    let a = bindings::random_samples(7, 64);
    let b = bindings::random_samples(7, 64);
    assert_eq!(a, b);
    assert!(a.iter().all(|x| (0.0..1.0).contains(x)));
    assert_ne!(a, bindings::random_samples(8, 64));
}
