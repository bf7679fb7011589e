//! The robot side of a session for `zerocal plan` and `zerocal program`: core's
//! robot-time model (`zerocal_procedure::robot_time`) filled in from a robot profile and
//! the options, the room every capture needs on both sides of the backlash inside the
//! joint limits, the mounting and parking poses, and the pendant's capture rule
//! checked along every move.
//!
//! The procedure: every pose (stage 1's two and every stage-2 pose) is
//! captured twice, first with every joint arriving moving in its positive direction
//! (from [`APPROACH_DEG`] below), then with every joint arriving moving negative (from
//! [`OVERSHOOT_DEG`] above); the overshoot is also the move that re-arms the pendant.
//! Joint values here are the controller's: "positive" is the controller's positive.
//! After stage 2 the robot parks at the flange's mounting pose and the pendant is
//! reversed on the bench (the closing reversal).
//!
//! What is a source's figure and what is a stated default:
//!
//! - joint speeds: the profile's `max_speed_deg_s` (each cites its source); where a
//!   profile gives none, [`DEFAULT_JOINT_SPEED_DEG_S`];
//! - joint accelerations: no profile source gives them: [`DEFAULT_ACCEL_DEG_S2`];
//! - the reduced speed, the settling, the remount, an operator's OK and the approach
//!   distance: stated defaults ([`DEFAULT_SPEED_PERCENT`], [`DEFAULT_SETTLE_S`],
//!   [`DEFAULT_REMOUNT_S`], [`OPERATOR_OK_S`], [`APPROACH_DEG`]);
//! - the overshoot: the smallest round figure that re-arms the pendant at every pose of
//!   the built-in plans ([`OVERSHOOT_DEG`]);
//! - the still window and its threshold, and the move that arms the next capture:
//!   the pendant's own (core's `StillnessConfig` and `ProcedureConfig` defaults);
//!   the sensor period: the pendant's 20 Hz read rate, [`SAMPLE_PERIOD_S`]; the
//!   sensor's range: mode 4's ±10° (core's `MEMS_RANGE_DEG`).

