//! What `tests/fuzz.rs` feeds the entry points: hostile JSON values and
//! mutations of real presets, hostile floats, argument vectors built from
//! every flag of the three binaries.

use proptest::prelude::*;
use serde_json::Value;

/// Values a hostile or careless user writes.
pub fn hostile_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        prop::sample::select(vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            1e-45,
            1e-7,
            0.01,
            2.0,
            100.0,
            1e3,
            1e5,
            999_980.0,
            1e6,
            1e7,
            3.4e38,
            -3.4e38,
            1e300,
            4_294_967_295.0,
            18_446_744_073_709_551_615.0,
        ])
        .prop_map(|x| serde_json::json!(x)),
        prop::sample::select(vec![
            0i64,
            1,
            -1,
            2,
            7,
            1000,
            100_000,
            1_000_001,
            i64::MAX,
            i64::MIN
        ])
        .prop_map(|x| serde_json::json!(x)),
        any::<f32>().prop_map(|x| serde_json::json!(x)),
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        "[a-zA-Z]{0,8}".prop_map(Value::String),
        Just(serde_json::json!([])),
        Just(serde_json::json!([1, 2])),
        Just(serde_json::json!({})),
        Just(serde_json::json!({"kind": "circle", "center": [0, 0], "angularSpeed": 100})),
    ]
}

/// Every (path into `v`) to a value, objects and arrays included.
pub fn paths(v: &Value, here: &mut Vec<Value>, out: &mut Vec<Vec<Value>>) {
    out.push(here.clone());
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                here.push(Value::String(k.clone()));
                paths(x, here, out);
                here.pop();
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                here.push(serde_json::json!(i));
                paths(x, here, out);
                here.pop();
            }
        }
        _ => {}
    }
}

pub fn at<'a>(v: &'a mut Value, path: &[Value]) -> &'a mut Value {
    path.iter().fold(v, |v, k| match k {
        Value::String(s) => &mut v[s.as_str()],
        Value::Number(n) => &mut v[n.as_u64().unwrap() as usize],
        _ => unreachable!(),
    })
}

pub fn get<'a>(v: &'a Value, path: &[Value]) -> Option<&'a Value> {
    path.iter().try_fold(v, |v, k| match k {
        Value::String(s) => v.get(s.as_str()),
        Value::Number(n) => v.get(n.as_u64()? as usize),
        _ => None,
    })
}

/// One mutation: a field replaced, a field removed, an unknown field, or
/// raw bytes changed.
#[derive(Clone, Debug)]
pub enum Mutation {
    Set(prop::sample::Index, Value),
    Remove(prop::sample::Index),
    Unknown(prop::sample::Index, String),
    Byte(prop::sample::Index, u8),
    Truncate(prop::sample::Index),
    /// A number scaled (a near-valid edit: most stay in range).
    Scale(prop::sample::Index, f64),
}

pub fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        6 => (any::<prop::sample::Index>(), hostile_value()).prop_map(|(i, v)| Mutation::Set(i, v)),
        1 => any::<prop::sample::Index>().prop_map(Mutation::Remove),
        1 => (any::<prop::sample::Index>(), "[a-z]{1,6}").prop_map(|(i, k)| Mutation::Unknown(i, k)),
        1 => (any::<prop::sample::Index>(), any::<u8>()).prop_map(|(i, b)| Mutation::Byte(i, b)),
        1 => any::<prop::sample::Index>().prop_map(Mutation::Truncate),
        4 => (any::<prop::sample::Index>(), prop::sample::select(vec![0.5, 0.9, 1.1, 2.0, -1.0, 10.0]))
            .prop_map(|(i, f)| Mutation::Scale(i, f)),
    ]
}

