//! Damaged scenario files, as a bad download, an editor or a hand edit
//! leaves them: seeded damage of the presets in `scenarios/` (pretty, and
//! on one line as the lab exports them), four kinds in turn: byte flips,
//! a value's type swapped, truncation, a field deleted. Each file goes to
//! `steer run` as a user runs it, and to `Scenario::from_bytes` (what the
//! page's `loadScenario` calls). Every refusal names the path of the field
//! at fault (none only a line and column), none panics, and a refused run
//! leaves its output file as it was.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;
use steering::base::field_error::TOP_LEVEL;
use steering::base::rng::Rng;
use steering::world::scenario::Scenario;

use crate::inputs::{at, paths};

/// Damaged files written and run.
pub const FILES: usize = 400;

/// What an output file holds before a run: a refused run must leave it so.
const BEFORE: &str = "a trajectory from an earlier run\n";

/// The four kinds of damage, in turn.
#[derive(Clone, Copy, Debug)]
enum Damage {
    /// One to three bytes replaced by any byte (not UTF-8 included).
    Flip,
    /// A value replaced by one of another JSON type.
    Swap,
    /// The file cut short.
    Truncate,
    /// A field of an object deleted.
    Delete,
}

const KINDS: [Damage; 4] = [Damage::Flip, Damage::Swap, Damage::Truncate, Damage::Delete];

fn pick<T: Clone>(rng: &mut Rng, from: &[T]) -> T {
    from[rng.below(from.len() as u32) as usize].clone()
}

/// A value of another JSON type than `v`.
fn swapped(v: &Value, rng: &mut Rng) -> Value {
    use serde_json::json;
    let others: Vec<Value> = match v {
        Value::Number(_) => vec![json!([1]), json!("1"), json!({}), json!(true), Value::Null],
        Value::String(_) => vec![json!(3), json!([]), json!(false), Value::Null],
        Value::Array(_) => vec![json!({}), json!(1), json!("list")],
        Value::Object(_) => vec![json!([]), json!("x"), json!(0)],
        Value::Bool(_) => vec![json!(0), json!("true")],
        Value::Null => vec![json!(1)],
    };
    pick(rng, &others)
}

/// `text` damaged once by `kind` (bytes: a flip may leave them not UTF-8).
fn damage(text: &str, kind: Damage, rng: &mut Rng) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    match kind {
        Damage::Flip => {
            for _ in 0..=rng.below(3) {
                let k = rng.below(bytes.len() as u32) as usize;
                bytes[k] = rng.below(256) as u8;
            }
            bytes
        }
        Damage::Truncate => {
            bytes.truncate(rng.below(bytes.len() as u32) as usize);
            bytes
        }
        Damage::Swap | Damage::Delete => {
            let mut v: Value = serde_json::from_str(text).unwrap();
            let mut ps = Vec::new();
            paths(&v, &mut Vec::new(), &mut ps);
            ps.remove(0); // the file itself
            if let Damage::Delete = kind {
                // Keys of objects only: deleting from a list is another file.
                ps.retain(|p| p.last().is_some_and(Value::is_string));
            }
            let p = pick(rng, &ps);
            match kind {
                Damage::Swap => {
                    let x = at(&mut v, &p);
                    *x = swapped(x, rng);
                }
                _ => {
                    let (key, parent) = p.split_last().unwrap();
                    if let Value::Object(o) = at(&mut v, parent) {
                        o.remove(key.as_str().unwrap());
                    }
                }
            }
            if rng.below(2) == 0 {
                serde_json::to_vec_pretty(&v).unwrap()
            } else {
                serde_json::to_vec(&v).unwrap()
            }
        }
    }
}

/// The presets, each pretty (as committed) and on one line (as the lab
/// exports a scene).
fn presets() -> Vec<String> {
    let dir = format!("{}/scenarios", env!("CARGO_MANIFEST_DIR"));
    let mut names: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    names.sort();
    names
        .iter()
        .flat_map(|p| {
            let text = std::fs::read_to_string(p).unwrap();
            let line = serde_json::from_str::<Value>(&text).unwrap().to_string();
            [text, line]
        })
        .collect()
}