use crate::args::{CountIn, RealIn};
use crate::error::CliError;
use clap::Args;
use serde::Serialize;
use zerocal_core::model::{BaseTilt, Convention, SensorModel, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::stage2::{Stage2Model, MEMS_RANGE_DEG};
use zerocal_procedure::robot_time::{shortest_tour, Mounting, SessionPath, SessionTime, TimeModel};
use zerocal_procedure::stillness::StillnessConfig;
use zerocal_procedure::ProcedureConfig;
use zerocal_profile::{Coupling, Profile};

/// The session's joint speed, percent of each joint's maximum (stated default: slow
/// enough to stop short of a collision the first run reveals, as the controller
/// pages' examples do; not a source's figure).
pub const DEFAULT_SPEED_PERCENT: u8 = 10;

/// A joint's maximum speed where the profile gives none (deg/s): a stated default
/// below every joint speed the built-in profiles cite (the lowest is 156°/s, KUKA
/// KR 16-2 axes 1-3), so that the time is not underestimated.
pub const DEFAULT_JOINT_SPEED_DEG_S: f64 = 90.0;

/// Every joint's acceleration (deg/s²): 1.2 rad/s², the joint acceleration RoboDK's
/// UR post-processor uses by default (docs/controllers/ur.md [U10]). No source gives
/// these robots' joint accelerations: a stated default. At the reduced speed a ramp
/// lasts `v/a`, about 0.2 s on a 150°/s joint at 10 %.
pub const DEFAULT_ACCEL_DEG_S2: f64 = 1.2 * 180.0 / std::f64::consts::PI;

/// From the robot's stop to the start of the pendant's still window (s): a stated
/// default. No public source gives these arms' settling after a stop at reduced speed
/// to the pendant's 0.05° peak-to-peak; the pendant's `settling NN%` screen measures
/// it, and `--settle-s` takes the measured figure.
pub const DEFAULT_SETTLE_S: f64 = 1.0;

/// Each of the pendant's three mountings (s): clipping it to the upper arm, moving it
/// to the flange, taking it off to the bench for the closing reversal. A stated
/// default.
pub const DEFAULT_REMOUNT_S: f64 = 60.0;

/// An operator's OK on the pendant at a stop of the program, and the restart (s): a
/// stated default.
pub const OPERATOR_OK_S: f64 = 10.0;

/// How far below a pose every joint starts the last move to the pose's first capture
/// (deg): a stated default, 50× the order of gear backlash named in the controller
/// leads (0.01-0.02°, calibration-practice leads, not verified against a source).
pub const APPROACH_DEG: f64 = 1.0;

/// How far above a pose every joint goes before coming back to it for the pose's
/// second capture (deg). The excursion must also re-arm the pendant: move its reading
/// by [`ARM_MARGIN`] × its 0.2° re-arm threshold, 0.4°. 4° does at every pose of every
/// built-in profile's default plan and at stage 1; the smallest change is 0.49° (a
/// FANUC M-20iA pose, whose J2/J3 coupling moves the forearm little when J2 and J3 turn
/// together), against 0.36° at 3° and 0.23° at 2° (`overshoot_rearms_every_builtin_plan`).
/// Where a plan of the user's is not re-armed, the program stops for an OK instead.
pub const OVERSHOOT_DEG: f64 = 4.0;

/// The pendant's sensor period (s): the SCL3300 is read at 20 Hz (the project's decision:
/// 40 samples of its 10 Hz output make one 2 s capture; core's `MEMS_CAPTURE_NOISE_DEG`).
pub const SAMPLE_PERIOD_S: f64 = 0.05;

/// A move arms the next capture if the predicted reading leaves the last capture by
/// this many times the pendant's re-arm threshold: the margin covers the offsets not
/// yet known and the sensor's gain errors (stated).
pub const ARM_MARGIN: f64 = 2.0;

/// A stretch of a move as long as the still window whose predicted readings stay
/// within this many times the stillness threshold could be captured before the robot
/// arrives (stated margin, for the arm's vibration and the sensor noise).
pub const EARLY_STILL_MARGIN: f64 = 2.0;

/// How far a mounting pose turns joint 2 from the stage-1 pose (deg): enough to tilt
/// the pendant past its range on the upper arm and on the flange (stated).
pub const MOUNT_TURN_DEG: f64 = 45.0;

/// A mounting pose's predicted reading must be at least this far past the sensor's
/// range, mode 4's ±10° (deg; stated margin for the base tilt, the sensor's offset and
/// the bracket's seating).
pub const MOUNT_MARGIN_DEG: f64 = 5.0;

/// Longest time one move of a session may take (s): a stated bound. The pendant's
/// capture rule is checked along every move at the sensor's 20 Hz
/// ([`SAMPLE_PERIOD_S`]), so this bounds that check to [`MAX_MOVE_SAMPLES`] readings
/// a move; a move across a joint's whole range that takes longer comes from a speed
/// too low for a session (a profile's figure in the wrong unit, or a tiny
/// `--speed-percent`), and is refused before anything is planned.
pub const MAX_MOVE_S: f64 = 600.0;

/// Readings of the capture rule's check along one move at most: [`MAX_MOVE_S`] at
/// [`SAMPLE_PERIOD_S`].
pub const MAX_MOVE_SAMPLES: usize = (MAX_MOVE_S / SAMPLE_PERIOD_S) as usize;

/// The session options `zerocal plan` and `zerocal program` share.
#[derive(Args, Debug, Clone)]
pub struct TimingArgs {
    /// Joint speed of every move, percent of each joint's maximum speed (the
    /// profile's; 90 deg/s where it gives none). Range: [1, 100].
    #[arg(long, default_value_t = DEFAULT_SPEED_PERCENT, value_parser = CountIn::<u8>::new(1, 100))]
    pub speed_percent: u8,
    /// Settling of the arm after a stop, before the pendant's 2 s still window starts
    /// (s; stated default, measure it on the pendant's `settling` screen).
    /// Range: [0, 60] s.
    #[arg(long, default_value_t = DEFAULT_SETTLE_S, value_parser = RealIn::closed(0.0, 60.0, "s"))]
    pub settle_s: f64,
    /// Time for each of the pendant's three mountings (clipped to the upper arm, moved
    /// to the flange, taken off to the bench for the closing reversal) (s; stated
    /// default). Range: [0, 3600] s.
    #[arg(long, default_value_t = DEFAULT_REMOUNT_S, value_parser = RealIn::closed(0.0, 3600.0, "s"))]
    pub remount_s: f64,
}

impl Default for TimingArgs {
    fn default() -> Self {
        TimingArgs {
            speed_percent: DEFAULT_SPEED_PERCENT,
            settle_s: DEFAULT_SETTLE_S,
            remount_s: DEFAULT_REMOUNT_S,
        }
    }
}

/// Where a joint's maximum speed comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SpeedSource {
    /// The profile's `max_speed_deg_s` (with its source).
    Profile,
    /// Not given: [`DEFAULT_JOINT_SPEED_DEG_S`].
    StatedDefault,
}

/// The session's poses in the controller's joint degrees.
///
/// The pendant captures by itself once it has moved and then stays still (core's
/// procedure): clipped on at a pose it reads within its range, it would capture that
/// pose before the robot goes where the session wants it. So the robot stands at a
/// *mounting pose* while the pendant is clipped on or taken off, a pose that tilts the
/// pendant past its range ([`mount_poses`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SessionPoses {
    /// Where the pendant is clipped to the upper arm.
    pub mount1: [f64; JOINTS],
    /// The stage-1 pose.
    pub stage1: [f64; JOINTS],
    /// The same with joint 1 turned by 180° (in the model's direction).
    pub turned: [f64; JOINTS],
    /// Where the pendant is moved to the flange.
    pub mount2: [f64; JOINTS],
    /// The stage-2 poses, in the plan's order.
    pub poses: Vec<[f64; JOINTS]>,
    /// Where the robot parks while the pendant is taken off for the closing reversal:
    /// the flange's mounting pose (the operator reached the flange there, and the
    /// pendant reads past its range there, so it cannot capture while it is taken off).
    pub park: [f64; JOINTS],
}

