//! `Lab`'s settings: the vehicle parameters, the funnelling and relaxed
//! settings, a reading (paper or ours) put in force, and the label the page
//! shows for the controller.

use wasm_bindgen::prelude::*;

use super::lab::Lab;
use crate::base::vehicle::VehicleParams;
use crate::bindings::boundary::{from_js, from_js_in, js_err, to_js};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::Reading;
use crate::funnelling::relaxed::RelaxedConfig;

#[wasm_bindgen]
impl Lab {
    /// The vehicle parameters in force.
    #[wasm_bindgen(unchecked_return_type = "VehicleParams")]
    pub fn params(&self) -> Result<JsValue, JsError> {
        to_js(self.world.params())
    }

    /// Replaces the vehicle parameters (validated). Returns a warning when
    /// they differ from the ones the table was built with (its η values are
    /// then only approximate), else an empty string.
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Partial<VehicleParams>")] params: JsValue,
    ) -> Result<String, JsError> {
        let p: VehicleParams = from_js("vehicle parameters", params)?;
        self.world
            .set_params(p)
            .map_err(|e| js_err("vehicle parameters", e))?;
        Ok(match self.table.as_ref().map(|t| t.check_params(&p)) {
            None | Some(Ok(())) => String::new(),
            Some(Err(e)) => format!("{e} (η predictions are approximate until then)"),
        })
    }

    /// The funnelling settings every agent uses (μ bound, gain, seek
    /// threshold), so the page can show what is in force.
    #[wasm_bindgen(unchecked_return_type = "FunnelConfig")]
    pub fn funnel(&self) -> Result<JsValue, JsError> {
        to_js(self.world.config())
    }

    /// Replaces the funnelling settings (validated; a refused config
    /// leaves the current one in force). Agents keep their state, goals
    /// and mode memory: the next update uses the new settings, so μ-bound
    /// variants can be compared on a running scene.
    #[wasm_bindgen(js_name = setFunnel)]
    pub fn set_funnel(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "FunnelConfig")] config: JsValue,
    ) -> Result<(), JsError> {
        let c: FunnelConfig = from_js_in("funnel settings", "funnel.", config)?;
        self.world
            .set_config(c)
            .map_err(|e| js_err("funnel settings", e))
    }

    /// Replaces the relaxed controller's settings (paper 001; in force
    /// whenever the world runs the relaxed controller), e.g. its aim: the
    /// disk's entry point (default) or the paper's relaxed point.
    #[wasm_bindgen(js_name = setRelaxed)]
    pub fn set_relaxed(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "RelaxedConfig")] config: JsValue,
    ) -> Result<(), JsError> {
        let c: RelaxedConfig = from_js_in("relaxed settings", "relaxed.", config)?;
        let kind = self.world.controller();
        self.world
            .set_controller(kind, c)
            .map_err(|e| js_err("relaxed settings", e))
    }

    /// Puts the funnelling and relaxed settings of a reading in force:
    /// `"paper"` (paper 000's standard and paper 001's relaxed funnelling
    /// exactly as written) or `"ours"` (the defaults). Agents keep their
    /// state and goals.
    #[wasm_bindgen(js_name = setReading)]
    pub fn set_reading(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Reading")] reading: JsValue,
    ) -> Result<(), JsError> {
        let r: Reading = from_js("reading", reading)?;
        let kind = self.world.controller();
        self.world
            .set_controller(kind, r.relaxed())
            .map_err(|e| js_err("reading", e))?;
        self.world
            .set_config(r.funnel())
            .map_err(|e| js_err("reading", e))
    }

    /// What the page shows for the controller in force: `paper 001
    /// relaxed`, `paper 000 standard`, `ours standard`, `custom relaxed`, …
    #[wasm_bindgen(js_name = controllerLabel)]
    #[must_use]
    pub fn controller_label(&self) -> String {
        Reading::label(
            self.world.controller(),
            self.world.config(),
            self.world.relaxed(),
        )
    }
}
