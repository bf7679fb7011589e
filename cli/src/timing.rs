//! The robot side of a session for `zerocal plan` and `zerocal program`: core's
//! robot-time model (`zerocal_core::plan::time`) filled in from a robot profile and
//! the options, the approach directions that keep every target inside the joint
//! limits, and the pendant's capture rule checked along every move.
//!
//! What is a source's figure and what is a stated default:
//!
//! - joint speeds: the profile's `max_speed_deg_s` (each cites its source); where a
//!   profile gives none, [`DEFAULT_JOINT_SPEED_DEG_S`];
//! - joint accelerations: no profile source gives them: [`DEFAULT_ACCEL_DEG_S2`];
//! - the reduced speed, the settling, the remount, an operator's OK and the approach
//!   distance: stated defaults ([`DEFAULT_SPEED_PERCENT`], [`DEFAULT_SETTLE_S`],
//!   [`DEFAULT_REMOUNT_S`], [`OPERATOR_OK_S`], [`APPROACH_DEG`]);
//! - the still window and its threshold, and the move that arms the next capture:
//!   the pendant's own (core's `StillnessConfig` and `ProcedureConfig` defaults);
//!   the sensor period: the pendant's 20 Hz read rate, [`SAMPLE_PERIOD_S`].

use crate::args::{CountIn, RealIn};
use crate::error::CliError;
use clap::Args;
use serde::Serialize;
use zerocal_core::model::{BaseTilt, Convention, SensorModel, Tilt, JOINTS};
use zerocal_core::plan::time::{shortest_tour, SessionPath, SessionTime, TimeModel};
use zerocal_core::procedure::ProcedureConfig;
use zerocal_core::stage2::{FitConfig, Stage2Model};
use zerocal_core::stillness::StillnessConfig;
use zerocal_profile::Profile;

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

/// Clipping the pendant on, at each of its two mountings (the upper arm; from there to
/// the flange) (s): a stated default.
pub const DEFAULT_REMOUNT_S: f64 = 60.0;

/// An operator's OK on the pendant at a stop of the program, and the restart (s): a
/// stated default.
pub const OPERATOR_OK_S: f64 = 10.0;

/// How far short of a target a joint turns round to arrive in its approach direction
/// (deg): a stated default, 50× the order of gear backlash named in the controller
/// leads (0.01-0.02°, `../shared/CONTROLLERS.md`, not verified).
pub const APPROACH_DEG: f64 = 1.0;

/// The pendant's sensor period (s): the SCL3300 is read at 20 Hz (issue 15's decision:
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

/// How far a mounting pose turns one joint from the pose that follows it (deg): enough
/// to tilt the pendant past its range (stated).
pub const MOUNT_TURN_DEG: f64 = 45.0;

/// A mounting pose's predicted reading must be at least this far past the pendant's
/// range (deg; stated margin for the base tilt and the bracket's seating).
pub const MOUNT_MARGIN_DEG: f64 = 5.0;

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
    /// Time to clip the pendant on, at each of its two mountings (the upper arm, then
    /// the flange) (s; stated default). Range: [0, 3600] s.
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
/// pose before the robot goes where the session wants it, and the clipping may push
/// the joints inside their backlash. So the robot stands at a *mounting pose* while
/// the pendant is clipped on, a pose that tilts the pendant past its range (no
/// capture there), then goes to the next capture pose, arriving in the approach
/// direction ([`mount_poses`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SessionPoses {
    /// Where the pendant is clipped to the upper arm.
    pub mount1: [f64; JOINTS],
    /// The stage-1 pose.
    pub stage1: [f64; JOINTS],
    /// The same with joint 1 turned by 180° (in the model's direction).
    pub turned: [f64; JOINTS],
    /// Where the pendant is clipped to the flange.
    pub mount2: [f64; JOINTS],
    /// The stage-2 poses, in the plan's order.
    pub poses: Vec<[f64; JOINTS]>,
}