/// Whether `message` names a field path: the refusal's own path, after
/// `prefix` (`scenario is not valid: ` and the like).
fn names_a_path(message: &str, path: &str) -> bool {
    let shown = if path.is_empty() { TOP_LEVEL } else { path };
    message.contains(&format!(": {shown}: "))
}

/// `steer run FILE --out OUT` as a user runs it, on the committed table
/// (a vehicle damaged into another table's limits is then refused rather
/// than built for minutes): (exit success, stderr).
fn steer_run(file: &Path, out: &Path) -> (bool, String) {
    let root = env!("CARGO_MANIFEST_DIR");
    let o = Command::new(env!("CARGO_BIN_EXE_steer"))
        .current_dir(root)
        .args([
            "run",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .args([
            "--table",
            &format!("{root}/tables/eta.bin"),
            "--every",
            "600",
        ])
        .output()
        .unwrap();
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Counts of one run of the test, printed at its end.
#[derive(Default, Debug)]
struct Counts {
    refused: usize,
    named: usize,
    top_level: usize,
    accepted: usize,
    refused_by_steer: usize,
}

#[test]
fn damaged_scenario_files_are_refused_naming_the_field_and_clobber_nothing() {
    let presets = presets();
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-damaged-scenarios");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut rng = Rng::new(54);
    let mut c = Counts::default();
    let mut unnamed = Vec::new();
    for k in 0..FILES {
        let kind = KINDS[k % KINDS.len()];
        let bytes = damage(&pick(&mut rng, &presets), kind, &mut rng);
        let file = dir.join(format!("{k:03}.json"));
        let out = dir.join(format!("{k:03}.csv"));
        std::fs::write(&file, &bytes).unwrap();
        std::fs::write(&out, BEFORE).unwrap();
        let parsed = Scenario::from_bytes(&bytes);
        let (ran, stderr) = steer_run(&file, &out);
        assert!(
            !stderr.contains("panicked"),
            "{k:03} ({kind:?}) panicked: {stderr}"
        );
        match &parsed {
            Ok(_) => c.accepted += 1,
            Err(e) => {
                c.refused += 1;
                let f = e.field();
                let message = e.to_string();
                if f.path.is_empty() {
                    // The file as a whole (cut before its first key, its
                    // braces or top-level commas broken): shown, to judge.
                    c.top_level += 1;
                    println!("top level {k:03} ({kind:?}): {message}");
                }
                if names_a_path(&message, &f.path) {
                    c.named += 1;
                } else {
                    unnamed.push(format!("{k:03} ({kind:?}): {message}"));
                }
                assert!(
                    !ran,
                    "{k:03}: steer ran a file the parser refuses: {message}"
                );
                assert!(
                    stderr.contains(&message),
                    "{k:03}: steer says `{stderr}`, the parser `{message}`"
                );
            }
        }
        if !ran {
            c.refused_by_steer += 1;
            assert_eq!(
                std::fs::read_to_string(&out).unwrap(),
                BEFORE,
                "{k:03} ({kind:?}): a refused run changed its output: {stderr}"
            );
        }
    }
    // Nothing but the files written here: no temporary file left behind.
    let left = std::fs::read_dir(&dir).unwrap().count();
    assert_eq!(left, 2 * FILES, "files left beside the outputs");
    println!(
        "fuzz damaged scenario files: {FILES} files, {} refused by the parser ({} naming a field \
         path, {} of them the top level), {} accepted; steer refused {}",
        c.refused, c.named, c.top_level, c.accepted, c.refused_by_steer
    );
    assert!(
        unnamed.is_empty(),
        "refusals naming no field:\n{}",
        unnamed.join("\n")
    );
    assert!(c.refused >= FILES / 2, "{c:?}");
}