/// `text` (JSON) with `muts` applied in order.
pub fn mutate(text: &str, muts: &[Mutation]) -> String {
    let mut s = text.to_owned();
    for m in muts {
        let Ok(mut v) = serde_json::from_str::<Value>(&s) else {
            // Already broken: keep mutating bytes.
            if let Mutation::Byte(i, _) | Mutation::Unknown(i, _) = m {
                let mut bytes = s.into_bytes();
                if !bytes.is_empty() {
                    let k = i.index(bytes.len());
                    bytes[k] = if let Mutation::Byte(_, b) = m {
                        *b
                    } else {
                        b'['
                    };
                }
                s = String::from_utf8_lossy(&bytes).into_owned();
            }
            continue;
        };
        let mut ps = Vec::new();
        paths(&v, &mut Vec::new(), &mut ps);
        match m {
            Mutation::Set(i, x) => *at(&mut v, &ps[i.index(ps.len())]) = x.clone(),
            Mutation::Scale(i, f) => {
                let numbers: Vec<&Vec<Value>> = ps
                    .iter()
                    .filter(|p| get(&v, p).is_some_and(Value::is_number))
                    .collect();
                if let Some(p) = numbers.get(i.index(numbers.len().max(1))) {
                    let x = at(&mut v, p);
                    let n = x.as_f64().unwrap_or(0.0) * f;
                    *x = if x.is_u64() && n >= 0.0 {
                        serde_json::json!(n.round() as u64)
                    } else {
                        serde_json::json!(n)
                    };
                }
            }
            Mutation::Remove(i) => {
                let p = &ps[i.index(ps.len())];
                if let Some((last, parent)) = p.split_last() {
                    match (at(&mut v, parent), last) {
                        (Value::Object(o), Value::String(k)) => {
                            o.remove(k);
                        }
                        (Value::Array(a), Value::Number(n)) => {
                            a.remove(n.as_u64().unwrap() as usize);
                        }
                        _ => {}
                    }
                }
            }
            Mutation::Unknown(i, k) => {
                if let Value::Object(o) = at(&mut v, &ps[i.index(ps.len())]) {
                    o.insert(k.clone(), Value::Null);
                }
            }
            Mutation::Byte(i, b) => {
                let mut bytes = v.to_string().into_bytes();
                let k = i.index(bytes.len());
                bytes[k] = *b;
                s = String::from_utf8_lossy(&bytes).into_owned();
                continue;
            }
            Mutation::Truncate(i) => {
                let t = v.to_string();
                let mut k = i.index(t.len());
                while !t.is_char_boundary(k) {
                    k -= 1;
                }
                s = t[..k].to_owned();
                continue;
            }
        }
        s = v.to_string();
    }
    s
}

/// Floats a drag, a slider or a URL can produce.
pub fn hostile_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        1 => prop::sample::select(vec![
            0.0f32, -0.0, 0.01, 0.05, 0.1, 1.3, 2.0, 50.0, 100.0, 1e3, 4e4, 1e5, 999_980.0, 1e6,
            -1e6, 3.4e38, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, f32::MIN_POSITIVE,
        ]),
        3 => -1e3f32..1e3,
        1 => any::<f32>(),
    ]
}

/// Numbers and words as typed: edge values, overflow, signs, junk.
pub fn arg_value() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "0",
            "1",
            "2",
            "-1",
            "7",
            "1000000",
            "1000001",
            "99999999999",
            "18446744073709551615",
            "1e3",
            "0x10",
            " 5",
            "+3",
            "",
            "NaN",
            "inf",
            "-0",
            "0.5",
            "1.5",
            "256",
            "257",
            "standard",
            "relaxed",
            "entry",
            "paper-arc",
            "standard,relaxed",
            "nope",
            "a.csv",
            "a.CSV",
            "a.json",
            "a.jsonl",
            "a.txt",
            "scenarios/p000_fig1_seek.json",
            "{\"gain\": 3}",
            "{\"gain\": -1}",
            "{}",
            "[1]",
            "max_force=0.3",
            "measure_steps=4294967295",
            "boids=1000000",
            "warmup_steps=-1",
            "=1",
            "seed=\"x\"",
            "16,36,5,9,9",
            "2,2,2,2,2",
            "4096,4096,4096,4096,4096",
            "1,2",
            "5000,2,2,2,2",
            "circle32,doorway",
            "circle7",
        ])
        .prop_map(str::to_owned),
        any::<u64>().prop_map(|n| n.to_string()),
        any::<i64>().prop_map(|n| n.to_string()),
        "[ -~]{0,12}",
    ]
}

pub fn steer_args() -> impl Strategy<Value = Vec<String>> {
    let flag = prop::sample::select(vec![
        "--n",
        "--every",
        "--seed",
        "--out",
        "--table",
        "--threads",
        "--controller",
        "--aim",
        "--disk-margin",
        "--orientation-margin",
        "--only",
        "--standard",
        "--json",
        "--scenarios",
        "--brief",
        "--seeds",
        "--write-presets",
        "--help",
        "--version",
        "-h",
    ]);
    (
        prop::sample::select(vec![
            "run", "reach", "relaxed", "envelope", "avoid", "walk", "",
        ]),
        prop::collection::vec((flag, arg_value(), any::<bool>()), 0..6),
        arg_value(),
    )
        .prop_map(|(sub, flags, pos)| {
            let mut v = vec!["steer".to_owned(), sub.to_owned()];
            if sub == "run" {
                v.push(pos);
            }
            for (f, val, with_value) in flags {
                v.push(f.to_owned());
                if with_value {
                    v.push(val);
                }
            }
            v
        })
}

pub fn other_args(bin: &'static str) -> impl Strategy<Value = Vec<String>> {
    let flag = prop::sample::select(vec![
        "--set",
        "--set",
        "--write-presets",
        "--out",
        "--counts",
        "--threads",
        "--help",
    ]);
    prop::collection::vec((flag, arg_value()), 0..4).prop_map(move |flags| {
        let mut v = vec![bin.to_owned()];
        for (f, val) in flags {
            // --write-presets would write files: parse, never run it.
            v.push(f.to_owned());
            v.push(val);
        }
        v
    })
}
