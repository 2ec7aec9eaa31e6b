//! Splitting a world into slices that step on their own (the lab steps
//! its agents in Web Workers, each owning a slice).
//!
//! Problem: [`World::step`] reads every agent's state from a snapshot taken
//! at the start of the step, and updates each agent from its own state, its
//! goal queue and that snapshot only (paper 000 §6: agents are independent).
//! The one exception is a goal that faces another agent (Fig. 6,
//! [`GoalMotion::FaceAgent`]): it reads that agent's snapshot state. A slice
//! that holds both ends of every such link therefore steps its agents to the
//! same bits as the whole world does.
//!
//! Design: slices are *contiguous* index ranges, so a worker's states land
//! at one offset of the page's state array and index `i` of the world is
//! index `i - start` of the slice. [`World::split_ranges`] balances the
//! ranges by count and moves each cut to the nearest index no facing link
//! crosses (the links of the lab's presets join two or three neighbours;
//! the random crowd has none). [`World::retain_range`] keeps one range and
//! renumbers the facing links inside it. The alternative, sharing every
//! agent's state with every worker once per step, needs a barrier per step
//! between workers; keeping linked agents together needs none.
//!
//! Fallback: a world whose agents are coupled (avoidance on: every agent
//! reads its neighbours) is one slice.

use core::ops::Range;

use crate::avoidance::config::AvoidanceMethod;
use crate::world::{goals::GoalMotion, World};

/// Why a world cannot keep only a range of its agents; nothing is changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SplitError {
    /// The range is empty, reversed or past the last agent.
    BadRange {
        /// Range asked for.
        start: usize,
        /// Its end (exclusive).
        end: usize,
        /// Agents in the world.
        count: usize,
    },
    /// An agent inside faces an agent outside (or the reverse).
    CutLink {
        /// The agent whose goal faces another.
        agent: usize,
        /// The agent it faces.
        faces: usize,
    },
    /// Avoidance couples every agent to its neighbours.
    Coupled,
}

impl core::fmt::Display for SplitError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::BadRange { start, end, count } => {
                write!(
                    f,
                    "agents {start}..{end} are not a range of the {count} agents"
                )
            }
            Self::CutLink { agent, faces } => write!(
                f,
                "agent {agent} faces agent {faces}: the range would separate them"
            ),
            Self::Coupled => write!(
                f,
                "avoidance couples every agent to its neighbours: the world steps as one"
            ),
        }
    }
}

impl std::error::Error for SplitError {}

impl World {
    /// Every facing link `(agent, faced)`, in agent order (one per goal that
    /// faces an existing other agent).
    pub fn face_links(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.agents.iter().enumerate().flat_map(|(i, a)| {
            a.goals.iter().filter_map(move |g| match g.motion {
                GoalMotion::FaceAgent { agent, .. } if agent != i => Some((i, agent)),
                _ => None,
            })
        })
    }

    /// At most `parts` contiguous ranges covering every agent, in order,
    /// about equal in size, no facing link crossing a cut (a cut moves to the
    /// nearest admissible index; ranges left empty are dropped). One range
    /// when avoidance is on. An empty world gives none.
    #[must_use]
    pub fn split_ranges(&self, parts: usize) -> Vec<Range<usize>> {
        let n = self.agents.len();
        if n == 0 {
            return Vec::new();
        }
        let parts = if self.avoidance.method == AvoidanceMethod::Off {
            parts.clamp(1, n)
        } else {
            1
        };
        // blocked[c]: a link crosses the cut before index c.
        let mut cross = vec![0i32; n + 1];
        for (a, b) in self.face_links() {
            if b >= n {
                continue;
            }
            let (lo, hi) = (a.min(b), a.max(b));
            cross[lo + 1] += 1;
            cross[hi + 1] -= 1;
        }
        let mut blocked = vec![false; n + 1];
        let mut run = 0;
        for (c, d) in cross.iter().enumerate() {
            run += d;
            blocked[c] = run > 0;
        }
        let mut cuts = vec![0];
        for k in 1..parts {
            let ideal = k * n / parts;
            let last = *cuts.last().unwrap_or(&0);
            // The nearest admissible cut after the last one.
            let found = (0..n).find_map(|off| {
                [ideal.saturating_sub(off), ideal + off]
                    .into_iter()
                    .find(|&c| c > last && c < n && !blocked[c])
            });
            if let Some(c) = found {
                if !cuts.contains(&c) {
                    cuts.push(c);
                }
            }
        }
        cuts.sort_unstable();
        cuts.push(n);
        cuts.windows(2)
            .filter(|w| w[0] < w[1])
            .map(|w| w[0]..w[1])
            .collect()
    }

    /// Keeps agents `range` only, renumbered from 0 (facing links inside
    /// renumbered with them): stepped, they give the same states, bit for
    /// bit, as the same agents in the whole world.
    ///
    /// # Errors
    /// A bad range, a facing link the range would cut, or avoidance on;
    /// nothing is changed then.
    pub fn retain_range(&mut self, range: Range<usize>) -> Result<(), SplitError> {
        let n = self.agents.len();
        let (start, end) = (range.start, range.end);
        if start >= end || end > n {
            return Err(SplitError::BadRange {
                start,
                end,
                count: n,
            });
        }
        if self.avoidance.method != AvoidanceMethod::Off && (start, end) != (0, n) {
            return Err(SplitError::Coupled);
        }
        if let Some((agent, faces)) = self
            .face_links()
            .find(|&(a, b)| b < n && range.contains(&a) != range.contains(&b))
        {
            return Err(SplitError::CutLink { agent, faces });
        }
        self.agents.truncate(end);
        self.agents.drain(..start);
        self.snapshot.truncate(end);
        self.snapshot.drain(..start);
        for a in &mut self.agents {
            for g in &mut a.goals {
                if let GoalMotion::FaceAgent { agent, .. } = &mut g.motion {
                    // Links to agents that do not exist stay dangling (the
                    // goal then keeps its own position, as in the whole world).
                    *agent = if *agent < n {
                        *agent - start
                    } else {
                        usize::MAX
                    };
                }
            }
        }
        self.queues_changed();
        Ok(())
    }
}
