//! The bench where the pendant is turned by hand: the headings of stage 0's and the
//! closing readings, and a bracket's calibration as its procedure makes it (the
//! reversals on the levelled plate and on the sine plate, with this world's sensor
//! and the procedure's own errors), or exactly where the world says the brackets are
//! known.

use super::{small_rotation, uniform};
use crate::sensor::Scl3300Unit;
use nalgebra::Rotation3;
use rand_chacha::ChaCha8Rng;
use zerocal_core::bracket::{
    bracket_id, calibrate, calibrate_yaw, BracketCalibration, BracketYaw, CAPTURES_PER_READING,
    FENCE_CONTACT_TOLERANCE_DEG, REFERENCE_TURN_TOLERANCE_DEG,
};
use zerocal_core::model::{rot_x, rot_y, rot_z, up_in_sensor, Convention, Tilt};
use zerocal_core::real::deg_to_rad;
use zerocal_core::stage0::BenchTurns;
use zerocal_core::stage2::{MEMS_CAPTURE_NOISE_DEG, MEMS_RANGE_DEG};

/// The calibration of a bracket whose turn is known exactly (`made`: about x, y, z).
/// It holds the turn as a calibration reads it (the level reversals see
/// `R_z(−c)·(−sin b·cos a, sin a)`), and the yaw.
pub(super) fn exact_calibration(made: &[f64; 3]) -> BracketCalibration<f64> {
    let [a, b, c] = *made;
    let (x, y) = (-(b.sin() * a.cos()), a.sin());
    let (read_x, read_y) = (x * c.cos() + y * c.sin(), -x * c.sin() + y * c.cos());
    let read_a = read_y.asin();
    BracketCalibration {
        // "EXACT" is a valid ID: five ASCII letters.
        id: bracket_id("EXACT").unwrap_or_default(),
        rotation_rad: Tilt::new(read_a, (-read_x / read_a.cos()).asin()),
        uncertainty_rad: 0.0,
        date: Some(SIM_CALIBRATION_DATE),
        temperature_c: Some(23.0),
        yaw: Some(BracketYaw {
            yaw_rad: c,
            uncertainty_rad: 0.0,
        }),
    }
}

/// The date the simulated calibrations carry.
const SIM_CALIBRATION_DATE: u32 = 20_261_127;

/// Where a bracket is calibrated: the plate (tilted within ± `tilt_deg` about each
/// horizontal axis), the box, and the temperature.
pub(super) struct BracketBench<'a> {
    pub(super) chip_in_box: &'a Rotation3<f64>,
    pub(super) headings: usize,
    pub(super) tilt_deg: f64,
    pub(super) seat_deg: f64,
    pub(super) temperature_c: f64,
}

/// How far each turn between two of the bench's headings, made by hand about a quarter
/// turn (or a third, for three), may be off that (± deg): a stated figure for a turn
/// judged by eye; the solve finds the turns, so any figure would do.
pub const HAND_TURN_SPREAD_DEG: f64 = 30.0;

/// The headings (rad, the first at 0) of `count` bench readings turned by hand: two a
/// half turn off by up to ±`half_turn_error_deg`; more, spread over a turn, each off
/// its share by up to ±[`HAND_TURN_SPREAD_DEG`].
pub(super) fn bench_headings(
    count: usize,
    half_turn_error_deg: f64,
) -> impl Fn(&mut ChaCha8Rng) -> Vec<f64> {
    move |rng: &mut ChaCha8Rng| {
        let pi = core::f64::consts::PI;
        if count <= 2 {
            return vec![0.0, pi + deg_to_rad(uniform(rng, half_turn_error_deg))];
        }
        (0..count)
            .map(|k| {
                if k == 0 {
                    0.0
                } else {
                    2.0 * pi * k as f64 / count as f64
                        + deg_to_rad(uniform(rng, HAND_TURN_SPREAD_DEG))
                }
            })
            .collect()
    }
}