impl SessionPoses {
    /// From model angles (rad) through the profile's controller conventions; the
    /// mounting poses are set by [`with_mounts`](Self::with_mounts).
    pub fn new(profile: &Profile, poses_rad: &[[f64; JOINTS]]) -> Self {
        let q1 = profile.stage1_joints_rad;
        let mut turned = q1;
        turned[0] += std::f64::consts::PI;
        let stage1 = profile.shown_deg(&q1);
        let poses: Vec<[f64; JOINTS]> = poses_rad.iter().map(|q| profile.shown_deg(q)).collect();
        let first = poses.first().copied().unwrap_or(stage1);
        SessionPoses {
            mount1: stage1,
            stage1,
            turned: profile.shown_deg(&turned),
            mount2: first,
            poses,
            park: first,
        }
    }

    /// The same with the mounting poses ([`mount_poses`]); the robot parks at the
    /// flange's.
    ///
    /// # Errors
    /// No mounting pose inside the joint limits tilts the pendant past its range.
    pub fn with_mounts(mut self, profile: &Profile) -> Result<Self, CliError> {
        (self.mount1, self.mount2) = mount_poses(&Pendant::new(profile), &self)?;
        self.park = self.mount2;
        Ok(self)
    }

    /// The same poses in another order (indices into `poses`), the flange's mounting
    /// pose following the new first pose.
    ///
    /// # Errors
    /// As [`with_mounts`](Self::with_mounts).
    pub fn reordered(&self, profile: &Profile, order: &[usize]) -> Result<Self, CliError> {
        let mut s = self.clone();
        s.poses = order
            .iter()
            .filter_map(|&i| self.poses.get(i).copied())
            .collect();
        s.with_mounts(profile)
    }

    /// Core's view of the session.
    pub fn path(&self) -> SessionPath<'_, f64> {
        SessionPath {
            mount1: self.mount1,
            stage1: self.stage1,
            turned: self.turned,
            mount2: self.mount2,
            poses: &self.poses,
            park: self.park,
        }
    }

    /// Every pose the pendant captures at, once each (each is captured twice): stage 1's
    /// two, then stage 2's, with what each is.
    pub fn capture_poses(&self) -> Vec<(String, [f64; JOINTS])> {
        let mut v = vec![
            ("the stage-1 pose".to_owned(), self.stage1),
            (
                "the stage-1 pose with joint 1 turned by 180 deg".to_owned(),
                self.turned,
            ),
        ];
        v.extend(
            self.poses
                .iter()
                .enumerate()
                .map(|(i, q)| (format!("stage-2 pose {}", i + 1), *q)),
        );
        v
    }
}

/// The time model of a session on `profile`.
#[derive(Clone, Debug, PartialEq)]
pub struct Timing {
    /// Core's model.
    pub model: TimeModel<f64>,
    /// Each joint's maximum speed (deg/s) before the reduction.
    pub max_speed_deg_s: [f64; JOINTS],
    /// Where each comes from.
    pub speed_source: [SpeedSource; JOINTS],
    /// The reduction (%).
    pub speed_percent: u8,
}

impl Timing {
    /// The model for `profile` with the options.
    ///
    /// # Errors
    /// A setting core's model refuses (cannot come from the options' ranges).
    pub fn new(profile: &Profile, args: &TimingArgs) -> Result<Self, CliError> {
        let mut max_speed_deg_s = [DEFAULT_JOINT_SPEED_DEG_S; JOINTS];
        let mut speed_source = [SpeedSource::StatedDefault; JOINTS];
        for (k, j) in profile.joints.iter().enumerate().take(JOINTS) {
            if let Some(v) = j.max_speed_deg_s {
                max_speed_deg_s[k] = v;
                speed_source[k] = SpeedSource::Profile;
            }
        }
        let fraction = f64::from(args.speed_percent) / 100.0;
        let stillness = StillnessConfig::<f64>::default();
        let model = TimeModel {
            speed_deg_s: max_speed_deg_s.map(|v| v * fraction),
            accel_deg_s2: [DEFAULT_ACCEL_DEG_S2; JOINTS],
            approach_deg: APPROACH_DEG,
            overshoot_deg: OVERSHOOT_DEG,
            settle_s: args.settle_s,
            window_s: f64::from(stillness.window_ms) / 1000.0,
            sample_period_s: SAMPLE_PERIOD_S,
            remount_s: args.remount_s,
            operator_ok_s: OPERATOR_OK_S,
        };
        model
            .validate()
            .map_err(|e| CliError::Input(format!("time model: {e}")))?;
        for (k, max_speed) in max_speed_deg_s.iter().enumerate() {
            let range = |j: usize| {
                profile
                    .joints
                    .get(j)
                    .map_or(0.0, |info| info.max_deg - info.min_deg)
            };
            // The controller's J3 of a coupled display moves with J2 as well.
            let coupled = k == 2 && profile.controller.coupling == Coupling::J3MinusJ2;
            let across =
                range(k) + if coupled { range(1) } else { 0.0 } + APPROACH_DEG + OVERSHOOT_DEG;
            let t = model.joint_move_s(k, across);
            if t.is_nan() || t > MAX_MOVE_S {
                return Err(CliError::Input(format!(
                    "{}: at {} % of {} deg/s a move across its limits ({across:.0} deg) takes {t:.0} s, longer than the {MAX_MOVE_S} s a session's move may take; raise --speed-percent or check the profile's max_speed_deg_s",
                    joint_label(profile, k),
                    args.speed_percent,
                    max_speed
                )));
            }
        }
        Ok(Timing {
            model,
            max_speed_deg_s,
            speed_source,
            speed_percent: args.speed_percent,
        })
    }
}

