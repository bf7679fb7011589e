//! The export's writers read back by its readers: `write_row` and `write_export_row`
//! (with its capture index) by `LogReader::feed`, `write_bench` (stage 0's or the
//! closing bench readings, two to four headings), `write_fit_extras` and
//! `write_bracket` by `parse_meta`, with both number parsers (core's and the
//! desktop's): parse(write(x)) == x to the export's 1e-12 deg.
#![no_main]
use arbitrary::{Arbitrary, Unstructured};
use libfuzzer_sys::fuzz_target;
use zerocal_core::bracket::{
    bracket_id, BracketCalibration, BracketMount, BracketYaw, MAX_BRACKET_TURN_DEG,
};
use zerocal_core::capture::{Approach, CaptureIndex, MAX_PLAN_POSES};
use zerocal_core::model::Tilt;
use zerocal_core::stage0::{BenchTurns, BenchTurnsAt, MAX_HEADINGS};
use zerocal_core::stage2::{Extras, PoseReading};
use zerocal_procedure::log::{
    parse_meta, write_bench, write_bracket, write_export_row, write_fit_extras, write_row, Line,
    LogLine, LogReader, MetaItem, CLOSING_BENCH_KEY, EXPORT_HEADER, LOG_HEADER, STAGE0_BENCH_KEY,
};

/// A value in `[-limit, limit]` from a fuzzed fraction (an f32, as the pendant holds).
fn within(u: &mut Unstructured<'_>, limit: f64) -> arbitrary::Result<f64> {
    let raw = u32::arbitrary(u)?;
    let fraction = f64::from(raw) / f64::from(u32::MAX) * 2.0 - 1.0;
    Ok(f64::from((fraction * limit) as f32))
}

fn tilt(u: &mut Unstructured<'_>) -> arbitrary::Result<Tilt<f64>> {
    Ok(Tilt::from_deg(within(u, 180.0)?, within(u, 180.0)?))
}

fn temperature(u: &mut Unstructured<'_>) -> arbitrary::Result<Option<f64>> {
    Ok(if bool::arbitrary(u)? {
        // Hundredths of a kelvin in the export: what the writer can say exactly.
        Some((within(u, 1.0)? * 10_000.0).round() / 100.0 + 45.0)
    } else {
        None
    })
}

type Parser = fn(&str) -> Option<f64>;
const PARSERS: [Parser; 2] = [
    zerocal_core::decimal::parse,
    zerocal_inputs::log_file::parse_number,
];
/// The export's last decimal of a degree (half of it for the rounding, the rest for
/// f64's rounding of values up to 720 deg on the way), in radians.
const ANGLE_TOLERANCE_RAD: f64 = 1e-12 / 57.29577951308232;

fn close_tilt(a: Tilt<f64>, b: Tilt<f64>) -> bool {
    (a.x_rad - b.x_rad).abs() <= ANGLE_TOLERANCE_RAD
        && (a.y_rad - b.y_rad).abs() <= ANGLE_TOLERANCE_RAD
}

fn close_temperature(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => (a - b).abs() <= 1e-9,
        _ => false,
    }
}

