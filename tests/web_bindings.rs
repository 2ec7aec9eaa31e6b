//! The JavaScript bindings in a real browser (`wasm-pack test --headless --chrome`):
//! the committed η table loads, a corrupt one is a `JsError` with a message,
//! agents step, and bulk state comes back as typed arrays.
#![cfg(target_arch = "wasm32")]

use steering::bindings::{self, Lab};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

static TABLE: &[u8] = include_bytes!("../tables/eta.bin");

fn message(e: wasm_bindgen::JsError) -> String {
    let v: JsValue = e.into();
    js_sys::Error::from(v).message().into()
}

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

#[wasm_bindgen_test]
fn the_committed_table_loads_and_gives_a_field() {
    let lab = Lab::new(TABLE).map_err(message).unwrap();
    let field = lab.eta_field(1.0, 0.0, 1.3);
    assert!(
        field.len() >= 4 * 100 && field.len() % 4 == 0,
        "{}",
        field.len()
    );
    assert!(field.iter().all(|x| x.is_finite()));
    let ring = lab.eta_ring_at(3.0, 1.0, 0.0, 1.3);
    assert!(!ring.is_empty() && ring.len() % 4 == 0);
    let d0 = ring[0];
    assert!(ring.chunks(4).all(|c| c[0] == d0), "one ring, one distance");
}

#[wasm_bindgen_test]
fn corrupt_tables_are_errors_with_a_message() {
    let m = message(
        Lab::new(b"not a table")
            .err()
            .expect("garbage must be refused"),
    );
    assert!(m.contains("η table"), "{m}");
    let mut flipped = TABLE.to_vec();
    let mid = flipped.len() / 2;
    flipped[mid] ^= 0x40;
    let m = message(
        Lab::new(&flipped)
            .err()
            .expect("a flipped bit must be refused"),
    );
    assert!(m.contains("checksum") || m.contains("corrupt"), "{m}");
    let m = message(
        Lab::new(&TABLE[..TABLE.len() - 7])
            .err()
            .expect("truncation must be refused"),
    );
    assert!(m.contains("truncated") || m.contains("η table"), "{m}");
}
