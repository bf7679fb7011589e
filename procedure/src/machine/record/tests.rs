//! The records' round trips and refusals.

use super::*;
use zerocal_core::bracket::{bracket_id, BracketCalibration, BracketYaw, BRACKET_ID_LEN};

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
            calibration: StoredBracket {
                id,
                id_len: 5,
                // Within the design's ±1° (`t` is 7°).
                rotation_rad: Tilt::new(0.012_345_679_f32, -1.0e-7),
                uncertainty_rad: 1.4e-5,
                date: None,
                temperature_c,
                yaw: Some(BracketYaw {
                    yaw_rad: -3e-3,
                    uncertainty_rad: 7e-4,
                }),
            },
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
    let mut c = StoredBracket {
        id: [0; BRACKET_ID_LEN],
        id_len: 3,
        rotation_rad: Tilt::new(0.0f32, 0.0),
        uncertainty_rad: 1e-5,
        date: None,
        temperature_c: None,
        yaw: Some(BracketYaw {
            yaw_rad: 0.0,
            uncertainty_rad: 7e-4,
        }),
    };
    c.id[..3].copy_from_slice(b"F-1");
    let r = Record::BracketCalibration {
        mount: BracketMount::Flange,
        calibration: c,
    };
    let n = r.encode(&mut buf).unwrap();
    assert_eq!(
        Record::<f32>::decode(key::BRACKET_CALIBRATION, &buf[..n]),
        Err(RecordError::BadField)
    );
    c.id[1] = b' ';
    let n = bench_bytes(BracketMount::Flange, &c, &mut buf);
    assert_eq!(
        Record::<f32>::decode(r.key(), &buf[..n]),
        Err(RecordError::BadField)
    );
    // Nor is one written.
    let r = Record::BracketCalibration {
        mount: BracketMount::Flange,
        calibration: c,
    };
    assert_eq!(r.encode(&mut buf), Err(RecordError::BadField));
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

/// A bench calibration's bytes as [`BRACKET_FORMAT`] writes them, unchecked.
fn bench_bytes(mount: BracketMount, c: &StoredBracket<f32>, buf: &mut [u8]) -> usize {
    let mut w = Writer { buf, len: 0 };
    w.put(&[BRACKET_FORMAT, mount_code(mount)]).unwrap();
    c.put_unchecked(&mut w).unwrap();
    w.len
}

/// A profile's bracket line's bytes as [`BRACKET_FORMAT`] writes them, unchecked.
fn profile_bytes(generation: u8, flange: bool, c: &StoredBracket<f32>, buf: &mut [u8]) -> usize {
    let mut w = Writer { buf, len: 0 };
    w.put(&[BRACKET_FORMAT, generation, u8::from(flange), 1])
        .unwrap();
    c.put_unchecked(&mut w).unwrap();
    w.len
}

