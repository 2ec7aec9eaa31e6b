//! The η table file: every loader error, no panic on any byte string, and
//! the committed file is exactly what the generator produces.
#![cfg(not(target_arch = "wasm32"))]

use proptest::prelude::*;
use steering::base::vehicle::VehicleParams;
use steering::funnelling::table::spec::TableSpec;
use steering::funnelling::table::{
    codec::crc32, format::TableError, format::FORMAT_VERSION, format::HEADER_LEN, lookup::EtaTable,
};

fn committed() -> Vec<u8> {
    std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin")).expect("tables/eta.bin")
}

/// Re-seals a modified file with a correct checksum, so that the checks
/// behind the checksum are reached.
fn reseal(mut b: Vec<u8>) -> Vec<u8> {
    let n = b.len();
    let c = crc32(&b[..n - 4]);
    b[n - 4..].copy_from_slice(&c.to_le_bytes());
    b
}

/// A small table (fast to generate) with the default layout.
fn small_spec() -> TableSpec {
    TableSpec::with_counts(VehicleParams::default(), [3, 12, 3, 2, 2])
}

#[test]
fn committed_table_loads_and_matches_the_controller() {
    let t = EtaTable::from_bytes(&committed()).expect("committed table is valid");
    t.check_params(&VehicleParams::default())
        .expect("built for the default vehicle");
    assert_eq!(
        t.len(),
        TableSpec::default_for(VehicleParams::default()).len()
    );
    assert!(t.len() >= 40_000);
}

#[test]
fn committed_table_is_what_the_generator_produces() {
    let bytes = committed();
    let t = EtaTable::from_bytes(&bytes).unwrap();
    let spec = TableSpec::default_for(VehicleParams::default());
    // Same header, parameters and axes, byte for byte.
    let axes_len = 4 * (0..5).map(|k| spec.axes[k].len()).sum::<usize>();
    let mut expect_head = Vec::new();
    expect_head.extend_from_slice(b"STEERETA");
    expect_head.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    let head = spec
        .assemble(vec![(0.0, 0.0, 0); spec.len()])
        .unwrap()
        .to_bytes();
    assert_eq!(
        &bytes[..HEADER_LEN + axes_len],
        &head[..HEADER_LEN + axes_len]
    );
    assert_eq!(&bytes[..12], &expect_head[..]);
    // A documented slice of entries (every 61st, about 6,000 of them)
    // regenerated with the same code equals the file exactly.
    let mut checked = 0;
    for i in (0..spec.len()).step_by(61) {
        let (eta, v, f) = if spec.is_mirrored(i) {
            let (e, v, f) = spec.entry(spec.mirror(i));
            (steering::base::angle::wrap(-e), v, f)
        } else {
            spec.entry(i)
        };
        let got = t.entry(spec.unravel(i));
        assert_eq!(
            (eta.to_bits(), v.to_bits(), f),
            (got.0.to_bits(), got.1.to_bits(), got.2),
            "entry {i}"
        );
        checked += 1;
    }
    assert!(checked > 5_000);
}

#[test]
fn generation_is_deterministic_whatever_the_thread_count() {
    let spec = small_spec();
    let on = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| spec.generate()).unwrap().to_bytes()
    };
    let (a, b, c) = (on(1), on(2), on(3));
    assert_eq!(a, b);
    assert_eq!(a, c);
    // And symmetric generation equals brute force up to the mirror rounding.
    let t = spec.generate().unwrap();
    for i in 0..spec.len() {
        let direct = spec.entry(i);
        let got = t.entry(spec.unravel(i));
        assert_eq!(direct.2, got.2, "flags of entry {i}");
        assert!(
            steering::base::angle::diff(direct.0, got.0).abs() < 2e-3,
            "η of entry {i}"
        );
    }
}

#[test]
fn round_trip_through_bytes() {
    let t = small_spec().generate().unwrap();
    let b = t.to_bytes();
    assert_eq!(EtaTable::from_bytes(&b).unwrap(), t);
}

#[test]
fn truncated() {
    let b = committed();
    for cut in [
        0,
        4,
        8,
        20,
        HEADER_LEN,
        HEADER_LEN + 10,
        b.len() / 2,
        b.len() - 1,
    ] {
        match EtaTable::from_bytes(&b[..cut]) {
            Err(TableError::Truncated { .. }) => {}
            other => panic!("cut at {cut}: {other:?}"),
        }
    }
}

#[test]
fn trailing_bytes() {
    let mut b = committed();
    b.push(0);
    assert!(matches!(
        EtaTable::from_bytes(&b),
        Err(TableError::TrailingBytes { .. })
    ));
}

#[test]
fn bad_magic() {
    let mut b = committed();
    b[0] = b'X';
    assert_eq!(EtaTable::from_bytes(&b), Err(TableError::BadMagic));
    assert_eq!(EtaTable::from_bytes(b"PNG"), Err(TableError::BadMagic));
    assert!(EtaTable::from_bytes(b"<!doctype html>")
        .unwrap_err()
        .to_string()
        .contains("not an η table"));
}

#[test]
fn unknown_version() {
    let mut b = committed();
    b[8..12].copy_from_slice(&99u32.to_le_bytes());
    assert_eq!(
        EtaTable::from_bytes(&b),
        Err(TableError::UnknownVersion(99))
    );
}

#[test]
fn checksum_mismatch() {
    let mut b = committed();
    let mid = b.len() / 2;
    b[mid] ^= 0x40;
    let e = EtaTable::from_bytes(&b).unwrap_err();
    assert!(matches!(e, TableError::ChecksumMismatch { .. }), "{e:?}");
    assert!(e.to_string().contains("corrupt"));
}

