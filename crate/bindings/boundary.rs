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
//! requires every key of the input object, at every depth, to be in it or
//! to be read by the type (a field left out of the tree at its default).

use serde::{Deserialize, Serialize};
use serde_json::Value;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// `"{context}: {e}"` as a JavaScript `Error`.
pub(crate) fn js_err(context: &str, e: impl core::fmt::Display) -> JsError {
    JsError::new(&format!("{context}: {e}"))
}

/// Decodes a configuration object, refusing keys the type does not know.
/// A refused object names the field at fault by its path
/// ([`crate::base::field_error`]): `"{what}, field `{path}`: {what is
/// wrong}"`, e.g. `agent, field `goals[1].x`: expected a number, found a
/// list` or `agent, field `theta`: missing`.
pub(crate) fn from_js<T>(what: &str, v: JsValue) -> Result<T, JsError>
where
    T: for<'de> Deserialize<'de> + Serialize,
{
    from_js_in(what, "", v)
}

/// [`from_js`] with the field named as `{prefix}{path}` (the funnel
/// settings say `funnel.gain`, as their range checks do).
pub(crate) fn from_js_in<T>(what: &str, prefix: &str, v: JsValue) -> Result<T, JsError>
where
    T: for<'de> Deserialize<'de> + Serialize,
{
    let t: T =
        crate::base::field_error::deserialize(serde_wasm_bindgen::Deserializer::from(v.clone()))
            .map_err(|e| {
                if e.path.is_empty() {
                    js_err(what, e.message)
                } else {
                    js_err(&format!("{what}, field `{prefix}{}`", e.path), e.message)
                }
            })?;
    check_known_keys(what, &v, &t)?;
    Ok(t)
}

/// A Rust value as a plain JavaScript object (maps as objects, not `Map`s).
pub(crate) fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| js_err("conversion to JavaScript", e))
}

/// The error for the first key of `input` that `decoded` (the value it was
/// decoded to) does not have and that `T` does not read; `Ok` when there is
/// none.
pub(crate) fn check_known_keys<T>(what: &str, input: &JsValue, decoded: &T) -> Result<(), JsError>
where
    T: for<'de> Deserialize<'de> + Serialize,
{
    // A value serde_json cannot represent (none of our configs) is not checked.
    let Ok(tree) = serde_json::to_value(decoded) else {
        return Ok(());
    };
    // A field serialised only when it differs from its default
    // (`skip_serializing_if`: `minTurnRadius: 0`, an empty obstacle list)
    // is missing from the tree yet declared. It is known when decoding
    // fails with a string put in its place: serde-wasm-bindgen asks the
    // object only for the fields the type declares, and every such field
    // is a number, a list, a struct or an enum of other names. An unknown
    // key stays unread, or is buffered whole by an internally tagged enum
    // (which takes any string), so decoding still succeeds.
    let read = |path: &[JsValue]| {
        let probe = JsValue::from_str("\u{1}probe");
        serde_wasm_bindgen::from_value::<T>(replaced(input, path, &probe)).is_err()
    };
    match unknown_key(input, &tree, &mut Vec::new(), &read) {
        None => Ok(()),
        Some((path, known)) => Err(js_err(
            what,
            format!("unknown field `{path}` (known here: {})", known.join(", ")),
        )),
    }
}

/// A shallow copy of `input` along `path` (object keys, array indices) with
/// the value at its end replaced by `value`; the rest is shared.
fn replaced(input: &JsValue, path: &[JsValue], value: &JsValue) -> JsValue {
    let Some((key, rest)) = path.split_first() else {
        return value.clone();
    };
    let copy: JsValue = if js_sys::Array::is_array(input) {
        js_sys::Array::from(input).into()
    } else {
        js_sys::Object::assign(&js_sys::Object::new(), input.unchecked_ref()).into()
    };
    let inner = js_sys::Reflect::get(input, key).unwrap_or(JsValue::UNDEFINED);
    // Setting a property on a fresh plain object or array cannot fail.
    let _ = js_sys::Reflect::set(&copy, key, &replaced(&inner, rest, value));
    copy
}

/// The dotted form of a path (`goals[0].speed`).
fn dotted(path: &[JsValue]) -> String {
    let mut out = String::new();
    for key in path {
        match key.as_f64() {
            Some(i) => out.push_str(&format!("[{i}]")),
            None => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(&key.as_string().unwrap_or_default());
            }
        }
    }
    out
}

/// Walks `input` alongside `tree`; returns the dotted path of the first
/// key that is neither in the tree nor `read` by the type (see
/// [`check_known_keys`]), and the keys known at that depth. Keys whose
/// value is `null` or `undefined` are skipped: an absent optional field
/// serialises to nothing, and such a key asks for nothing anyway.
fn unknown_key(
    input: &JsValue,
    tree: &Value,
    path: &mut Vec<JsValue>,
    read: &dyn Fn(&[JsValue]) -> bool,
) -> Option<(String, Vec<String>)> {
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
                path.push(key);
                let found = match map.get(&k) {
                    None if read(path) => None,
                    None => Some((dotted(path), map.keys().cloned().collect())),
                    Some(sub) => unknown_key(&value, sub, path, read),
                };
                path.pop();
                if found.is_some() {
                    return found;
                }
            }
            None
        }
        Value::Array(items) => items.iter().enumerate().find_map(|(i, sub)| {
            let value = js_sys::Reflect::get_u32(input, i as u32).ok()?;
            path.push(JsValue::from(i as u32));
            let found = unknown_key(&value, sub, path, read);
            path.pop();
            found
        }),
        _ => None,
    }
}
