//! Reading JSON input (scenario, vehicle, crowd and wander files, the
//! page's configuration objects) so that a refusal names the field at
//! fault by its path, `agents[0].goals[1].x: expected a number, found a
//! list`, never only a line and column (a file the lab exports is one
//! line long).
//!
//! How: [`serde_path_to_error`] tracks the path while serde decodes, for
//! any deserializer (serde_json's text and tree, serde-wasm-bindgen's
//! JavaScript values), so one [`FieldError`] serves every input. serde's
//! own words are then put in a user's: a missing or unknown field is named
//! as the field itself (`theta: missing`, not `x: missing field
//! `theta``), types as JSON says them (a number, a list, an object).

use core::fmt;

use serde::de::{Deserialize, DeserializeOwned, Deserializer};

/// Why an input was refused: the path of the field at fault and what is
/// wrong with it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldError {
    /// The field's path as a user writes it (`agents[0].goals[1].x`,
    /// `vehicle.vMax`); empty for the input as a whole (not JSON, not an
    /// object).
    pub path: String,
    /// What is wrong, in words (`expected a number, found a list`), with
    /// the line and column of a text input when known.
    pub message: String,
}

/// How [`FieldError`] shows an empty path: the input as a whole.
pub const TOP_LEVEL: &str = "(top level)";

impl FieldError {
    /// An error at `path` (`""` for the input as a whole).
    #[must_use]
    pub fn new(path: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            message: message.into(),
        }
    }

    /// The same error with `prefix` put before its path (a sub-object
    /// decoded alone: `funnel` before `gain`).
    #[must_use]
    pub fn within(mut self, prefix: &str) -> Self {
        self.path = join(prefix, &self.path);
        self
    }

    /// From serde's message `raw` at `path` (serde_path_to_error's, `.`
    /// for the top level): a missing, unknown or repeated field moves into
    /// the path, and the rest is put in plain words.
    fn from_serde(path: &str, raw: &str) -> Self {
        // serde_path_to_error writes `.` for the top level and `?` for a
        // key it could not read (a file cut inside a key): the object
        // holding that key is the path then.
        let path = path.trim_end_matches(".?").trim_end_matches('?');
        let path = if path == "." { "" } else { path };
        // serde-wasm-bindgen's errors are JavaScript `Error`s, whose text
        // starts "Error: ": the message alone reads better after the field.
        let raw = raw.strip_prefix("Error: ").unwrap_or(raw);
        let named = |prefix: &str| {
            let rest = raw.strip_prefix(prefix)?;
            let (name, tail) = rest.split_once('`')?;
            Some((name, tail))
        };
        if let Some((name, tail)) = named("missing field `") {
            return Self::new(join(path, name), format!("missing{tail}"));
        }
        if let Some((name, tail)) = named("duplicate field `") {
            return Self::new(join(path, name), format!("given twice{tail}"));
        }
        if let Some((name, tail)) = named("unknown field `") {
            let known = tail
                .trim_start_matches(", ")
                .replace("expected one of ", "known here: ")
                .replace("expected ", "known here: ")
                .replace("there are no fields", "none known here");
            return Self::new(join(path, name), format!("unknown field ({known})"));
        }
        Self::new(path, plain(raw))
    }
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let path = if self.path.is_empty() {
            TOP_LEVEL
        } else {
            &self.path
        };
        write!(f, "{path}: {}", self.message)
    }
}

impl std::error::Error for FieldError {}

/// `parent.name` (or `name` at the top level); `parent` itself when it
/// already ends with `name` (serde_path_to_error reads an unknown key
/// before the refusal).
fn join(parent: &str, name: &str) -> String {
    if parent == name || parent.ends_with(&format!(".{name}")) {
        return parent.to_owned();
    }
    match (parent.is_empty(), name.is_empty()) {
        (true, _) => name.to_owned(),
        (_, true) => parent.to_owned(),
        _ if name.starts_with('[') => format!("{parent}{name}"),
        _ => format!("{parent}.{name}"),
    }
}

/// serde's "invalid type: sequence, expected f32" as "expected a number,
/// found a list"; other messages as they are.
fn plain(raw: &str) -> String {
    let split = |prefix: &str| {
        let rest = raw.strip_prefix(prefix)?;
        rest.split_once(", expected ")
    };
    if let Some((found, expected)) = split("invalid type: ").or_else(|| split("invalid value: ")) {
        return format!(
            "expected {}, found {}",
            expected_words(expected),
            found_words(found)
        );
    }
    raw.to_owned()
}

/// What serde says it expected, as JSON says it.
fn expected_words(e: &str) -> String {
    match e {
        "f32" | "f64" => "a number".to_owned(),
        "u8" | "u16" | "u32" | "u64" | "usize" | "i8" | "i16" | "i32" | "i64" | "isize" => {
            "a whole number".to_owned()
        }
        "a boolean" => "true or false".to_owned(),
        "a sequence" => "a list".to_owned(),
        _ if e.starts_with("struct ") || e.starts_with("internally tagged enum") => {
            "an object".to_owned()
        }
        _ => e
            .replace("a sequence of", "a list of")
            .replace("f32 values", "numbers")
            .replace("f32", "number"),
    }
}

