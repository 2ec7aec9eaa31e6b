//! Vehicle files: `eta-table --vehicle FILE`, `steer envelope
//! --vehicle FILE` and the lab's reference vehicles read one JSON object,
//! the scenarios' `vehicle` schema ([`VehicleParams`], camelCase keys,
//! unknown keys refused, missing keys the pedestrian's) either bare or
//! wrapped with a name and a description:
//!
//! ```json
//! { "name": "car", "description": "…", "vehicle": { "vMax": 15, "omegaMax": 0.8 } }
//! ```
//!
//! Why a module: a bad file must be refused with the field named. Ranges
//! and ratios are [`check_vehicle`]'s (the scenarios' validation plus the
//! generator's ratios); JSON has no NaN or Infinity, so a file that writes
//! one is a syntax error, which [`parse`] reports at the path of the key
//! whose value failed to parse ([`crate::base::field_error`]).
//!
//! The reference vehicles ([`REFERENCE`]) are the files in
//! `scenarios/vehicles/`, compiled in so the lab and the tests read the
//! same bytes.

use serde::Deserialize;

use crate::base::field_error::{self, FieldError};
use crate::base::vehicle::VehicleParams;
use crate::funnelling::table::spec::check_vehicle;

/// A parsed vehicle file.
#[derive(Clone, Debug, PartialEq)]
pub struct VehicleFile {
    /// Short name (empty for a bare object).
    pub name: String,
    /// What it is.
    pub description: String,
    /// The limits and gains.
    pub vehicle: VehicleParams,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Wrapped {
    #[serde(default)]
    name: String,
    #[serde(default)]
    description: String,
    vehicle: VehicleParams,
}

/// The reference vehicles (name, file text): pedestrian (the default),
/// car (a unicycle with a car's limits), small fast-turning robot, and
/// the car-like car (the car's limits with a minimum turning radius).
pub const REFERENCE: [(&str, &str); 4] = [
    (
        "pedestrian",
        include_str!("../../scenarios/vehicles/pedestrian.json"),
    ),
    ("car", include_str!("../../scenarios/vehicles/car.json")),
    ("robot", include_str!("../../scenarios/vehicles/robot.json")),
    (
        "car_like",
        include_str!("../../scenarios/vehicles/car_like.json"),
    ),
];

/// Parses and checks a vehicle file.
///
/// # Errors
/// A message naming the refused field by its path
/// ([`crate::base::field_error`]): a syntax error (NaN, Infinity) names
/// the key it follows, a wrong type or an unknown key the key itself
/// (`vehicle.accelMax: expected a number, found the string "fast"`);
/// ranges and ratios are [`check_vehicle`]'s.
pub fn parse(text: &str) -> Result<VehicleFile, String> {
    let refused = |e: FieldError| format!("vehicle file: {e}");
    let value: serde_json::Value = field_error::from_str(text).map_err(refused)?;
    let file = if value.get("vehicle").is_some() {
        let w: Wrapped = field_error::from_value(&value).map_err(refused)?;
        VehicleFile {
            name: w.name,
            description: w.description,
            vehicle: w.vehicle,
        }
    } else {
        let vehicle: VehicleParams = field_error::from_value(&value).map_err(refused)?;
        VehicleFile {
            name: String::new(),
            description: String::new(),
            vehicle,
        }
    };
    check_vehicle(&file.vehicle)?;
    Ok(file)
}

/// The reference vehicle called `name`.
#[must_use]
pub fn reference(name: &str) -> Option<VehicleFile> {
    REFERENCE
        .iter()
        .find(|(n, _)| *n == name)
        .and_then(|(_, text)| parse(text).ok())
}
