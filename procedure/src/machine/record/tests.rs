//! The records' round trips and refusals.

use super::*;
use zerocal_core::bracket::{bracket_id, BracketCalibration};

fn round_trip(r: Record<f32>) {
    let mut buf = [0u8; MAX_RECORD_LEN];
    let n = r.encode(&mut buf).unwrap();
    assert_eq!(Record::decode(r.key(), &buf[..n]), Ok(r));
    // Every strict prefix is refused, never misread.
    for cut in 0..n {
        assert!(
            Record::<f32>::decode(r.key(), &buf[..cut]).is_err(),
            "{r:?} cut {cut}"
        );
    }
}

#[test]
fn every_kind_round_trips_bit_exactly() {
    let t = Tilt::new(0.123_456_79_f32, -1.0e-7);
    round_trip(Record::Bias(t));
    for slot in ReadingSlot::all() {
        round_trip(Record::Reading {
            slot,
            capture: Capture {
                reading: t,
                temperature_c: Some(23.25),
            },
        });
    }
    round_trip(Record::Reading {
        slot: ReadingSlot::CLOSING_LAST,
        capture: Capture {
            reading: t,
            temperature_c: None,
        },
    });
    for (stage0_skipped, closing_skipped, check) in [
        (true, false, false),
        (false, true, true),
        (true, true, false),
    ] {
        round_trip(Record::Progress {
            phase: Phase::Closing,
            cursor: 3,
            captures: 6,
            stage0_skipped,
            closing_skipped,
            check,
        });
    }
    round_trip(Record::Capture {
        slot: 5,
        index: CaptureIndex::from_sequence(9).unwrap(),
        pose: PoseReading {
            joints_rad: [0.0, -1.5, 0.1, -3.1, 2.0, 1e-9],
            reading: t,
            temperature_c: Some(24.5),
        },
    });
    round_trip(Record::Capture {
        slot: 6,
        index: CaptureIndex::from_sequence(10).unwrap(),
        pose: PoseReading {
            joints_rad: [0.0; 6],
            reading: t,
            temperature_c: None,
        },
    });
    // The last of the 96 capture slots, its index the plan's last pose from above.
    round_trip(Record::Capture {
        slot: MAX_CAPTURES as u8 - 1,
        index: CaptureIndex::from_sequence(MAX_CAPTURES - 1).unwrap(),
        pose: PoseReading {
            joints_rad: [0.0, 0.7, -0.2, 1.0, -1.0, 2.5],
            reading: t,
            temperature_c: Some(30.0),
        },
    });
    round_trip(Record::Progress {
        phase: Phase::Stage2,
        cursor: MAX_CAPTURES as u8,
        captures: MAX_CAPTURES as u8,
        stage0_skipped: false,
        closing_skipped: false,
        check: false,
    });
    round_trip(Record::PlanLen(12));
    round_trip(Record::PlanPose {
        index: MAX_POSES as u8 - 1,
        joints_rad: [0.0, -1.5, 1.0, 2.0, 3.0, -3.0],
    });
    for (mount, temperature_c) in [
        (BracketMount::UpperArm, Some(21.5)),
        (BracketMount::Flange, None),
    ] {
        let mut id = [0; BRACKET_ID_LEN];
        id[..5].copy_from_slice(b"F-017");
        round_trip(Record::BracketCalibration {
            mount,
            id,
            id_len: 5,
            rotation_rad: t,
            uncertainty_rad: 1.4e-5,
            yaw_rad: -3e-3,
            yaw_uncertainty_rad: 7e-4,
            temperature_c,
        });
    }
    round_trip(Record::LastResult {
        offsets_rad: [1e-3, -2e-3, 3e-3, 4e-3],
        sigma_rad: [1e-6; 4],
        delta_theta2_rad: 5e-4,
        residual_rms_rad: 2e-5,
    });
}

