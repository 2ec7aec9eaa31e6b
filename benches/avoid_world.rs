//! The avoidance benchmark's world, shared by
//! `benches/avoidance.rs` and `diagnostics/avoid_icount.rs` (included with
//! `#[path]`): `side²` agents on a square lattice of 1.6 m (π·3²/1.6² ≈ 11
//! within the 3 m neighbour reach), each funnelling to a seeded oriented
//! target 20–30 m away in any direction, so paths cross everywhere and the
//! avoidance is active for most agents.

use glam::Vec2;
use steering::avoidance::{config::AvoidanceConfig, config::AvoidanceMethod};
use steering::base::rng::Rng;
use steering::base::vehicle::{VehicleParams, VehicleState};
use steering::funnelling::config::FunnelConfig;
use steering::funnelling::goal::Goal;
use steering::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

/// The lattice world with `side × side` agents and avoidance `method`.
pub fn world(side: usize, method: AvoidanceMethod) -> World {
    let p = VehicleParams::default();
    let mut w = World::new(p, FunnelConfig::default()).unwrap();
    w.set_avoidance(AvoidanceConfig::with_method(method), Vec::new())
        .unwrap();
    let mut rng = Rng::new(18);
    for i in 0..side * side {
        let pos = Vec2::new((i % side) as f32, (i / side) as f32) * 1.6;
        let a = rng.range(-3.1, 3.1);
        let d = rng.range(20.0, 30.0);
        let goal = Goal {
            pos: pos + steering::base::trig::unit(a) * d,
            beta: rng.range(-3.1, 3.1),
            d_tol: 0.3,
            eps_tol: 10f32.to_radians(),
            speed: 1.3,
            halting: true,
            vel: Vec2::ZERO,
        };
        let spec = GoalSpec {
            goal,
            motion: GoalMotion::Static,
            switch: SwitchRule::EndOfSteering,
        };
        w.add_agent(VehicleState::new(pos, a, 1.0, 0.0), vec![spec])
            .unwrap();
    }
    w
}