fn stored_bracket() -> StoredBracket<f32> {
    let c = BracketCalibration::new(
        bracket_id("U-017").unwrap(),
        Tilt::new(0.0037_f32, -0.0007),
        2.1e-5,
        Some(20261127),
        Some(21.5),
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
        let n = match r {
            // A calibration is refused when written, too: its bytes are made here.
            Record::ProfileBracket {
                generation,
                flange,
                calibration: Some(c),
            } => {
                assert_eq!(r.encode(&mut buf), Err(RecordError::BadField), "{r:?}");
                profile_bytes(generation, flange, &c, &mut buf)
            }
            _ => r.encode(&mut buf).unwrap(),
        };
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
    refused(bracket(|c| c.date = Some(20260230)));
    refused(bracket(|c| c.rotation_rad.y_rad = 0.021));
    refused(bracket(|c| c.uncertainty_rad = 4.0));
    refused(bracket(|c| c.temperature_c = Some(200.0)));
    refused(bracket(|c| {
        c.yaw = Some(BracketYaw {
            yaw_rad: 0.0,
            uncertainty_rad: -1e-3,
        })
    }));
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

/// The one stored form: a calibration kept on the bench and the same calibration as a
/// profile's bracket holds it store in their two records and read back as the same
/// value, the same core calibration; the profile's text line for it (what `profile
/// set` sends) reads back to that value within the line's last digit.
#[test]
fn a_bench_calibration_and_a_profile_bracket_read_back_the_same() {
    let c = BracketCalibration::new(
        bracket_id("F-017").unwrap(),
        Tilt::new(0.0037_f32, -0.0007),
        2.1e-5,
        None,
        Some(21.5),
    )
    .unwrap()
    .with_yaw(BracketYaw {
        yaw_rad: -3e-3,
        uncertainty_rad: 7e-4,
    })
    .unwrap();
    let bench = Record::BracketCalibration {
        mount: BracketMount::Flange,
        calibration: StoredBracket::of(&c),
    };
    let profile = Record::ProfileBracket {
        generation: 3,
        flange: true,
        calibration: Some(StoredBracket::of(&c)),
    };
    let read = |r: Record<f32>| {
        let mut buf = [0u8; MAX_RECORD_LEN];
        let n = r.encode(&mut buf).unwrap();
        match Record::<f32>::decode(r.key(), &buf[..n]).unwrap() {
            Record::BracketCalibration { calibration, .. } => calibration,
            Record::ProfileBracket {
                calibration: Some(calibration),
                ..
            } => calibration,
            other => panic!("{other:?}"),
        }
    };
    let (a, b) = (read(bench), read(profile));
    assert_eq!(a, b);
    assert_eq!(a, StoredBracket::of(&c));
    assert_eq!(a.calibration(), Some(c.clone()));
    // The profile's line carries the same calibration, its date and temperature
    // `none` or not, to 1e-12° (the line's decimals; f32's step here is 2e-10 rad).
    let mut line = crate::link::Line::new();
    crate::log::write_bracket_fields(&mut line, Some(&c)).unwrap();
    assert!(
        line.as_str().contains(" date none temp_c 21.50"),
        "{}",
        line.as_str()
    );
    let from_line: BracketCalibration<f32> =
        crate::log::parse_bracket_fields(line.as_str().split_whitespace(), |s| s.parse().ok())
            .unwrap()
            .unwrap();
    let l = StoredBracket::of(&from_line);
    assert_eq!(
        (l.id, l.id_len, l.date, l.temperature_c),
        (a.id, a.id_len, a.date, a.temperature_c)
    );
    let step = 2.5e-10;
    assert!((l.rotation_rad.x_rad - a.rotation_rad.x_rad).abs() <= step);
    assert!((l.rotation_rad.y_rad - a.rotation_rad.y_rad).abs() <= step);
    assert!((l.uncertainty_rad - a.uncertainty_rad).abs() <= step);
    let (ly, ay) = (l.yaw.unwrap(), a.yaw.unwrap());
    assert!((ly.yaw_rad - ay.yaw_rad).abs() <= step);
    assert!((ly.uncertainty_rad - ay.uncertainty_rad).abs() <= step);
}

/// Bracket records format 5 wrote, before the one stored form, still read: the
/// bench's (a yaw, no date) and the profile's (a date and a temperature, a yaw or
/// none), into the same stored form, so an update loses no kept calibration.
#[test]
fn bracket_records_of_format_5_still_read() {
    let mut id = [0u8; BRACKET_ID_LEN];
    id[..5].copy_from_slice(b"F-017");
    let mut v = vec![FORMAT, 1, 5];
    v.extend_from_slice(&id);
    for x in [0.0037_f64, -0.0007, 2.1e-5, -3e-3, 7e-4] {
        v.extend_from_slice(&x.to_le_bytes());
    }
    v.push(1);
    v.extend_from_slice(&21.5_f64.to_le_bytes());
    let yaw = Some(BracketYaw {
        yaw_rad: -3e-3,
        uncertainty_rad: 7e-4,
    });
    let bench = StoredBracket {
        id,
        id_len: 5,
        rotation_rad: Tilt::new(0.0037, -0.0007),
        uncertainty_rad: 2.1e-5,
        date: None,
        temperature_c: Some(21.5),
        yaw,
    };
    assert_eq!(
        Record::<f64>::decode(key::BRACKET_CALIBRATION + 1, &v),
        Ok(Record::BracketCalibration {
            mount: BracketMount::Flange,
            calibration: bench,
        })
    );
    // Under the other mount's key, or cut short: refused.
    assert!(Record::<f64>::decode(key::BRACKET_CALIBRATION, &v).is_err());
    assert!(Record::<f64>::decode(key::BRACKET_CALIBRATION + 1, &v[..v.len() - 1]).is_err());
    for with_yaw in [false, true] {
        let mut v = vec![FORMAT, 7, 1, 1, 5];
        v.extend_from_slice(&id);
        for x in [0.0037_f64, -0.0007, 2.1e-5] {
            v.extend_from_slice(&x.to_le_bytes());
        }
        v.extend_from_slice(&20261127_u32.to_le_bytes());
        v.extend_from_slice(&21.5_f64.to_le_bytes());
        v.push(u8::from(with_yaw));
        if with_yaw {
            for x in [-3e-3_f64, 7e-4] {
                v.extend_from_slice(&x.to_le_bytes());
            }
        }
        let profile = StoredBracket {
            date: Some(20261127),
            yaw: yaw.filter(|_| with_yaw),
            ..bench
        };
        assert_eq!(
            Record::<f64>::decode(key::PROFILE_BRACKET + 1, &v),
            Ok(Record::ProfileBracket {
                generation: 7,
                flange: true,
                calibration: Some(profile),
            })
        );
        // Written again, it is the one encoding, and reads back the same.
        let r = Record::<f64>::decode(key::PROFILE_BRACKET + 1, &v).unwrap();
        let mut buf = [0u8; MAX_RECORD_LEN];
        let n = r.encode(&mut buf).unwrap();
        assert_eq!(buf[0], BRACKET_FORMAT);
        assert_eq!(Record::decode(r.key(), &buf[..n]), Ok(r));
    }
    // Another format byte on a bracket record is named, as on any record.
    v[0] = 9;
    assert_eq!(
        Record::<f64>::decode(key::BRACKET_CALIBRATION + 1, &v),
        Err(RecordError::WrongFormat(9))
    );
}
