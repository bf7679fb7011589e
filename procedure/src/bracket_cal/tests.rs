//! The bracket calibration's runs, refusals and its line.

use super::*;
use zerocal_core::bracket::bracket_id;
use zerocal_core::model::{rot_x, rot_y, rot_z, up_in_sensor, Convention, SensorModel};
use zerocal_core::real::deg_to_rad;
use zerocal_core::stage0::BenchTurns;

/// A step with the still window the pendant lends from its session: one per test
/// thread here (each test runs on its own).
fn step(
    config: &ProcedureConfig<f64>,
    s: &mut BracketCalState<f64>,
    event: Event<f64>,
) -> BracketOutput<f64> {
    std::thread_local!(static WINDOW: std::cell::RefCell<StillnessFilter<f64>> =
        std::cell::RefCell::new(StillnessFilter::new()));
    WINDOW.with(|w| bracket_step(config, s, &mut w.borrow_mut(), event))
}

/// A chip offset of 0.58° in its box, as core's bracket test.
fn bias() -> Tilt<f64> {
    Tilt::from_deg(0.5, -0.3)
}

/// What the sensor reads with the pendant turned `r` from the plate's level frame.
fn read(r: &nalgebra::Rotation3<f64>) -> Tilt<f64> {
    SensorModel::new(Convention::Axis, bias())
        .read_up(&up_in_sensor(r), &bias())
        .reading
}

/// Feeds `reading` every 50 ms (the pendant's period) until the still window
/// fires; returns the clock after it.
fn hold(
    config: &ProcedureConfig<f64>,
    s: &mut BracketCalState<f64>,
    mut t_ms: u32,
    reading: Tilt<f64>,
    temperature_c: f64,
) -> u32 {
    let taken = s.taken();
    // Four still windows a reading, each some 40 samples.
    for _ in 0..1000 {
        step(
            config,
            s,
            Event::Sample {
                t_ms,
                reading,
                temperature_c: Some(temperature_c),
            },
        );
        t_ms += 50;
        if s.taken() != taken || s.outcome().is_some() {
            break;
        }
    }
    t_ms
}

/// OK, then the pendant held still at `reading` until captured.
fn capture(
    config: &ProcedureConfig<f64>,
    s: &mut BracketCalState<f64>,
    t_ms: u32,
    reading: Tilt<f64>,
    temperature_c: f64,
) -> u32 {
    assert_eq!(step(config, s, Event::Ok), BracketOutput::Stay, "OK arms");
    hold(config, s, t_ms, reading, temperature_c)
}

/// The headings the pendant (and then the reference) is turned to on the plate, by
/// hand: about a quarter turn each, none exact (deg).
const ALONE_HEADINGS_DEG: [f64; BENCH_HEADINGS] = [0.0, 93.0, 178.0, 271.0];
const SEATED_HEADINGS_DEG: [f64; BENCH_HEADINGS] = [12.0, 97.5, 195.0, 283.0];

/// The readings of a bracket turned R_x(a)·R_y(b)·R_z(c): the pendant's headings and
/// the reference's on a plate tilted `plate_tilt_x_deg` about x and 0.04° about y,
/// then four on a sine plate at `sine_deg` against its fence, end for end (the
/// pendant machine's tests run a calibration on them too).
pub(crate) fn readings(
    a_rad: f64,
    b_rad: f64,
    c_rad: f64,
    plate_tilt_x_deg: f64,
    sine_deg: f64,
) -> [Tilt<f64>; BRACKET_CAPTURES] {
    let plate = rot_x(deg_to_rad(plate_tilt_x_deg)) * rot_y(deg_to_rad(-0.04)) * rot_z(0.7);
    let sine = rot_z(0.3) * rot_x(deg_to_rad(sine_deg));
    let half = rot_z(core::f64::consts::PI);
    let bracket = rot_x(a_rad) * rot_y(b_rad) * rot_z(c_rad);
    let mut r = [Tilt::default(); BRACKET_CAPTURES];
    for h in 0..BENCH_HEADINGS {
        r[h] = read(&(plate * rot_z(deg_to_rad(ALONE_HEADINGS_DEG[h]))));
        r[SEATED_START + h] = read(&(plate * rot_z(deg_to_rad(SEATED_HEADINGS_DEG[h])) * bracket));
    }
    r[TILTED_START..].copy_from_slice(&[
        read(&sine),
        read(&(sine * half)),
        read(&(sine * bracket)),
        read(&(sine * half * bracket)),
    ]);
    r
}

