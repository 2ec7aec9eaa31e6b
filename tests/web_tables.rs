//! A table built in the browser is byte-identical to the native
//! one for the same limits. Small tables (6 × 12 × 3 × 4 × 4 entries) of
//! every reference vehicle: natively from the generator, in headless
//! Chromium (`wasm-pack test`) through the bindings the Web Workers call
//! (`tableSlice` in three pieces, `assembleTable`); both compared with the
//! same golden CRC-32 of the whole file, so the two builds agree bit for
//! bit. A full pedestrian table built in wasm equals `tables/eta.bin`
//! (checked by its key and CRC).

use steering::funnelling::table::codec::crc32;
use steering::funnelling::vehicle_file;

const COUNTS: [usize; 5] = [6, 12, 3, 4, 4];
/// CRC-32 of the small tables' files: pedestrian, car, robot, car-like
/// (format version 2, its integrator bounding the curvature).
const GOLDEN: [(&str, u32); 4] = [
    ("pedestrian", 0x1806b4b8),
    ("car", 0xc79ccc23),
    ("robot", 0x4ce46a3a),
    ("car_like", 0xda444020),
];

/// The CRC-32 the file stores (of everything before it).
fn file_crc(bytes: &[u8]) -> u32 {
    crc32(&bytes[..bytes.len() - 4])
}

#[cfg(not(target_arch = "wasm32"))]
#[test]
fn native_small_tables_match_the_golden_crcs() {
    use steering::funnelling::table::spec::TableSpec;
    for (name, crc) in GOLDEN {
        let p = vehicle_file::reference(name).unwrap().vehicle;
        let bytes = TableSpec::for_vehicle(p, COUNTS)
            .unwrap()
            .generate()
            .unwrap()
            .to_bytes();
        let got = file_crc(&bytes);
        eprintln!("{name}: {got:#010x}");
        assert_eq!(got, crc, "{name}");
    }
}

#[cfg(target_arch = "wasm32")]
mod common;

#[cfg(target_arch = "wasm32")]
mod browser {
    use super::common::message;
    use super::*;
    use steering::bindings::tables::{assemble_table, table_job, table_key_of, table_slice};
    use wasm_bindgen::JsValue;
    use wasm_bindgen_test::*;

    wasm_bindgen_test_configure!(run_in_browser);

    fn js<T: serde::Serialize>(v: &T) -> JsValue {
        v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
            .unwrap()
    }

    fn build(p: &JsValue, counts: Option<Vec<u32>>, n: u32) -> Vec<u8> {
        let mut data = Vec::new();
        let cuts = [0, n / 3, n / 2, n];
        for w in cuts.windows(2) {
            data.extend(table_slice(p.clone(), counts.clone(), w[0], w[1]).unwrap());
        }
        assemble_table(p.clone(), counts, &data).unwrap()
    }

    #[wasm_bindgen_test]
    fn small_tables_built_in_the_browser_match_the_native_ones() {
        let counts: Vec<u32> = COUNTS.iter().map(|&c| c as u32).collect();
        for (name, crc) in GOLDEN {
            let p = js(&vehicle_file::reference(name).unwrap().vehicle);
            // The α count is the front spacing's (360°/12): more samples behind.
            let job: serde_json::Value =
                serde_wasm_bindgen::from_value(table_job(p.clone(), Some(counts.clone())).unwrap())
                    .unwrap();
            let n = job["entries"].as_u64().unwrap() as u32;
            let bytes = build(&p, Some(counts.clone()), n);
            assert_eq!(file_crc(&bytes), crc, "{name}");
            assert_eq!(job["key"], table_key_of(&bytes).unwrap().as_str());
        }
    }

    #[wasm_bindgen_test]
    fn the_pedestrian_built_in_the_browser_is_the_committed_table() {
        let committed = steering::funnelling::table::lookup::EtaTable::from_bytes(include_bytes!(
            "../tables/eta.bin"
        ))
        .unwrap();
        let p = js(&vehicle_file::reference("pedestrian").unwrap().vehicle);
        let bytes = build(&p, None, committed.len() as u32);
        assert_eq!(table_key_of(&bytes).unwrap(), committed.key());
        assert_eq!(bytes, committed.to_bytes());
    }

    #[wasm_bindgen_test]
    fn bad_jobs_are_errors_naming_the_field() {
        let bad = js(&serde_json::json!({ "vMax": 0.0 }));
        assert!(message(table_job(bad, None).unwrap_err()).contains("vMax"));
        let p = js(&serde_json::json!({}));
        assert!(message(table_slice(p.clone(), None, 5, 3).unwrap_err()).contains("outside"));
        assert!(assemble_table(p.clone(), None, &[0.0; 6]).is_err());
        assert!(table_job(p, Some(vec![1, 2])).is_err());
    }
}
