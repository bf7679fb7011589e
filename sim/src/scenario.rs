//! Operator scripts for the simulated pendant: the moves and button presses of a
//! calibration, as a technician would make them.

use crate::pendant::{Mount, SimPendant};
use crate::SimRobot;
use zerocal_core::model::{rot_x, rot_y, Convention, SensorModel, Tilt};
use zerocal_core::plan::{plan, Candidate, PlanConfig, PlanError, PoseList};
use zerocal_core::real::deg_to_rad;
use zerocal_core::stage2::Stage2Model;
use zerocal_core::Real;
use zerocal_procedure::{Approach, Event, Phase, ProcedureConfig};

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

/// The bench of stages 0 and the closing reversal: tilted by ~1°.
fn bench(heading_rad: f64) -> Mount {
    Mount::Bench {
        surface: rot_y(deg_to_rad(0.8)) * rot_x(deg_to_rad(-1.1)),
        heading_rad,
    }
}

/// How far past a pose a joint goes before arriving from one side (deg): the
/// pendant re-arms on a reading moved by more than 0.2°.
pub const APPROACH_DEG: f64 = 1.0;

/// Stage 0: a bench tilted by ~1°, a reading, a half turn on the spot (then OK), a reading.
pub fn stage0<T: Real>(p: &mut SimPendant<T>) {
    p.move_to(bench(0.4), 500);
    p.hold(HOLD_MS);
    p.move_to(bench(0.4 + std::f64::consts::PI), 2000);
    p.event(Event::Ok);
    p.hold(HOLD_MS);
}

/// Stage 1 at one position of axis 1: every joint arriving from below, a capture,
/// past the pose and back from above, a capture. `ok_first` presses OK before the
/// first (after the half turn, which the pendant does not take for a move).
fn stage1_pair<T: Real>(p: &mut SimPendant<T>, j1_rad: f64, move_ms: u32, ok_first: bool) {
    let at = |c2_deg: f64| Mount::UpperArm {
        j1_rad,
        c2_rad: deg_to_rad(c2_deg),
    };
    p.move_to(at(-APPROACH_DEG), move_ms);
    p.move_to(at(0.0), 500);
    if ok_first {
        p.event(Event::Ok);
    }
    p.hold(HOLD_MS);
    p.move_to(at(APPROACH_DEG), 500);
    p.move_to(at(0.0), 500);
    p.hold(HOLD_MS);
}

/// Stage 1: clip to the upper arm, read from below and from above, turn axis 1 by
/// 180° (then OK), read from below and from above.
pub fn stage1<T: Real>(p: &mut SimPendant<T>) {
    stage1_pair(p, 0.0, 1500, false);
    stage1_pair(p, std::f64::consts::PI, 4000, true);
}

/// Stage 2: clip to the flange and visit the remaining plan poses in order; capture
/// is armed by the motion itself.
pub fn stage2<T: Real>(p: &mut SimPendant<T>) {
    stage2_pressing_ok(p, false);
}

/// Stage 2, pressing OK at each capture when `press_ok` (poses whose readings barely
/// differ do not arm the capture by motion).
pub fn stage2_pressing_ok<T: Real>(p: &mut SimPendant<T>, press_ok: bool) {
    // Each visit captures once; a script that captures nothing stops instead of
    // looping, and the test's own checks then fail.
    let mut visits = 4 * p.session.plan().len() + 2;
    while visits > 0 && approach_next(p) {
        visits -= 1;
        if press_ok {
            p.event(Event::Ok);
        }
        p.hold(HOLD_MS);
    }
}

/// Takes the robot to the next stage-2 capture's pose from the side the pendant asks
/// for, starting [`APPROACH_DEG`] away on every joint; false outside stage 2. Like an
/// operator watching the screen: if a capture lands while the robot is leaving (a
/// window that filled just as it started), it goes where the screen asks now.
pub fn approach_next<T: Real>(p: &mut SimPendant<T>) -> bool {
    for _ in 0..4 {
        let view = p.session.view();
        let (Phase::Stage2, Some((_, _, q)), Some(approach)) =
            (view.phase, view.pose, view.approach)
        else {
            return false;
        };
        let captured = view.captured;
        let side = match approach {
            Approach::FromBelow => -1.0,
            Approach::FromAbove => 1.0,
        };
        let q = q.map(|v| v.to_f64());
        p.move_to(
            Mount::Flange {
                joints_rad: q.map(|v| v + side * deg_to_rad(APPROACH_DEG)),
            },
            2000,
        );
        if p.session.captures().len() != captured {
            continue;
        }
        p.move_to(Mount::Flange { joints_rad: q }, 500);
        return true;
    }
    false
}

/// The closing reversal: the pendant back on stage 0's bench (OK), a reading, a half
/// turn (OK), a reading.
pub fn closing<T: Real>(p: &mut SimPendant<T>) {
    p.move_to(bench(0.4), 3000);
    p.event(Event::Ok);
    p.hold(HOLD_MS);
    p.move_to(bench(0.4 + std::f64::consts::PI), 2000);
    p.event(Event::Ok);
    p.hold(HOLD_MS);
}

/// A whole calibration.
pub fn whole_session<T: Real>(p: &mut SimPendant<T>) {
    stage0(p);
    stage1(p);
    stage2(p);
    closing(p);
}