fn start() -> (ProcedureConfig<f64>, BracketCalState<f64>) {
    let config = ProcedureConfig::for_mems();
    let s = BracketCalState::new(BracketMount::Flange, bracket_id("F-017").unwrap());
    (config, s)
}

/// A whole run with the readings of a bracket turned by a known 0.41°, −0.27°, yaw
/// 0.3°: the level turn (as read: its x part moves by about c·b, which the session
/// undoes with the yaw, `BracketCalibration::turn`) comes back within 1e-5 rad of
/// core's own reading of it and the yaw within 1e-5 rad of the truth (the readings
/// are exact and the window's mean of a constant is the constant), the temperature
/// is the readings' mean, and OK keeps it as the record of the flange's bracket.
#[test]
fn a_full_run_gives_back_the_brackets_turn() {
    let (config, mut s) = start();
    let (a, b, c) = (deg_to_rad(0.41), deg_to_rad(-0.27), deg_to_rad(0.3));
    let r = readings(a, b, c, 0.06, 5.0);
    let mut t = 0;
    // Without OK nothing is captured, however still.
    t = hold(&config, &mut s, t, r[0], 20.0);
    assert_eq!(
        (s.taken(), s.step()),
        (0, BracketStep::Alone { heading: 0 })
    );
    for (i, reading) in r.iter().enumerate() {
        assert_eq!(s.step(), BracketStep::CAPTURES[i]);
        t = capture(&config, &mut s, t, *reading, 20.0 + i as f64);
    }
    assert_eq!(s.step(), BracketStep::Done);
    let result = match s.outcome() {
        Some(Ok(result)) => *result,
        other => panic!("{other:?}"),
    };
    let level = |i: usize| BenchTurns::from_readings(&r[i..i + BENCH_HEADINGS]).unwrap();
    let (core_turn, u) = calibrate(
        &level(0),
        &level(SEATED_START),
        Convention::Axis,
        config.fit.sensor_range_rad,
        config.fit.sensor_noise_rad,
    )
    .unwrap();
    assert!(
        (result.rotation_rad.x_rad - core_turn.x_rad).abs() < 1e-5
            && (result.rotation_rad.y_rad - core_turn.y_rad).abs() < 1e-5
            && result.yaw.is_some_and(|y| (y.yaw_rad - c).abs() < 1e-5),
        "{result:?}"
    );
    // Headings solved from the readings: no half-turn term, the noise alone.
    assert_eq!(result.uncertainty_rad, u);
    assert!(result.uncertainty_rad > 0.0, "{result:?}");
    // The turns by hand cost nothing: the same bracket read at exact quarter turns
    // gives the same turn, to 5e-8 rad (3e-6°, a hundredth of a capture's noise): on a
    // plate this level (0.07°) core's ridge on the headings holds them a little
    // (`stage0::HEADING_RIDGE`, 7e-9 rad here).
    let plate = rot_x(deg_to_rad(0.06)) * rot_y(deg_to_rad(-0.04)) * rot_z(0.7);
    let bracket = rot_x(a) * rot_y(b) * rot_z(c);
    let exact = |inside: &nalgebra::Rotation3<f64>| {
        let r: [Tilt<f64>; BENCH_HEADINGS] = core::array::from_fn(|h| {
            read(&(plate * rot_z(core::f64::consts::FRAC_PI_2 * h as f64) * inside))
        });
        BenchTurns::from_readings(&r).unwrap()
    };
    let (exact_turn, _) = calibrate(
        &exact(&nalgebra::Rotation3::identity()),
        &exact(&bracket),
        Convention::Axis,
        config.fit.sensor_range_rad,
        config.fit.sensor_noise_rad,
    )
    .unwrap();
    assert!(
        (result.rotation_rad.x_rad - exact_turn.x_rad).abs() < 5e-8
            && (result.rotation_rad.y_rad - exact_turn.y_rad).abs() < 5e-8,
        "{result:?} {exact_turn:?}"
    );
    // 20 to 31 °C.
    assert_eq!(result.temperature_c, Some(25.5));
    let BracketOutput::Keep(record) = step(&config, &mut s, Event::Ok) else {
        panic!("OK on a result keeps it");
    };
    let kept = StoredBrackets::from_records([record]);
    let flange = kept.get(BracketMount::Flange).unwrap();
    assert_eq!(flange.id().unwrap().as_str(), "F-017");
    assert_eq!(*flange, result);
    // Made on the pendant: no date until the desktop stamps one.
    assert_eq!(flange.date, None);
    assert!(kept.get(BracketMount::UpperArm).is_none());
}