#[test]
fn corrupt_values_are_named() {
    let mut buf = [0u8; MAX_RECORD_LEN];
    let r = Record::Capture {
        slot: 2,
        index: CaptureIndex::from_sequence(1).unwrap(),
        pose: PoseReading::<f32>::default(),
    };
    let n = r.encode(&mut buf).unwrap();
    assert_eq!(
        Record::<f32>::decode(key::CAPTURE + 3, &buf[..n]),
        Err(RecordError::BadField)
    );
    assert_eq!(
        Record::<f32>::decode(999, &buf[..n]),
        Err(RecordError::UnknownKey(999))
    );
    buf[0] = 9;
    assert_eq!(
        Record::<f32>::decode(r.key(), &buf[..n]),
        Err(RecordError::WrongFormat(9))
    );
    // A reading stored under another slot's key.
    let r = Record::Reading {
        slot: ReadingSlot::STAGE1_AFTER_BELOW,
        capture: Capture::<f32>::default(),
    };
    let n = r.encode(&mut buf).unwrap();
    assert_eq!(
        Record::<f32>::decode(key::READING, &buf[..n]),
        Err(RecordError::BadField)
    );
    // A bracket's calibration under the other mount's key, or with an ID that is
    // not one (a space in it).
    let mut id = [0; BRACKET_ID_LEN];
    id[..3].copy_from_slice(b"F 1");
    let r = Record::BracketCalibration {
        mount: BracketMount::Flange,
        id,
        id_len: 3,
        rotation_rad: Tilt::new(0.0f32, 0.0),
        uncertainty_rad: 1e-5,
        yaw_rad: 0.0,
        yaw_uncertainty_rad: 7e-4,
        temperature_c: None,
    };
    let n = r.encode(&mut buf).unwrap();
    assert_eq!(
        Record::<f32>::decode(key::BRACKET_CALIBRATION, &buf[..n]),
        Err(RecordError::BadField)
    );
    assert_eq!(
        Record::<f32>::decode(r.key(), &buf[..n]),
        Err(RecordError::BadField)
    );
    let nan = Record::Bias(Tilt::new(f32::NAN, 0.0));
    let n = nan.encode(&mut buf).unwrap();
    assert_eq!(
        Record::<f32>::decode(key::BIAS, &buf[..n]),
        Err(RecordError::BadField)
    );
    assert_eq!(
        Record::Bias(Tilt::new(0.0f32, 0.0)).encode(&mut [0u8; 4]),
        Err(RecordError::BufferTooSmall)
    );
}

fn stored_bracket() -> StoredBracket<f32> {
    let c = BracketCalibration::new(
        bracket_id("U-017").unwrap(),
        Tilt::new(0.0037_f32, -0.0007),
        2.1e-5,
        20261127,
        21.5,
    )
    .unwrap();
    StoredBracket::of(&c)
}

#[test]
fn profile_masses_and_brackets_round_trip_bit_exactly() {
    for part in 0..PROFILE_MASSES as u8 {
        round_trip(Record::ProfileMass {
            generation: 9,
            part,
            kg: 0.123_456_79,
            com_m: [0.01, -0.2, 1.5e-7],
        });
    }
    for flange in [false, true] {
        round_trip(Record::ProfileBracket {
            generation: 9,
            flange,
            calibration: Some(stored_bracket()),
        });
        round_trip(Record::ProfileBracket {
            generation: 9,
            flange,
            calibration: None,
        });
    }
}

/// A stored mass or calibration that no profile line could have given is refused,
/// never used: a negative mass or one beyond 10 t, a centre of mass 101 m away, a
/// bracket ID with a foreign byte or bytes after its length, a day that is not one,
/// a turn beyond 1° (twice the design's), an uncertainty beyond 180° (4 rad), a temperature
/// beyond the sensor's range.
#[test]
fn impossible_masses_and_calibrations_are_refused() {
    let refused = |r: Record<f32>| {
        let mut buf = [0u8; MAX_RECORD_LEN];
        let n = r.encode(&mut buf).unwrap();
        assert_eq!(
            Record::<f32>::decode(r.key(), &buf[..n]),
            Err(RecordError::BadField),
            "{r:?}"
        );
    };
    for (kg, com_m) in [(-1.0, [0.0; 3]), (2e4, [0.0; 3]), (1.0, [0.0, 0.0, 101.0])] {
        refused(Record::ProfileMass {
            generation: 1,
            part: 2,
            kg,
            com_m,
        });
    }
    let bracket = |edit: fn(&mut StoredBracket<f32>)| {
        let mut c = stored_bracket();
        edit(&mut c);
        Record::ProfileBracket {
            generation: 1,
            flange: true,
            calibration: Some(c),
        }
    };
    refused(bracket(|c| c.id[1] = b'/'));
    refused(bracket(|c| c.id[7] = b'x'));
    refused(bracket(|c| c.id_len = 13));
    refused(bracket(|c| c.date = 20260230));
    refused(bracket(|c| c.rotation_rad[1] = 0.021));
    refused(bracket(|c| c.uncertainty_rad = 4.0));
    refused(bracket(|c| c.temperature_c = 200.0));
    // A mass stored under another part's key.
    let mut buf = [0u8; MAX_RECORD_LEN];
    let r = Record::ProfileMass {
        generation: 1,
        part: 2,
        kg: 1.0_f32,
        com_m: [0.0; 3],
    };
    let n = r.encode(&mut buf).unwrap();
    assert_eq!(
        Record::<f32>::decode(key::PROFILE_MASS + 3, &buf[..n]),
        Err(RecordError::BadField)
    );
}

/// Found by the `record` fuzz target: a finite `f64` beyond `f32`'s range (a
/// stored 1e300) decoded into the pendant's `f32` as an infinity, which the export
/// then printed as "huge".
#[test]
fn a_value_beyond_the_readers_float_is_refused() {
    let mut value = [FORMAT; 17];
    value[1..9].copy_from_slice(&1e-3_f64.to_le_bytes());
    value[9..17].copy_from_slice(&(-1e300_f64).to_le_bytes());
    assert_eq!(
        Record::<f32>::decode(key::BIAS, &value),
        Err(RecordError::BadField)
    );
    // The same value is fine in f64.
    assert!(Record::<f64>::decode(key::BIAS, &value).is_ok());
}