fn check(u: &mut Unstructured<'_>) -> arbitrary::Result<()> {
    // A row.
    let mut joints = [0.0; 6];
    for q in &mut joints {
        *q = within(u, 720.0)?.to_radians();
    }
    let pose = PoseReading {
        joints_rad: joints,
        reading: tilt(u)?,
        temperature_c: temperature(u)?,
    };
    let mut line = Line::new();
    write_row(&mut line, &pose).expect("a row fits a line");
    for parse in PARSERS {
        let mut reader = LogReader::new();
        assert_eq!(reader.feed::<f64>(LOG_HEADER, parse), Ok(LogLine::Header));
        match reader.feed::<f64>(&line, parse) {
            Ok(LogLine::Pose(back)) => {
                for (a, b) in pose.joints_rad.iter().zip(back.joints_rad) {
                    assert!(
                        (a - b).abs() <= ANGLE_TOLERANCE_RAD,
                        "{line}: {pose:?} -> {back:?}"
                    );
                }
                assert!(
                    close_tilt(pose.reading, back.reading),
                    "{line}: {pose:?} -> {back:?}"
                );
                assert!(
                    close_temperature(pose.temperature_c, back.temperature_c),
                    "{line}"
                );
            }
            other => panic!("{line}: {other:?}"),
        }
    }
    // The same pose as an export row: its capture index reads back.
    let index = CaptureIndex {
        pose: u8::arbitrary(u)? % MAX_PLAN_POSES as u8,
        approach: Approach::of(usize::from(bool::arbitrary(u)?)),
    };
    let mut row = Line::new();
    write_export_row(&mut row, &pose, index).expect("an export row fits a line");
    for parse in PARSERS {
        let mut reader = LogReader::for_export();
        assert_eq!(
            reader.feed::<f64>(EXPORT_HEADER, parse),
            Ok(LogLine::Header)
        );
        assert!(
            matches!(reader.feed::<f64>(&row, parse), Ok(LogLine::Pose(_))),
            "{row}"
        );
        assert_eq!(reader.capture_index(), Some(index), "{row}");
    }
    // Bench readings: two to four headings, stage 0's or the closing ones.
    let count = 2 + usize::from(u8::arbitrary(u)?) % (MAX_HEADINGS - 1);
    let mut taken = [Tilt::default(); MAX_HEADINGS];
    for t in taken.iter_mut().take(count) {
        *t = tilt(u)?;
    }
    let bench = BenchTurnsAt {
        turns: BenchTurns::from_readings(&taken[..count]).expect("2..=4 readings"),
        temperature_c: temperature(u)?,
    };
    let closing = bool::arbitrary(u)?;
    let key = if closing {
        CLOSING_BENCH_KEY
    } else {
        STAGE0_BENCH_KEY
    };
    let mut line = Line::new();
    write_bench(&mut line, key, &bench).expect("bench readings fit a line");
    let comment = line.trim_start_matches('#').trim();
    for parse in PARSERS {
        match parse_meta::<f64>(comment, 1, parse) {
            Ok(Some(MetaItem::Closing(back))) if closing => {
                assert_eq!(back.turns.count, bench.turns.count, "{line}");
                for (a, b) in bench.turns.taken().iter().zip(back.turns.taken()) {
                    assert!(close_tilt(*a, *b), "{line}");
                }
                assert!(
                    close_temperature(bench.temperature_c, back.temperature_c),
                    "{line}"
                );
            }
            Ok(Some(MetaItem::Stage0Bench(back))) if !closing => {
                assert_eq!(back.turns.count, bench.turns.count, "{line}");
                for (a, b) in bench.turns.taken().iter().zip(back.turns.taken()) {
                    assert!(close_tilt(*a, *b), "{line}");
                }
                assert!(
                    close_temperature(bench.temperature_c, back.temperature_c),
                    "{line}"
                );
            }
            other => panic!("{line}: {other:?}"),
        }
    }
    // The fit's extras.
    let extras = Extras {
        gain: bool::arbitrary(u)?,
        cross_z: bool::arbitrary(u)?,
        sag: bool::arbitrary(u)?,
        bias_x: bool::arbitrary(u)?,
        bias_y: bool::arbitrary(u)?,
        drift: bool::arbitrary(u)?,
        // Held offsets, the geometric candidates and the reducers' terms follow from
        // the arm and its masses, not the line.
        held: [false; 4],
        tilt: 0,
        wrist_sag: 0,
        sag2: false,
        lash: 0,
        transmission: 0,
    };
    let mut line = Line::new();
    write_fit_extras(&mut line, extras).expect("extras fit a line");
    let comment = line.trim_start_matches('#').trim();
    match parse_meta::<f64>(comment, 1, zerocal_core::decimal::parse) {
        Ok(Some(MetaItem::FitExtras(back))) => assert_eq!(back, extras, "{line}"),
        other => panic!("{line}: {other:?}"),
    }
    // A bracket's calibration (or none).
    let mount = if bool::arbitrary(u)? {
        BracketMount::Flange
    } else {
        BracketMount::UpperArm
    };
    let calibration = if bool::arbitrary(u)? {
        const ALPHABET: &[u8] = b"AZaz09-_F";
        let len = 1 + usize::from(u8::arbitrary(u)? % 12);
        let mut id = String::new();
        for _ in 0..len {
            id.push(char::from(
                ALPHABET[usize::from(u8::arbitrary(u)?) % ALPHABET.len()],
            ));
        }
        // A calibration made on the pendant has no date until the desktop stamps one.
        let date = bool::arbitrary(u)?.then_some(
            2000_0101
                + u32::from(u16::arbitrary(u)? % 1000) * 10_000
                + u32::from(u8::arbitrary(u)? % 12) * 100
                + u32::from(u8::arbitrary(u)? % 28),
        );
        let temperature_c = temperature(u)?;
        Some(
            BracketCalibration::new(
                bracket_id(&id).expect("an ID of the alphabet"),
                Tilt::from_deg(
                    within(u, MAX_BRACKET_TURN_DEG)?,
                    within(u, MAX_BRACKET_TURN_DEG)?,
                ),
                within(u, 0.1)?.abs().to_radians(),
                date,
                temperature_c,
            )
            .expect("a plausible calibration")
            .with_yaw(BracketYaw {
                yaw_rad: within(u, MAX_BRACKET_TURN_DEG)?.to_radians(),
                uncertainty_rad: within(u, 0.1)?.abs().to_radians(),
            })
            .expect("a plausible yaw"),
        )
    } else {
        None
    };
    let mut line = Line::new();
    write_bracket(&mut line, mount, calibration.as_ref()).expect("a bracket fits a line");
    let comment = line.trim_start_matches('#').trim();
    for parse in PARSERS {
        match parse_meta::<f64>(comment, 1, parse) {
            Ok(Some(MetaItem::Bracket(m, back))) => {
                assert_eq!(m, mount, "{line}");
                match (&calibration, &back) {
                    (None, None) => {}
                    (Some(a), Some(b)) => {
                        assert_eq!((&a.id, a.date), (&b.id, b.date), "{line}");
                        assert!(close_tilt(a.rotation_rad, b.rotation_rad), "{line}");
                        assert!(
                            (a.uncertainty_rad - b.uncertainty_rad).abs() <= ANGLE_TOLERANCE_RAD,
                            "{line}"
                        );
                        assert!(
                            close_temperature(a.temperature_c, b.temperature_c),
                            "{line}"
                        );
                        let (ya, yb) = (a.yaw.expect("written"), b.yaw.expect("read back"));
                        assert!(
                            (ya.yaw_rad - yb.yaw_rad).abs() <= ANGLE_TOLERANCE_RAD
                                && (ya.uncertainty_rad - yb.uncertainty_rad).abs()
                                    <= ANGLE_TOLERANCE_RAD,
                            "{line}"
                        );
                    }
                    _ => panic!("{line}: {back:?}"),
                }
            }
            other => panic!("{line}: {other:?}"),
        }
    }
    Ok(())
}

fuzz_target!(|data: &[u8]| {
    let _ = check(&mut Unstructured::new(data));
});