/// A plate tilted 0.2° (twice what the method allows) is refused by name as soon
/// as the pendant's own headings are in, before the bracket is fitted; OK starts
/// again from the first step.
#[test]
fn a_tilted_plate_is_refused_by_name() {
    let (config, mut s) = start();
    let r = readings(0.0, 0.0, 0.0, 0.2, 5.0);
    let mut t = 0;
    for reading in &r[..BENCH_HEADINGS] {
        assert_eq!(s.outcome(), None, "refused before its headings are in");
        t = capture(&config, &mut s, t, *reading, 20.0);
    }
    assert_eq!(s.step(), BracketStep::Done);
    // The plate's 0.2° about x and 0.04° about y: 0.204°.
    match s.outcome() {
        Some(Err(BracketError::PlateNotLevel { tilt_deg })) => {
            assert!((tilt_deg - 0.204).abs() < 0.002, "{tilt_deg}")
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(step(&config, &mut s, Event::Ok), BracketOutput::Stay);
    assert_eq!(
        (s.step(), s.taken()),
        (BracketStep::Alone { heading: 0 }, 0)
    );
}

/// BACK undoes the last capture (also from the result, which it drops), and with
/// nothing captured leaves the calibration; a retaken capture gives the same turn.
#[test]
fn back_undoes_the_last_capture() {
    let (config, mut s) = start();
    let (a, b) = (deg_to_rad(-0.3), deg_to_rad(0.2));
    let r = readings(a, b, 0.0, 0.05, 5.0);
    let mut t = 0;
    t = capture(&config, &mut s, t, r[0], 20.0);
    // A wrong reading (the pendant already in its bracket) taken for the third heading,
    // undone.
    t = capture(&config, &mut s, t, r[1], 20.0);
    t = capture(&config, &mut s, t, r[SEATED_START], 20.0);
    assert_eq!(s.step(), BracketStep::Alone { heading: 3 });
    assert_eq!(step(&config, &mut s, Event::Back), BracketOutput::Stay);
    assert_eq!(s.step(), BracketStep::Alone { heading: 2 });
    // BACK disarms: no capture until OK.
    t = hold(&config, &mut s, t, r[2], 20.0);
    assert_eq!(s.step(), BracketStep::Alone { heading: 2 });
    for reading in &r[2..] {
        t = capture(&config, &mut s, t, *reading, 20.0);
    }
    assert!(matches!(s.outcome(), Some(Ok(_))));
    // From the result: the last capture goes, the result with it.
    step(&config, &mut s, Event::Back);
    assert_eq!(
        (s.step(), s.outcome()),
        (BracketStep::SeatedTiltedTurned, None)
    );
    capture(&config, &mut s, t, r[BRACKET_CAPTURES - 1], 20.0);
    match s.outcome() {
        Some(Ok(result)) => assert!(
            (result.rotation_rad.x_rad - a).abs() < 1e-5
                && (result.rotation_rad.y_rad - b).abs() < 1e-5
                && result.yaw.is_some_and(|y| y.yaw_rad.abs() < 1e-5),
            "{result:?}"
        ),
        other => panic!("{other:?}"),
    }
    for _ in 0..BRACKET_CAPTURES {
        assert_eq!(step(&config, &mut s, Event::Back), BracketOutput::Stay);
    }
    assert_eq!(s.taken(), 0);
    assert_eq!(step(&config, &mut s, Event::Back), BracketOutput::Leave);
}

/// The `brackets` line reads back to 1e-5° (its decimals), `none` included; a
/// line with a field missing or not a number is refused by the field's name.
#[test]
fn the_brackets_line_reads_back() {
    let (id, id_len) = id_bytes(&bracket_id("U-2").unwrap());
    let kept = StoredBracket {
        id,
        id_len,
        rotation_rad: Tilt::from_deg(0.412_345_6, -0.27),
        uncertainty_rad: deg_to_rad(0.000_83),
        date: None,
        temperature_c: Some(21.25_f64),
        yaw: Some(zerocal_core::bracket::BracketYaw {
            yaw_rad: deg_to_rad(-0.123_45),
            uncertainty_rad: deg_to_rad(0.041),
        }),
    };
    let line = bracket_line(BracketMount::UpperArm, Some(&kept)).unwrap();
    assert_eq!(
        line.as_str(),
        "bracket upper-arm id U-2 rot_deg +0.41235,-0.27000 u_deg 0.00083 yaw_deg -0.12345 \
         u_yaw_deg 0.04100 temp_c 21.25"
    );
    let (mount, back) = parse_bracket_line::<f64>(&line).unwrap();
    let back = back.unwrap();
    assert_eq!(
        (mount, back.id().unwrap().as_str()),
        (BracketMount::UpperArm, "U-2")
    );
    let (x, y) = back.rotation_rad.to_deg();
    assert!((x - 0.412_345_6).abs() <= 0.5e-5 && (y + 0.27).abs() < 1e-12);
    assert_eq!(back.temperature_c, Some(21.25));
    // A calibration without a yaw prints and reads back as one.
    let no_yaw = StoredBracket { yaw: None, ..kept };
    let line = bracket_line(BracketMount::UpperArm, Some(&no_yaw)).unwrap();
    assert!(
        line.as_str().contains(" yaw_deg none u_yaw_deg none "),
        "{}",
        line.as_str()
    );
    let back = parse_bracket_line::<f64>(&line).unwrap().1.unwrap();
    assert_eq!((back.yaw, back.date), (None, None));
    let none = bracket_line::<f64>(BracketMount::Flange, None).unwrap();
    assert_eq!(
        parse_bracket_line::<f64>(&none),
        Ok((BracketMount::Flange, None))
    );
    assert_eq!(
        parse_bracket_line::<f64>("bracket flange id F-1 rot_deg 0.1 u_deg 0 temp_c none"),
        Err(BracketLineError::BadField("rot_deg"))
    );
    assert_eq!(
        parse_bracket_line::<f64>(
            "bracket flange id F-1 rot_deg 0.1,0 u_deg -1 yaw_deg 0 u_yaw_deg 0 temp_c none"
        ),
        Err(BracketLineError::BadField("u_deg"))
    );
    assert_eq!(
        parse_bracket_line::<f64>("bracket wrist none"),
        Err(BracketLineError::NotABracketLine)
    );
}

/// A still reading beyond the sensor's ±10° is not captured, and says which axis.
#[test]
fn a_reading_out_of_range_is_not_captured() {
    let (config, mut s) = start();
    capture(&config, &mut s, 0, Tilt::from_deg(12.0, 0.0), 20.0);
    assert_eq!(s.taken(), 0);
    assert!(
        matches!(
            s.notice(),
            Some(BracketNotice::ReadingOutOfRange { axis: TiltAxis::X, value_deg })
                if (value_deg - 12.0).abs() < 1e-3
        ),
        "{:?}",
        s.notice()
    );
}
