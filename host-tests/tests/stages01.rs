//! g. Stage 0 (reversal) and stage 1 (half turn of axis 1) against a 3-D simulation:
//! exact, not small-angle, in both conventions, with readings well away from zero.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use zerocal_core::model::{rot_x, rot_y, rot_z, BaseTilt, Convention, Tilt};
use zerocal_core::stage0::BenchTurns;
use zerocal_core::stage1::AxisOneTurn;
use zerocal_sim::{Noise, SimInclinometer, SimRobot};

/// Sensor range for these checks: readings go up to ~9° on purpose.
const RANGE_RAD: f64 = 0.35;

#[test]
fn stage0_and_stage1_are_exact_in_3d() {
    let mut rng = ChaCha8Rng::seed_from_u64(0x6);
    let (mut worst_bias, mut worst_tilt, mut worst_dt2): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for case in 0..200 {
        let conv = if case % 2 == 0 {
            Convention::Rpy
        } else {
            Convention::Axis
        };
        let bias = Tilt::from_deg(rng.gen_range(-0.5..0.5), rng.gen_range(-0.5..0.5));
        let sensor = SimInclinometer::new(conv, bias, Noise::None, 0);

        // Stage 0 on a bench tilted up to 5°, the pendant at any heading.
        let surface = rot_y(rng.gen_range(-0.09..0.09))
            * rot_x(rng.gen_range(-0.09..0.09))
            * rot_z(rng.gen_range(-3.1..3.1));
        let rev = BenchTurns::half_turn(
            sensor.exact(&surface),
            sensor.exact(&(surface * rot_z(std::f64::consts::PI))),
        );
        let found = rev.bias(conv, RANGE_RAD).expect("in range");
        worst_bias = worst_bias
            .max((found.x_rad - bias.x_rad).to_degrees().abs())
            .max((found.y_rad - bias.y_rad).to_degrees().abs());

        // Stage 1: base tilt up to 1°, joint 2 commanded up to ±8° so x reads far from 0.
        let mut robot = SimRobot::paper(
            [0.0; 4],
            (rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0)),
        );
        robot.offsets_rad[1] = rng.gen_range(-2f64..2.0).to_radians();
        let robot = robot.with_j2_direction(if rng.gen_bool(0.5) { 1 } else { -1 });
        let c2 = rng.gen_range(-8f64..8.0).to_radians();
        let turn = AxisOneTurn {
            before: sensor.exact(&robot.upper_arm_orientation(0.0, c2)),
            after: sensor.exact(&robot.upper_arm_orientation(std::f64::consts::PI, c2)),
            j1_rad: 0.0,
            j2_rad: c2,
        };
        let s1 = turn
            .solve(&robot.arm, conv, Some((&found, 0.5)), RANGE_RAD)
            .expect("stage 1");
        let BaseTilt {
            alpha_rad,
            beta_rad,
        } = robot.base_tilt;
        worst_tilt = worst_tilt
            .max((s1.base_tilt.alpha_rad - alpha_rad).to_degrees().abs())
            .max((s1.base_tilt.beta_rad - beta_rad).to_degrees().abs())
            .max((s1.bias_y_rad - bias.y_rad).to_degrees().abs());
        worst_dt2 = worst_dt2.max(
            (s1.delta_theta2_rad - robot.delta_theta2_rad())
                .to_degrees()
                .abs(),
        );
        assert!(s1.bias_x_known);
    }
    println!(
        "200 cases, both conventions: worst error bias {worst_bias:.1e} deg, alpha/beta/by {worst_tilt:.1e} deg, dtheta2 {worst_dt2:.1e} deg"
    );
    // Stage 0's formula is exact, stage 1 is Newton's method on the exact model to a step
    // of 1e-13 rad (5.7e-12°): what is left is that and f64 rounding. 1e-10° is above
    // both and still fails any approximation (a small-angle one is ~1e-5°).
    let tol = 1e-10;
    assert!(worst_bias < tol && worst_tilt < tol && worst_dt2 < tol);
}

/// Without stage 0 the paper's assumption (bx = 0) leaves exactly bx in Δθ2 (rpy),
/// and the result says so.
#[test]
fn stage1_without_stage0_reports_the_unknown_x_bias() {
    let bias = Tilt::from_deg(0.03, -0.02);
    let sensor = SimInclinometer::new(Convention::Rpy, bias, Noise::None, 0);
    let mut robot = SimRobot::paper([0.0; 4], (0.4, -0.3));
    robot.offsets_rad[1] = 0.5f64.to_radians();
    let c2 = 0.0;
    let turn = AxisOneTurn {
        before: sensor.exact(&robot.upper_arm_orientation(0.0, c2)),
        after: sensor.exact(&robot.upper_arm_orientation(std::f64::consts::PI, c2)),
        j1_rad: 0.0,
        j2_rad: c2,
    };
    let s1 = turn
        .solve(&robot.arm, Convention::Rpy, None, RANGE_RAD)
        .expect("stage 1");
    assert!(!s1.bias_x_known);
    let err = s1.delta_theta2_rad - robot.delta_theta2_rad();
    println!(
        "no stage 0: dtheta2 error {:.6} deg = sensor x bias {:.6} deg",
        err.to_degrees(),
        0.03
    );
    // Newton to a step of 1e-13 rad: exact to that.
    assert!((err - bias.x_rad).abs() < 1e-12);
    // y bias and base tilt need no stage 0.
    assert!((s1.bias_y_rad - bias.y_rad).abs() < 1e-12);
    assert!((s1.base_tilt.alpha_rad - robot.base_tilt.alpha_rad).abs() < 1e-12);
}
