//! The avoidance examples' benchmark argument (`avoid_dump`, `avoid_stuck`,
//! `avoid_trace`): `corridor` (the default) | `doorway` | `circle32` |
//! `circle100`.
use steering::studies::avoidance::Bench;

/// The benchmark named by `arg`, the corridor when absent or unknown.
pub fn bench(arg: Option<&String>) -> Bench {
    match arg.map_or("corridor", String::as_str) {
        "doorway" => Bench::Doorway,
        "circle32" => Bench::CircleSwap(32),
        "circle100" => Bench::CircleSwap(100),
        _ => Bench::Corridor,
    }
}