/// Names a joint as the profile does, with its number.
pub fn joint_label(profile: &Profile, k: usize) -> String {
    match profile.joints.get(k) {
        Some(j) if j.name != format!("J{}", k + 1) => format!("{} (joint {})", j.name, k + 1),
        _ => format!("joint {}", k + 1),
    }
}

/// Refuses a point (controller degrees) outside the profile's joint limits, naming
/// the joint, its value and the limits (exit status 3).
///
/// # Errors
/// The first joint outside its limits.
pub fn check_limits(
    profile: &Profile,
    point_deg: &[f64; JOINTS],
    what: &str,
) -> Result<(), CliError> {
    let model = profile.model_rad(point_deg);
    if let Some((joint, value, lo, hi)) = profile.outside_limits(&model) {
        return Err(CliError::Refused(format!(
            "{what}: {} at {value:.3} deg (model angle) is outside its limits {lo}..{hi} deg of profile {}; nothing was written",
            joint_label(profile, joint - 1),
            profile.name
        )));
    }
    Ok(())
}

/// Refuses a capture pose without room on both sides of the backlash: the point
/// [`APPROACH_DEG`] below it and the point [`OVERSHOOT_DEG`] above it on every joint
/// must be inside the limits, or that pose cannot be captured from both sides.
///
/// # Errors
/// The first such pose, naming the side, the joint, its value and the limits.
pub fn check_room(profile: &Profile, poses: &SessionPoses) -> Result<(), CliError> {
    for (what, q) in poses.capture_poses() {
        check_limits(profile, &q, &what)?;
        for (side, d) in [("below", -APPROACH_DEG), ("above", OVERSHOOT_DEG)] {
            let p = q.map(|v| v + d);
            check_limits(
                profile,
                &p,
                &format!(
                    "{what} cannot be captured from {side} (every pose is captured from both sides of the backlash, reached from {} deg {side} on every joint)",
                    d.abs()
                ),
            )?;
        }
    }
    Ok(())
}

/// The limits (model degrees) of joints 3-6 the planner keeps its poses inside:
/// `limits_deg` less the room the two captures of a pose need, the model angles the
/// approach from [`APPROACH_DEG`] below and the overshoot to [`OVERSHOOT_DEG`] above
/// (controller degrees, on every joint) reach through the profile's signs and
/// coupling. So every planned pose passes [`check_room`] on joints 3-6 (joints 1 and
/// 2 stand at the stage-1 pose, which the planner does not choose).
pub fn planner_limits(
    profile: &Profile,
    limits_deg: &[(f64, f64); WRIST_JOINTS],
) -> [(f64, f64); WRIST_JOINTS] {
    let origin = profile.model_rad(&[0.0; JOINTS]);
    let mut below = [0.0f64; WRIST_JOINTS];
    let mut above = [0.0f64; WRIST_JOINTS];
    for d in [-APPROACH_DEG, OVERSHOOT_DEG] {
        let m = profile.model_rad(&[d; JOINTS]);
        for k in 0..WRIST_JOINTS {
            let change = (m[k + 2] - origin[k + 2]).to_degrees();
            above[k] = above[k].max(change);
            below[k] = below[k].max(-change);
        }
    }
    core::array::from_fn(|k| (limits_deg[k].0 + below[k], limits_deg[k].1 - above[k]))
}

/// The two mounting poses, each inside the joint limits and tilting the pendant at
/// least [`MOUNT_MARGIN_DEG`] past mode 4's ±10°, so that it cannot capture there:
///
/// - for the upper arm, the stage-1 pose with joint 2 turned by [`MOUNT_TURN_DEG`]
///   (downwards first);
/// - for the flange, the first stage-2 pose with joint 2 where the first mounting
///   pose has it, and if that leaves the flange within the range, joint 5, 3, 4 or 6
///   turned by as much too. The pendant is moved from the upper arm to the flange there: both
///   places read past the range, so it can capture neither before it is on the flange (its last reading on the
///   upper arm could otherwise look like a still pose once the half turn has moved it
///   by the base tilt).
///
/// # Errors
/// No such pair inside the limits, naming joint 2.
pub fn mount_poses(
    pendant: &Pendant<'_>,
    s: &SessionPoses,
) -> Result<([f64; JOINTS], [f64; JOINTS]), CliError> {
    let profile = pendant.profile;
    let range = MEMS_RANGE_DEG + MOUNT_MARGIN_DEG;
    let past = |t: Tilt<f64>| t.x_rad.to_degrees().abs().max(t.y_rad.to_degrees().abs()) > range;
    let inside = |q: &[f64; JOINTS]| profile.outside_limits(&profile.model_rad(q)).is_none();
    let first = s.poses.first().copied().unwrap_or(s.stage1);
    // Joint 2 alone, then with joint 5, 3, 4 or 6 turned as well (a controller whose
    // joint 3 is measured from the horizontal, FANUC's, keeps the forearm's tilt when
    // joint 2 alone turns).
    let extra: [Option<(usize, f64)>; 9] = [
        None,
        Some((4, -1.0)),
        Some((4, 1.0)),
        Some((2, -1.0)),
        Some((2, 1.0)),
        Some((3, -1.0)),
        Some((3, 1.0)),
        Some((5, -1.0)),
        Some((5, 1.0)),
    ];
    for sign in [-1.0, 1.0] {
        let mut m1 = s.stage1;
        m1[1] += sign * MOUNT_TURN_DEG;
        if !(inside(&m1) && past(pendant.upper_reading(&m1))) {
            continue;
        }
        for e in extra {
            let mut m2 = first;
            m2[1] = m1[1];
            if let Some((k, s)) = e {
                m2[k] += s * MOUNT_TURN_DEG;
            }
            if inside(&m2) && past(pendant.upper_reading(&m2)) && past(pendant.reading(&m2)) {
                return Ok((m1, m2));
            }
        }
    }
    Err(CliError::Refused(format!(
        "no mounting poses: {} turned {MOUNT_TURN_DEG} deg either way from the stage-1 pose (with the first stage-2 pose's joints 3-6, one of them turned as much, for the flange) leaves the limits or keeps the pendant within {range:.0} deg; nothing was written",
        joint_label(profile, 1)
    )))
}

