//! The program model every writer shares: a session as a list of [`Step`]s (moves in
//! the controller's joint degrees, each with why the robot goes there; dwells; stops
//! for the operator), built once by [`build`](super::build::build) and written by one
//! module per family.

use super::read::ReadMove;
use crate::robot_time::{Mounting, SessionTime};
use crate::timing::{SessionPoses, Timing};
use zerocal_core::model::JOINTS;
use zerocal_profile::{OffsetUnit, Profile};

/// What a capture pose is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Capture {
    /// Stage 1, joint 1 at its mark.
    Stage1,
    /// Stage 1, joint 1 turned by 180°.
    Stage1Turned,
    /// Stage-2 pose `i` (0-based) of the plan.
    Pose(usize),
}

impl Capture {
    /// What the capture pose is, for messages.
    pub fn describe(self) -> String {
        match self {
            Capture::Stage1 => "the stage-1 pose".to_owned(),
            Capture::Stage1Turned => "the stage-1 pose with joint 1 turned by 180 deg".to_owned(),
            Capture::Pose(i) => format!("stage-2 pose {}", i + 1),
        }
    }
}

/// Which side of the backlash a capture is taken from: every joint's last move before
/// it is positive (`Below`) or negative (`Above`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The pose's first capture: every joint arrives moving in its positive direction.
    Below,
    /// The pose's second capture: every joint arrives moving negative.
    Above,
}

/// Why the robot goes to a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Where the pendant is clipped on (`crate::timing::mount_poses`).
    Mount(Mounting),
    /// Where the robot parks for the closing bench readings (the flange's mounting pose).
    Park,
    /// Joint 1 turned by 180° (short of the turned pose by the approach distance).
    Turn,
    /// The point a capture's last move starts from: the approach distance below the
    /// pose on every joint (`Below`), or the overshoot above it (`Above`).
    Approach(Side),
    /// A pose the pendant captures at, from one side.
    Capture(Capture, Side),
}

/// One statement of the session.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    /// A comment line.
    Comment(String),
    /// A joint move with an exact stop, to controller degrees.
    Move {
        /// The target (controller degrees).
        target_deg: [f64; JOINTS],
        /// Why.
        role: Role,
        /// The move's time in the time model (s): RAPID's `\T`. `None` for the
        /// first move, which starts from a pose the program does not know.
        time_s: Option<f64>,
    },
    /// Stand still (s).
    Dwell(f64),
    /// Show the message lines and stop until the operator continues.
    Stop(Vec<String>),
}

/// A whole session, ready for a family's writer.
#[derive(Clone, Debug)]
pub struct Session {
    /// The program's name.
    pub name: String,
    /// The robot.
    pub profile: Profile,
    /// The header's lines (what, speed, collision warning).
    pub header: Vec<String>,
    /// The statements in order.
    pub steps: Vec<Step>,
    /// The time model.
    pub timing: Timing,
    /// The predicted robot time.
    pub time: SessionTime<f64>,
    /// The session's poses in the controller's degrees, stage 2's in order.
    pub poses: SessionPoses,
}

impl Session {
    /// Each move's target with the dwell and the stop that follow it, if any: what a
    /// reader gives back (a stop's message lines joined by spaces).
    pub fn moves(&self) -> Vec<ReadMove> {
        let mut out: Vec<ReadMove> = Vec::new();
        for s in &self.steps {
            match s {
                Step::Move { target_deg, .. } => out.push(ReadMove {
                    joints_deg: *target_deg,
                    dwell_s: None,
                    stop: None,
                }),
                Step::Dwell(t) => {
                    if let Some(last) = out.last_mut() {
                        last.dwell_s = Some(*t);
                    }
                }
                Step::Stop(lines) => {
                    if let Some(last) = out.last_mut() {
                        last.stop = Some(lines.join(" "));
                    }
                }
                Step::Comment(_) => {}
            }
        }
        out
    }

    /// The joint speed (rad/s) and acceleration (rad/s²) of URScript's `movej`: the
    /// reduced speed of the slowest joint, so no joint exceeds its own.
    pub fn ur_speed(&self) -> (f64, f64) {
        let v = self
            .timing
            .model
            .speed_deg_s
            .iter()
            .fold(f64::INFINITY, |m, v| m.min(*v));
        let a = self
            .timing
            .model
            .accel_deg_s2
            .iter()
            .fold(f64::INFINITY, |m, v| m.min(*v));
        (v.to_radians(), a.to_radians())
    }

    /// Pulses per degree of each joint, for INFORM.
    pub fn pulses_per_deg(&self) -> Option<[f64; JOINTS]> {
        match self.profile.controller.unit {
            OffsetUnit::Counts(Some(c)) => Some(c),
            _ => None,
        }
    }
}
