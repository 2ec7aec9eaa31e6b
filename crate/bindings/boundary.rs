//! Conversions at the JavaScript boundary shared by the three binding
//! modules (`lab`, `crowd`, `wander`): JavaScript
//! values in and out through serde-wasm-bindgen, and errors as `JsError`s
//! that name what was refused.
//!
//! Why the key check: serde-wasm-bindgen reads a struct by asking the
//! JavaScript object for the fields the struct declares, so a key it does not
//! declare is never seen and `#[serde(deny_unknown_fields)]` cannot fire. A
//! misspelt `{gian: 3}` would be dropped without a word and the default used
//! instead, which breaks the project rule that bad input gets a clear error.
//! [`from_js`] therefore serialises what it decoded back to a JSON tree and
//! requires every key of the input object, at every depth, to be in it.

use serde::{Deserialize, Serialize};
use serde_json::Value;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// `"{context}: {e}"` as a JavaScript `Error`.
pub(crate) fn js_err(context: &str, e: impl core::fmt::Display) -> JsError {
    JsError::new(&format!("{context}: {e}"))
}

/// Decodes a configuration object, refusing keys the type does not know.
/// A refused object names the top-level field at fault (see
/// [`field_at_fault`]): `"{what}, field `{key}`: {serde's message}"`.
pub(crate) fn from_js<T>(what: &str, v: JsValue) -> Result<T, JsError>
where
    T: for<'de> Deserialize<'de> + Serialize,
{
    from_js_in(what, "", v)
}

/// [`from_js`] with the field named as `{prefix}{key}` (the funnel settings
/// say `funnel.gain`, as their range checks do).
pub(crate) fn from_js_in<T>(what: &str, prefix: &str, v: JsValue) -> Result<T, JsError>
where
    T: for<'de> Deserialize<'de> + Serialize,
{
    let t: T =
        serde_wasm_bindgen::from_value(v.clone()).map_err(|e| match field_at_fault::<T>(&v) {
            Some(k) => js_err(&format!("{what}, field `{prefix}{k}`"), e),
            None => js_err(what, e),
        })?;
    check_known_keys(what, &v, &t)?;
    Ok(t)
}

/// The key of `input` whose value made decoding fail, when one can be told.
///
/// serde's messages carry no path ("invalid type: string "2", expected
/// f32"). serde-wasm-bindgen reads the declared fields in turn, stops at the
/// first bad value and reports missing fields only after the present ones;
/// so a key is at fault exactly when, with that key removed, decoding
/// succeeds (the field has a default) or fails only for that key's absence.
/// Runs on the error path only.
fn field_at_fault<T: for<'de> Deserialize<'de>>(input: &JsValue) -> Option<String> {
    if js_sys::Array::is_array(input) {
        return None;
    }
    let obj = input.dyn_ref::<js_sys::Object>()?;
    js_sys::Object::keys(obj).iter().find_map(|key| {
        let k = key.as_string()?;
        let without = js_sys::Object::assign(&js_sys::Object::new(), obj);
        js_sys::Reflect::delete_property(&without, &key).ok()?;
        match serde_wasm_bindgen::from_value::<T>(without.into()) {
            Ok(_) => Some(k),
            Err(e) => e
                .to_string()
                .contains(&format!("missing field `{k}`"))
                .then_some(k),
        }
    })
}

/// A Rust value as a plain JavaScript object (maps as objects, not `Map`s).
pub(crate) fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| js_err("conversion to JavaScript", e))
}

/// The error for the first key of `input` that `decoded` (the value it was
/// decoded to) does not have; `Ok` when there is none.
pub(crate) fn check_known_keys<T: Serialize>(
    what: &str,
    input: &JsValue,
    decoded: &T,
) -> Result<(), JsError> {
    // A value serde_json cannot represent (none of our configs) is not checked.
    let Ok(tree) = serde_json::to_value(decoded) else {
        return Ok(());
    };
    match unknown_key(input, &tree, "") {
        None => Ok(()),
        Some((path, known)) => Err(js_err(
            what,
            format!("unknown field `{path}` (known here: {})", known.join(", ")),
        )),
    }
}

/// Walks `input` alongside `tree`; returns the dotted path of the first
/// unknown key and the keys known at that depth. Keys whose value is `null`
/// or `undefined` are skipped: an absent optional field serialises to
/// nothing, and such a key asks for nothing anyway.
fn unknown_key(input: &JsValue, tree: &Value, path: &str) -> Option<(String, Vec<String>)> {
    match tree {
        Value::Object(map) => {
            if js_sys::Array::is_array(input) {
                return None;
            }
            let obj = input.dyn_ref::<js_sys::Object>()?;
            for key in js_sys::Object::keys(obj).iter() {
                let k = key.as_string()?;
                let value = js_sys::Reflect::get(input, &key).ok()?;
                if value.is_null() || value.is_undefined() {
                    continue;
                }
                let here = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                match map.get(&k) {
                    None => return Some((here, map.keys().cloned().collect())),
                    Some(sub) => {
                        if let Some(found) = unknown_key(&value, sub, &here) {
                            return Some(found);
                        }
                    }
                }
            }
            None
        }
        Value::Array(items) => items.iter().enumerate().find_map(|(i, sub)| {
            let value = js_sys::Reflect::get_u32(input, i as u32).ok()?;
            unknown_key(&value, sub, &format!("{path}[{i}]"))
        }),
        _ => None,
    }
}
