//! Separation's command for one planning agent: a push away from what is
//! too near, added to the funnel's velocity.

use glam::Vec2;

use crate::avoidance::command::{unicycle, Command};
use crate::avoidance::neighbours::{Nearest, Neighbours};
use crate::avoidance::planning::{Agent, Pass};
use crate::base::vehicle::VehicleState;

impl Neighbours {
    /// Separation's command: a push away from every neighbour closer than
    /// two radii and from every obstacle closer than one, added to the
    /// funnel's velocity; the funnel's own command when nothing pushes.
    #[inline(always)]
    pub(crate) fn separation_command(
        &self,
        pass: &Pass,
        a: &Agent,
        near: &Nearest,
        states: &[VehicleState],
    ) -> Command {
        let (r, s, i) = (pass.r, a.state, a.peer.index as usize);
        let mut push = Vec2::ZERO;
        for &(d2, sj) in &near.near[..near.k] {
            let d = d2.sqrt();
            if d < 2.0 * r {
                let j = self.peers[sj as usize].index as usize;
                let dir = if d > 1e-9 {
                    (s.pos - states[j].pos) / d
                } else if i < j {
                    -Vec2::X
                } else {
                    Vec2::X
                };
                push += dir * (2.0 * r - d);
            }
        }
        for o in pass.obstacles {
            let (dist, nrm) = o.distance_normal(s.pos);
            if dist < r {
                push += nrm * (r - dist);
            }
        }
        if push == Vec2::ZERO {
            return a.funnel_command();
        }
        let v = (a.v_pref + push * pass.cfg.separation_weight).clamp_length_max(pass.p.v_max);
        unicycle(s, a.peer.fwd, a.h_pref, v, v, &pass.no_lines, pass.p.v_max)
    }
}
