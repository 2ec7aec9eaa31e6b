//! Avoidance in headless Chromium: the circle swap preset played through the
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

/// The lab's obstacle drags send the whole list back (`setObstacles`, the
/// layout of `obstacles()`): a good list replaces the world's; a bad one
/// is refused naming the obstacle and changes nothing.
#[wasm_bindgen_test]
fn set_obstacles_replaces_the_list_or_refuses_naming_the_obstacle() {
    let mut lab = Lab::new(TABLE).map_err(|_| ()).unwrap();
    lab.load_scenario(include_str!("../scenarios/avoid_corridor.json"))
        .map_err(|_| ())
        .unwrap();
    let before = lab.obstacles();
    assert_eq!(before.len(), 10);
    let mut moved = before.clone();
    moved[2] += 0.5;
    moved[4] += 0.5;
    lab.set_obstacles(&moved).map_err(|_| ()).unwrap();
    assert_eq!(lab.obstacles(), moved);
    let disc = [0.0, 1.0, 2.0, 0.8, 0.0];
    lab.set_obstacles(&disc).map_err(|_| ()).unwrap();
    assert_eq!(lab.obstacles(), disc.to_vec());
    for bad in [
        vec![0.0, 1.0, 2.0, 0.8],                               // not 5 per obstacle
        vec![2.0, 1.0, 2.0, 0.8, 0.0],                          // unknown kind
        vec![0.0, 1.0, 2.0, 0.0, 0.0],                          // radius 0
        vec![0.0, f32::NAN, 2.0, 0.8, 0.0],                     // NaN
        vec![0.0, 1.0, 2.0, 0.8, 0.0, 1.0, 3.0, 3.0, 3.0, 3.0], // zero-length wall
        vec![1.0, 0.0, 0.0, 2e6, 0.0],                          // out of the world
    ] {
        assert!(lab.set_obstacles(&bad).is_err(), "{bad:?} accepted");
        assert_eq!(
            lab.obstacles(),
            disc.to_vec(),
            "a refused list changed the world"
        );
    }
    // Stepping with the new obstacles runs.
    assert!(lab.step(10).is_ok());
    assert!(lab.state().iter().all(|v| v.is_finite()));
}
