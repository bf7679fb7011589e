//! `zerocal plan --json`: the one object it prints (`poses_deg`, `predicted_sigma_deg`,
//! `predicted_k2_deg`, `correlation`, `robot_time`, settings), as written types.

use super::flags::PlanArgs;
use super::limits::LimitsDeg;
use super::prediction::{Correlations, PREDICTED_FROM};
use super::session_plan::SessionPlan;
use super::travel_trade::TravelTrade;
use crate::robot_time::CAPTURES_PER_POSE;
use crate::timing::SpeedSource;
use serde::Serialize;
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::real::rad_to_deg;
use zerocal_inputs::error::CliError;

/// The session's robot time in `--json`.
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct RobotTimeJson {
    /// The robot time (s): from the first mounting until the pendant is off the
    /// flange.
    pub total_s: f64,
    /// The closing bench readings after it, the robot free (s).
    pub closing_s: f64,
    /// Moving (s).
    pub motion_s: f64,
    /// Standing for settling and the pendant's still window (s).
    pub dwell_s: f64,
    /// The pendant's remount (s).
    pub remount_s: f64,
    /// Operator OKs at the pendant (s).
    pub operator_s: f64,
    /// Moves.
    pub moves: u16,
    /// Captures on the robot: two per pose (stage 1's two and every stage-2 pose).
    pub captures: u16,
    /// Mountings of the pendant (clipped to the upper arm, moved to the flange,
    /// taken off to the bench).
    pub mountings: u16,
    /// Stops for an operator's OK while the pendant is on the robot.
    pub ok_stops: u16,
    /// Joint speed, % of each joint's maximum.
    pub speed_percent: u8,
    /// Each joint's maximum speed (deg/s).
    pub max_speed_deg_s: [f64; JOINTS],
    /// Where each comes from.
    pub max_speed_source: [SpeedSource; JOINTS],
    /// Each joint's acceleration (deg/s², stated default).
    pub accel_deg_s2: [f64; JOINTS],
    /// Settling per pose (s).
    pub settle_s: f64,
    /// The wait at each capture (s): settling, still window, two sensor periods.
    pub dwell_per_capture_s: f64,
    /// Captures of every pose: first with every joint arriving from below, then from
    /// above.
    pub captures_per_pose: usize,
    /// How far below a pose every joint starts the last move to its first capture
    /// (controller degrees).
    pub approach_deg: f64,
    /// How far above a pose every joint goes before coming back for its second capture
    /// (controller degrees).
    pub overshoot_deg: f64,
    /// Why `zerocal program` would refuse this session (a capture pose without room
    /// on both sides inside the joint limits, say), if it would.
    pub program_refused: Option<String>,
    /// Poses swapped for travel where the session was over its aim
    /// ([`super::travel_trade`]); `null` where the planner's poses are kept.
    pub travel_trade: Option<TravelTrade>,
}

/// The `--json` output.
#[derive(Serialize, Debug)]
pub struct PlanJson {
    /// Robot profile.
    pub robot: String,
    /// θ1..θ6 per pose in the model's angles (deg), in the session's order: what the
    /// pendant's `plan set` takes.
    pub poses_deg: Vec<[f64; JOINTS]>,
    /// The same poses as the robot's controller shows them (deg).
    pub poses_controller_deg: Vec<[f64; JOINTS]>,
    /// Predicted 1σ of Δθ3..Δθ6 (deg).
    pub predicted_sigma_deg: [f64; WRIST_JOINTS],
    /// Predicted k = 2 uncertainty of Δθ2..Δθ6 (deg):
    /// [`predicted_k2_deg`](super::prediction::predicted_k2_deg).
    pub predicted_k2_deg: [f64; WRIST_JOINTS + 1],
    /// What the prediction includes.
    pub predicted_from: &'static str,
    /// The target asked for (deg), if any.
    pub target_k2_deg: Option<f64>,
    /// Correlations of the plan's parameters.
    pub correlation: Correlations,
    /// The session's robot time.
    pub robot_time: RobotTimeJson,
    /// Condition number of the plan's Jacobian.
    pub condition_number: f64,
    /// Largest |reading| at zero offsets (deg).
    pub max_reading_deg: f64,
    /// Window (± deg).
    pub window_deg: f64,
    /// Margin (deg).
    pub margin_deg: f64,
    /// Limits the poses were planned inside (model degrees): the profile's or
    /// `--limits`', less the room the approach from below and the overshoot above need.
    pub limits_deg: LimitsDeg,
    /// The capture noise assumed, 1σ (deg).
    pub noise_sigma_deg: f64,
    /// What the plan separates besides the offsets.
    pub fitted: Vec<&'static str>,
    /// Captures per pose the prediction assumes.
    pub captures_per_pose: usize,
    /// Criterion ("a" or "d").
    pub criterion: &'static str,
    /// Seed.
    pub seed: u64,
}

impl RobotTimeJson {
    /// The robot time of a planned session.
    pub fn new(sp: &SessionPlan) -> Self {
        let t = &sp.time;
        let tm = &sp.timing;
        RobotTimeJson {
            total_s: t.total_s,
            closing_s: t.closing_s,
            motion_s: t.motion_s,
            dwell_s: t.dwell_s,
            remount_s: t.remount_s,
            operator_s: t.operator_s,
            moves: t.moves,
            captures: t.captures,
            mountings: t.mountings,
            ok_stops: t.ok_stops,
            speed_percent: tm.speed_percent,
            max_speed_deg_s: tm.max_speed_deg_s,
            max_speed_source: tm.speed_source,
            accel_deg_s2: tm.model.accel_deg_s2,
            settle_s: tm.model.settle_s,
            dwell_per_capture_s: tm.model.dwell_s(),
            captures_per_pose: CAPTURES_PER_POSE,
            approach_deg: tm.model.approach_deg,
            overshoot_deg: tm.model.overshoot_deg,
            program_refused: sp.program_refused.clone(),
            travel_trade: sp.trade,
        }
    }
}

impl PlanJson {
    /// The object of a planned session made with `args`.
    pub fn new(args: &PlanArgs, sp: &SessionPlan) -> Self {
        let (config, p) = (&sp.config, &sp.plan);
        PlanJson {
            robot: sp.profile.name.clone(),
            poses_deg: sp.poses_model_deg(),
            poses_controller_deg: sp.poses.poses.clone(),
            predicted_sigma_deg: p.predicted_sigma_deg(),
            predicted_k2_deg: sp.k2_deg,
            predicted_from: PREDICTED_FROM,
            target_k2_deg: args.target_k2_deg,
            correlation: sp.correlation.clone(),
            robot_time: RobotTimeJson::new(sp),
            condition_number: p.condition_number,
            max_reading_deg: rad_to_deg(p.max_reading_rad),
            window_deg: args.window_deg,
            margin_deg: args.margin_deg,
            limits_deg: config
                .limits_rad
                .map(|(lo, hi)| (rad_to_deg(lo), rad_to_deg(hi))),
            noise_sigma_deg: rad_to_deg(config.noise_sigma_rad),
            fitted: p.extras.layout().params()[WRIST_JOINTS..]
                .iter()
                .map(|p| p.name())
                .collect(),
            captures_per_pose: args.captures_per_pose(),
            criterion: args.criterion.name(),
            seed: args.seed,
        }
    }

    /// The object as `--json` prints it.
    ///
    /// # Errors
    /// The serialiser's (cannot come from these types).
    pub fn to_text(&self) -> Result<String, CliError> {
        serde_json::to_string_pretty(self)
            .map_err(|e| CliError::Input(format!("cannot write JSON: {e}")))
    }
}