#[test]
fn non_finite_values() {
    let spec = small_spec();
    let t = spec.generate().unwrap();
    let b = t.to_bytes();
    let axes_len = 4 * (0..5).map(|k| spec.axes[k].len()).sum::<usize>();
    let eta0 = HEADER_LEN + axes_len;
    let mut c = b.clone();
    c[eta0..eta0 + 4].copy_from_slice(&f32::NAN.to_le_bytes());
    assert!(matches!(
        EtaTable::from_bytes(&reseal(c)),
        Err(TableError::NonFinite {
            what: "η",
            index: 0
        })
    ));
    // A non-finite axis value and a non-finite build parameter.
    let mut c = b.clone();
    c[HEADER_LEN..HEADER_LEN + 4].copy_from_slice(&f32::INFINITY.to_le_bytes());
    assert!(matches!(
        EtaTable::from_bytes(&reseal(c)),
        Err(TableError::NonFinite { .. })
    ));
    let mut c = b;
    c[16..20].copy_from_slice(&f32::NAN.to_le_bytes());
    assert!(matches!(
        EtaTable::from_bytes(&reseal(c)),
        Err(TableError::NonFinite { .. })
    ));
}

#[test]
fn non_monotonic_axis() {
    let spec = small_spec();
    let b = spec.generate().unwrap().to_bytes();
    let mut c = b.clone();
    // Swap the first two distances.
    let (d0, d1) = (HEADER_LEN, HEADER_LEN + 4);
    let first: [u8; 4] = c[d0..d0 + 4].try_into().unwrap();
    let second: [u8; 4] = c[d1..d1 + 4].try_into().unwrap();
    c[d0..d0 + 4].copy_from_slice(&second);
    c[d1..d1 + 4].copy_from_slice(&first);
    assert_eq!(
        EtaTable::from_bytes(&reseal(c)),
        Err(TableError::NonMonotonicAxis("distance"))
    );
}

#[test]
fn invalid_structure() {
    let b = small_spec().generate().unwrap().to_bytes();
    // Unknown flag bits in the last entry.
    let mut c = b.clone();
    let n = c.len();
    c[n - 5] = 0xFF;
    assert!(matches!(
        EtaTable::from_bytes(&reseal(c)),
        Err(TableError::Invalid(_))
    ));
    // Two distances one ulp apart (strictly increasing, but no spacing).
    let mut c = b.clone();
    let d0 = f32::from_le_bytes(c[HEADER_LEN..HEADER_LEN + 4].try_into().unwrap());
    let squeezed = f32::from_bits(d0.to_bits() + 1);
    c[HEADER_LEN + 4..HEADER_LEN + 8].copy_from_slice(&squeezed.to_le_bytes());
    let e = EtaTable::from_bytes(&reseal(c)).unwrap_err();
    assert!(e.to_string().contains("closer than"), "{e}");
    // Unknown integrator code.
    let mut c = b;
    c[12..16].copy_from_slice(&7u32.to_le_bytes());
    assert!(matches!(
        EtaTable::from_bytes(&reseal(c)),
        Err(TableError::Invalid(_))
    ));
}

#[test]
fn params_mismatch() {
    let t = EtaTable::from_bytes(&committed()).unwrap();
    let p = VehicleParams {
        kp: 3.0,
        ..Default::default()
    };
    let e = t.check_params(&p).unwrap_err();
    assert!(
        matches!(e, TableError::ParamsMismatch { field: "kp", .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("regenerate"));
    let p = VehicleParams {
        integrator: steering::base::vehicle::Integrator::SemiImplicitEuler,
        ..Default::default()
    };
    assert!(matches!(
        t.check_params(&p),
        Err(TableError::ParamsMismatch {
            field: "integrator",
            ..
        })
    ));
}

#[test]
fn every_truncation_of_the_real_file_is_an_error_not_a_panic() {
    let b = committed();
    for cut in 0..b.len() {
        assert!(EtaTable::from_bytes(&b[..cut]).is_err(), "cut {cut}");
    }
}

#[test]
fn crc32_is_the_textbook_crc() {
    // crc32fast computes the checksum; the textbook byte-at-a-time loop agrees.
    use steering::funnelling::table::codec::crc32_bytewise;
    assert_eq!(crc32(b"123456789"), 0xCBF4_3926, "the CRC-32 check value");
    let t = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/eta.bin")).unwrap();
    assert_eq!(crc32(&t), crc32_bytewise(&t));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn crc32_equals_the_bytewise_reference(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
        prop_assert_eq!(crc32(&bytes), steering::funnelling::table::codec::crc32_bytewise(&bytes));
    }

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..512)) {
        let _ = EtaTable::from_bytes(&bytes);
    }

    #[test]
    fn arbitrary_header_after_valid_magic_never_panics(tail in proptest::collection::vec(any::<u8>(), 0..512)) {
        let mut b = b"STEERETA".to_vec();
        b.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        b.extend_from_slice(&tail);
        let _ = EtaTable::from_bytes(&b);
        let _ = EtaTable::from_bytes(&b.clone().into_iter().chain(0u32.to_le_bytes()).collect::<Vec<_>>());
    }

    #[test]
    fn flipped_byte_of_a_small_table_is_an_error(pos in 0usize..10_000, bit in 0u8..8) {
        let b = small_spec().generate().unwrap().to_bytes();
        let mut c = b.clone();
        let at = pos % c.len();
        c[at] ^= 1 << bit;
        prop_assert!(EtaTable::from_bytes(&c).is_err());
    }
}
