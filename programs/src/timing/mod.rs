//! The robot side of a session for `zerocal plan` and `zerocal program`: the
//! robot-time model ([`crate::robot_time`]) filled in from a robot profile and
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
//!   the pendant's own (the procedure's `StillnessConfig` and `ProcedureConfig` defaults);
//!   the sensor period: the pendant's 20 Hz read rate, [`SAMPLE_PERIOD_S`]; the
//!   sensor's range: mode 4's ±10° (core's `MEMS_RANGE_DEG`).
//!
//! The parts: the session's poses and the mounting poses ([`poses`]), the room every
//! capture needs inside the joint limits ([`joint_limits`]), the pendant's capture rule
//! along a move ([`capture_rule`]), and the order of the poses that makes the session
//! short ([`tour`]).

pub mod capture_rule;
pub mod joint_limits;
pub mod poses;
pub mod tour;
pub mod unwind;

pub use capture_rule::{LegCheck, Pendant, ARM_MARGIN, EARLY_STILL_MARGIN};
pub use joint_limits::{
    check_capture_room, check_limits, check_room, planner_limit, planner_limits,
};
pub use poses::{mount_poses, SessionPoses, MOUNT_MARGIN_DEG, MOUNT_TURN_DEG};
pub use tour::{check_time, session_time, time_order};
pub use unwind::unwound;

use crate::robot_time::TimeModel;
use clap::Args;
use serde::Serialize;
use zerocal_core::model::JOINTS;
use zerocal_inputs::args::{CountIn, RealIn};
use zerocal_inputs::error::CliError;
use zerocal_procedure::stillness::StillnessConfig;
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
/// UR post-processor uses by default (docs/controllers/ur.md \[U10\]). No source gives
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

/// Longest run of a check's program (s): its moves, dwells and operator OKs, the two
/// mountings of the pendant (the technician's, [`DEFAULT_REMOUNT_S`] each) apart. Three
/// minutes: a check is meant to take no longer than a break in production (a stated
/// target, not a source's figure); five check poses keep every built-in profile inside
/// it at [`DEFAULT_SPEED_PERCENT`].
pub const CHECK_RUN_LIMIT_S: f64 = 180.0;

/// The capture scheme's approach and overshoot distances (deg): `zerocal_core::capture`
/// says why each is what it is.
pub use zerocal_core::capture::{APPROACH_DEG, OVERSHOOT_DEG};

/// The pendant's sensor period (s): the stillness rule's
/// [`zerocal_procedure::stillness::SAMPLE_PERIOD_MS`].
pub const SAMPLE_PERIOD_S: f64 = zerocal_procedure::stillness::SAMPLE_PERIOD_MS as f64 / 1000.0;

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
    /// A setting the robot-time model refuses (cannot come from the options' ranges).
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot_time::Mounting;

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
        pendant.samples(&t.model, Mounting::Flange, (&a, &b), 0.0, &mut samples);
        assert!(
            samples.len() <= MAX_MOVE_SAMPLES && samples.len() > MAX_MOVE_SAMPLES / 2,
            "{}",
            samples.len()
        );
    }
}
