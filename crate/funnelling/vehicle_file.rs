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
//! one is a syntax error, which serde reports by line and column only:
//! [`parse`] names the key whose value failed to parse.
//!
//! The reference vehicles ([`REFERENCE`]) are the files in
//! `scenarios/vehicles/`, compiled in so the lab and the tests read the
//! same bytes.

use serde::Deserialize;

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

/// The key whose value starts before byte `at` of `text` (the last
/// `"key":` before it), for naming the field of a syntax error.
fn key_before(text: &str, at: usize) -> Option<&str> {
    let head = &text[..at.min(text.len())];
    let colon = head.rfind(':')?;
    let before = head[..colon].trim_end().strip_suffix('"')?;
    let open = before.rfind('"')?;
    Some(&before[open + 1..])
}

/// Byte offset of 1-based `line`, `column` in `text`.
fn offset(text: &str, line: usize, column: usize) -> usize {
    let start: usize = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum();
    (start + column.saturating_sub(1)).min(text.len())
}

/// Parses and checks a vehicle file.
///
/// # Errors
/// A message naming the refused field: a syntax error (NaN, Infinity,
/// a string for a number) names the key it follows, unknown keys and
/// wrong types are serde's (which name them), ranges and ratios
/// [`check_vehicle`]'s.
pub fn parse(text: &str) -> Result<VehicleFile, String> {
    let value: serde_json::Value = serde_json::from_str(text).map_err(|e| {
        let at = offset(text, e.line(), e.column());
        match key_before(text, at) {
            Some(k) => format!("field `{k}`: not a JSON number or value ({e})"),
            None => format!("not a JSON vehicle file: {e}"),
        }
    })?;
    // serde's type errors carry no path: name the key of a non-number.
    let obj = value.get("vehicle").unwrap_or(&value);
    if let Some(m) = obj.as_object() {
        for (k, v) in m {
            if k != "integrator" && !v.is_number() {
                return Err(format!("field `{k}`: expected a number, got {v}"));
            }
        }
    }
    let file = if value.get("vehicle").is_some() {
        let w: Wrapped = serde_json::from_value(value).map_err(|e| format!("vehicle file: {e}"))?;
        VehicleFile {
            name: w.name,
            description: w.description,
            vehicle: w.vehicle,
        }
    } else {
        let vehicle: VehicleParams =
            serde_json::from_value(value).map_err(|e| format!("vehicle: {e}"))?;
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