impl SessionPoses {
    /// From model angles (rad) through the profile's controller conventions; the
    /// mounting poses are set by [`with_mounts`](Self::with_mounts) once the approach
    /// directions are known.
    pub fn new(profile: &Profile, poses_rad: &[[f64; JOINTS]]) -> Self {
        let q1 = profile.stage1_joints_rad;
        let mut turned = q1;
        turned[0] += std::f64::consts::PI;
        let stage1 = profile.shown_deg(&q1);
        let poses: Vec<[f64; JOINTS]> = poses_rad.iter().map(|q| profile.shown_deg(q)).collect();
        SessionPoses {
            mount1: stage1,
            stage1,
            turned: profile.shown_deg(&turned),
            mount2: poses.first().copied().unwrap_or(stage1),
            poses,
        }
    }

    /// The same with the mounting poses ([`mount_poses`]).
    ///
    /// # Errors
    /// No mounting pose inside the joint limits tilts the pendant past its range.
    pub fn with_mounts(
        mut self,
        profile: &Profile,
        approach: &[i8; JOINTS],
    ) -> Result<Self, CliError> {
        (self.mount1, self.mount2) = mount_poses(&Pendant::new(profile), &self, approach)?;
        Ok(self)
    }

    /// The same poses in another order (indices into `poses`), the flange's mounting
    /// pose following the new first pose.
    ///
    /// # Errors
    /// As [`with_mounts`](Self::with_mounts).
    pub fn reordered(
        &self,
        profile: &Profile,
        order: &[usize],
        approach: &[i8; JOINTS],
    ) -> Result<Self, CliError> {
        let mut s = self.clone();
        s.poses = order
            .iter()
            .filter_map(|&i| self.poses.get(i).copied())
            .collect();
        s.with_mounts(profile, approach)
    }

