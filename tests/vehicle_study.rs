//! The fast slice of the per-vehicle study (`steer envelope
//! --vehicle scenarios/vehicles/NAME.json` runs the long one): for each
//! reference vehicle, its table (the committed one for the pedestrian,
//! built here for the car and the robot), η interpolation error at
//! D ≥ 4 turning radii, reachability agreement, reach and oriented entries
//! at D ≥ 5 turning radii and ε_tol 5° on the envelope scaled to it.
//! Seed 2 (the envelope's report seed); the per-vehicle targets.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use steering::funnelling::table::spec::{TableSpec, DEFAULT_COUNTS};
use steering::funnelling::vehicle_file;
use steering::studies::envelope::{variants, EnvelopeStudy};
use steering::studies::vehicle::{accuracy, oriented_far};

#[test]
fn every_reference_vehicle_meets_the_targets() {
    for name in ["pedestrian", "car", "robot"] {
        let p = vehicle_file::reference(name).unwrap().vehicle;
        let table = if name == "pedestrian" {
            common::table()
        } else {
            TableSpec::for_vehicle(p, DEFAULT_COUNTS)
                .unwrap()
                .generate()
                .unwrap()
        };
        table.check_params(&p).unwrap();
        let acc = accuracy(&table, &p, 1500, 2, 4.0);
        let mut study = EnvelopeStudy {
            seed: 2,
            ..EnvelopeStudy::for_vehicle(&p)
        };
        (study.n_static, study.n_moving, study.n_chain) = (1200, 0, 0);
        let standard = variants()[0];
        let report = study.run_all(&table, &p, &[standard]);
        let a = oriented_far(&report.variants[0]);
        eprintln!(
            "{name}: η median {:.3}°, p95 {:.3}° ({} queries), agreement {:.2} %; reach {:.2} % of {}; oriented at D ≥ 5 R, ε 5°: {:.1} % of {}",
            acc.median_deg,
            acc.p95_deg,
            acc.both_reachable,
            100.0 * acc.agreement,
            100.0 * a.reach,
            a.runs,
            100.0 * a.far_oriented,
            a.far_runs
        );
        assert!(
            acc.median_deg <= 0.2 && acc.p95_deg <= 2.0,
            "{name}: {acc:?}"
        );
        assert!(acc.agreement >= 0.99, "{name}: {acc:?}");
        assert!(a.reach >= 0.995, "{name}: {a:?}");
        assert!(a.far_runs >= 50 && a.far_oriented >= 0.95, "{name}: {a:?}");
    }
}
