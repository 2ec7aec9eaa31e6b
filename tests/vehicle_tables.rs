//! η tables for any vehicle. The axes scale with the vehicle
//! (the pedestrian's table is the committed one, byte for byte), vehicle
//! files are refused with the field named, the worker slices assemble to
//! the generator's bytes, and `steer run` never uses a table built for
//! other limits (error, or the matching table built and cached).

use std::path::{Path, PathBuf};
use std::process::Command;

use steering::base::vehicle::VehicleParams;
use steering::funnelling::table::lookup::EtaTable;
use steering::funnelling::table::spec::{check_vehicle, TableSpec, VehicleScale, DEFAULT_COUNTS};
use steering::funnelling::vehicle_file::{self, REFERENCE};

fn committed() -> Vec<u8> {
    std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/eta.bin")).unwrap()
}

#[test]
fn the_pedestrian_is_the_unit_and_its_table_the_committed_one() {
    let p = VehicleParams::default();
    let s = VehicleScale::of(&p);
    assert_eq!((s.length, s.speed, s.time()), (1.0, 1.0, 1.0));
    let spec = TableSpec::for_vehicle(p, DEFAULT_COUNTS).unwrap();
    let t = EtaTable::from_bytes(&committed()).unwrap();
    assert_eq!(t.key(), spec.key());
    assert_eq!(t.params(), &spec.params);
    for k in 0..5 {
        assert_eq!(t.axis(k), spec.axes[k].as_slice(), "axis {k}");
    }
}

#[test]
fn reference_vehicles_parse_and_scale() {
    let ped = vehicle_file::reference("pedestrian").unwrap();
    assert_eq!(ped.vehicle, VehicleParams::default());
    let car = vehicle_file::reference("car").unwrap().vehicle;
    assert_eq!((car.v_max, car.accel_max, car.omega_max), (15.0, 3.0, 0.8));
    assert_eq!((car.omega_accel_max, car.normal_accel_max), (2.0, 4.0));
    let robot = vehicle_file::reference("robot").unwrap().vehicle;
    assert_eq!((robot.v_max, robot.omega_max), (0.5, 4.0));
    for (name, _) in REFERENCE {
        let v = vehicle_file::reference(name).unwrap().vehicle;
        let spec = TableSpec::with_counts(v, DEFAULT_COUNTS);
        let s = VehicleScale::of(&v);
        // Distances in turning radii, speeds in fractions of v_max.
        let r = steering::funnelling::table::spec::turn_radius(&v);
        assert!((spec.axes[0][0] / r - 0.1875).abs() < 1e-4, "{name}");
        assert_eq!(*spec.axes[3].last().unwrap(), v.v_max);
        assert_eq!(spec.axes[4][0], 0.125 * v.v_max);
        assert!((spec.params.reach_radius - 0.25 * s.length).abs() < 1e-6);
    }
    // Car: turning radius 56.25 m, 21.1 × the pedestrian's 2.67 m.
    let s = VehicleScale::of(&car);
    assert!((s.length - 21.09375).abs() < 1e-3, "{}", s.length);
}

fn refused(text: &str, field: &str) {
    match vehicle_file::parse(text) {
        Ok(_) => panic!("accepted: {text}"),
        Err(e) => assert!(e.contains(field), "{text}: `{e}` does not name {field}"),
    }
}

