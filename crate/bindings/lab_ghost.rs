//! `Lab`'s look inside an agent: its controller's internals for the
//! current state, the predicted seek path (the ghost, paper 000 Fig. 1c)
//! and the table ring at its target distance.

use glam::Vec2;
use wasm_bindgen::prelude::*;

use super::lab::Lab;
use super::lab_types::{ArcOut, GhostOut, InternalsOut};
use crate::base::vehicle::VehicleState;
use crate::bindings::boundary::{js_err, to_js};
use crate::funnelling::controller::ControllerKind;
use crate::funnelling::ghost::{seek_ghost, table_limits, update_ghost, Ghost};
use crate::funnelling::update::{Internals, Mode, Update};
use crate::world::provisional_plan;

/// Points a ghost path keeps at most ([`crate::funnelling::ghost`]).
const GHOST_POINTS: usize = 256;

#[wasm_bindgen]
impl Lab {
    /// Agent `i`'s controller internals for its *current* state and goal,
    /// evaluated without stepping (so a drag while paused shows the new
    /// mode at once).
    #[wasm_bindgen(unchecked_return_type = "Internals")]
    pub fn internals(&self, i: u32) -> Result<JsValue, JsError> {
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        let mut out = InternalsOut::from(self.plan_of(i)?);
        if self.world.controller() == ControllerKind::Relaxed && !a.done() && self.table.is_some() {
            let r = &a.relaxed;
            out.arc = Some(ArcOut {
                alpha_min: r.arc_min,
                alpha_max: r.arc_max,
                alpha_r: r.alpha_r,
                radius: r.ring,
                f_min: r.f_min,
                f_max: r.f_max,
                t_min: r.t_min,
                t_max: r.t_max,
                branch: r.branch as u8,
            });
        }
        to_js(&out)
    }

    /// The predicted seek path of agent `i`'s current update (paper 000
    /// Fig. 1c, [`crate::funnelling::ghost::update_ghost`]): from its state towards the
    /// point its controller asked the η table about, at the queried speed
    /// (or the fallback v_dt where the table says unreachable). `points`
    /// holds x, y pairs (at most 256 points).
    #[wasm_bindgen(unchecked_return_type = "Ghost")]
    pub fn ghost(&mut self, i: u32) -> Result<JsValue, JsError> {
        let inter = self.plan_of(i)?;
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        let Some(table) = self.table.as_deref() else {
            // Before the table: the plain seek towards the goal centre.
            self.ghost.clear();
            let g = seek_ghost(
                self.world.params(),
                a.state,
                a.goal_now.pos,
                a.goal_now.speed,
                &self.expected.limits,
                GHOST_POINTS,
                &mut self.ghost,
            );
            return self.ghost_out(&g);
        };
        let g = update_ghost(
            table,
            self.world.params(),
            &a.state,
            &inter,
            &a.goal_now,
            GHOST_POINTS,
            &mut self.ghost,
        );
        self.ghost_out(&g)
    }

    /// The predicted seek path from any state (position, heading θ, speed
    /// v, angular speed ω) towards the point (`tx`, `ty`) at desired speed
    /// `v_d`: the table generator's simulation ([`crate::funnelling::ghost::seek_ghost`]).
    #[wasm_bindgen(js_name = ghostFrom, unchecked_return_type = "Ghost")]
    #[allow(clippy::too_many_arguments)]
    pub fn ghost_from(
        &mut self,
        x: f32,
        y: f32,
        theta: f32,
        v: f32,
        omega: f32,
        tx: f32,
        ty: f32,
        v_d: f32,
    ) -> Result<JsValue, JsError> {
        let s = VehicleState::new(Vec2::new(x, y), theta, v, omega);
        s.validate(self.world.params())
            .map_err(|e| js_err("ghost state", e))?;
        crate::base::range::check_range("ghost.tx", tx, -1e6, 1e6)
            .map_err(|e| js_err("ghost", e))?;
        crate::base::range::check_range("ghost.ty", ty, -1e6, 1e6)
            .map_err(|e| js_err("ghost", e))?;
        crate::base::range::check_range("ghost.vD", v_d, 0.0, self.world.params().v_max)
            .map_err(|e| js_err("ghost", e))?;
        self.ghost.clear();
        let g = seek_ghost(
            self.world.params(),
            s,
            Vec2::new(tx, ty),
            v_d,
            &self
                .table
                .as_deref()
                .map_or(self.expected.limits, table_limits),
            GHOST_POINTS,
            &mut self.ghost,
        );
        self.ghost_out(&g)
    }

    fn ghost_out(&self, g: &Ghost) -> Result<JsValue, JsError> {
        let out = to_js(&GhostOut::from(g))?;
        let pts: Vec<f32> = self.ghost.iter().flat_map(|p| [p.x, p.y]).collect();
        js_sys::Reflect::set(
            &out,
            &JsValue::from_str("points"),
            &js_sys::Float32Array::from(pts.as_slice()),
        )
        .map_err(|_| JsError::new("ghost: could not attach the points"))?;
        Ok(out)
    }

    /// What agent `i`'s controller chooses for its current state and goal
    /// (no stepping; the relaxed controller's last update).
    fn plan_of(&self, i: u32) -> Result<Internals, JsError> {
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        Ok(if a.done() {
            Internals {
                mode: Mode::EndOfSteering,
                gamma: a.state.theta,
                ..Default::default()
            }
        } else if self.table.is_none() {
            // Before the table: what the core can say without one; no η.
            Internals {
                eta: f32::NAN,
                delta_eta: f32::NAN,
                mu: f32::NAN,
                mu_max: f32::NAN,
                ..provisional_plan(self.world.params(), &a.state, &a.goal_now)
            }
        } else if self.world.controller() == ControllerKind::Relaxed
            || self.world.params().car_like()
        {
            // Relaxed funnelling plans towards the relaxed point, and a
            // car-like vehicle's manoeuvre, once begun, lives in its memory
            // (crate::funnelling::manoeuvre): a fresh plan from here would
            // forget either. Show what its last update did.
            a.internals
        } else {
            let (mut mem, mut state) = (a.memory, a.state);
            self.world.config().plan(&mut Update {
                table: self.table()?,
                params: self.world.params(),
                state: &mut state,
                goal: &a.goal_now,
                memory: &mut mem,
            })
        })
    }

    /// The table ring nearest to agent `i`'s target distance, in its frame,
    /// for its current speeds and goal speed (paper 001 Fig. 4).
    #[wasm_bindgen(js_name = etaRing)]
    pub fn eta_ring(&self, i: u32) -> Result<Vec<f32>, JsError> {
        let a = self
            .world
            .agent(i as usize)
            .map_err(|e| js_err("agent", e))?;
        let d = (a.goal_now.pos - a.state.pos).length();
        Ok(self.eta_ring_at(d, a.state.v, a.state.omega, a.goal_now.speed))
    }
}