/// A bracket's calibration as docs/bracket-calibration.md describes it, with this
/// world's sensor: the pendant's reversal on the levelled plate, then in the bracket
/// (turned by `made`, seated on its reference within the seat's repeatability) with the
/// reference reversed on the plate, each half turn by hand within
/// ±[`zerocal_core::bracket::REFERENCE_TURN_TOLERANCE_DEG`]; then the same two reversals
/// on a 5° sine plate, each face against the fence within
/// ±[`FENCE_CONTACT_TOLERANCE_DEG`] (the yaw). Each reading averages the calibration's
/// captures. `None` if the core refuses the readings (then the session has no
/// calibration for it).
pub(super) fn calibrate_bracket(
    sensor: &mut Scl3300Unit,
    bench: &BracketBench<'_>,
    made: &[f64; 3],
    id: &str,
    rng: &mut ChaCha8Rng,
) -> Option<BracketCalibration<f64>> {
    let plate = rot_y(deg_to_rad(uniform(rng, bench.tilt_deg)))
        * rot_x(deg_to_rad(uniform(rng, bench.tilt_deg)))
        * rot_z(uniform(rng, core::f64::consts::PI));
    let headings = bench_headings(bench.headings, REFERENCE_TURN_TOLERANCE_DEG);
    let bracket = rot_x(made[0]) * rot_y(made[1]) * rot_z(made[2]);
    // Each reading the mean of the calibration's captures.
    let mut read = |r: &Rotation3<f64>, rng: &mut ChaCha8Rng| {
        let u = up_in_sensor(&(r * bench.chip_in_box));
        let (mut x, mut y) = (0.0, 0.0);
        for _ in 0..CAPTURES_PER_READING {
            let c = sensor.capture(&u, bench.temperature_c, rng).reading;
            x += c.x_rad;
            y += c.y_rad;
        }
        let n = CAPTURES_PER_READING as f64;
        Tilt::new(x / n, y / n)
    };
    let mut turned = |on: &Rotation3<f64>, rng: &mut ChaCha8Rng| {
        let taken: Vec<Tilt<f64>> = headings(rng)
            .iter()
            .map(|h| read(&(plate * rot_z(*h) * on), rng))
            .collect();
        BenchTurns::from_readings(&taken)
    };
    let pendant = turned(&Rotation3::identity(), rng)?;
    let seat_on_reference = small_rotation(rng, bench.seat_deg).1;
    let seated = bracket * seat_on_reference;
    let in_bracket = turned(&seated, rng)?;
    let noise = deg_to_rad(MEMS_CAPTURE_NOISE_DEG);
    let (rotation, u) = calibrate(
        &pendant,
        &in_bracket,
        Convention::Axis,
        deg_to_rad(MEMS_RANGE_DEG),
        noise,
    )
    .ok()?;
    // The yaw: the same two reversals on a sine plate at 5°, each face laid against
    // its fence within the fence's tolerance, turned end for end against it.
    let sine = rot_z(uniform(rng, core::f64::consts::PI)) * rot_x(deg_to_rad(5.0));
    let at_fence = |rng: &mut ChaCha8Rng, half: f64| {
        rot_z(half + deg_to_rad(uniform(rng, FENCE_CONTACT_TOLERANCE_DEG)))
    };
    let pi = core::f64::consts::PI;
    let pendant_tilted = BenchTurns::half_turn(
        read(&(sine * at_fence(rng, 0.0)), rng),
        read(&(sine * at_fence(rng, pi)), rng),
    );
    let bracket_tilted = BenchTurns::half_turn(
        read(&(sine * at_fence(rng, 0.0) * seated), rng),
        read(&(sine * at_fence(rng, pi) * seated), rng),
    );
    let bias = pendant
        .bias(Convention::Axis, deg_to_rad(MEMS_RANGE_DEG))
        .ok()?;
    let yaw = calibrate_yaw(
        &pendant_tilted,
        &bracket_tilted,
        &rotation,
        &bias,
        Convention::Axis,
        noise,
    )
    .ok()?;
    BracketCalibration::new(
        bracket_id(id).ok()?,
        rotation,
        u,
        Some(SIM_CALIBRATION_DATE),
        Some(bench.temperature_c),
    )
    .and_then(|c| c.with_yaw(yaw))
    .ok()
}
