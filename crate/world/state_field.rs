//! The record of one agent that [`World::write_state`](crate::world::World::write_state)
//! writes: its fields by name ([`StateField`]), its length, and the writer.

use crate::world::agent::Agent;

/// One float of an agent's record in [`World::write_state`](crate::world::World::write_state); the
/// discriminant is its offset. Defined once here so that the writer, the
/// bindings' export (`StateField` in JavaScript) and the page agree by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
#[allow(missing_docs)] // the names are the quantities of `Internals` and `Goal`
pub enum StateField {
    X = 0,
    Y,
    Theta,
    V,
    Omega,
    /// [`Mode`](crate::funnelling::update::Mode) as its number.
    Mode,
    D,
    Alpha,
    Eta,
    DeltaEta,
    Mu,
    Gamma,
    /// 1 reachable at v_dt, else 0.
    Reachable,
    VDt,
    GoalX,
    GoalY,
    GoalBeta,
    GoalDTol,
    GoalEpsTol,
}

impl StateField {
    /// Every field in offset order: `ALL[k] as usize == k` (checked below).
    pub const ALL: [StateField; STATE_STRIDE] = {
        use StateField as F;
        [
            F::X,
            F::Y,
            F::Theta,
            F::V,
            F::Omega,
            F::Mode,
            F::D,
            F::Alpha,
            F::Eta,
            F::DeltaEta,
            F::Mu,
            F::Gamma,
            F::Reachable,
            F::VDt,
            F::GoalX,
            F::GoalY,
            F::GoalBeta,
            F::GoalDTol,
            F::GoalEpsTol,
        ]
    };
}

/// Floats per agent in [`World::write_state`](crate::world::World::write_state): one past the last field.
pub const STATE_STRIDE: usize = StateField::GoalEpsTol as usize + 1;

const _: () = {
    let mut k = 0;
    while k < STATE_STRIDE {
        assert!(
            StateField::ALL[k] as usize == k,
            "StateField::ALL is in offset order"
        );
        k += 1;
    }
};

/// One agent's record of [`World::write_state`](crate::world::World::write_state) into `o`
/// ([`STATE_STRIDE`] floats).
#[inline(always)]
pub(super) fn write_record(a: &Agent, o: &mut [f32]) {
    use StateField as F;
    let i = &a.internals;
    let g = &a.goal_now;
    let mut put = |f: StateField, v: f32| o[f as usize] = v;
    put(F::X, a.state.pos.x);
    put(F::Y, a.state.pos.y);
    put(F::Theta, a.state.theta);
    put(F::V, a.state.v);
    put(F::Omega, a.state.omega);
    put(F::Mode, f32::from(i.mode as u8));
    put(F::D, i.d);
    put(F::Alpha, i.alpha);
    put(F::Eta, i.eta);
    put(F::DeltaEta, i.delta_eta);
    put(F::Mu, i.mu);
    put(F::Gamma, i.gamma);
    put(F::Reachable, f32::from(u8::from(i.reachable)));
    put(F::VDt, i.v_dt);
    put(F::GoalX, g.pos.x);
    put(F::GoalY, g.pos.y);
    put(F::GoalBeta, g.beta);
    put(F::GoalDTol, g.d_tol);
    put(F::GoalEpsTol, g.eps_tol);
}
