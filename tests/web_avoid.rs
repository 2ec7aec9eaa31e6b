//! Issue 18 in headless Chromium: the circle swap preset played through the
//! lab's binding, the overlap count read from the core (0 with ORCA, many
//! with avoidance off), the method switch and its error.
#![cfg(target_arch = "wasm32")]

use steering::bindings::lab::Lab;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

static TABLE: &[u8] = include_bytes!("../tables/eta.bin");
static CIRCLE32: &str = include_str!("../scenarios/avoid_circle32.json");

/// Plays the preset for 30 s; the most pairs overlapping at one frame.
fn play(method: &str) -> u32 {
    let mut lab = Lab::new(TABLE).map_err(|_| ()).unwrap();
    lab.load_scenario(CIRCLE32).map_err(|_| ()).unwrap();
    assert_eq!(lab.avoidance_method(), "orca");
    lab.set_avoidance_method(method).map_err(|_| ()).unwrap();
    let mut worst = 0;
    for _ in 0..900 {
        lab.step(2).map_err(|_| ()).unwrap();
        worst = worst.max(lab.overlaps());
    }
    worst
}

#[wasm_bindgen_test]
fn the_circle_swap_has_no_overlap_with_orca_and_many_without() {
    assert_eq!(play("orca"), 0);
    assert!(play("off") > 100);
}

#[wasm_bindgen_test]
fn a_bad_method_is_refused_and_changes_nothing() {
    let mut lab = Lab::new(TABLE).map_err(|_| ()).unwrap();
    lab.load_scenario(include_str!("../scenarios/avoid_doorway.json"))
        .map_err(|_| ())
        .unwrap();
    assert!(lab.set_avoidance_method("rvo").is_err());
    assert_eq!(lab.avoidance_method(), "orca");
    assert_eq!(lab.obstacles().len(), 10);
}
