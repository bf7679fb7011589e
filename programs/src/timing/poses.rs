//! The session's poses in the controller's joint degrees, and the mounting poses the
//! robot stands at while the pendant is clipped on or moved: poses that tilt the
//! pendant past its range, so that it cannot capture there.

use super::capture_rule::Pendant;
use super::joint_label;
use crate::robot_time::SessionPath;
use zerocal_core::model::{Tilt, JOINTS};
use zerocal_core::stage2::MEMS_RANGE_DEG;
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// How far a mounting pose turns joint 2 from the stage-1 pose (deg): enough to tilt
/// the pendant past its range on the upper arm and on the flange (stated).
pub const MOUNT_TURN_DEG: f64 = 45.0;

/// A mounting pose's predicted reading must be at least this far past the sensor's
/// range, mode 4's ±10° (deg; stated margin for the base tilt, the sensor's offset and
/// the bracket's seating).
pub const MOUNT_MARGIN_DEG: f64 = 5.0;

/// The session's poses in the controller's joint degrees.
///
/// The pendant captures by itself once it has moved and then stays still (the
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