/// The pendant's view of a path: whether it arms the next capture, and whether a
/// stretch of it looks still long enough to be captured before the robot arrives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegCheck {
    /// The predicted reading leaves the last capture by the re-arm threshold (with
    /// [`ARM_MARGIN`]).
    pub armed: bool,
    /// After arming, a stretch as long as the still window stays within the stillness
    /// threshold (with [`EARLY_STILL_MARGIN`]) before the robot arrives.
    pub early_still: bool,
    /// The largest change of the predicted reading from the last capture along the
    /// path, either axis (deg).
    pub largest_change_deg: f64,
}

/// The pendant as the planner sees it: readings predicted at zero offsets on a level
/// base, in the SCL3300's `axis` convention, on the flange or on the upper arm.
#[derive(Clone, Debug)]
pub struct Pendant<'a> {
    profile: &'a Profile,
    model: Stage2Model<f64>,
    rearm_rad: f64,
    still_rad: f64,
}

/// Position along a synchronised move of duration `total_s` at time `t`, as a
/// fraction of the move, for the slowest joint's trapezoid (speed `v`, acceleration
/// `a`, distance `d`).
fn fraction_at(t: f64, total_s: f64, v: f64, a: f64, d: f64) -> f64 {
    if d <= 0.0 || total_s <= 0.0 {
        return 1.0;
    }
    let ramp = if d >= v * v / a { v / a } else { total_s / 2.0 };
    let peak = a * ramp;
    let x = if t <= ramp {
        0.5 * a * t * t
    } else if t <= total_s - ramp {
        0.5 * a * ramp * ramp + peak * (t - ramp)
    } else {
        let r = (total_s - t).max(0.0);
        d - 0.5 * a * r * r
    };
    (x / d).clamp(0.0, 1.0)
}

impl<'a> Pendant<'a> {
    /// The pendant on `profile`.
    pub fn new(profile: &'a Profile) -> Self {
        let procedure = ProcedureConfig::<f64>::default();
        Pendant {
            profile,
            model: Stage2Model {
                arm: profile.arm,
                base_tilt: BaseTilt::level(),
                sensor: SensorModel::new(Convention::Axis, Tilt::default()),
                ..Stage2Model::default()
            },
            rearm_rad: procedure.rearm_motion_rad,
            still_rad: procedure.stillness.max_peak_to_peak_rad,
        }
    }

    /// The predicted reading of the pendant on the upper arm (stage 1's mounting) at
    /// a pose in controller degrees (rad).
    pub fn upper_reading(&self, pose_deg: &[f64; JOINTS]) -> Tilt<f64> {
        let q = self.profile.model_rad(pose_deg);
        let r = self
            .profile
            .arm
            .upper_arm_sensor(&BaseTilt::level(), q[0], q[1]);
        Convention::Axis.read(&zerocal_core::model::up_in_sensor(&r))
    }

    /// The predicted reading of the pendant on the flange at a pose in controller
    /// degrees (rad).
    pub fn reading(&self, pose_deg: &[f64; JOINTS]) -> Tilt<f64> {
        self.model
            .predict(&self.profile.model_rad(pose_deg), &[0.0; 4])
    }

    /// The predicted reading where the pendant is mounted.
    pub fn reading_on(&self, mounting: Mounting, pose_deg: &[f64; JOINTS]) -> Tilt<f64> {
        match mounting {
            Mounting::UpperArm => self.upper_reading(pose_deg),
            Mounting::Flange => self.reading(pose_deg),
        }
    }