#[test]
fn bad_vehicle_files_are_refused_with_the_field_named() {
    // NaN and Infinity are not JSON: the key they follow is named.
    refused(r#"{"vMax": NaN}"#, "vMax");
    refused(
        "{\n  \"vehicle\": {\n    \"dt\": 0.01,\n    \"omegaMax\": Infinity\n  }\n}",
        "omegaMax",
    );
    refused(r#"{"vehicle": {"accelMax": "fast"}}"#, "accelMax");
    // Zero and negative values: out of range.
    refused(r#"{"vehicle": {"omegaMax": 0}}"#, "omegaMax");
    refused(r#"{"vMax": -1}"#, "vMax");
    refused(r#"{"normalAccelMax": 0}"#, "normalAccelMax");
    refused(r#"{"dt": 0}"#, "dt");
    refused(r#"{"kd": -6}"#, "kd");
    refused(r#"{"vMax": 1e9}"#, "vMax");
    // Unknown keys (a misspelling) and a missing vehicle object.
    refused(r#"{"vmax": 2}"#, "vmax");
    refused(
        r#"{"name": "x", "vehicle": {"vMax": 2}, "colour": 1}"#,
        "colour",
    );
    // Absurd ratios.
    refused(
        r#"{"vMax": 100, "dt": 0.1, "omegaMax": 100, "normalAccelMax": 1000}"#,
        "vMax·dt",
    );
    refused(
        r#"{"omegaMax": 0.01, "normalAccelMax": 0.01}"#,
        "turning radius / vMax / dt",
    );
    refused(r#"{"accelMax": 0.01}"#, "accelMax");
    refused(r#"{"omegaAccelMax": 0.01}"#, "omegaAccelMax");
    refused(r#"{"kd": 100}"#, "kd·dt");
    refused(r#"{"kp": 5000}"#, "kp·dt²");
    // The table generator applies the same check.
    let bad = VehicleParams {
        omega_max: f32::NAN,
        ..VehicleParams::default()
    };
    assert!(check_vehicle(&bad).unwrap_err().contains("omegaMax"));
    assert!(TableSpec::for_vehicle(bad, DEFAULT_COUNTS).is_err());
}

#[test]
fn worker_slices_assemble_to_the_generators_bytes() {
    let car = vehicle_file::reference("car").unwrap().vehicle;
    let spec = TableSpec::with_counts(car, [4, 12, 3, 3, 3]);
    let whole = spec.generate().unwrap().to_bytes();
    let n = spec.len();
    let mut data = Vec::new();
    for r in [0..n / 3, n / 3..n / 2, n / 2..n] {
        data.extend(spec.encode_slice(r));
    }
    assert_eq!(spec.assemble_encoded(&data).unwrap().to_bytes(), whole);
    // Missing, truncated and corrupt slices are refused.
    assert!(spec.assemble_encoded(&data[..data.len() - 3]).is_err());
    let mut bad = data.clone();
    bad[3 * (n - 1) + 2] = 7.0;
    assert!(spec.assemble_encoded(&bad).is_err());
    let first_computed = (0..n).find(|&i| !spec.is_mirrored(i)).unwrap();
    let mut hole = data;
    hole[3 * first_computed + 2] = -1.0;
    assert!(spec.assemble_encoded(&hole).is_err());
    // The key follows every parameter.
    let other = TableSpec::with_counts(VehicleParams::default(), [4, 12, 3, 3, 3]);
    assert_ne!(other.key(), spec.key());
    let t = EtaTable::from_bytes(&whole).unwrap();
    assert_eq!(t.key(), spec.key());
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("steer-vehicle-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A short one-agent scenario for `vehicle` (JSON), with `extra` keys.
fn scenario(dir: &Path, vehicle: &str, extra: &str) -> PathBuf {
    let p = dir.join("sc.json");
    std::fs::write(
        &p,
        format!(
            r#"{{"name": "t", "duration": 3, "vehicle": {vehicle}, {extra}
               "agents": [{{"x": 0, "y": 0, "goals": [{{"x": 4, "y": 3, "speed": 0.8}}]}}]}}"#
        ),
    )
    .unwrap();
    p
}

fn steer(dir: &Path, cache: &Path, args: &[&str]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_steer"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("STEER_TABLE_CACHE", cache)
        .args(args)
        .arg("--out")
        .arg(dir.join("out.csv"))
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn steer_run_builds_caches_and_never_uses_a_mismatched_table() {
    let dir = scratch("run");
    let cache = dir.join("cache");
    let vehicle = r#"{"vMax": 1.0}"#;
    let sc = scenario(&dir, vehicle, "");
    let s = sc.to_str().unwrap();
    // The committed table is the pedestrian's: this vehicle gets its own,
    // built once and cached under its key.
    let (ok, e) = steer(&dir, &cache, &["run", s]);
    assert!(ok && e.contains("built the η table"), "{e}");
    let p: VehicleParams = serde_json::from_str(vehicle).unwrap();
    let key = TableSpec::with_counts(p, DEFAULT_COUNTS).key();
    let file = cache.join(format!("eta-{key}.bin"));
    assert!(file.exists(), "{}", file.display());
    let (ok, e) = steer(&dir, &cache, &["run", s]);
    assert!(ok && e.contains("from the cache"), "{e}");
    // A corrupt cache file is rebuilt, not used.
    let mut bytes = std::fs::read(&file).unwrap();
    bytes[100] ^= 1;
    std::fs::write(&file, &bytes).unwrap();
    let (ok, e) = steer(&dir, &cache, &["run", s]);
    assert!(ok && e.contains("built the η table"), "{e}");
    // The pedestrian's table under this vehicle's key: rebuilt too.
    std::fs::write(&file, committed()).unwrap();
    let (ok, e) = steer(&dir, &cache, &["run", s]);
    assert!(ok && e.contains("built the η table"), "{e}");
    // An explicit table for other limits is an error naming the field.
    let (ok, e) = steer(&dir, &cache, &["run", s, "--table", "tables/eta.bin"]);
    assert!(!ok && e.contains("vMax = 2") && e.contains("uses 1"), "{e}");
    // So is a scenario that names one.
    let committed_path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/eta.bin");
    let named = scenario(
        &dir,
        vehicle,
        &format!(r#""table": {:?},"#, committed_path.to_str().unwrap()),
    );
    let (ok, e) = steer(&dir, &cache, &["run", named.to_str().unwrap()]);
    assert!(!ok && e.contains("vMax"), "{e}");
    // The pedestrian runs on the committed table, no cache involved.
    let ped = scenario(&dir, "{}", "");
    let empty = dir.join("empty-cache");
    let (ok, e) = steer(&dir, &empty, &["run", ped.to_str().unwrap()]);
    assert!(ok && !e.contains("η table") && !empty.exists(), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn eta_table_writes_a_vehicles_table() {
    let dir = scratch("eta");
    let out = dir.join("t.bin");
    let vf = dir.join("v.json");
    std::fs::write(&vf, r#"{"name": "slow", "vehicle": {"vMax": 1.0}}"#).unwrap();
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_eta-table"))
            .args(args)
            .output()
            .unwrap()
    };
    let o = run(&[
        "--vehicle",
        vf.to_str().unwrap(),
        "--counts",
        "4,12,3,3,3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let t = EtaTable::from_bytes(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(t.params().vehicle.v_max, 1.0);
    std::fs::write(&vf, r#"{"vehicle": {"vMax": 0}}"#).unwrap();
    let o = run(&[
        "--vehicle",
        vf.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("vMax") && e.contains("v.json"),
        "{e}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