/// What serde says it found, as JSON says it.
fn found_words(found: &str) -> String {
    let quoted = |prefix: &str| {
        found
            .strip_prefix(prefix)
            .map(|v| v.trim_matches('`').to_owned())
    };
    // serde-wasm-bindgen shows other JavaScript values as `JsValue(…)`.
    let js = found
        .strip_prefix("JsValue(")
        .and_then(|v| v.strip_suffix(')'));
    match (found, js) {
        ("sequence", _) => "a list".to_owned(),
        ("map", _) => "an object".to_owned(),
        ("unit value" | "unit" | "null", _) => "null".to_owned(),
        (_, Some(v)) if v.starts_with('[') => "a list".to_owned(),
        (_, Some(v)) if v.starts_with("Object(") || v.starts_with('{') => "an object".to_owned(),
        (_, Some(v)) => v.to_owned(),
        _ => quoted("floating point ")
            .or_else(|| quoted("integer "))
            .map(|n| format!("the number {n}"))
            .or_else(|| quoted("boolean "))
            .or_else(|| {
                found
                    .strip_prefix("string ")
                    .map(|s| format!("the string {s}"))
            })
            .unwrap_or_else(|| found.to_owned()),
    }
}

/// A serde_json error at `path` (`.` for the top level): its message
/// without " at line L column C", put in plain words, then the position.
fn from_json_error(path: &str, e: &serde_json::Error) -> FieldError {
    let s = e.to_string();
    let suffix = format!(" at line {} column {}", e.line(), e.column());
    match s.strip_suffix(&suffix) {
        Some(m) if e.line() > 0 => {
            let mut f = FieldError::from_serde(path, m);
            f.message = format!("{} (line {}, column {})", f.message, e.line(), e.column());
            f
        }
        _ => FieldError::from_serde(path, &s),
    }
}

/// Decodes `T` from JSON text, the whole text (trailing characters are
/// refused).
///
/// # Errors
/// A [`FieldError`] naming the field at fault (a syntax error names the
/// field it interrupts), with the line and column.
pub fn from_str<T: DeserializeOwned>(text: &str) -> Result<T, FieldError> {
    from_slice(text.as_bytes())
}

/// [`from_str`] on bytes (a file as read: bytes that are not UTF-8 are
/// refused at the field they are in).
///
/// # Errors
/// As [`from_str`].
pub fn from_slice<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, FieldError> {
    let mut de = serde_json::Deserializer::from_slice(bytes);
    let t = serde_path_to_error::deserialize(&mut de)
        .map_err(|e| from_json_error(&e.path().to_string(), e.inner()))?;
    de.end().map_err(|e| from_json_error("", &e))?;
    Ok(t)
}

/// Decodes `T` from a JSON tree.
///
/// # Errors
/// A [`FieldError`] naming the field at fault.
pub fn from_value<T: DeserializeOwned>(v: &serde_json::Value) -> Result<T, FieldError> {
    deserialize(v)
}

/// Decodes `T` from any deserializer (serde-wasm-bindgen's JavaScript
/// values in the bindings).
///
/// # Errors
/// A [`FieldError`] naming the field at fault.
pub fn deserialize<'de, T, D>(d: D) -> Result<T, FieldError>
where
    T: Deserialize<'de>,
    D: Deserializer<'de>,
{
    serde_path_to_error::deserialize(d)
        .map_err(|e| FieldError::from_serde(&e.path().to_string(), &e.inner().to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Goal {
        x: f32,
        #[serde(default)]
        n: u32,
    }

    #[derive(Debug, serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Agent {
        x: f32,
        theta: f32,
        goals: Vec<Goal>,
    }

    #[derive(Debug, serde::Deserialize)]
    #[allow(dead_code)]
    struct File {
        agents: Vec<Agent>,
    }

    fn err(text: &str) -> String {
        from_str::<File>(text).unwrap_err().to_string()
    }

    #[test]
    fn a_refusal_names_the_path_in_plain_words() {
        let ok = r#"{"x": 0, "theta": 1, "goals": [{"x": 1}]}"#;
        assert!(from_str::<File>(&format!(r#"{{"agents": [{ok}]}}"#)).is_ok());
        let e = err(r#"{"agents": [{"x": 0, "theta": 1, "goals": [{"x": 1}, {"x": [1]}]}]}"#);
        assert!(
            e.starts_with("agents[0].goals[1].x: expected a number, found a list"),
            "{e}"
        );
        let e = err(r#"{"agents": [{"x": 0, "goals": []}]}"#);
        assert!(e.starts_with("agents[0].theta: missing"), "{e}");
        let e = err(r#"{"agents": [{"x": 0, "theta": 1, "goals": [], "tehta": 2}]}"#);
        assert!(
            e.starts_with("agents[0].tehta: unknown field (known here: `x`, `theta`, `goals`)"),
            "{e}"
        );
        let e = err(r#"{"agents": [{"x": 0, "theta": 1, "goals": [{"x": 1, "n": -2}]}]}"#);
        assert!(
            e.starts_with("agents[0].goals[0].n: expected a whole number, found the number -2"),
            "{e}"
        );
        let e = err(r#"{"agents": [{"x": 0, "theta": "#);
        assert!(e.starts_with("agents[0].theta: EOF while parsing"), "{e}");
        let e = err("1");
        assert!(
            e.starts_with("(top level): expected an object, found the number 1"),
            "{e}"
        );
        let e = err(r#"{"agents": []} x"#);
        assert!(e.starts_with("(top level): trailing characters"), "{e}");
    }
}