    /// Readings every sensor period along one move (the last sample at arrival).
    fn samples(
        &self,
        time: &TimeModel<f64>,
        mounting: Mounting,
        from: &[f64; JOINTS],
        to: &[f64; JOINTS],
        out: &mut Vec<Tilt<f64>>,
    ) {
        let total = time.move_s(from, to);
        // The joint that takes longest sets the profile the others follow.
        let (mut slow, mut slow_t) = (0, -1.0);
        for k in 0..JOINTS {
            let t = time.joint_move_s(k, to[k] - from[k]);
            if t > slow_t {
                (slow, slow_t) = (k, t);
            }
        }
        let d = (to[slow] - from[slow]).abs();
        let (v, a) = (time.speed_deg_s[slow], time.accel_deg_s2[slow]);
        // Timing::new bounds every move to MAX_MOVE_S; the bound here keeps a model
        // built otherwise from allocating without end (its samples then spread out).
        let needed = (total / time.sample_period_s).ceil().max(1.0);
        let steps = (needed as usize).clamp(1, MAX_MOVE_SAMPLES);
        let dt = if needed > steps as f64 {
            total / steps as f64
        } else {
            time.sample_period_s
        };
        for i in 1..=steps {
            let t = (i as f64 * dt).min(total);
            let s = fraction_at(t, total, v, a, d);
            let p: [f64; JOINTS] = core::array::from_fn(|k| from[k] + (to[k] - from[k]) * s);
            out.push(self.reading_on(mounting, &p));
        }
    }

    /// What the pendant makes of driving `path` (the moves through its points in
    /// turn), its first point being where it last captured.
    pub fn leg(
        &self,
        time: &TimeModel<f64>,
        mounting: Mounting,
        path: &[[f64; JOINTS]],
    ) -> LegCheck {
        let mut samples = Vec::new();
        for w in path.windows(2) {
            self.samples(time, mounting, &w[0], &w[1], &mut samples);
        }
        let Some(start) = path.first() else {
            return LegCheck {
                armed: false,
                early_still: false,
                largest_change_deg: 0.0,
            };
        };
        let last = self.reading_on(mounting, start);
        let change = |r: &Tilt<f64>| {
            let m = r.minus(&last);
            m.x_rad.abs().max(m.y_rad.abs())
        };
        let largest_change_deg = samples.iter().map(change).fold(0.0, f64::max).to_degrees();
        let arm_at = samples
            .iter()
            .position(|r| change(r) > ARM_MARGIN * self.rearm_rad);
        let Some(arm_at) = arm_at else {
            return LegCheck {
                armed: false,
                early_still: false,
                largest_change_deg,
            };
        };
        // Samples spanning the still window, all within the threshold, before arrival.
        let span = (time.window_s / time.sample_period_s).ceil() as usize + 1;
        let limit = EARLY_STILL_MARGIN * self.still_rad;
        let before_arrival = samples.len().saturating_sub(1);
        let early_still = (arm_at..before_arrival.saturating_sub(span - 1)).any(|i| {
            let w = &samples[i..i + span];
            let (lo_x, hi_x, lo_y, hi_y) = w.iter().fold(
                (
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                ),
                |(a, b, c, d), r| {
                    (
                        a.min(r.x_rad),
                        b.max(r.x_rad),
                        c.min(r.y_rad),
                        d.max(r.y_rad),
                    )
                },
            );
            hi_x - lo_x <= limit && hi_y - lo_y <= limit
        });
        LegCheck {
            armed: true,
            early_still,
            largest_change_deg,
        }
    }
}

/// Penalty (s) in the tour's costs for a move that could be captured early: high
/// enough that the tour avoids it whenever an order exists that does.
const EARLY_PENALTY_S: f64 = 1e6;

/// The order of the stage-2 poses that makes the session short (core's
/// [`shortest_tour`] on the robot times from one pose's second capture to the next
/// pose's first, an operator's OK where that does not arm the next capture, and moves
/// that could be captured early avoided): indices into `poses.poses`.
pub fn time_order(
    pendant: &Pendant<'_>,
    time: &TimeModel<f64>,
    poses: &SessionPoses,
) -> Vec<usize> {
    let n = poses.poses.len();
    let leg = |a: &[f64; JOINTS], b: &[f64; JOINTS]| {
        let path = time.first_capture_path(a, b);
        let check = pendant.leg(time, Mounting::Flange, &path);
        let mut c = time.path_s(&path);
        if !check.armed {
            c += time.operator_ok_s;
        }
        if check.early_still {
            c += EARLY_PENALTY_S;
        }
        c
    };
    // The robot comes from stage 1's turned pose (through the flange's mounting pose,
    // a turn of one joint away from the first pose, about the same for any).
    let start: Vec<f64> = poses
        .poses
        .iter()
        .map(|q| time.path_s(&time.first_capture_path(&poses.turned, q)))
        .collect();
    let cost: Vec<Vec<f64>> = poses
        .poses
        .iter()
        .map(|a| poses.poses.iter().map(|b| leg(a, b)).collect())
        .collect();
    shortest_tour(
        n,
        |i| start.get(i).copied().unwrap_or(0.0),
        |i, j| cost.get(i).and_then(|r| r.get(j)).copied().unwrap_or(0.0),
    )
    .iter()
    .map(|&i| usize::from(i))
    .collect()
}

