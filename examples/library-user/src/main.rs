//! Steers three pedestrians to oriented targets with the steering core,
//! as a program that depends on it would: the library's prelude, its
//! embedded η table, a world stepped with the table checked. Prints where
//! each agent stopped and exits with failure unless every one rests
//! inside both tolerances of its target within a minute.

use std::process::ExitCode;

use steering::prelude::*;

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("library-user: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<bool, Box<dyn std::error::Error>> {
    let vehicle = VehicleParams::default();
    let table = EtaTable::for_vehicle(&vehicle)?;
    let mut world = World::new(vehicle, FunnelConfig::default())?;
    // (start x, y, heading°) → (target x, y, orientation°): ahead, to the
    // side, and behind the start heading.
    let trips = [
        ((0.0, 0.0, 0.0), (10.0, 4.0, 90.0)),
        ((-3.0, 5.0, 45.0), (4.0, -6.0, -90.0)),
        ((6.0, -2.0, 0.0), (-5.0, 1.0, 180.0)),
    ];
    let mut targets = Vec::new();
    for ((x, y, theta), (gx, gy, beta)) in trips {
        let goal = Goal {
            pos: Vec2::new(gx, gy),
            beta: f32::to_radians(beta),
            halting: true,
            ..Goal::default() // D_tol 0.25 m, ε_tol 5°, 1.3 m/s
        };
        let start = VehicleState::new(Vec2::new(x, y), f32::to_radians(theta), 0.0, 0.0);
        world.add_agent(start, vec![GoalSpec { goal, ..GoalSpec::default() }])?;
        targets.push(goal);
    }
    while !world.agents().iter().all(Agent::at_rest) && world.time() < 60.0 {
        world.step(&table)?;
    }
    let mut all = true;
    for (i, (a, g)) in world.agents().iter().zip(&targets).enumerate() {
        let d = (a.state.pos - g.pos).length();
        let e = steering::base::angle::diff(g.beta, a.state.theta);
        let ok = a.at_rest() && d < g.d_tol && e.abs() < g.eps_tol;
        println!(
            "agent {i}: {} at ({:.2}, {:.2}), {d:.3} m from its target, heading off by {:.2}°, done at {:.2} s",
            if ok { "at rest" } else { "NOT ARRIVED" },
            a.state.pos.x,
            a.state.pos.y,
            e.to_degrees(),
            a.finished_at.unwrap_or(f32::NAN),
        );
        all &= ok;
    }
    println!("{:.2} s simulated", world.time());
    Ok(all)
}
