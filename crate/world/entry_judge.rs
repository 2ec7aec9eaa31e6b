//! Counting, per agent, the goals it has left and those it entered
//! oriented: the arrival verdict a GPU kernel's free run is compared on
//! (docs/DESIGN.md §20). A goal counts as entered oriented when, on the step
//! its queue advanced, the heading after the step was within `ε_tol` of β.

use crate::base::angle::diff;
use crate::world::World;

/// Goals left and goals entered oriented, per agent, over the steps
/// observed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EntryJudge {
    current: Vec<usize>,
    oriented: Vec<u32>,
}

impl EntryJudge {
    /// Starts counting from `w` as it is.
    #[must_use]
    pub fn new(w: &World) -> Self {
        Self {
            current: w.agents.iter().map(|a| a.current).collect(),
            oriented: vec![0; w.agents.len()],
        }
    }

    /// Looks at `w` after one step: an agent whose queue advanced is judged
    /// on the goal it left (a step advances a queue by one goal at most).
    pub fn observe(&mut self, w: &World) {
        for ((a, seen), oriented) in w
            .agents
            .iter()
            .zip(&mut self.current)
            .zip(&mut self.oriented)
        {
            if a.current > *seen {
                if let Some(g) = a.goals.get(a.current - 1) {
                    if diff(g.goal.beta, a.state.theta).abs() < g.goal.eps_tol {
                        *oriented += 1;
                    }
                }
            }
            *seen = a.current;
        }
    }

    /// Per agent: its current goal's index and the goals entered oriented.
    #[must_use]
    pub fn verdicts(&self) -> Vec<u32> {
        self.current
            .iter()
            .zip(&self.oriented)
            .flat_map(|(&c, &o)| [c as u32, o])
            .collect()
    }
}
