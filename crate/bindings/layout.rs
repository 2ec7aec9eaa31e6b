//! The numbers the page shares with the core, exported so that TypeScript
//! reads them by name: the control modes and the per-agent record of
//! `Lab.state()`. wasm-bindgen enums need literal discriminants, so each is
//! a mirror of the core's type, tied to it at compile time (an exhaustive
//! `match` for new variants, a `const` check for the numbers).

use wasm_bindgen::prelude::*;

use crate::funnelling::update::Mode as CoreMode;
use crate::world::{StateField as CoreField, STATE_STRIDE};

/// The control mode (paper 000 Fig. 5), as `Lab.state()` and
/// `Lab.internals()` give it: `crate::funnelling::update::Mode`.
#[wasm_bindgen]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // the paper's names; see crate::funnelling::update::Mode
pub enum Mode {
    EndOfSteering = 0,
    OrientationOnly = 1,
    PositionOnly = 2,
    Funnelling = 3,
}

/// Offsets within one agent's record of `Lab.state()` (`Lab.stateStride()`
/// floats per agent): `crate::world::StateField`.
#[wasm_bindgen]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // the quantities of crate::funnelling::update::Internals and the goal
pub enum StateField {
    X = 0,
    Y = 1,
    Theta = 2,
    V = 3,
    Omega = 4,
    Mode = 5,
    D = 6,
    Alpha = 7,
    Eta = 8,
    DeltaEta = 9,
    Mu = 10,
    Gamma = 11,
    Reachable = 12,
    VDt = 13,
    GoalX = 14,
    GoalY = 15,
    GoalBeta = 16,
    GoalDTol = 17,
    GoalEpsTol = 18,
}

impl From<CoreMode> for Mode {
    fn from(m: CoreMode) -> Self {
        mode(m)
    }
}

impl From<CoreField> for StateField {
    fn from(f: CoreField) -> Self {
        field(f)
    }
}

/// Exhaustive: a new core mode does not compile until it is exported.
const fn mode(m: CoreMode) -> Mode {
    match m {
        CoreMode::EndOfSteering => Mode::EndOfSteering,
        CoreMode::OrientationOnly => Mode::OrientationOnly,
        CoreMode::PositionOnly => Mode::PositionOnly,
        CoreMode::Funnelling => Mode::Funnelling,
    }
}

/// Exhaustive: a new core field does not compile until it is exported.
const fn field(f: CoreField) -> StateField {
    use CoreField as C;
    use StateField as S;
    match f {
        C::X => S::X,
        C::Y => S::Y,
        C::Theta => S::Theta,
        C::V => S::V,
        C::Omega => S::Omega,
        C::Mode => S::Mode,
        C::D => S::D,
        C::Alpha => S::Alpha,
        C::Eta => S::Eta,
        C::DeltaEta => S::DeltaEta,
        C::Mu => S::Mu,
        C::Gamma => S::Gamma,
        C::Reachable => S::Reachable,
        C::VDt => S::VDt,
        C::GoalX => S::GoalX,
        C::GoalY => S::GoalY,
        C::GoalBeta => S::GoalBeta,
        C::GoalDTol => S::GoalDTol,
        C::GoalEpsTol => S::GoalEpsTol,
    }
}

// The exported numbers are the core's.
const _: () = {
    let modes = [
        CoreMode::EndOfSteering,
        CoreMode::OrientationOnly,
        CoreMode::PositionOnly,
        CoreMode::Funnelling,
    ];
    let mut k = 0;
    while k < modes.len() {
        assert!(
            mode(modes[k]) as u8 == modes[k] as u8,
            "Mode numbers differ"
        );
        k += 1;
    }
    let mut k = 0;
    while k < STATE_STRIDE {
        let f = CoreField::ALL[k];
        assert!(field(f) as usize == f as usize, "StateField offsets differ");
        k += 1;
    }
};