    /// Core's view of the session.
    pub fn path(&self) -> SessionPath<'_, f64> {
        SessionPath {
            mount1: self.mount1,
            stage1: self.stage1,
            turned: self.turned,
            mount2: self.mount2,
            poses: &self.poses,
        }
    }

    /// Every pose the pendant captures at, each reached in the approach direction:
    /// stage 1's two, then stage 2's.
    pub fn captures(&self) -> Vec<[f64; JOINTS]> {
        let mut v = vec![self.stage1, self.turned];
        v.extend_from_slice(&self.poses);
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
    /// The model for `profile` with the options and approach directions.
    ///
    /// # Errors
    /// A setting core's model refuses (cannot come from the options' ranges).
    pub fn new(
        profile: &Profile,
        args: &TimingArgs,
        approach: [i8; JOINTS],
    ) -> Result<Self, CliError> {
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
            approach,
            approach_deg: APPROACH_DEG,
            settle_s: args.settle_s,
            window_s: f64::from(stillness.window_ms) / 1000.0,
            sample_period_s: SAMPLE_PERIOD_S,
            remount_s: args.remount_s,
            operator_ok_s: OPERATOR_OK_S,
        };
        model
            .validate()
            .map_err(|e| CliError::Input(format!("time model: {e}")))?;
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

/// The two mounting poses: the stage-1 pose with joint 2 turned by
/// [`MOUNT_TURN_DEG`] (the upper-arm pendant tilts with it), and the first stage-2
/// pose with joint 5, 3, 4 or 6 turned by as much (the first that fits): each inside
/// the joint limits and tilting the pendant at least [`MOUNT_MARGIN_DEG`] past its
/// range, so that it cannot capture there. The turn goes against the joint's approach
/// direction first, so that the move on to the capture pose arrives the right way.
///
/// # Errors
/// No such pose inside the limits (naming the joints tried).
pub fn mount_poses(
    pendant: &Pendant<'_>,
    s: &SessionPoses,
    approach: &[i8; JOINTS],
) -> Result<([f64; JOINTS], [f64; JOINTS]), CliError> {
    let profile = pendant.profile;
    let range = FitConfig::<f64>::default().sensor_range_rad.to_degrees() + MOUNT_MARGIN_DEG;
    let past = |t: Tilt<f64>| t.x_rad.to_degrees().abs().max(t.y_rad.to_degrees().abs()) > range;
    // The pose and the point short of it on every joint (where a move to it may turn
    // round) inside the limits.
    let inside = |q: &[f64; JOINTS]| {
        let short: [f64; JOINTS] =
            core::array::from_fn(|k| q[k] - f64::from(approach[k]) * APPROACH_DEG);
        [q, &short]
            .iter()
            .all(|p| profile.outside_limits(&profile.model_rad(p)).is_none())
    };
    let find =
        |from: &[f64; JOINTS], joints: &[usize], read: &dyn Fn(&[f64; JOINTS]) -> Tilt<f64>| {
            for &k in joints {
                let back = -f64::from(approach[k]);
                for sign in [back, -back] {
                    let mut q = *from;
                    q[k] += sign * MOUNT_TURN_DEG;
                    if inside(&q) && past(read(&q)) {
                        return Some(q);
                    }
                }
            }
            None
        };
    let names = |joints: &[usize]| {
        joints
            .iter()
            .map(|&k| joint_label(profile, k))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let m1 = find(&s.stage1, &[1], &|q: &[f64; JOINTS]| pendant.upper_reading(q)).ok_or_else(|| {
        CliError::Refused(format!(
            "no mounting pose for the upper arm: {} turned {MOUNT_TURN_DEG} deg either way from the stage-1 pose leaves its limits or keeps the pendant within its {range:.0} deg",
            names(&[1])
        ))
    })?;
    let first = s.poses.first().copied().unwrap_or(s.stage1);
    let order = [4, 2, 3, 5];
    let m2 = find(&first, &order, &|q: &[f64; JOINTS]| pendant.reading(q)).ok_or_else(|| {
        CliError::Refused(format!(
            "no mounting pose for the flange: {} turned {MOUNT_TURN_DEG} deg either way from the first stage-2 pose leaves the limits or keeps the pendant within {range:.0} deg",
            names(&order)
        ))
    })?;
    Ok((m1, m2))
}

/// Each joint's approach direction: +1 (from below) unless a target's approach point
/// on that joint would leave its limits and −1 keeps it inside.
///
/// # Errors
/// A joint whose approach point leaves the limits either way, named with the target,
/// the value and the limits.
pub fn approach_directions(
    profile: &Profile,
    targets: &[[f64; JOINTS]],
) -> Result<[i8; JOINTS], CliError> {
    let mut dirs = [1i8; JOINTS];
    for k in 0..JOINTS {
        let fits = |dir: i8| -> Result<(), CliError> {
            for (i, t) in targets.iter().enumerate() {
                let mut p = *t;
                p[k] -= f64::from(dir) * APPROACH_DEG;
                check_limits(
                    profile,
                    &p,
                    &format!(
                        "the approach to capture pose {} ({APPROACH_DEG} deg short of it on {}, from {})",
                        i + 1,
                        joint_label(profile, k),
                        if dir > 0 { "below" } else { "above" }
                    ),
                )?;
            }
            Ok(())
        };
        match fits(1) {
            Ok(()) => dirs[k] = 1,
            Err(below) => match fits(-1) {
                Ok(()) => dirs[k] = -1,
                Err(_) => return Err(below),
            },
        }
    }
    Ok(dirs)
}

/// The pendant's view of a move: whether it arms the next capture, and whether a
/// stretch of it looks still long enough to be captured before the robot arrives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LegCheck {
    /// The predicted reading leaves the last capture by the re-arm threshold (with
    /// [`ARM_MARGIN`]).
    pub armed: bool,
    /// After arming, a stretch as long as the still window stays within the stillness
    /// threshold (with [`EARLY_STILL_MARGIN`]) before the robot arrives.
    pub early_still: bool,
}

/// The flange pendant as the planner sees it: readings predicted at zero offsets on a
/// level base, in the SCL3300's `axis` convention.
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
    /// The pendant on `profile`'s flange.
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

    /// Readings every sensor period along one move (the last sample at arrival).
    fn samples(
        &self,
        time: &TimeModel<f64>,
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
        let steps = (total / time.sample_period_s).ceil().max(1.0) as usize;
        for i in 1..=steps {
            let t = (i as f64 * time.sample_period_s).min(total);
            let s = fraction_at(t, total, v, a, d);
            let p: [f64; JOINTS] = core::array::from_fn(|k| from[k] + (to[k] - from[k]) * s);
            out.push(self.reading(&p));
        }
    }

    /// What the pendant makes of the move `from` → `to` (through the approach point
    /// if there is one), `from` being where it last captured.
    pub fn leg(&self, time: &TimeModel<f64>, from: &[f64; JOINTS], to: &[f64; JOINTS]) -> LegCheck {
        let mut samples = Vec::new();
        match time.via(from, to) {
            Some(v) => {
                self.samples(time, from, &v, &mut samples);
                self.samples(time, &v, to, &mut samples);
            }
            None => self.samples(time, from, to, &mut samples),
        }
        let last = self.reading(from);
        let arm_at = samples.iter().position(|r| {
            let m = r.minus(&last);
            m.x_rad.abs() > ARM_MARGIN * self.rearm_rad
                || m.y_rad.abs() > ARM_MARGIN * self.rearm_rad
        });
        let Some(arm_at) = arm_at else {
            return LegCheck {
                armed: false,
                early_still: false,
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
        }
    }
}

/// Penalty (s) in the tour's costs for a move that could be captured early: high
/// enough that the tour avoids it whenever an order exists that does.
const EARLY_PENALTY_S: f64 = 1e6;

/// The order of the stage-2 poses that makes the session short (core's
/// [`shortest_tour`] on the legs' robot times, an operator's OK where a move does not
/// arm the next capture, and moves that could be captured early avoided): indices
/// into `poses.poses`.
pub fn time_order(
    pendant: &Pendant<'_>,
    time: &TimeModel<f64>,
    poses: &SessionPoses,
) -> Vec<usize> {
    let n = poses.poses.len();
    let leg = |a: &[f64; JOINTS], b: &[f64; JOINTS]| {
        let check = pendant.leg(time, a, b);
        let mut c = time.leg_s(a, b);
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
        .map(|q| time.leg_s(&poses.turned, q))
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
    time.session_time(&poses.path(), |a, b| !pendant.leg(time, a, b).armed)
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
        let t = Timing::new(&profile, &TimingArgs::default(), [1; JOINTS])
            .unwrap_or_else(|e| panic!("{e}"));
        let pendant = Pendant::new(&profile);
        let mut a = profile.shown_deg(&profile.stage1_joints_rad);
        a[2] = -90.0;
        let mut b = a;
        b[5] += 0.05;
        assert!(!pendant.leg(&t.model, &a, &b).armed);
        b = a;
        b[4] += 20.0;
        let check = pendant.leg(&t.model, &a, &b);
        assert!(check.armed && !check.early_still, "{check:?}");
        // Either way round: the way back arrives against A5's approach direction and
        // goes through the approach point, still arming.
        assert!(pendant.leg(&t.model, &b, &a).armed);
    }

    #[test]
    fn approach_turns_round_at_a_limit() {
        let profile = zerocal_profile::builtin("kuka-kr16").unwrap_or_else(|e| panic!("{e}"));
        // A5 at its lower limit, -130: from below it would start at -131, outside.
        let mut t = profile.shown_deg(&profile.stage1_joints_rad);
        t[4] = -130.0;
        let dirs = approach_directions(&profile, &[t]).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(dirs, [1, 1, 1, 1, -1, 1]);
        // Both limits within the approach distance: refused, naming A5 and the limit.
        let mut narrow = profile.clone();
        narrow.joints[4].min_deg = -130.0;
        narrow.joints[4].max_deg = -129.5;
        let e = approach_directions(&narrow, &[t]).unwrap_err();
        assert_eq!(e.exit_code(), 3);
        assert!(
            e.to_string().contains("A5 (joint 5)") && e.to_string().contains("-130"),
            "{e}"
        );
    }
}
