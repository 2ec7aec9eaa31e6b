//! η tables built in the browser: what the page's Web Workers
//! call to build the table of the vehicle in use, split across workers.
//! Thin: the core's [`TableSpec`] does the work ([`TableSpec::encode_slice`]
//! per worker, [`TableSpec::assemble_encoded`] once), so a table built here
//! is byte-identical to `eta-table --vehicle` (`tests/web_tables.rs`).
//!
//! A job is described by the vehicle alone: the spec is the default layout
//! scaled to it ([`TableSpec::for_vehicle`], refused with the field named
//! when the generator cannot serve the vehicle). `counts` is optional (the
//! default size when absent), for small tables in tests.

use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::base::vehicle::VehicleParams;
use crate::bindings::boundary::{from_js, js_err, to_js};
use crate::funnelling::table::spec::{TableSpec, DEFAULT_COUNTS};
use crate::funnelling::table::{format::AXES, lookup::EtaTable};
use crate::funnelling::vehicle_file::REFERENCE;

fn spec(params: JsValue, counts: Option<Vec<u32>>) -> Result<TableSpec, JsError> {
    let p: VehicleParams = from_js("vehicle parameters", params)?;
    let counts = match counts {
        None => DEFAULT_COUNTS,
        Some(c) => {
            let c: [u32; AXES] = c
                .try_into()
                .map_err(|_| JsError::new("table counts: five integers expected"))?;
            if c.iter().any(|&n| !(2..=64).contains(&n)) {
                return Err(JsError::new("table counts: each in [2, 64]"));
            }
            c.map(|n| n as usize)
        }
    };
    TableSpec::for_vehicle(p, counts).map_err(|e| js_err("η table", e))
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct TableJob {
    key: String,
    entries: usize,
}

/// The job of building `params`' table: its cache key and entry count.
#[wasm_bindgen(js_name = tableJob, unchecked_return_type = "{ key: string; entries: number }")]
pub fn table_job(
    #[wasm_bindgen(unchecked_param_type = "Partial<VehicleParams>")] params: JsValue,
    counts: Option<Vec<u32>>,
) -> Result<JsValue, JsError> {
    let s = spec(params, counts)?;
    to_js(&TableJob {
        key: s.key(),
        entries: s.len(),
    })
}

/// Entries `start..end` of `params`' table, three f32 each (a worker's
/// share).
#[wasm_bindgen(js_name = tableSlice)]
pub fn table_slice(
    #[wasm_bindgen(unchecked_param_type = "Partial<VehicleParams>")] params: JsValue,
    counts: Option<Vec<u32>>,
    start: u32,
    end: u32,
) -> Result<Vec<f32>, JsError> {
    let s = spec(params, counts)?;
    let (start, end) = (start as usize, end as usize);
    if start > end || end > s.len() {
        return Err(JsError::new(&format!(
            "table slice {start}..{end} is outside 0..{}",
            s.len()
        )));
    }
    Ok(s.encode_slice(start..end))
}

/// The table file's bytes from every slice, concatenated in order.
#[wasm_bindgen(js_name = assembleTable)]
pub fn assemble_table(
    #[wasm_bindgen(unchecked_param_type = "Partial<VehicleParams>")] params: JsValue,
    counts: Option<Vec<u32>>,
    data: &[f32],
) -> Result<Vec<u8>, JsError> {
    let s = spec(params, counts)?;
    let t = s.assemble_encoded(data).map_err(|e| js_err("η table", e))?;
    Ok(t.to_bytes())
}

/// The parameter key of a table file (its cache key), after loading it
/// whole (a corrupt file is an error).
#[wasm_bindgen(js_name = tableKeyOf)]
pub fn table_key_of(bytes: &[u8]) -> Result<String, JsError> {
    let t = EtaTable::from_bytes(bytes).map_err(|e| js_err("η table", e))?;
    Ok(t.key())
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Reference {
    name: String,
    description: String,
    vehicle: VehicleParams,
}

/// The reference vehicles (`scenarios/vehicles/*.json`): pedestrian, car,
/// robot, and the car-like car (`vehicle.minTurnRadius` set).
#[wasm_bindgen(
    js_name = referenceVehicles,
    unchecked_return_type = "{ name: string; description: string; vehicle: VehicleParams }[]"
)]
pub fn reference_vehicles() -> Result<JsValue, JsError> {
    let all: Vec<Reference> = REFERENCE
        .iter()
        .filter_map(|(n, _)| crate::funnelling::vehicle_file::reference(n))
        .map(|f| Reference {
            name: f.name,
            description: f.description,
            vehicle: f.vehicle,
        })
        .collect();
    to_js(&all)
}