/// The robot time of a session in the given order.
pub fn session_time(
    pendant: &Pendant<'_>,
    time: &TimeModel<f64>,
    poses: &SessionPoses,
) -> SessionTime<f64> {
    time.session_time(&poses.path(), |m, p| !pendant.leg(time, m, p).armed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn synchronised_profile_runs_from_zero_to_one() {
        // 10° at 5°/s with 50°/s²: ramps of 0.1 s, 2.1 s in all.
        let total = 10.0 / 5.0 + 5.0 / 50.0;
        assert_eq!(fraction_at(0.0, total, 5.0, 50.0, 10.0), 0.0);
        assert!((fraction_at(total, total, 5.0, 50.0, 10.0) - 1.0).abs() < 1e-12);
        // Half way in time is half way in distance (the profile is symmetric).
        assert!((fraction_at(total / 2.0, total, 5.0, 50.0, 10.0) - 0.5).abs() < 1e-12);
        let mut last = 0.0;
        for i in 0..=100 {
            let s = fraction_at(total * f64::from(i) / 100.0, total, 5.0, 50.0, 10.0);
            assert!(s >= last);
            last = s;
        }
    }

    /// A move of a few hundredths of a degree cannot arm the pendant (its re-arm
    /// threshold is 0.2°, here with a factor 2); a 20° turn of A5 does, and moves the
    /// reading all the way, so nothing looks still before the robot arrives.
    #[test]
    fn small_moves_do_not_arm_the_next_capture() {
        let profile = zerocal_profile::builtin("kuka-kr16").unwrap_or_else(|e| panic!("{e}"));
        let t = Timing::new(&profile, &TimingArgs::default()).unwrap_or_else(|e| panic!("{e}"));
        let pendant = Pendant::new(&profile);
        let mut a = profile.shown_deg(&profile.stage1_joints_rad);
        a[2] = -90.0;
        let mut b = a;
        b[5] += 0.05;
        let f = Mounting::Flange;
        assert!(!pendant.leg(&t.model, f, &[a, b]).armed);
        b = a;
        b[4] += 20.0;
        let check = pendant.leg(&t.model, f, &[a, b]);
        assert!(check.armed && !check.early_still, "{check:?}");
        assert!(
            pendant
                .leg(&t.model, f, &t.model.first_capture_path(&b, &a))
                .armed
        );
        // Out and back by a few hundredths: not armed either.
        let mut c = a;
        c[4] += 0.05;
        assert!(!pendant.leg(&t.model, f, &[a, c, a]).armed);
    }

    /// The overshoot re-arms the pendant between the two captures of every pose of
    /// every built-in profile's default plan, and at stage 1 (on the upper arm): the
    /// reading leaves the first capture by more than twice the 0.2° re-arm threshold,
    /// with nothing still for a window before the robot is back. Smaller overshoots
    /// would not do everywhere: the smallest change at each is printed.
    #[test]
    fn overshoot_rearms_every_builtin_plan() {
        let figures = [1.0, 2.0, 3.0, OVERSHOOT_DEG];
        let mut smallest: [(f64, String); 4] =
            core::array::from_fn(|_| (f64::INFINITY, String::new()));
        for name in zerocal_profile::builtin_names() {
            let profile = zerocal_profile::builtin(name).unwrap_or_else(|e| panic!("{e}"));
            let plan = match crate::program::default_plan(name, &TimingArgs::default()) {
                Ok(p) => p,
                // The planner refuses the UR5e (joints 2-4 parallel).
                Err(_) if name == "ur5e" => continue,
                Err(e) => panic!("{name}: {e}"),
            };
            let t = Timing::new(&profile, &TimingArgs::default()).unwrap_or_else(|e| panic!("{e}"));
            let pendant = Pendant::new(&profile);
            let poses = SessionPoses::new(&profile, &plan);
            let cases = [
                (Mounting::UpperArm, poses.stage1),
                (Mounting::UpperArm, poses.turned),
            ]
            .into_iter()
            .chain(poses.poses.iter().map(|q| (Mounting::Flange, *q)));
            for (i, (m, q)) in cases.enumerate() {
                let what = match i {
                    0 => format!("{name} stage 1"),
                    1 => format!("{name} stage 1 turned"),
                    _ => format!("{name} stage-2 pose {}", i - 1),
                };
                for (f, low) in figures.iter().zip(smallest.iter_mut()) {
                    let mut model = t.model;
                    model.overshoot_deg = *f;
                    let c = pendant.leg(&model, m, &model.second_capture_path(&q));
                    if c.largest_change_deg < low.0 {
                        *low = (c.largest_change_deg, what.clone());
                    }
                    if *f == OVERSHOOT_DEG {
                        assert!(c.armed && !c.early_still, "{what}: {c:?}");
                    }
                }
            }
        }
        for (f, (d, at)) in figures.iter().zip(&smallest) {
            println!("overshoot {f} deg: smallest reading change {d:.3} deg ({at})");
        }
        // Re-armed at the chosen figure, not at 3°.
        assert!(smallest[3].0 > ARM_MARGIN * 0.2, "{:?}", smallest[3]);
        assert!(
            smallest[2].0 <= ARM_MARGIN * 0.2 * 1.2,
            "{:?}: 3 deg would do",
            smallest[2]
        );
    }

    /// The planner's limits leave the approach's and the overshoot's room, through the
    /// controller's signs and coupling: a pose at a shrunk limit has its two points at
    /// the profile's limit at most.
    #[test]
    fn planner_limits_leave_room_for_both_sides() {
        for name in ["kuka-kr16", "fanuc-m20ia", "abb-irb140"] {
            let profile = zerocal_profile::builtin(name).unwrap_or_else(|e| panic!("{e}"));
            let full: [(f64, f64); WRIST_JOINTS] = core::array::from_fn(|k| {
                (profile.joints[k + 2].min_deg, profile.joints[k + 2].max_deg)
            });
            let shrunk = planner_limits(&profile, &full);
            for k in 0..WRIST_JOINTS {
                // At least the approach and the overshoot, at most twice (J2/J3 coupled).
                let (lo, hi) = (shrunk[k].0 - full[k].0, full[k].1 - shrunk[k].1);
                assert!(
                    (APPROACH_DEG - 1e-9..=2.0 * OVERSHOOT_DEG + 1e-9).contains(&lo)
                        && (APPROACH_DEG - 1e-9..=2.0 * OVERSHOOT_DEG + 1e-9).contains(&hi),
                    "{name} j{}: {lo} {hi}",
                    k + 3
                );
            }
            // Every corner of the shrunk box, at the stage-1 joints 1-2, has room.
            for corner in 0..16u32 {
                let mut q = profile.stage1_joints_rad;
                for k in 0..WRIST_JOINTS {
                    let (lo, hi) = shrunk[k];
                    q[k + 2] = if corner >> k & 1 == 1 { hi } else { lo }.to_radians();
                }
                let shown = profile.shown_deg(&q);
                for d in [-APPROACH_DEG, OVERSHOOT_DEG] {
                    let m = profile.model_rad(&shown.map(|v| v + d));
                    for (k, (q, j)) in m.iter().zip(&profile.joints).enumerate().skip(2) {
                        let v = q.to_degrees();
                        assert!(
                            v >= j.min_deg - 1e-9 && v <= j.max_deg + 1e-9,
                            "{name} corner {corner} j{}: {v}",
                            k + 1
                        );
                    }
                }
            }
        }
    }

    /// A speed at which a move across a joint's range would take longer than
    /// [`MAX_MOVE_S`] is refused naming the joint and what to change; the slowest
    /// accepted move's check takes at most [`MAX_MOVE_SAMPLES`] readings.
    #[test]
    fn moves_longer_than_the_bound_are_refused() {
        // No built-in profile is refused, at the lowest --speed-percent either.
        for name in zerocal_profile::builtin_names() {
            let profile = zerocal_profile::builtin(name).unwrap_or_else(|e| panic!("{e}"));
            let args = TimingArgs {
                speed_percent: 1,
                ..TimingArgs::default()
            };
            assert!(Timing::new(&profile, &args).is_ok(), "{name}");
        }
        let mut profile = zerocal_profile::builtin("kuka-kr16").unwrap_or_else(|e| panic!("{e}"));
        // A5 at 0.2 deg/s (inside the profile's plausible range), 1 %: 0.002 deg/s.
        profile.joints[4].max_speed_deg_s = Some(0.2);
        let slow = TimingArgs {
            speed_percent: 1,
            ..TimingArgs::default()
        };
        let e = Timing::new(&profile, &slow).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        let m = e.to_string();
        assert!(
            m.contains("A5 (joint 5)") && m.contains("--speed-percent") && m.contains("600 s"),
            "{m}"
        );
        // The slowest speed accepted for A5's 265 deg (limits, approach, overshoot): the
        // move's check stays within the bound.
        let across = profile.joints[4].max_deg - profile.joints[4].min_deg + 5.0;
        profile.joints[4].max_speed_deg_s = Some(100.0 * across / (MAX_MOVE_S - 1.0));
        let t = Timing::new(&profile, &slow).unwrap_or_else(|e| panic!("{e}"));
        let pendant = Pendant::new(&profile);
        let mut a = profile.shown_deg(&profile.stage1_joints_rad);
        a[4] = profile.joints[4].min_deg;
        let mut b = a;
        b[4] = profile.joints[4].max_deg;
        let mut samples = Vec::new();
        pendant.samples(&t.model, Mounting::Flange, &a, &b, &mut samples);
        assert!(
            samples.len() <= MAX_MOVE_SAMPLES && samples.len() > MAX_MOVE_SAMPLES / 2,
            "{}",
            samples.len()
        );
    }

    #[test]
    fn a_pose_without_room_on_one_side_is_refused() {
        let profile = zerocal_profile::builtin("kuka-kr16").unwrap_or_else(|e| panic!("{e}"));
        let mut poses = SessionPoses::new(&profile, &[profile.stage1_joints_rad]);
        assert!(check_room(&profile, &poses).is_ok());
        // A5 at -129.5: 1 deg below it is past the -130 limit.
        poses.poses[0][4] = -129.5;
        let e = check_room(&profile, &poses).unwrap_err();
        assert_eq!(e.exit_code(), 3);
        let m = e.to_string();
        assert!(
            m.contains("stage-2 pose 1")
                && m.contains("from below")
                && m.contains("A5 (joint 5)")
                && m.contains("-130..130"),
            "{m}"
        );
        // At 127 the overshoot reaches 131.
        poses.poses[0][4] = 127.0;
        let m = check_room(&profile, &poses).unwrap_err().to_string();
        assert!(m.contains("from above") && m.contains("131.000"), "{m}");
        // Outside the limits itself: named with its own value.
        poses.poses[0][4] = 131.5;
        let m = check_room(&profile, &poses).unwrap_err().to_string();
        assert!(
            m.starts_with("refused: stage-2 pose 1: A5") && m.contains("131.500"),
            "{m}"
        );
    }
}
