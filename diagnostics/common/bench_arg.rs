//! The avoidance diagnostics' benchmark argument (`avoid_dump`, `avoid_stuck`,
//! `avoid_trace`), a clap value: `corridor` (the default) | `doorway` |
//! `circle32` | `circle100`.
use steering::studies::avoidance::Bench;

/// A benchmark an avoidance diagnostic runs.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum BenchArg {
    /// Two groups crossing in a corridor.
    Corridor,
    /// A doorway two body diameters wide.
    Doorway,
    /// The circle swap with 32 agents.
    Circle32,
    /// The circle swap with 100 agents.
    Circle100,
}

impl BenchArg {
    /// The benchmark.
    pub fn bench(self) -> Bench {
        match self {
            Self::Corridor => Bench::Corridor,
            Self::Doorway => Bench::Doorway,
            Self::Circle32 => Bench::CircleSwap(32),
            Self::Circle100 => Bench::CircleSwap(100),
        }
    }
}
