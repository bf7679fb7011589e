//! Operator scripts for the simulated pendant: the moves and button presses of a
//! calibration, as a technician would make them.

use crate::pendant::{Mount, SimPendant};
use crate::SimRobot;
use zerocal_core::model::{rot_x, rot_y, Convention, SensorModel, Tilt};
use zerocal_core::plan::{plan, Candidate, PlanConfig, PlanError, PoseList};
use zerocal_core::procedure::{Event, Phase, ProcedureConfig};
use zerocal_core::real::deg_to_rad;
use zerocal_core::stage2::Stage2Model;
use zerocal_core::Real;

/// Per-sample noise of the simulated SCL3300 (deg, 1σ): ~0.001°/√Hz over its 10 Hz
/// band in inclination mode.
pub const SCL3300_NOISE_DEG: f64 = 0.003;

/// The pendant's default plan: `n` poses from core's planner (axis convention, level
/// base, zero offsets: all the pendant knows before stage 2).
///
/// # Errors
/// The planner's refusal (too many poses, an unobservable plan).
pub fn default_plan<T: Real>(n: usize) -> Result<PoseList<T>, PlanError> {
    let model = Stage2Model {
        sensor: SensorModel::new(Convention::Axis, Tilt::default()),
        ..Stage2Model::default()
    };
    let config = PlanConfig {
        poses: n,
        ..PlanConfig::default()
    };
    let mut pool = vec![Candidate::default(); config.candidates];
    Ok(plan(&model, &config, &mut pool)?.poses_rad)
}

/// A robot and sensor truth for the scenarios (deg): offsets to ±0.3°, base tilt,
/// sensor bias.
pub fn truth_robot() -> (SimRobot, Tilt<f64>) {
    let mut robot = SimRobot::paper([0.12, -0.25, 0.08, 0.3], (0.35, -0.2)).with_j2_direction(-1);
    robot.offsets_rad[1] = deg_to_rad(-0.15);
    (robot, Tilt::from_deg(0.04, -0.03))
}

/// A pendant on the truth robot with the default plan of `n` poses.
///
/// # Errors
/// The planner's refusal of `n` poses.
pub fn pendant<T: Real>(n: usize, seed: u64) -> Result<SimPendant<T>, PlanError> {
    let (robot, bias) = truth_robot();
    let config = ProcedureConfig {
        arm: robot.arm.cast(),
        ..ProcedureConfig::default()
    };
    Ok(SimPendant::new(
        robot,
        bias,
        deg_to_rad(SCL3300_NOISE_DEG),
        config,
        default_plan(n)?,
        seed,
    ))
}

/// How long the operator holds still at each capture (ms): the stillness window and
/// a margin.
pub const HOLD_MS: u32 = 3000;

/// Stage 0: a bench tilted by ~1°, a reading, a half turn on the spot (then OK), a reading.
pub fn stage0<T: Real>(p: &mut SimPendant<T>) {
    let surface = rot_y(deg_to_rad(0.8)) * rot_x(deg_to_rad(-1.1));
    p.move_to(
        Mount::Bench {
            surface,
            heading_rad: 0.4,
        },
        500,
    );
    p.hold(HOLD_MS);
    p.move_to(
        Mount::Bench {
            surface,
            heading_rad: 0.4 + std::f64::consts::PI,
        },
        2000,
    );
    p.event(Event::Ok);
    p.hold(HOLD_MS);
}

/// Stage 1: clip to the upper arm, read, turn axis 1 by 180° (then OK), read.
pub fn stage1<T: Real>(p: &mut SimPendant<T>) {
    let c2 = 0.0;
    p.move_to(
        Mount::UpperArm {
            j1_rad: 0.0,
            c2_rad: c2,
        },
        1500,
    );
    p.hold(HOLD_MS);
    p.move_to(
        Mount::UpperArm {
            j1_rad: std::f64::consts::PI,
            c2_rad: c2,
        },
        4000,
    );
    p.event(Event::Ok);
    p.hold(HOLD_MS);
}

/// Stage 2: clip to the flange and visit the remaining plan poses in order; capture
/// is armed by the motion itself.
pub fn stage2<T: Real>(p: &mut SimPendant<T>) {
    stage2_pressing_ok(p, false);
}

/// Stage 2, pressing OK at each pose when `press_ok` (poses whose readings barely
/// differ do not arm the capture by motion).
pub fn stage2_pressing_ok<T: Real>(p: &mut SimPendant<T>, press_ok: bool) {
    // Each visit captures one pose; a script that captures nothing stops instead of
    // looping, and the test's own checks then fail.
    let mut visits = 2 * p.session.plan().len() + 2;
    while p.session.phase() == Phase::Stage2 && visits > 0 {
        visits -= 1;
        let Some((_, _, q)) = p.session.view().pose else {
            break;
        };
        p.move_to(
            Mount::Flange {
                joints_rad: q.map(|v| v.to_f64()),
            },
            2500,
        );
        if press_ok {
            p.event(Event::Ok);
        }
        p.hold(HOLD_MS);
    }
}

/// A whole calibration.
pub fn whole_session<T: Real>(p: &mut SimPendant<T>) {
    stage0(p);
    stage1(p);
    stage2(p);
}
