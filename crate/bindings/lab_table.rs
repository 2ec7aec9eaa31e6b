//! `Lab`'s η table: what it holds, a new one in force (built by the page's
//! workers or read from its cache), and the key it is cached under.

use std::rc::Rc;

use wasm_bindgen::prelude::*;

use super::lab::Lab;
use super::lab_types::TableInfo;
use crate::bindings::boundary::{js_err, to_js};
use crate::funnelling::table::lookup::EtaTable;

#[wasm_bindgen]
impl Lab {
    /// The table's axes and build parameters.
    #[wasm_bindgen(js_name = tableInfo, unchecked_return_type = "TableInfo")]
    pub fn table_info(&self) -> Result<JsValue, JsError> {
        let t = self.table()?;
        to_js(&TableInfo {
            entries: t.len(),
            distances: t.axis(0),
            alphas: t.axis(1),
            omega_fractions: t.axis(2),
            speeds: t.axis(3),
            desired_speeds: t.axis(4),
            d_eta: t.d_eta(),
            params: t.params().vehicle,
        })
    }

    /// Replaces the η table (the bytes of a table file, e.g. one built
    /// by the workers for the limits in force, or read from the browser's
    /// cache); the agents keep their state. Returns the table's key. A
    /// corrupt file, or one whose key is not `expected_key` when given,
    /// is an error and changes nothing (the cache's bytes are checked
    /// here, loaded once). The first table of a lab made
    /// [`Lab::without_table`] also plans every agent, as adding them to a
    /// lab with a table would have (its clock has not run).
    #[wasm_bindgen(js_name = setTable)]
    pub fn set_table(
        &mut self,
        bytes: &[u8],
        expected_key: Option<String>,
    ) -> Result<String, JsError> {
        let t = EtaTable::from_bytes(bytes).map_err(|e| js_err("η table", e))?;
        let key = t.key();
        if let Some(want) = expected_key {
            if key != want {
                return Err(JsError::new(&format!(
                    "η table: built for other limits (key {key}, expected {want})"
                )));
            }
        }
        let first = self.table.is_none();
        self.expected = Self::expected_of(&t);
        self.table = Some(Rc::new(t));
        if first {
            if let Some(t) = &self.table {
                self.world.plan(t).map_err(|e| js_err("η table", e))?;
            }
        }
        Ok(key)
    }

    /// The key of the table in force (its cache key); before the table of
    /// a lab [`Lab::without_table`] has arrived, the key of the table it
    /// waits for (the default vehicle's).
    #[wasm_bindgen(js_name = tableKey)]
    #[must_use]
    pub fn table_key(&self) -> String {
        self.table
            .as_ref()
            .map_or_else(|| self.expected.key.clone(), |t| t.key())
    }
}
