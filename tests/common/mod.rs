//! What several test files share, written once: the FNV-1a hash
//! behind every golden trajectory, the wander presets with their golden
//! hashes (checked natively and through the bindings in Chromium), and a
//! counting allocator for the allocation-free-step checks.
//!
//! Each file in `tests/` is its own crate and uses a part of this with
//! `mod common;`, hence `dead_code`; the allocator is the only unsafe code
//! and forwards every call unchanged.
#![allow(dead_code, unsafe_code)]

pub mod figures;
pub mod paths;

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// FNV-1a offset basis: the hash of nothing.
pub const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

/// FNV-1a over the f32 bit patterns (little-endian bytes), so that a golden
/// value pins the bits, not rounded values (docs/DESIGN.md §5).
pub fn fnv(hash: &mut u64, values: &[f32]) {
    for v in values {
        for b in v.to_bits().to_le_bytes() {
            *hash ^= u64::from(b);
            *hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

/// FNV-1a over every agent's state bits at every step of `steps` world
/// steps: the golden trajectory hash of a funnelling or avoidance world.
pub fn world_hash(
    table: &steering::funnelling::table::lookup::EtaTable,
    w: &mut steering::world::World,
    steps: u32,
) -> u64 {
    let mut h = FNV_OFFSET;
    let mut buf = Vec::new();
    for _ in 0..steps {
        w.step(table).unwrap();
        buf.clear();
        w.write_state(&mut buf);
        fnv(&mut h, &buf);
    }
    h
}

/// The wander gallery's preset files (paper 004, one per component) and the
/// golden hash of every variant's trace after the preset's suggested steps
/// (recorded natively; `tests/web_gallery.rs` checks the same values
/// through the bindings). `control`'s figure series includes variants 116
/// and 119 (second runs, seed 2); `markov` includes the 2D response curve
/// (§6).
pub const WANDER_PRESETS: [(&str, &str, u64); 8] = [
    (
        "control",
        include_str!("../../scenarios/wander/control.json"),
        0x6e91_06ad_bb79_7d80,
    ),
    (
        "distributions",
        include_str!("../../scenarios/wander/distributions.json"),
        0xfc4a_d28a_96ea_0ecb,
    ),
    (
        "fields",
        include_str!("../../scenarios/wander/fields.json"),
        0xd388_8293_835d_0d35,
    ),
    (
        "time-functions",
        include_str!("../../scenarios/wander/time-functions.json"),
        0x6d73_78d6_c8fc_744f,
    ),
    (
        "timed",
        include_str!("../../scenarios/wander/timed.json"),
        0xcb03_e86b_eccc_24a2,
    ),
    (
        "markov",
        include_str!("../../scenarios/wander/markov.json"),
        0x19ec_b655_a121_05ec,
    ),
    (
        "paths",
        include_str!("../../scenarios/wander/paths.json"),
        0xdca7_270c_11a5_ae3b,
    ),
    (
        "composed",
        include_str!("../../scenarios/wander/composed.json"),
        0xd2b8_71aa_0185_462c,
    ),
];

/// A global allocator that counts the allocations and reallocations made
/// by the thread inside [`allocations`], and forwards every call unchanged
/// to the system allocator. A test file installs it with
/// `#[global_allocator] static GLOBAL: common::CountingAlloc = common::CountingAlloc;`.
pub struct CountingAlloc;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static COUNT: Cell<usize> = const { Cell::new(0) };
}

fn tally() {
    if COUNTING.with(Cell::get) {
        COUNT.with(|c| c.set(c.get() + 1));
    }
}

// SAFETY: forwards every call unchanged to the system allocator; the
// tally touches only const-initialised thread-locals (no allocation).
unsafe impl GlobalAlloc for CountingAlloc {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        tally();
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        tally();
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

/// Runs `f` and returns its result with the number of allocations this
/// thread made meanwhile (0 unless [`CountingAlloc`] is the global
/// allocator).
pub fn allocations<R>(f: impl FnOnce() -> R) -> (R, usize) {
    COUNT.with(|c| c.set(0));
    COUNTING.with(|c| c.set(true));
    let r = f();
    COUNTING.with(|c| c.set(false));
    (r, COUNT.with(Cell::get))
}

/// The committed η table (`tables/eta.bin`), read from disk (native tests).
pub fn table() -> steering::funnelling::table::lookup::EtaTable {
    steering::funnelling::table::lookup::EtaTable::from_bytes(
        &std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin")).unwrap(),
    )
    .unwrap()
}

/// The crowd's golden trajectories (one core or split across workers), as
/// `(name, config, steps, hash)`. The hash is FNV-1a over positions and
/// velocities after every step, then the traced boid's lap trace
/// ([`crowd_hash_step`]); a cheaper step or one split across workers must
/// give the same bits, checked natively with metrics on and
/// off (`tests/crowd_determinism.rs`) and through the bindings in Chromium
/// (`tests/web_gallery.rs`).
pub fn crowd_golden_cases() -> Vec<(&'static str, steering::crowd::config::CrowdConfig, u32, u64)> {
    use steering::crowd::boid_seek::Seek;
    use steering::crowd::config::{CrowdConfig, PaperTest};
    let parker = Seek::Parker { fraction: 0.1 };
    let scaled = |n: usize| {
        let mut c = CrowdConfig::paper(PaperTest::IV, parker);
        let k = n as f32 / 300.0;
        c.boids = n;
        for p in &mut c.path.points {
            p[0] *= k;
            p[1] *= k;
        }
        c
    };
    let dense = {
        let mut c = CrowdConfig::paper(PaperTest::IV, parker);
        c.boids = 3000;
        c
    };
    vec![
        (
            "test4_parker10",
            CrowdConfig::paper(PaperTest::IV, parker),
            400,
            0xc4ff_2cc1_605d_d61d,
        ),
        (
            "test4_reynolds",
            CrowdConfig::paper(PaperTest::IV, Seek::Reynolds),
            400,
            0xb936_957f_a86f_5290,
        ),
        (
            "test2_reynolds",
            CrowdConfig::paper(PaperTest::II, Seek::Reynolds),
            400,
            0xaeb7_f014_ee30_0aa1,
        ),
        (
            "test3_parker0.1",
            CrowdConfig::paper(PaperTest::III, Seek::Parker { fraction: 0.001 }),
            400,
            0x2852_2229_5aac_ddce,
        ),
        ("scaled_3000", scaled(3000), 120, 0x264c_216b_b58e_876b),
        ("dense_3000", dense, 60, 0x7569_4fff_b6c3_685e),
    ]
}

/// Adds one crowd step's positions and velocities to `h`.
pub fn crowd_hash_step(h: &mut u64, pos: &[f32], vel: &[f32]) {
    fnv(h, pos);
    fnv(h, vel);
}

/// The message of an error a binding returned, as the page reads it
/// (`Error.message`): what the browser suites compare.
#[cfg(target_arch = "wasm32")]
pub fn message(e: wasm_bindgen::JsError) -> String {
    let v: wasm_bindgen::JsValue = e.into();
    js_sys::Error::from(v).message().into()
}
